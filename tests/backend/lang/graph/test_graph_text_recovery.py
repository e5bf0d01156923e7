"""Broken .graph text: each mistake is one diagnostic with its code, line and column, reading
goes on with the next row, step, transition or block, and nothing raises, even on mangled or
very long files."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nasaq.lang.graph.model import Action
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph, print_graph
from nasaq.lang.lad.model import Contact, Series

FIXTURES = Path(__file__).parent / "fixtures" / "ok"

HEAD = """\
FUNCTION_BLOCK FB 1
BEGIN
SEQUENCER Main
INITIAL_STEP Idle (1)
ACTIONS
  N Q 0.0;
END_ACTIONS
END_STEP
"""  # the snippet starts on line 9
TAIL = """
STEP Last (9)
ACTIONS
  S Q 9.9;
END_ACTIONS
END_STEP
TRANSITION T_last (9) FROM Idle TO Last
CONDITION Contact(I 9.9) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""


def where(parsed: ParsedGraph) -> list[tuple[str, int | None, int | None]]:
    return [(d.code, d.span.line, d.span.column) for d in parsed.diagnostics if d.span]


def assert_rest_was_read(parsed: ParsedGraph) -> None:
    [block] = parsed.blocks
    [sequencer] = block.sequencers
    last = next(step for step in sequencer.steps if step.name == "Last")
    assert last.actions == [Action(id="a1", qualifier="S", operand="Q 9.9")]
    final = next(t for t in sequencer.transitions if t.name == "T_last")
    assert final.condition is not None
    assert final.condition.elements == [Contact(id="e1", operand="I 9.9")]
    assert sequencer.steps[0].actions[0].operand == "Q 0.0"


ROW = "STEP Two (2)\nACTIONS\n{row}\n  N Q 1.1;\nEND_ACTIONS\nEND_STEP"
BROKEN = [
    # action rows: the row is dropped, the next row is read
    (ROW.format(row="  X Q 1.0;"), [("GRA121", 11, 3)], 1),
    (ROW.format(row="  S1 ;"), [("GRA121", 11, 6)], 1),
    (ROW.format(row="  N ;"), [("GRA122", 11, 3)], 1),
    (ROW.format(row="  D Q 1.0, T#1S, x;"), [("GRA124", 11, 16)], 1),
    (ROW.format(row="  D Q 1.0, ;"), [("GRA125", 11, 10)], 1),
    (ROW.format(row='  N "Q 1.0;'), [("LAD127", 11, 5)], 1),
    # ... or kept when only its ';' or its id is wrong (reported)
    (ROW.format(row="  N Q 1.0"), [("GRA123", 11, 10)], 2),
    (ROW.format(row="  N Q 1.0 @;"), [("GRA127", 11, 11)], 2),
    (ROW.format(row="  N Q 1.0 @a2;"), [("GRA126", 12, 3)], 2),
    # steps
    ("STEP Two\nACTIONS\n  N Q 1.0;\nEND_ACTIONS\nEND_STEP", [("GRA109", 10, 1)], None),
    ("STEP Two (0)\nEND_STEP", [("GRA110", 9, 11)], None),
    ("STEP (2)\nEND_STEP", [("GRA108", 9, 6)], None),
    ("STEP Two (2)\nACTIONS\n  N Q 1.0;\nEND_ACTIONS", [("GRA111", 13, 1)], 1),
    ("STEP Two (2)\nACTIONS\n  N Q 1.0;\nEND_STEP", [("GRA111", 12, 1)], 1),
    ("STEP Two (2)\nFOO Q 1.0\nACTIONS N Q 1.0; END_ACTIONS\nEND_STEP", [("GRA113", 10, 1)], 1),
    ("STEP Two (2)\nACTIONS N Q 1.0; END_ACTIONS\nACTIONS END_ACTIONS\nEND_STEP",
     [("GRA115", 11, 1)], 0),
    # transitions
    ("TRANSITION Tx (5) Idle TO Last\nEND_TRANSITION", [("GRA118", 9, 19)], None),
    ("TRANSITION Tx (5) FROM Idle Last\nEND_TRANSITION", [("GRA119", 9, 29)], None),
    ("TRANSITION Tx (5) FROM (Idle Last) TO Last\nEND_TRANSITION", [("GRA132", 9, 30)], None),
    ("TRANSITION Tx (5) FROM () TO Last\nEND_TRANSITION", [("GRA120", 9, 25)], None),
    ("TRANSITION Tx FROM Idle TO Last\nEND_TRANSITION", [("GRA109", 9, 15)], None),
    ("TRANSITION Tx (5) FROM Idle TO Last\nCOMMENT = ok\nEND_STEP\nEND_TRANSITION",
     [("GRA114", 11, 1)], None),
    # conditions: LAD mistakes are LAD's codes, Graph's structure is never swallowed
    ("TRANSITION Tx (5) FROM Idle TO Last\nCONDITION Contact(I 1.0) Coil(Q 1.0) END_CONDITION\n"
     "END_TRANSITION", [("GRA116", 10, 26)], None),
    ("TRANSITION Tx (5) FROM Idle TO Last\nCONDITION Contacts(I 1.0) END_CONDITION\n"
     "END_TRANSITION", [("LAD110", 10, 11)], None),
    ("TRANSITION Tx (5) FROM Idle TO Last\nCONDITION Contact(I 1.0 END_CONDITION\n"
     "END_TRANSITION", [("LAD111", 10, 25)], None),
    ("TRANSITION Tx (5) FROM Idle TO Last\nCONDITION Contact(I 1.0)\nEND_TRANSITION",
     [("GRA111", 11, 1)], None),
    ("TRANSITION Tx (5) FROM Idle TO Last\nCONDITION Contact(I 1.0) @x Contact(I 1.1) @x "
     "END_CONDITION\nEND_TRANSITION", [("GRA117", 10, 44)], None),
    ("TRANSITION Tx (5) FROM Idle TO Last\nCONDITION END_CONDITION\nCONDITION END_CONDITION\n"
     "END_TRANSITION", [("GRA115", 11, 1)], None),
    ("STEP Two (2)\nINTERLOCK PARALLEL BRANCH Contact(I 1.0) END_BRANCH END_INTERLOCK\n"
     "END_STEP", [("LAD117", 10, 53)], 0),
    # the sequencer
    ("hello world", [("GRA112", 9, 1)], None),
]  # fmt: skip


@pytest.mark.parametrize(("snippet", "expected", "rows"), BROKEN)
def test_one_mistake_is_one_diagnostic_and_the_rest_is_read(
    snippet: str, expected: list[tuple[str, int, int]], rows: int | None
) -> None:
    parsed = parse_graph(HEAD + snippet + TAIL, "bad.graph")
    assert where(parsed) == expected
    assert all(d.span is not None and d.span.file == "bad.graph" for d in parsed.diagnostics)
    assert_rest_was_read(parsed)
    steps = {step.name: step for step in parsed.blocks[0].sequencers[0].steps}
    if rows is not None:  # the step with the mistake is kept with its good rows
        assert len(steps["Two"].actions) == rows
    elif snippet.startswith("STEP"):  # a step whose header is broken is left out
        assert "Two" not in steps


def test_several_mistakes_in_one_file_are_each_reported_with_their_line() -> None:
    text = """\
FUNCTION_BLOCK FB 1
BEGIN
SEQUENCER Main
INITIAL_STEP Idle (1)
ACTIONS
  N Q 0.0;
  Q Q 0.1;
  S Q 0.2;
END_ACTIONS
END_STEP
STEP Broken
ACTIONS N Q 5.0; END_ACTIONS
END_STEP
TRANSITION T1 (1) FROM Idle TO Fill
CONDITION Contact(I 0.0) SetCoil(M 0.0) END_CONDITION
END_TRANSITION
STEP Fill (2)
ACTIONS
  D Q 1.0, ;
  N Q 1.1;
END_ACTIONS
END_STEP
TRANSITION T2 (2) FROM Fill Idle
END_TRANSITION
TRANSITION T3 (3) FROM Fill TO Idle
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""
    parsed = parse_graph(text, "many.graph")
    assert [(code, line) for code, line, _ in where(parsed)] == [
        ("GRA121", 7),
        ("GRA109", 12),
        ("GRA116", 15),
        ("GRA125", 19),
        ("GRA119", 23),
    ]
    [sequencer] = parsed.blocks[0].sequencers
    assert [step.name for step in sequencer.steps] == ["Idle", "Fill"]
    assert [a.operand for a in sequencer.steps[0].actions] == ["Q 0.0", "Q 0.2"]
    assert [a.operand for a in sequencer.steps[1].actions] == ["Q 1.1"]
    assert [t.name for t in sequencer.transitions] == ["T1", "T3"]
    assert sequencer.transitions[0].condition is not None
    assert sequencer.transitions[0].condition.elements == [Contact(id="e1", operand="I 0.0")]
    assert parsed.places[0]["T3"] == 25


BLOCKS = [
    ("junk\nFUNCTION_BLOCK FB 1\nBEGIN\nEND_FUNCTION_BLOCK\n", [("GRA101", 1, 1)]),
    ("FUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION\nFUNCTION_BLOCK FB 1\nBEGIN\n"
     "END_FUNCTION_BLOCK\n", [("GRA102", 1, 1)]),
    ("FUNCTION_BLOCK FC 1\nBEGIN\nEND_FUNCTION_BLOCK\n", [("GRA103", 1, 16)]),
    ("FUNCTION_BLOCK FB 1\nVAR x : INT; END_VAR\nSEQUENCER A\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n",
     [("GRA104", 3, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nEND_SEQUENCER\n", [("GRA105", 5, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nSTEP A (1) END_STEP\nEND_FUNCTION_BLOCK\n",
     [("GRA106", 3, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nEND_SEQUENCER\nPERMANENT_PRE\n"
     "END_PERMANENT_PRE\nEND_FUNCTION_BLOCK\n", [("GRA107", 5, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nSTEP B (1) END_STEP\nEND_FUNCTION_BLOCK\n",
     [("GRA111", 5, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER 12\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n",
     [("GRA108", 3, 11)]),
    ("FUNCTION_BLOCK FB 1\nSETTINGS\n  SKIP := TRUE;\n  ACKNOWLEDGE := YES;\n"
     "  PARAMETERS := MINIMUM;\n  PARAMETERS = MAXIMUM;\n  SKIP_STEPS := TRUE\n"
     "  SKIP_STEPS := FALSE;\nEND_SETTINGS\nBEGIN\nEND_FUNCTION_BLOCK\n",
     [("GRA128", 3, 3), ("GRA129", 4, 18), ("GRA132", 6, 14), ("GRA132", 8, 3),
      ("GRA130", 8, 3)]),
    ("FUNCTION_BLOCK FB 1\nSETTINGS\n  PARAMETERS := MINIMUM;\nVAR\n  x : INT;\nEND_VAR\n"
     "BEGIN\nEND_FUNCTION_BLOCK\n", [("GRA111", 4, 1)]),
    ("FUNCTION_BLOCK FB 1\nTITLE = a\nTITLE = b\nBEGIN\nEND_FUNCTION_BLOCK\n", [("GRA130", 3, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nPERMANENT_PRE\nRUNG Contact(I 0.0) Coil(Q 0.0) END_RUNG\n"
     "END_PERMANENT_PRE\nEND_FUNCTION_BLOCK\n", [("GRA131", 4, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nPERMANENT_POST\nNETWORK\nRUNG Contact(I 0.0) Coil(Q 0.0)\n"
     "END_PERMANENT_POST\nEND_FUNCTION_BLOCK\n", [("LAD109", 6, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\nPERMANENT_POST\nNETWORK\nRUNG Contact(I 0.0) Coil(Q 0.0)\n"
     "END_RUNG\nEND_FUNCTION_BLOCK\n", [("GRA111", 7, 1)]),
    ("FUNCTION_BLOCK FB 1\nBEGIN\n(* never closed\nEND_FUNCTION_BLOCK\n", [("LAD126", 3, 1)]),
]  # fmt: skip


@pytest.mark.parametrize(("text", "expected"), BLOCKS)
def test_block_mistakes_are_reported_and_reading_goes_on(
    text: str, expected: list[tuple[str, int, int]]
) -> None:
    parsed = parse_graph(text, "block.graph")
    assert where(parsed) == expected
    assert len(parsed.places) == len(parsed.blocks)
    if "LAD126" not in text and not text.startswith("FUNCTION FC"):
        assert parsed.blocks, "the block is kept with what could be read"


def test_without_begin_the_declarations_end_where_the_sequencers_start() -> None:
    text = "FUNCTION_BLOCK FB 1\nVAR\n  x : INT;\nEND_VAR\nSEQUENCER A\nSTEP B (1) END_STEP\n"
    parsed = parse_graph(text + "END_SEQUENCER\nEND_FUNCTION_BLOCK\n", "begin.graph")
    assert where(parsed) == [("GRA104", 5, 1)]
    [block] = parsed.blocks
    assert block.declarations == "VAR\n  x : INT;\nEND_VAR"
    assert block.sequencers[0].steps[0].name == "B"


def test_the_next_block_is_read_after_an_unclosed_one() -> None:
    text = (
        "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nSTEP X (1)\n"
        "FUNCTION_BLOCK FB 2\nBEGIN\nSEQUENCER B\nSTEP Y (1) END_STEP\nEND_SEQUENCER\n"
        "END_FUNCTION_BLOCK\n"
    )
    parsed = parse_graph(text, "two.graph")
    assert [code for code, _, _ in where(parsed)] == ["GRA111", "GRA111", "GRA105"]
    assert [b.name for b in parsed.blocks] == ["FB 1", "FB 2"]
    assert parsed.blocks[1].sequencers[0].steps[0].name == "Y"


# ---- never a traceback ------------------------------------------------------------------------

PIECES = [
    "FUNCTION_BLOCK FB 1\n", "BEGIN\n", "END_FUNCTION_BLOCK\n", "SEQUENCER S\n",
    "END_SEQUENCER\n", "STEP A (1)\n", "INITIAL_STEP B (2)\n", "END_STEP\n",
    "TRANSITION T (1) FROM A TO B\n", "FROM (A, B) ", "JUMP A ", "STOP ", "END_TRANSITION\n",
    "CONDITION ", "END_CONDITION ", "INTERLOCK ", "END_INTERLOCK ", "SUPERVISION ",
    "END_SUPERVISION ", "ACTIONS\n", "END_ACTIONS\n", "S1 NC Q 0.0;", "D Q 0.1, T#5S;",
    "CS C 1, C#2;", "N #a := #a + 1;", "CALL FB 2, DB 2;", " @x", ";", ",", "(", ")", '"',
    "(*", "*)", "//", "\n", "Contact(I 0.0) ", "Coil(Q 0.0) ", "PARALLEL BRANCH ",
    "END_BRANCH ", "END_PARALLEL ", "PERMANENT_PRE\n", "END_PERMANENT_PRE\n", "NETWORK\n",
    "RUNG ", "END_RUNG\n", "SETTINGS\n", "PARAMETERS := MAXIMUM;", "END_SETTINGS\n",
    "COMMENT = c\n", "VAR x : INT; END_VAR\n", ":=",
]  # fmt: skip


def check_never_broken(parsed: ParsedGraph) -> None:
    assert all(d.span is not None and d.span.line and d.span.column for d in parsed.diagnostics)
    assert len(parsed.places) == len(parsed.blocks)
    if not parsed.diagnostics:
        again = parse_graph(print_graph(parsed.blocks), "again.graph")
        assert (again.blocks, again.diagnostics) == (parsed.blocks, [])


@settings(max_examples=120, deadline=None)
@given(st.lists(st.sampled_from(PIECES), max_size=40))
def test_any_sequence_of_pieces_reads_without_exception(pieces: list[str]) -> None:
    check_never_broken(parse_graph("".join(pieces), "pieces.graph"))


@settings(max_examples=60, deadline=None)
@given(st.data())
def test_mangled_fixtures_never_raise(data: st.DataObject) -> None:
    text = (
        FIXTURES / data.draw(st.sampled_from(["branches.graph", "permanent.graph"]))
    ).read_text()
    for _ in range(data.draw(st.integers(1, 4))):
        start = data.draw(st.integers(0, len(text)))
        end = data.draw(st.integers(start, min(len(text), start + 15)))
        piece = data.draw(st.sampled_from(["", ";", "(", '"', "(*", "END_STEP", text[start:end]]))
        text = text[:start] + piece + text[end:]
    check_never_broken(parse_graph(text, "fuzz.graph"))


# ---- a very long file -------------------------------------------------------------------------


def long_source(steps: int, broken: int | None = None) -> str:
    parts = ["FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Big\n"]
    for n in range(1, steps + 1):
        keyword = "INITIAL_STEP" if n == 1 else "STEP"
        qualifier = "Q" if n == broken else "N"  # Q is no qualifier: one broken row
        condition = f"CONDITION Contact(I 0.{n % 8}) END_CONDITION " if n % 10 == 0 else ""
        parts.append(
            f"{keyword} S_{n} ({n})\nACTIONS\n  {qualifier} Q {n % 100}.{n % 8};\n"
            "END_ACTIONS\nEND_STEP\n"
            f"TRANSITION T_{n} ({n}) FROM S_{n} TO S_{n % steps + 1}\n"
            f"{condition}END_TRANSITION\n"
        )
    parts.append("END_SEQUENCER\nEND_FUNCTION_BLOCK\n")
    return "".join(parts)


def test_a_ten_thousand_step_source_reads_completely() -> None:
    """No timing here (the benches time it): the whole file is read, right, without a
    traceback, and a mistake in its middle is one diagnostic on its line."""
    parsed = parse_graph(long_source(10_000, broken=5_000), "big.graph")
    assert [(code, line) for code, line, _ in where(parsed)] == [("GRA121", 5_000 * 7 - 1)]
    [sequencer] = parsed.blocks[0].sequencers
    assert len(sequencer.steps) == len(sequencer.transitions) == 10_000
    assert sequencer.steps[-1].actions[0].operand == "Q 0.0"
    assert sequencer.steps[4_999].actions == []
    assert sequencer.transitions[-1].target == ["S_1"]
    assert sequencer.transitions[9].condition == Series(
        elements=[Contact(id="e1", operand="I 0.2")]
    )
    assert sequencer.transitions[10].condition is None
    assert parsed.places[0]["S10000"] == 10_000 * 7 - 3
    assert parsed.places[0]["T10000"] == 10_000 * 7 + 2

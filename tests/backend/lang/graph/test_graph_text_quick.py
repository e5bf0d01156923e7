"""The quick readings of plain action rows and conditions (``text_actions.plain_row``,
``text_conditions.plain_condition``) give exactly what the general reading gives: the same
blocks, ids, places and diagnostics, on plain text and on text that only looks plain."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nasaq.lang.graph import text_parse
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.graph.text_actions import plain_row as row
from nasaq.lang.graph.text_conditions import plain_condition as condition

SOURCE = """\
FUNCTION_BLOCK FB 1
BEGIN
SEQUENCER Main
INITIAL_STEP One (1)
INTERLOCK {interlock} END_INTERLOCK
ACTIONS
{rows}
END_ACTIONS
END_STEP
TRANSITION Go (1) FROM One TO Two
CONDITION {condition} END_CONDITION
END_TRANSITION
STEP Two (2)
ACTIONS
  N Q 1.1;
END_ACTIONS
END_STEP
TRANSITION Back (2) FROM Two JUMP One
CONDITION Contact(I 9.9) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""


@contextmanager
def general_reading_only() -> Iterator[None]:
    """The reader with its quick ways switched off."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(text_parse, "plain_row", lambda *args: None)
        patch.setattr(text_parse, "plain_condition", lambda *args: None)
        yield


def reading(parsed: ParsedGraph) -> tuple[Any, ...]:
    problems = [
        (d.code, d.span.line if d.span else None, d.span.column if d.span else None, d.message)
        for d in parsed.diagnostics
    ]
    return [block.model_dump() for block in parsed.blocks], problems, parsed.places


def assert_same_as_general(text: str) -> ParsedGraph:
    quick = parse_graph(text, "quick.graph")
    with general_reading_only():
        general = parse_graph(text, "quick.graph")
    assert reading(quick) == reading(general)
    return quick


def source(rows: list[str], condition: str, interlock: str = "ContactNC(I 3.1)") -> str:
    return SOURCE.format(
        rows="\n".join(f"  {row}" for row in rows), condition=condition, interlock=interlock
    )


PLAIN_ROWS = [
    "N Q 0.0;",
    "S1 N M 10.1;  // on entry",
    "s0 r M 10.2;//",
    "NC Q 0.1;",
    "N C Q 0.2;",  # the C suffix as a word of its own
    "CS C 1, C#26;",  # C 1 is the counter, not the suffix
    "N C, T#2S;",
    "D M 14.4, T#2S;",
    "L\tM 14.5 ,\tT#1S ;",
    "S1 N #count := #count + 1;",
    "S1 N   #a   :=   #b  *  2 ;",
    "CALL FB 2, DB 2;",
    "TL T 0, S5T#8S;",
    "ON S3;",
    "OFF S_ALL;",
]
TRICKY_ROWS = [
    "N Q 0.0, T#1S, T#2S;",  # two commas: reported
    "D M 1.0, ;",  # no time after the comma
    "X Q 0.0;",  # no qualifier
    "S9 N Q 0.0;",  # no event
    "N Q 0.0 STEP;",  # a Graph word in the operand: the row ends before it
    "N Q 0.0",  # no ';'
    "N ;",
    "N := 1;",
    'N "Motor Start";',
    "N Q 0.0 @a1;",
    "N Q 0.0; N Q 0.1 @a1;",
    "N Q 0.0 (* why *);",
    "N #a := SIN(MD 0);",
    "N Q 0.0 / 2;",
    "N1 Q 0.0;",
]
PLAIN_CONDITIONS = [
    "",
    "Contact(I 0.1) ContactNC(I 1.1)",
    'Contact("Start") ContactNC( "Stop".bit )',
    "Parallel Branch Contact(I 0.1) END_BRANCH Branch END_BRANCH END_PARALLEL Contact(M 1.0)",
    "Box(CMP>=D, IN1 := One.T, IN2 := T#5S) Contact(I 0.0)",
    "Box(CMP==I, IN1 := MW 2, IN2 := 7, OUT => M 0.0)",
    "Parallel Branch Parallel Branch Contact(A) END_BRANCH Branch Contact(B) END_BRANCH "
    "END_PARALLEL END_BRANCH Branch Contact(C) END_BRANCH END_PARALLEL",
    "contact(I 0.1)\n  contactnc(I 0.2)",
]
TRICKY_CONDITIONS = [
    "Contact(I 0.1) @e1 Contact(I 0.2)",
    "Contact(I 0.1) Contact(I 0.2) @e1",
    "Contact(I 0.1 STEP)",
    "Contact(I 0.1, I 0.2)",
    "Contact()",
    "Contact(I\n0.1)",
    "Contact(I 0.1) // why\nContact(I 0.2)",
    "Contact(DB1.DBX(2))",
    'Contact("open)',
    "Parallel Branch Contact(A) END_BRANCH END_PARALLEL",
    "Parallel Branch Contact(A) END_PARALLEL",
    "Box(CMP>D, IN1 := #a, IN1 := #b)",
    "Box(CMP>D, INSTANCE DB 1, IN1 := #a)",
    "Box(CMP>D, EN := RUNG Contact(A) END_RUNG, IN1 := #a, IN2 := 1)",
    "Box(, IN1 := #a)",
    "Coil(Q 0.0)",
    "Not",
    "Contact(I 0.1) END_STEP",
]


@pytest.mark.parametrize("row", PLAIN_ROWS + TRICKY_ROWS)
def test_each_row_reads_as_the_general_reading_reads_it(row: str) -> None:
    assert_same_as_general(source(["N Q 9.0;", row, "R Q 9.1;"], "Contact(I 0.0)"))


@pytest.mark.parametrize("condition", PLAIN_CONDITIONS + TRICKY_CONDITIONS)
def test_each_condition_reads_as_the_general_reading_reads_it(condition: str) -> None:
    assert_same_as_general(source(["N Q 0.0;"], condition, interlock=condition))


def test_plain_rows_and_conditions_are_read_the_quick_way() -> None:
    """The quick ways do take the plain text (else the tests above would compare the general
    reading with itself)."""
    plain = source(PLAIN_ROWS, PLAIN_CONDITIONS[4])
    taken: list[str] = []

    def counting_row(*args: Any) -> Any:
        found = row(*args)
        taken.append("row" if found is not None else "general row")
        return found

    def counting_condition(*args: Any) -> Any:
        found = condition(*args)
        taken.append("condition" if found is not None else "general condition")
        return found

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(text_parse, "plain_row", counting_row)
        patch.setattr(text_parse, "plain_condition", counting_condition)
        parsed = assert_same_as_general(plain)
    assert parsed.diagnostics == []
    assert taken.count("row") == len(PLAIN_ROWS) + 1
    assert taken.count("condition") == 3
    assert "general condition" not in taken


WORDS = ["N", "S1", "C", "Q", "0.1", "M", "#a", ":=", "+", ",", "T#2S", "STEP", "@a1", "//x"]
MARKS = ["", " ", "  ", "\t", ";", ",", "(", ")", '"', "(*", "*)", "\n"]
ELEMENTS = [
    "Contact(I 0.1)",
    "ContactNC(#x)",
    "Box(CMP>I, IN1 := #a, IN2 := 3)",
    "Parallel",
    "Branch",
    "END_BRANCH",
    "END_PARALLEL",
    "@e2",
    "(",
    ")",
    ",",
    "//c\n",
]


@settings(max_examples=150, deadline=None)
@given(
    rows=st.lists(
        st.lists(st.sampled_from(WORDS + MARKS), max_size=8).map("".join).map(lambda r: r + ";"),
        max_size=4,
    ),
    condition=st.lists(st.sampled_from(ELEMENTS), max_size=6).map(" ".join),
)
def test_generated_rows_and_conditions_read_as_the_general_reading_reads_them(
    rows: list[str], condition: str
) -> None:
    assert_same_as_general(source(rows, condition, interlock=condition))

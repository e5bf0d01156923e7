"""Reading the .graph format: action rows (events, qualifiers, the C suffix, operands, times,
assignments), links, settings, comments, case, and where each part was written."""

from __future__ import annotations

import pytest

from nasaq.lang.graph.model import Action, Settings
from nasaq.lang.graph.text import parse_graph, print_graph
from nasaq.lang.lad.model import Box, Contact

HEAD = "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Main\nINITIAL_STEP Idle (1)\nACTIONS\n"
TAIL = "END_ACTIONS\nEND_STEP\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n"


def row(text: str) -> Action:
    parsed = parse_graph(HEAD + text + "\n" + TAIL, "row.graph")
    assert parsed.diagnostics == [], [d.message for d in parsed.diagnostics]
    [action] = parsed.blocks[0].sequencers[0].steps[0].actions
    return action


ROWS = [
    ("N Q 0.0;", None, "N", False, "Q 0.0", None),
    ("S1 N Q 0.0;", "S1", "N", False, "Q 0.0", None),
    ("S \"Belt\";", None, "S", False, '"Belt"', None),
    ("S1 S S3;", "S1", "S", False, "S3", None),  # S1 is an event, S the qualifier
    ("NC Q 0.0;", None, "N", True, "Q 0.0", None),
    ("N C Q 0.0;", None, "N", True, "Q 0.0", None),
    ("n c #flag;", None, "N", True, "#flag", None),
    ("V1 SC M 1.0;", "V1", "S", True, "M 1.0", None),
    ("CS C 1, C#26;", None, "CS", False, "C 1", "C#26"),  # C 1 is the counter
    ("CSC C 1, MW 4;", None, "CS", True, "C 1", "MW 4"),
    ("CS C C 1, C#5;", None, "CS", True, "C 1", "C#5"),
    ("CU C 2;", None, "CU", False, "C 2", None),
    ("A1 CRC C 3;", "A1", "CR", True, "C 3", None),
    ("D Q 0.1, T#5S;", None, "D", False, "Q 0.1", "T#5S"),
    ("LC M 2.0 ,  #wait ;", None, "L", True, "M 2.0", "#wait"),
    ("TL T 0, S5T#8S;", None, "TL", False, "T 0", "S5T#8S"),
    ("L0 TDC T 1, S5T#1S;", "L0", "TD", True, "T 1", "S5T#1S"),
    ("TR T 1;", None, "TR", False, "T 1", None),
    ("CALL FC 1;", None, "CALL", False, "FC 1", None),
    ("S0 CALLC FB 2, DB 2;", "S0", "CALL", True, "FB 2, DB 2", None),
    ("ON S3;", None, "ON", False, "S3", None),
    ("R1 OFFC S_ALL;", "R1", "OFF", True, "S_ALL", None),
    ("ON Fill;", None, "ON", False, "Fill", None),
    ("S1 N #count:=#count+1;", "S1", "N", False, "#count := #count+1", None),
    ("N   #a   :=   #a  +  1 ;", None, "N", False, "#a := #a + 1", None),
    ('NC #E := SIN(MD 0) * "k  2";', None, "N", True, '#E := SIN(MD 0) * "k  2"', None),
    ("N MW 2 := MAX(IN1 := MW 4, IN2 := 3);", None, "N", False,
     "MW 2 := MAX(IN1 := MW 4, IN2 := 3)", None),
    ("S DB5.DBX 2.1;", None, "S", False, "DB5.DBX 2.1", None),
    ('R "Data".flags[2];', None, "R", False, '"Data".flags[2]', None),
    ("N Q (* not this *) 0.0;", None, "N", False, "Q   0.0", None),
    ('N "a;b//c";', None, "N", False, '"a;b//c"', None),
]  # fmt: skip


@pytest.mark.parametrize(("text", "event", "qualifier", "interlock", "operand", "time"), ROWS)
def test_an_action_row_reads_as_written(
    text: str, event: str | None, qualifier: str, interlock: bool, operand: str, time: str | None
) -> None:
    found = row(text)
    assert (found.event, found.qualifier, found.interlock) == (event, qualifier, interlock)
    assert (found.operand, found.time) == (operand, time)
    assert found.id == "a1"


def test_any_event_goes_with_any_qualifier_when_reading() -> None:
    """Legality of event x qualifier is the checker's: the reader keeps what was written."""
    assert row("A1 TL T 0, S5T#1S;").event == "A1"
    assert row("V0 CALL FC 3;").event == "V0"


def test_row_comments_ids_and_several_rows_on_a_line() -> None:
    text = (
        "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Main\nINITIAL_STEP Idle (1)\nACTIONS\n"
        "  S Q 0.0;  // switch on\n"
        "  ON S3;  OFF S_ALL; // both\n"
        "  // a comment line between rows\n"
        "  N Q 0.1 @blink;\n"
        "  (* a block comment *) R Q 0.2;\n"
        "END_ACTIONS\nEND_STEP\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n"
    )
    parsed = parse_graph(text, "rows.graph")
    assert parsed.diagnostics == []
    actions = parsed.blocks[0].sequencers[0].steps[0].actions
    assert [(a.id, a.operand, a.comment) for a in actions] == [
        ("a1", "Q 0.0", "switch on"),
        ("a2", "S3", ""),
        ("a3", "S_ALL", "both"),
        ("blink", "Q 0.1", ""),
        ("a5", "Q 0.2", ""),
    ]
    places = parsed.places[0]
    assert [places[f"S1/A{n}"] for n in range(1, 6)] == [6, 7, 7, 9, 10]


BRIEF = """\
FUNCTION_BLOCK "Conveyors"                 // or FB 1
TITLE = Two conveyors                      // optional
COMMENT = Start B then A
COMMENT = stop A then B
settings
  PARAMETERS := maximum;
  interlock_blocks := TRUE;
END_SETTINGS
VERSION : 0.1
VAR
  count : INT;   // BEGIN in a comment does not end the declarations
END_VAR
BEGIN
SEQUENCER Conveyor
COMMENT = optional
INITIAL_STEP Idle (1)
END_STEP
transition Trans1 (1) from Idle to (B_on, Lamp)
condition Contact("Start") ContactNC("Emergency") end_condition
END_TRANSITION
STEP B_on (2)
INTERLOCK Contact(I 0.5) END_INTERLOCK
SUPERVISION Box(CMP>D, IN1 := B_on.T, IN2 := T#10S) END_SUPERVISION
END_STEP
STEP Lamp (3) END_STEP
TRANSITION Trans2 (2) FROM (B_on, Lamp) JUMP Idle
CONDITION END_CONDITION
END_TRANSITION
TRANSITION Trans3 (3) FROM Lamp STOP
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""


def test_the_brief_example_reads_as_its_model() -> None:
    parsed = parse_graph(BRIEF, "brief.graph")
    assert parsed.diagnostics == []
    [block] = parsed.blocks
    assert (block.name, block.title, block.comment) == (
        '"Conveyors"',
        "Two conveyors                      // optional",
        "Start B then A\nstop A then B",
    )
    assert block.settings == Settings(parameters="MAXIMUM", interlock_blocks=True)
    assert block.declarations == (
        "VERSION : 0.1\nVAR\n  count : INT;   // BEGIN in a comment does not end the "
        "declarations\nEND_VAR"
    )
    [sequencer] = block.sequencers
    assert sequencer.comment == "optional"
    assert [(s.name, s.number, s.initial) for s in sequencer.steps] == [
        ("Idle", 1, True),
        ("B_on", 2, False),
        ("Lamp", 3, False),
    ]
    first, second, third = sequencer.transitions
    assert (first.source, first.target, first.jump) == (["Idle"], ["B_on", "Lamp"], False)
    assert first.condition is not None
    assert first.condition.elements == [
        Contact(id="e1", operand='"Start"'),
        Contact(id="e2", operand='"Emergency"', negated=True),
    ]
    assert (second.source, second.target, second.jump) == (["B_on", "Lamp"], ["Idle"], True)
    assert second.condition is not None
    assert second.condition.elements == []
    assert (third.target, third.condition) == ([], None)
    step = sequencer.steps[1]
    assert step.interlock is not None
    assert step.supervision is not None
    assert step.supervision.elements == [
        Box(id="e1", name="CMP>D", inputs={"IN1": "B_on.T", "IN2": "T#10S"})
    ]
    assert parsed.places == [
        {
            "BLOCK": 1,
            "SETTINGS": 5,
            "SEQ:Conveyor": 14,
            "S1": 16,
            "T1": 18,
            "S2": 21,
            "S2/C": 22,
            "S2/V": 23,
            "S3": 25,
            "T2": 26,
            "T3": 29,
        }
    ]
    assert parsed.line(0, "S2/V") == 23
    assert parsed.line(0, "S99") == 1


def test_a_title_comment_in_the_header_stays_in_the_title() -> None:
    """As in a .lad file, TITLE = takes the rest of its line (comments included)."""
    parsed = parse_graph(BRIEF, "brief.graph")
    assert parsed.blocks[0].title.endswith("// optional")


def test_permanent_networks_are_lad_networks_with_their_places() -> None:
    text = (
        "FUNCTION_BLOCK FB 4\nBEGIN\nPERMANENT_PRE\nNETWORK\nTITLE = first\n"
        "RUNG Contact(I 0.0) Coil(Q 0.0) END_RUNG\nNETWORK\nRUNG Contact(I 0.1) @in "
        "SetCoil(Q 0.1) END_RUNG\nEND_PERMANENT_PRE\nSEQUENCER S\nEND_SEQUENCER\n"
        "PERMANENT_POST\nNETWORK\nSTL\n      L     MW 10\n      T     MW 12\nEND_STL\n"
        "END_PERMANENT_POST\nEND_FUNCTION_BLOCK\n"
    )
    parsed = parse_graph(text, "perm.graph")
    assert parsed.diagnostics == []
    [block] = parsed.blocks
    assert [n.title for n in block.pre] == ["first", ""]
    assert block.pre[1].logic.elements[0].id == "in"
    assert block.post[0].stl == "      L     MW 10\n      T     MW 12"
    assert {k: v for k, v in parsed.places[0].items() if k[:3] in ("PRE", "POS")} == {
        "PRE1": 4,
        "PRE2": 7,
        "POST1": 13,
    }
    again = parse_graph(print_graph(parsed.blocks), "perm.graph")  # STL lines all kept
    assert (again.blocks, again.diagnostics) == (parsed.blocks, [])


def test_several_blocks_each_with_their_places() -> None:
    text = (
        "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER A\nSTEP One (1) END_STEP\nEND_SEQUENCER\n"
        "END_FUNCTION_BLOCK\n\nFUNCTION_BLOCK FB 2\nBEGIN\nSEQUENCER B\nSTEP One (1)\n"
        "END_STEP\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n"
    )
    parsed = parse_graph(text, "two.graph")
    assert parsed.diagnostics == []
    assert [b.name for b in parsed.blocks] == ["FB 1", "FB 2"]
    assert parsed.places == [
        {"BLOCK": 1, "SEQ:A": 3, "S1": 4},
        {"BLOCK": 8, "SEQ:B": 10, "S1": 11},
    ]


def test_an_empty_file_has_no_blocks_and_no_problems() -> None:
    parsed = parse_graph("  // nothing yet\n", "empty.graph")
    assert (parsed.blocks, parsed.diagnostics, parsed.places) == ([], [], [])


def test_names_may_be_words_that_only_links_use() -> None:
    text = (
        "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Stop\nINITIAL_STEP Stop (1) END_STEP\n"
        "STEP To (2) END_STEP\nTRANSITION From (1) FROM Stop TO To END_TRANSITION\n"
        "TRANSITION Jump (2) FROM (To, Stop) JUMP Stop END_TRANSITION\n"
        "TRANSITION T3 (3) FROM To STOP END_TRANSITION\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n"
    )
    parsed = parse_graph(text, "names.graph")
    assert parsed.diagnostics == []
    [sequencer] = parsed.blocks[0].sequencers
    assert sequencer.name == "Stop"
    assert [(t.name, t.source, t.target, t.jump) for t in sequencer.transitions] == [
        ("From", ["Stop"], ["To"], False),
        ("Jump", ["To", "Stop"], ["Stop"], True),
        ("T3", ["To"], [], False),
    ]
    assert parse_graph(print_graph(parsed.blocks), "names.graph").blocks == parsed.blocks

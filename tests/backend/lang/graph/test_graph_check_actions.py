"""The action rules of the Graph checker (``check_actions``): the legal event × qualifier × C
table of the digest's §2.5.3 with its notes, operands, values, and the warnings about C
without an interlock, steps without actions and transitions without conditions."""

from __future__ import annotations

import itertools

import pytest

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.model import (
    Action,
    Event,
    GraphBlock,
    Qualifier,
    Sequencer,
    Step,
    Transition,
)
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.lad.model import Contact, Series

EVENTS: list[Event | None] = [None, "S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1"]
QUALIFIERS: list[Qualifier] = [
    "N", "S", "R", "D", "L", "CALL", "ON", "OFF", "CS", "CU", "CD", "CR", "TL", "TD", "TR"
]  # fmt: skip
# A fitting operand and value per qualifier, so that only the table decides.
OPERANDS: dict[str, tuple[str, str | None]] = {
    "N": ("Q 0.0", None), "S": ("Q 0.0", None), "R": ("Q 0.0", None),
    "D": ("Q 0.1", "T#5S"), "L": ("Q 0.1", "T#5S"), "CALL": ("FC 1", None),
    "ON": ("S2", None), "OFF": ("S2", None),
    "CS": ("C 1", "C#10"), "CU": ("C 1", None), "CD": ("C 1", None), "CR": ("C 1", None),
    "TL": ("T 1", "S5T#2S"), "TD": ("T 1", "S5T#2S"), "TR": ("T 1", None),
}  # fmt: skip
TABLE_CODES = {"GRA230", "GRA231", "GRA232"}


def _legal(event: str | None, qualifier: str, interlock: bool) -> bool:
    """The digest's §2.5.3 table, written out as the book's rows read."""
    if event is None:
        return qualifier in ("N", "S", "R", "D", "L", "CALL")
    if qualifier in ("D", "L"):
        return False
    return not interlock or event in ("S1", "V1", "A1", "R1")


def _block(*actions: Action, interlock: bool = True) -> ParsedGraph:
    condition = Series(elements=[Contact(operand="I 0.0")])
    steps = [
        Step(
            number=1,
            name="Idle",
            initial=True,
            actions=[Action(qualifier="N", operand="M 0.0")],
        ),
        Step(
            number=2,
            name="Work",
            interlock=condition if interlock else None,
            actions=list(actions),
        ),
    ]
    transitions = [
        Transition(number=1, name="Go", source=["Idle"], target=["Work"], condition=condition),
        Transition(number=2, name="Back", source=["Work"], target=["Idle"], condition=condition),
    ]
    block = GraphBlock(
        name="FB 1",
        sequencers=[Sequencer(name="Main", steps=steps, transitions=transitions)],
    )
    return ParsedGraph(
        file="a.graph", blocks=[block], places=[{"BLOCK": 1, "S2/A1": 9, "S2/A2": 10}]
    )


def _row(
    event: Event | None, qualifier: Qualifier, interlock: bool = False, **more: str
) -> list[Diagnostic]:
    operand, time = OPERANDS[qualifier]
    action = Action(
        event=event,
        qualifier=qualifier,
        interlock=interlock,
        operand=more.get("operand", operand),
        time=more.get("time", time),
    )
    return check_block(_block(action), 0)


@pytest.mark.parametrize(
    ("event", "qualifier", "interlock"),
    list(itertools.product(EVENTS, QUALIFIERS, (False, True))),
)
def test_event_qualifier_and_c_follow_the_table(
    event: Event | None, qualifier: Qualifier, interlock: bool
) -> None:
    found = {problem.code for problem in _row(event, qualifier, interlock)} & TABLE_CODES
    assert (not found) == _legal(event, qualifier, interlock), (
        event,
        qualifier,
        interlock,
        found,
    )


def test_the_codes_say_which_rule_is_broken() -> None:
    assert {p.code for p in _row("S0", "N", interlock=True)} == {"GRA230"}
    assert {p.code for p in _row("S1", "D")} == {"GRA231"}
    assert {p.code for p in _row(None, "CU")} == {"GRA232"}
    found = _row("S0", "N", interlock=True)[0]
    assert found.params == {"action": "S0 NC", "event": "S0"}
    assert found.span is not None
    assert (found.span.element, found.span.line) == (
        "S2/A1",
        9,
    )


@pytest.mark.parametrize("event", EVENTS[1:])
def test_off_s_all_only_with_s1_v1_and_l1_and_never_on_s_all(event: Event) -> None:
    off = {p.code for p in _row(event, "OFF", operand="S_ALL")}
    assert ("GRA233" in off) == (event not in ("S1", "V1", "L1"))
    assert "GRA234" in {p.code for p in _row(event, "ON", operand="S_ALL")}


def test_on_and_off_name_an_existing_step_by_number_or_name() -> None:
    assert "GRA235" not in {p.code for p in _row("S1", "ON", operand="Idle")}
    assert "GRA235" not in {p.code for p in _row("S1", "OFF", operand="s1")}
    missing = [p for p in _row("S1", "ON", operand="S7") if p.code == "GRA235"]
    assert missing[0].params == {"action": "S1 ON", "step": "S7"}


@pytest.mark.parametrize(
    ("qualifier", "time", "code"),
    [
        ("D", None, "GRA236"),
        ("L", None, "GRA236"),
        ("CS", None, "GRA236"),
        ("TL", None, "GRA236"),
        ("TD", None, "GRA236"),
        ("N", "T#5S", "GRA237"),
        ("CU", "C#5", "GRA237"),
        ("D", "S5T#5S", "GRA238"),
        ("L", "C#5", "GRA238"),
        ("TL", "T#5S", "GRA238"),
        ("TD", "TIME#5S", "GRA238"),
        ("CS", "26", "GRA238"),
        ("CS", "S5T#1S", "GRA238"),
    ],
)
def test_values_after_the_comma(qualifier: Qualifier, time: str | None, code: str) -> None:
    event: Event | None = None if qualifier in ("D", "L", "N") else "S1"
    operand, _ = OPERANDS[qualifier]
    action = Action(event=event, qualifier=qualifier, operand=operand, time=time)
    assert code in {p.code for p in check_block(_block(action), 0)}


@pytest.mark.parametrize(
    ("qualifier", "time"),
    [
        ("D", "MD 4"),
        ("D", "#delay"),
        ("TL", '"Blink_time"'),
        ("CS", "MW 2"),
        ("CS", "C#999"),
    ],
)
def test_an_operand_or_the_right_constant_is_a_fitting_value(
    qualifier: Qualifier, time: str
) -> None:
    event: Event | None = None if qualifier == "D" else "S1"
    action = Action(event=event, qualifier=qualifier, operand=OPERANDS[qualifier][0], time=time)
    assert check_block(_block(action), 0) == []


@pytest.mark.parametrize(
    ("event", "qualifier", "operand", "code"),
    [
        (None, "CALL", "Q 0.0", "GRA239"),
        (None, "CALL", "DB 1", "GRA239"),
        ("S1", "CU", "T 1", "GRA240"),
        ("S1", "CS", "MW 0", "GRA240"),
        ("S1", "TR", "C 1", "GRA241"),
        ("S1", "TL", "M 0.0", "GRA241"),
        (None, "N", "C 1", "GRA246"),
        (None, "S", "T 3", "GRA246"),
        (None, "R", "FC 2", "GRA246"),
        ("S1", "S", "S_ALL", "GRA246"),
        (None, "S", "#a := 1", "GRA242"),
        ("S1", "CALL", "#b := #b + 1", "GRA242"),
    ],
)
def test_operands_fit_the_instruction(
    event: Event | None, qualifier: Qualifier, operand: str, code: str
) -> None:
    time = "S5T#1S" if qualifier == "TL" else "C#1" if qualifier == "CS" else None
    assert code in {p.code for p in _row(event, qualifier, operand=operand, time=time or "")}


@pytest.mark.parametrize(
    ("qualifier", "operand"),
    [
        ("CALL", "FC 10"),
        ("CALL", "FB 2, DB 2"),
        ("CALL", 'SFB 4, "Timer_DB"'),
        ("CALL", '"Motor"'),
        ("CALL", "FB 3, #inst"),
        ("N", '"Belt_A"'),
        ("N", "DB1.DBX 0.0"),
        ("S", "#flag"),
        ("N", "#count := #count + 1"),
        ("N", "#e := SIN(MD 0)"),
    ],
)
def test_good_operands_pass(qualifier: Qualifier, operand: str) -> None:
    action = Action(qualifier=qualifier, operand=operand)
    block = _block(action)
    declared = "VAR\n  count : INT;\n  e : REAL;\n  flag : BOOL;\nEND_VAR"
    block.blocks[0] = block.blocks[0].model_copy(update={"declarations": declared})
    assert check_block(block, 0) == []


def test_c_without_interlock_is_a_warning_per_row() -> None:
    action = Action(qualifier="N", interlock=True, operand="Q 0.0")
    found = check_block(_block(action, action, interlock=False), 0)
    warned = [p for p in found if p.code == "GRA243"]
    assert [p.span.element for p in warned if p.span] == ["S2/A1", "S2/A2"]
    assert all(p.severity == "warning" for p in warned)
    assert warned[0].params == {"action": "NC", "step": "Work"}


def test_action_without_operand() -> None:
    found = check_block(_block(Action(qualifier="S", operand=" ")), 0)
    assert [p.code for p in found] == ["GRA247"]


def _text(body: str) -> list[Diagnostic]:
    parsed = parse_graph(f"FUNCTION_BLOCK FB 1\nBEGIN\n{body}END_FUNCTION_BLOCK\n", "t.graph")
    assert parsed.diagnostics == []
    return check_block(parsed, 0)


def test_empty_step_is_info_and_only_a_missing_condition_is_a_warning() -> None:
    text = """SEQUENCER Main
INITIAL_STEP Idle (1)
END_STEP
TRANSITION Go (1) FROM Idle TO Run
END_TRANSITION
STEP Run (2)
ACTIONS
  S1 CU C 1;
  NC Q 0.0;
END_ACTIONS
END_STEP
TRANSITION Back (2) FROM Run STOP
CONDITION END_CONDITION
END_TRANSITION
END_SEQUENCER
"""
    found = [(p.code, p.severity.value, p.span.element if p.span else None) for p in _text(text)]
    assert found == [
        ("GRA244", "info", "S1"),
        ("GRA245", "warning", "T1"),
        ("GRA243", "warning", "S2/A2"),
    ]

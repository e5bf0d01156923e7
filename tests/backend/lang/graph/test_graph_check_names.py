"""The name rules of the Graph checker (``check_names``): step and transition names become
instance-DB members, and step variables in conditions and arithmetic must name them."""

from __future__ import annotations

import pytest

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.model import GraphBlock, Sequencer, Step, Transition
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.lad.model import Contact, Series

CHAIN = """SEQUENCER Main
INITIAL_STEP {first} (1)
ACTIONS
  N Q 0.0;
END_ACTIONS
END_STEP
TRANSITION {go} (1) FROM {first} TO {second}
CONDITION {condition} END_CONDITION
END_TRANSITION
STEP {second} (2)
ACTIONS
  {action}
END_ACTIONS
END_STEP
TRANSITION Back (2) FROM {second} JUMP {first}
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
"""


def _check(
    *,
    first: str = "Idle",
    second: str = "Run",
    go: str = "Go",
    condition: str = "Contact(I 0.0)",
    action: str = "N Q 0.1;",
    head: str = "",
) -> list[Diagnostic]:
    body = CHAIN.format(first=first, second=second, go=go, condition=condition, action=action)
    text = f"FUNCTION_BLOCK FB 1\n{head}BEGIN\n{body}END_FUNCTION_BLOCK\n"
    parsed = parse_graph(text, "n.graph")
    assert parsed.diagnostics == []
    return check_block(parsed, 0)


def _found(found: list[Diagnostic]) -> list[tuple[str, str | None, dict[str, object]]]:
    return [(p.code, p.span.element if p.span else None, p.params) for p in found]


def test_clean_names_and_references_pass() -> None:
    condition = "Contact(Idle.X) Contact(S1.X) Contact(#Back.TT) Contact(T2.TT) " + (
        "Box(CMP>D, IN1 := S1.T, IN2 := T#1S) Box(CMP<D, IN1 := #Idle.U, IN2 := T#9S)"
    )
    assert (
        _check(
            condition=condition,
            action="S1 N #t := Run.T;",
            head="VAR\n t : TIME;\nEND_VAR\n",
        )
        == []
    )


def test_duplicate_names_ignore_case_and_span_steps_and_transitions() -> None:
    assert _found(_check(go="run")) == [
        ("GRA281", "T1", {"name": "run", "owner": "T1", "other": "S2"})
    ]


@pytest.mark.parametrize(
    ("parameters", "name", "clashes"),
    [
        ("MINIMUM", "INIT_SQ", True),
        ("MINIMUM", "OFF_SQ", False),
        ("STANDARD", "S_NO", True),
        ("STANDARD", "ERROR", False),
        ("MAXIMUM", "HALT_SQ", True),
        ("USER_DEFINED", "Error", True),
        ("USER_DEFINED", "SW_TOP", True),
    ],
)
def test_a_step_named_as_a_parameter_of_the_chosen_set(
    parameters: str, name: str, clashes: bool
) -> None:
    head = f"SETTINGS\n  PARAMETERS := {parameters};\nEND_SETTINGS\n"
    found = [p for p in _check(second=name, head=head) if p.code == "GRA282"]
    assert bool(found) == clashes
    if clashes:
        assert found[0].params == {"name": name, "owner": "S2", "set": parameters}


def test_reserved_prefix_and_declared_names() -> None:
    assert [p.code for p in _check(second="G7_Run")] == ["GRA283"]
    declared = "VAR\n  Run : INT;\n  motor : STRUCT T : TIME; END_STRUCT;\nEND_VAR\n"
    assert _found(_check(head=declared)) == [("GRA284", "S2", {"name": "Run", "owner": "S2"})]


def test_declarations_may_not_use_the_prefix_or_a_parameter() -> None:
    head = "VERSION : 0.1\nVAR_INPUT\n  g7_mode : INT;\n  S_SEL : INT;\nEND_VAR\n"
    assert _found(_check(head=head)) == [
        ("GRA283", "BLOCK", {"name": "g7_mode"}),
        ("GRA285", "BLOCK", {"name": "S_SEL", "set": "STANDARD"}),
    ]


def test_a_step_named_like_another_steps_number_is_a_warning() -> None:
    found = _check(first="S2")
    assert _found(found) == [
        (
            "GRA287",
            "S1",
            {"name": "S2", "owner": "S1", "other": "S2", "other_name": "Run"},
        )
    ]
    assert found[0].severity == "warning"
    assert _check(first="S1") == []  # its own number: no mix-up


@pytest.mark.parametrize(
    ("condition", "expected"),
    [
        (
            "Contact(Fill.X)",
            [("GRA288", "T1/e1", {"reference": "Fill.X", "name": "Fill"})],
        ),
        ("Contact(S9.X)", [("GRA288", "T1/e1", {"reference": "S9.X", "name": "S9"})]),
        (
            "Contact(#T7.TT)",
            [("GRA288", "T1/e1", {"reference": "#T7.TT", "name": "T7"})],
        ),
        ("Contact(Go.X)", [("GRA289", "T1/e1", {"reference": "Go.X"})]),
        ("Contact(Run.TT)", [("GRA289", "T1/e1", {"reference": "Run.TT"})]),
        ("Contact(Run.Y)", [("GRA289", "T1/e1", {"reference": "Run.Y"})]),
        (
            "Contact(I 0.0) Contact(Run.T)",
            [("GRA290", "T1/e2", {"reference": "Run.T"})],
        ),
        (
            "Box(CMP==I, IN1 := S2.X, IN2 := 1)",
            [("GRA291", "T1/e1", {"reference": "S2.X"})],
        ),
    ],
)
def test_step_variables_in_conditions(
    condition: str, expected: list[tuple[str, str, dict[str, object]]]
) -> None:
    assert _found(_check(condition=condition)) == expected


@pytest.mark.parametrize(
    "condition",
    [
        'Contact("Data".T)',
        "Contact(DB5.X)",
        "Contact(DB5.DBX 0.1)",
        "Contact(#motor.X)",
        "Contact(M 10.1)",
    ],
)
def test_dotted_operands_that_are_not_step_variables(condition: str) -> None:
    head = "VAR\n  motor : STRUCT X : BOOL; END_STRUCT;\nEND_VAR\n"
    assert _check(condition=condition, head=head) == []


def test_step_variables_in_arithmetic_and_permanent_networks() -> None:
    head = "VAR\n  t : TIME;\nEND_VAR\n"
    found = _check(action="S0 N #t := Ran.T + S1.T;", head=head)
    assert _found(found) == [("GRA288", "S2/A1", {"reference": "Ran.T", "name": "Ran"})]
    pre = "PERMANENT_PRE\nNETWORK\nRUNG Contact(Rnu.X) Coil(Q 3.0) END_RUNG\nEND_PERMANENT_PRE\n"
    body = CHAIN.format(
        first="Idle",
        second="Run",
        go="Go",
        condition="Contact(I 0.0)",
        action="N Q 0.1;",
    )
    parsed = parse_graph(f"FUNCTION_BLOCK FB 1\nBEGIN\n{pre}{body}END_FUNCTION_BLOCK\n", "p.graph")
    assert _found(check_block(parsed, 0)) == [
        ("GRA288", "PRE1/e1", {"reference": "Rnu.X", "name": "Rnu"})
    ]


def _model(step_name: str) -> list[Diagnostic]:
    rail = Series(elements=[Contact(operand="I 0.0")])
    steps = [
        Step(number=1, name=step_name, initial=True),
        Step(number=2, name="Run"),
    ]
    transitions = [
        Transition(number=1, name="Go", source=[step_name], target=["Run"], condition=rail),
        Transition(number=2, name="Back", source=["Run"], target=[step_name], condition=rail),
    ]
    block = GraphBlock(
        name="FB 1",
        sequencers=[Sequencer(name="M", steps=steps, transitions=transitions)],
    )
    return check_block(ParsedGraph(file="m.graph", blocks=[block], places=[{"BLOCK": 1}]), 0)


@pytest.mark.parametrize("name", ["2nd", "Step one", "Schritt-1", "Été", ""])
def test_names_the_editor_could_type_that_are_not_identifiers(name: str) -> None:
    found = [p for p in _model(name) if p.code == "GRA280"]
    assert [(p.params["owner"], p.params["name"]) for p in found] == [("S1", name)]


@pytest.mark.parametrize("name", ["BEGIN", "end_var", "Var_Temp", "FUNCTION_BLOCK"])
def test_reserved_words_of_stl_sources(name: str) -> None:
    assert [p.code for p in _model(name) if p.code.startswith("GRA28")] == ["GRA286"]

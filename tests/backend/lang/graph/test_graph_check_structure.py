"""The structure rules of the Graph checker (``check_structure``): numbers, FROM/TO links,
closed paths, initial steps, reachability, limits and loops without conditions."""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block, has_errors
from nasaq.lang.graph.model import GraphBlock, Sequencer, Step, Transition
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.lad.model import Contact, Series


def _check(body: str, head: str = "") -> list[Diagnostic]:
    parsed = parse_graph(f"FUNCTION_BLOCK FB 1\n{head}BEGIN\n{body}END_FUNCTION_BLOCK\n", "t.graph")
    assert parsed.diagnostics == []
    return check_block(parsed, 0)


def _model(*sequencers: Sequencer) -> list[Diagnostic]:
    block = GraphBlock(name="FB 1", sequencers=list(sequencers))
    return check_block(ParsedGraph(file="m.graph", blocks=[block], places=[{"BLOCK": 1}]), 0)


def _codes(found: list[Diagnostic]) -> list[str]:
    return [problem.code for problem in found if problem.code != "GRA244"]


def _step(name: str, number: int, initial: bool = False) -> Step:
    return Step(number=number, name=name, initial=initial)


def _go(number: int, source: list[str], target: list[str], condition: bool = True) -> Transition:
    series = Series(elements=[Contact(operand="I 0.0")]) if condition else None
    return Transition(
        number=number,
        name=f"Tr{number}",
        source=source,
        target=target,
        condition=series,
    )


CYCLE = """SEQUENCER Main
INITIAL_STEP Idle (1)
END_STEP
TRANSITION Go (1) FROM Idle TO Run
CONDITION Contact(I 0.0) END_CONDITION
END_TRANSITION
STEP Run (2)
ACTIONS
  N Q 0.0;
END_ACTIONS
END_STEP
TRANSITION Back (2) FROM Run JUMP Idle
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
"""


def test_a_closed_cycle_with_conditions_is_clean() -> None:
    assert _codes(_check(CYCLE)) == []


def test_duplicate_step_number_names_both_steps_on_the_second() -> None:
    text = CYCLE.replace(
        "TRANSITION Back (2) FROM Run JUMP Idle", "TRANSITION Back (2) FROM Run TO Twin"
    )
    text = text.replace(
        "END_SEQUENCER",
        "STEP Twin (2)\nEND_STEP\nTRANSITION Out (3) FROM Twin STOP\n"
        "CONDITION Contact(I 1.0) END_CONDITION\nEND_TRANSITION\nEND_SEQUENCER",
    )
    found = [problem for problem in _check(text) if problem.code == "GRA200"]
    assert len(found) == 1
    assert found[0].params == {"number": 2, "first": "Run", "second": "Twin"}
    assert found[0].span is not None
    assert found[0].span.element == "S2"


def test_duplicate_transition_number() -> None:
    found = _check(CYCLE.replace("Back (2)", "Back (1)"))
    assert [p.params for p in found if p.code == "GRA201"] == [
        {"number": 1, "first": "Go", "second": "Back"}
    ]


def test_missing_source_and_target_steps_are_named_with_the_known_steps() -> None:
    found = _check(CYCLE.replace("FROM Idle TO Run", "FROM Idel TO Rnu"))
    by_code = {problem.code: problem for problem in found}
    assert by_code["GRA202"].params == {
        "transition": "Go",
        "step": "Idel",
        "known": "Idle, Run",
    }
    assert by_code["GRA203"].params["step"] == "Rnu"
    assert by_code["GRA202"].span is not None
    assert by_code["GRA202"].span.line == 6
    assert has_errors(found)


def test_step_names_in_from_and_to_ignore_case() -> None:
    assert _codes(_check(CYCLE.replace("FROM Idle TO Run", "FROM IDLE TO run"))) == []


def test_a_step_no_transition_leaves_is_an_error_but_stop_closes_a_path() -> None:
    open_end = CYCLE.replace(
        "TRANSITION Back (2) FROM Run JUMP Idle\nCONDITION Contact(I 0.1) END_CONDITION\n"
        "END_TRANSITION\n",
        "",
    )
    found = _check(open_end)
    assert [(p.code, p.params) for p in found if p.code == "GRA204"] == [
        ("GRA204", {"step": "Run"})
    ]
    stopped = CYCLE.replace("FROM Run JUMP Idle", "FROM Run STOP")
    assert _codes(_check(stopped)) == []


def test_unreachable_step_but_not_when_an_on_action_reaches_it() -> None:
    spare = (
        "STEP Spare (3)\nEND_STEP\n"
        "TRANSITION Out (3) FROM Spare STOP\nCONDITION Contact(I 1.0) END_CONDITION\n"
        "END_TRANSITION\nEND_SEQUENCER"
    )
    text = CYCLE.replace("END_SEQUENCER", spare)
    found = _check(text)
    assert [(p.code, p.params) for p in found if p.code == "GRA205"] == [
        ("GRA205", {"step": "Spare"})
    ]
    assert next(p for p in found if p.code == "GRA205").severity == "warning"
    switched = text.replace("  N Q 0.0;", "  N Q 0.0;\n  S1 ON S3;")
    assert "GRA205" not in _codes(_check(switched))


def test_a_loop_no_initial_step_reaches_is_unreachable() -> None:
    ring = (
        "STEP Left (3)\nEND_STEP\n"
        "TRANSITION L2R (3) FROM Left TO Right\nCONDITION Contact(I 1.0) END_CONDITION\n"
        "END_TRANSITION\nSTEP Right (4)\nEND_STEP\n"
        "TRANSITION R2L (4) FROM Right JUMP Left\nCONDITION Contact(I 1.1) END_CONDITION\n"
        "END_TRANSITION\nEND_SEQUENCER"
    )
    found = _check(CYCLE.replace("END_SEQUENCER", ring))
    assert sorted(p.params["step"] for p in found if p.code == "GRA205") == [
        "Left",
        "Right",
    ]


def test_no_initial_step_is_one_warning_for_the_fb() -> None:
    found = _check(CYCLE.replace("INITIAL_STEP Idle", "STEP Idle"))
    assert _codes(found) == ["GRA206"]
    assert found[0].severity == "warning"
    assert not has_errors(found)


def test_several_initial_steps_are_allowed() -> None:
    assert _codes(_check(CYCLE.replace("STEP Run (2)", "INITIAL_STEP Run (2)"))) == []


def test_sequencer_without_initial_step_unless_another_one_jumps_into_it() -> None:
    second = (
        "SEQUENCER Lamp\nSTEP Wait (3)\nEND_STEP\n"
        "TRANSITION Blink (3) FROM Wait JUMP Wait\nCONDITION Contact(I 1.0) END_CONDITION\n"
        "END_TRANSITION\nEND_SEQUENCER\n"
    )
    found = _check(CYCLE + second)
    assert [(p.code, p.params) for p in found if p.code != "GRA244"] == [
        ("GRA207", {"sequencer": "Lamp"})
    ]
    jumped = CYCLE.replace("FROM Run JUMP Idle", "FROM Run JUMP Wait") + second
    assert _codes(_check(jumped)) == []


def test_transition_written_in_the_wrong_sequencer() -> None:
    second = "SEQUENCER Lamp\nINITIAL_STEP Wait (3)\nEND_STEP\nEND_SEQUENCER\n"
    moved = CYCLE.replace(
        "END_SEQUENCER",
        "TRANSITION Blink (3) FROM Wait JUMP Wait\nCONDITION Contact(I 1.0) END_CONDITION\n"
        "END_TRANSITION\nEND_SEQUENCER",
    )
    found = _check(moved + second)
    assert [p.params for p in found if p.code == "GRA215"] == [
        {"transition": "Blink", "sequencer": "Main", "step": "Wait", "other": "Lamp"}
    ]


def test_simultaneous_divergence_and_convergence_in_one_sequencer_are_clean() -> None:
    text = """SEQUENCER Main
INITIAL_STEP Idle (1)
END_STEP
TRANSITION Split (1) FROM Idle TO (Left, Right)
CONDITION Contact(I 0.0) END_CONDITION
END_TRANSITION
STEP Left (2)
END_STEP
STEP Right (3)
END_STEP
TRANSITION Join (2) FROM (Left, Right) JUMP Idle
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
"""
    assert _codes(_check(text)) == []
    twice = text.replace("FROM (Left, Right)", "FROM (Left, Left)")
    assert [(p.code, p.params) for p in _check(twice) if p.code == "GRA213"] == [
        ("GRA213", {"transition": "Join", "step": "Left"})
    ]


def test_loop_of_transitions_without_condition_is_an_error_once() -> None:
    loop = CYCLE.replace("CONDITION Contact(I 0.1) END_CONDITION\n", "").replace(
        "CONDITION Contact(I 0.0) END_CONDITION\n", ""
    )
    found = [p for p in _check(loop) if p.code == "GRA212"]
    assert len(found) == 1
    assert found[0].params == {"steps": "Idle, Run", "transitions": "Go, Back"}
    assert found[0].span is not None
    assert found[0].span.element == "T1"


def test_an_explicitly_empty_condition_also_closes_a_loop() -> None:
    loop = CYCLE.replace("Contact(I 0.1) ", "").replace("Contact(I 0.0) ", "")
    assert "GRA212" in _codes(_check(loop))
    assert "GRA245" not in _codes(_check(loop))


def test_one_condition_breaks_the_loop_and_a_chain_without_conditions_is_no_loop() -> None:
    one = CYCLE.replace("CONDITION Contact(I 0.1) END_CONDITION\n", "")
    assert "GRA212" not in _codes(_check(one))
    chain = one.replace("FROM Run JUMP Idle", "FROM Run STOP").replace(
        "CONDITION Contact(I 0.0) END_CONDITION\n", ""
    )
    assert "GRA212" not in _codes(_check(chain))


def test_a_step_jumping_to_itself_without_condition_is_a_loop() -> None:
    found = _model(
        Sequencer(
            name="Main",
            steps=[_step("Idle", 1, initial=True)],
            transitions=[_go(1, ["Idle"], ["Idle"], condition=False)],
        )
    )
    assert [p.params for p in found if p.code == "GRA212"] == [
        {"steps": "Idle", "transitions": "Tr1"}
    ]


def test_jump_must_name_one_step() -> None:
    jump = Transition(number=1, name="Tr1", source=["Idle"], target=["Idle", "Run"], jump=True)
    found = _model(
        Sequencer(
            name="Main",
            steps=[_step("Idle", 1, initial=True), _step("Run", 2)],
            transitions=[jump, _go(2, ["Run"], ["Idle"])],
        )
    )
    assert "GRA214" in _codes(found)


def test_limits_of_steps_transitions_and_branches() -> None:
    steps = [_step(f"Step{k}", k, initial=k == 1) for k in range(1, 258)]
    transitions = [_go(k, [f"Step{k}"], [f"Step{k % 257 + 1}"]) for k in range(1, 258)]
    found = _model(Sequencer(name="Main", steps=steps, transitions=transitions))
    by_code = {p.code: p for p in found}
    assert by_code["GRA208"].params == {"count": 257, "limit": 256}
    assert by_code["GRA208"].span is not None
    assert by_code["GRA208"].span.element == "S257"
    assert by_code["GRA209"].params == {"count": 257, "limit": 256}
    assert "GRA210" not in by_code
    assert "GRA211" not in by_code

    hub = [_step("Hub", 1, initial=True), *(_step(f"B{k}", k + 1) for k in range(126))]
    out = [_go(k + 1, ["Hub"], [f"B{k}"]) for k in range(126)]
    back = [_go(k + 200, [f"B{k}"], ["Hub"]) for k in range(126)]
    found = _model(Sequencer(name="Main", steps=hub, transitions=out + back))
    assert [p.params for p in found if p.code == "GRA210"] == [{"count": 126, "limit": 125}]

    split = _go(1, ["Hub"], [f"B{k}" for k in range(126)])
    copies = [split.model_copy(update={"number": n}) for n in (2, 3)]
    two = _model(Sequencer(name="Main", steps=hub, transitions=[split, copies[0]]))
    assert "GRA211" not in _codes(two)  # 252 branches
    three = _model(Sequencer(name="Main", steps=hub, transitions=[split, *copies]))
    assert [p.params for p in three if p.code == "GRA211"] == [{"count": 378, "limit": 256}]


def test_sequencer_names_are_unique_and_a_sequencer_has_steps() -> None:
    empty = _check(CYCLE + "SEQUENCER Main\nEND_SEQUENCER\n")
    assert [p.code for p in empty if p.code in ("GRA217", "GRA218")] == [
        "GRA217",
        "GRA218",
    ]
    assert next(p for p in empty if p.code == "GRA218").severity == "warning"
    assert _codes(_check("")) == ["GRA219"]


def test_a_10000_step_source_gets_the_limit_diagnostic_and_no_recursion_error() -> None:
    parts = ["SEQUENCER Long\n"]
    for k in range(1, 10_001):
        initial = "INITIAL_STEP" if k == 1 else "STEP"
        parts.append(f"{initial} Step{k} ({k})\nEND_STEP\n")
        target = "JUMP Step1" if k == 10_000 else f"TO Step{k + 1}"
        parts.append(f"TRANSITION Trans{k} ({k}) FROM Step{k} {target}\nEND_TRANSITION\n")
    parts.append("END_SEQUENCER\n")
    found = _check("".join(parts))
    codes = [p.code for p in found]
    assert codes.count("GRA208") == 1
    assert codes.count("GRA209") == 1
    # 10,000 transitions without a condition in one ring: one loop, found without recursion.
    assert codes.count("GRA212") == 1

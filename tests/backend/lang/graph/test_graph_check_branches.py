"""Simultaneous branches opened and closed alike (``check_branches``): a convergence of steps
that are never active together (GRA220) and simultaneous branches closed by separate
transitions (GRA221); well-formed charts, nested or long, give neither."""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.text import parse_graph


def _check(chart: str) -> list[tuple[str, dict[str, object]]]:
    text = f"FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Main\n{chart}END_SEQUENCER\nEND_FUNCTION_BLOCK\n"
    parsed = parse_graph(text, "b.graph")
    assert parsed.diagnostics == []
    found: list[Diagnostic] = check_block(parsed, 0)
    return [(p.code, p.params) for p in found if p.code in ("GRA220", "GRA221")]


def _steps(*names: str) -> str:
    return "".join(f"STEP {name} ({k + 2})\nEND_STEP\n" for k, name in enumerate(names))


def _t(number: int, link: str, condition: str = "Contact(I 0.0)") -> str:
    return (
        f"TRANSITION T{number}x ({number}) {link}\n"
        f"CONDITION {condition} END_CONDITION\nEND_TRANSITION\n"
    )


IDLE = "INITIAL_STEP Idle (1)\nEND_STEP\n"


def test_a_proper_divergence_and_convergence_pass_also_nested_and_long() -> None:
    chart = (
        IDLE
        + _steps("A1", "A2", "B1", "C1", "C2", "B2")
        + _t(1, "FROM Idle TO (A1, B1)")
        + _t(2, "FROM A1 TO A2")
        + _t(3, "FROM B1 TO (C1, C2)")
        + _t(4, "FROM (C1, C2) TO B2")
        + _t(5, "FROM (A2, B2) JUMP Idle")
    )
    assert _check(chart) == []


def test_an_alternative_branch_closed_by_one_step_is_fine() -> None:
    chart = (
        IDLE
        + _steps("Fast", "Slow", "Done")
        + _t(1, "FROM Idle TO Fast")
        + _t(2, "FROM Idle TO Slow", "Contact(I 0.1)")
        + _t(3, "FROM Fast TO Done")
        + _t(4, "FROM Slow JUMP Done")
        + _t(5, "FROM Done JUMP Idle")
    )
    assert _check(chart) == []


def test_joining_alternative_branches_never_fires() -> None:
    chart = (
        IDLE
        + _steps("Fast", "Slow", "Fast2")
        + _t(1, "FROM Idle TO Fast")
        + _t(2, "FROM Idle TO Slow", "Contact(I 0.1)")
        + _t(3, "FROM Fast TO Fast2")
        + _t(4, "FROM (Fast2, Slow) JUMP Idle")
    )
    assert _check(chart) == [("GRA220", {"transition": "T4x", "first": "Fast2", "second": "Slow"})]


def test_joining_two_steps_of_one_path_never_fires() -> None:
    chart = (
        IDLE
        + _steps("First", "Second")
        + _t(1, "FROM Idle TO First")
        + _t(2, "FROM First TO Second")
        + _t(3, "FROM (First, Second) JUMP Idle")
    )
    assert _check(chart) == [
        ("GRA220", {"transition": "T3x", "first": "First", "second": "Second"})
    ]


def test_simultaneous_branches_closed_by_separate_transitions() -> None:
    chart = (
        IDLE
        + _steps("Left", "Right", "Right2", "Done")
        + _t(1, "FROM Idle TO (Left, Right)")
        + _t(2, "FROM Right TO Right2")
        + _t(3, "FROM Left TO Done")
        + _t(4, "FROM Right2 JUMP Done")
        + _t(5, "FROM Done JUMP Idle")
    )
    assert _check(chart) == [("GRA221", {"step": "Done", "transitions": "T3x, T4x"})]


def test_a_ring_of_single_links_has_no_start_and_reports_nothing() -> None:
    chart = (
        IDLE
        + _steps("A", "B")
        + _t(1, "FROM Idle TO A")
        + _t(2, "FROM A TO B")
        + _t(3, "FROM B JUMP A")
    )
    assert _check(chart) == []

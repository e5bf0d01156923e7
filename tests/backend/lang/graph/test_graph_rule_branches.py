"""SEMANTICS §2 phase 4 and §3, the structure: an alternative divergence takes the first
enabled transition in chart order, never two; a simultaneous divergence activates every
target; a simultaneous convergence fires only when all its sources were active before the
call; a jump goes back; a sequence end (STOP) leaves the step without a successor."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, anyof, c, cmp, fb, make, seq, step, trans

from nasaq.lang.graph.model import GraphBlock


def alternative(left_first: bool) -> GraphBlock:
    left = trans(1, "A", "B", c("I 0.0"))
    right = trans(2, "A", "C", c("I 0.1"))
    back = [
        trans(3, "B", "A", c("I 0.2")).model_copy(update={"jump": True}),
        trans(4, "C", "A", c("I 0.3")).model_copy(update={"jump": True}),
    ]
    first = [left, right] if left_first else [right, left]
    steps = [
        step("A", 1, initial=True),
        step("B", 2, "N Q 0.0"),
        step("C", 3, "N Q 0.1"),
    ]
    return fb(seq("Choice", steps, [*first, *back]))


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("left_first", [True, False])
def test_the_first_enabled_branch_wins_never_both(kind: str, left_first: bool) -> None:
    ex = make(kind, alternative(left_first))
    ex.call()
    ex.call({"I 0.0": 1, "I 0.1": 1})
    taken, other = ("B", "C") if left_first else ("C", "B")
    assert ex.step(taken) == 1
    assert ex.step(other) == 0
    assert ex.step("A") == 0
    assert ex.out("S_MORE") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_the_second_branch_fires_when_the_first_is_false(kind: str) -> None:
    ex = make(kind, alternative(True))
    ex.call()
    ex.call({"I 0.1": 1})
    assert ex.step("C") == 1
    assert ex.step("B") == 0
    ex.call({"I 0.1": 0, "I 0.3": 1})
    assert ex.step("A") == 1
    assert ex.step("C") == 0


def simultaneous() -> GraphBlock:
    steps = [
        step("A", 1, initial=True),
        step("B", 2, "N Q 1.0"),
        step("C", 3, "N Q 1.1"),
        step("D", 4),
        step("E", 5),
        step("F", 6, "N Q 1.2"),
    ]
    transitions = [
        trans(1, "A", ["B", "C"], c("I 0.0")),
        trans(2, "B", "D", c("I 0.1")),
        trans(3, "C", "E", c("I 0.2")),
        trans(4, ["D", "E"], "F", c("I 0.3")),
        trans(5, "F", None, c("I 0.4")),
    ]
    return fb(seq("Both", steps, transitions))


@pytest.mark.parametrize("kind", KINDS)
def test_simultaneous_divergence_activates_every_branch(kind: str) -> None:
    ex = make(kind, simultaneous())
    ex.call()
    ex.call({"I 0.0": 1})
    assert (ex.step("B"), ex.step("C")) == (1, 1)
    assert (ex.bit("Q 1.0"), ex.bit("Q 1.1")) == (1, 1)
    assert ex.out("S_MORE") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_simultaneous_convergence_waits_for_every_source(kind: str) -> None:
    ex = make(kind, simultaneous())
    ex.call()
    ex.call({"I 0.0": 1})
    ex.call({"I 0.1": 1, "I 0.3": 1})  # only D reached: F waits
    assert (ex.step("D"), ex.step("C"), ex.step("F")) == (1, 1, 0)
    assert ex.tt("Trans4") == 0
    ex.call({"I 0.2": 1})  # E activated in this call: not a source yet
    assert (ex.step("D"), ex.step("E"), ex.step("F")) == (1, 1, 0)
    ex.call()
    assert (ex.step("D"), ex.step("E"), ex.step("F")) == (0, 0, 1)
    assert ex.step("D", "S0") == 1
    assert ex.step("E", "S0") == 1
    assert ex.tt("Trans4") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_a_sequence_end_leaves_no_active_step(kind: str) -> None:
    ex = make(kind, simultaneous())
    ex.call()
    for inputs in ({"I 0.0": 1}, {"I 0.1": 1, "I 0.2": 1}, {"I 0.3": 1}):
        ex.call(inputs)
    ex.call()
    assert ex.step("F") == 1
    assert ex.bit("Q 1.2") == 1
    ex.call({"I 0.4": 1})
    assert ex.step("F") == 0
    assert ex.step("F", "S0") == 1
    assert ex.bit("Q 1.2") == 0
    assert all(ex.step(name) == 0 for name in "ABCDEF")
    assert ex.out("S_NO") == 0
    assert ex.out("S_ACTIVE") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_a_transition_without_condition_passes_at_once(kind: str) -> None:
    steps = [step("A", 1, initial=True), step("B", 2, "N Q 0.5")]
    block = fb(seq("Free", steps, [trans(1, "A", "B"), trans(2, "B", "A", c("I 0.0"))]))
    ex = make(kind, block)
    ex.call()
    assert ex.step("A") == 1
    ex.call()
    assert ex.step("B") == 1
    assert ex.bit("Q 0.5") == 1
    assert ex.tt("Trans1") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_a_parallel_and_a_comparator_in_a_condition(kind: str) -> None:
    steps = [step("A", 1, initial=True), step("B", 2)]
    condition = (
        anyof(c("I 0.0"), c("I 0.1")),
        cmp(">=", "MW 30", "5", "I"),
    )
    block = fb(seq("Cond", steps, [trans(1, "A", "B", *condition), trans(2, "B", "A")]))
    ex = make(kind, block)
    ex.call({"MW 30": 4, "I 0.1": 1})
    ex.call()
    assert ex.step("B") == 0
    assert ex.tt("Trans1") == 0
    ex.call({"MW 30": 5})
    assert ex.step("B") == 1

"""SEMANTICS §2 phase 5, the bit qualifiers: N, S, R, D and L, on the reference and the CPU.

N writes 1 every call while the step is active and 0 in the call the step is left; S and R
write every call and the bit stays; D is 1 once the step time T reached the time, L while T is
below it, both 0 when the step is left. Each call below is 100 ms after the one before, and a
step's T is 0 in the call it is activated.
"""

from __future__ import annotations

import pytest
from graph_harness import KINDS, chain, enter_run, make


@pytest.mark.parametrize("kind", KINDS)
def test_n_is_on_while_the_step_is_active_and_off_when_it_is_left(kind: str) -> None:
    ex = make(kind, chain("N Q 0.0"))
    ex.call()
    assert ex.step("Idle") == 1
    assert ex.bit("Q 0.0") == 0
    ex.call({"I 0.0": 1})
    assert ex.step("Run") == 1
    assert ex.bit("Q 0.0") == 1
    ex.call({"I 0.0": 0})
    assert ex.bit("Q 0.0") == 1
    ex.call({"I 0.1": 1})
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 1
    assert ex.bit("Q 0.0") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_s_latches_and_r_resets(kind: str) -> None:
    ex = make(kind, chain("S Q 0.1", idle_actions=("R Q 0.1",)))
    enter_run(ex)
    assert ex.bit("Q 0.1") == 1
    ex.call({"I 0.0": 0, "I 0.1": 1})  # Run left: S keeps the bit, Idle activated resets it
    assert ex.step("Idle") == 1
    assert ex.bit("Q 0.1") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_s_stays_after_the_step_is_left(kind: str) -> None:
    ex = make(kind, chain("S Q 0.1"))
    enter_run(ex)
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.step("Run") == 0
    assert ex.bit("Q 0.1") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_s_is_written_every_call_while_the_step_is_active(kind: str) -> None:
    """A plain S re-issues the set in every call: a bit reset by a permanent network or the
    user is set again in the next call."""
    ex = make(kind, chain("S M 20.0"))
    enter_run(ex)
    ex.call({"M 20.0": 0})
    assert ex.bit("M 20.0") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_d_switches_on_once_the_step_time_reaches_its_time(kind: str) -> None:
    ex = make(kind, chain("D Q 0.2, T#300MS"))
    enter_run(ex)  # T = 0
    seen = []
    for _ in range(4):  # T = 100, 200, 300, 400
        ex.call()
        seen.append(ex.bit("Q 0.2"))
    assert seen == [0, 0, 1, 1]
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.step("Run") == 0
    assert ex.bit("Q 0.2") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_d_of_a_step_left_before_its_time_never_switches_on(kind: str) -> None:
    ex = make(kind, chain("D Q 0.2, T#300MS"))
    enter_run(ex)
    ex.call()
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.bit("Q 0.2") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_l_is_on_for_its_time_from_the_activation(kind: str) -> None:
    ex = make(kind, chain("L Q 0.3, T#300MS"))
    enter_run(ex)
    seen = [ex.bit("Q 0.3")]
    for _ in range(3):  # T = 100, 200, 300
        ex.call()
        seen.append(ex.bit("Q 0.3"))
    assert seen == [1, 1, 1, 0]


@pytest.mark.parametrize("kind", KINDS)
def test_l_is_off_when_the_step_is_left_early(kind: str) -> None:
    ex = make(kind, chain("L Q 0.3, T#1S"))
    enter_run(ex)
    assert ex.bit("Q 0.3") == 1
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.bit("Q 0.3") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_the_step_time_counts_while_active_and_stays_after(kind: str) -> None:
    ex = make(kind, chain())
    enter_run(ex)
    assert ex.step("Run", "T") == 0
    ex.call(dt=250)
    ex.call(dt=150)
    assert ex.step("Run", "T") == 400
    assert ex.step("Run", "U") == 400
    ex.call({"I 0.0": 0, "I 0.1": 1}, dt=50)  # phase 2 counts before phase 4 leaves the step
    assert ex.step("Run") == 0
    assert ex.step("Run", "T") == 450
    ex.call()
    assert ex.step("Run", "T") == 450

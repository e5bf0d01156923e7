"""SEMANTICS §2 phases 0, 3 and 5, the events: S1 in the call a step is activated, S0 in the
call it is left, V1/V0/A1 with supervision errors and their acknowledgement; an event row
acts once at its event. Decision (a): an ``S1 N`` bit is written once and reset when the step
is left; ``S0 N`` writes 1 when it is left and stays. (L1/L0 are in the interlock rule.)

R1 needs REG_EF (registration), which is not built (COMPATIBILITY.md): an R1 row is accepted
and never fires, which the last test checks."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, cond, enter_run, make


@pytest.mark.parametrize("kind", KINDS)
def test_s1_and_s0_are_set_for_one_call(kind: str) -> None:
    ex = make(kind, chain())
    ex.call()
    assert ex.step("Idle", "S1") == 1
    ex.call({"I 0.0": 1})
    assert ex.step("Idle", "S0") == 1
    assert ex.step("Run", "S1") == 1
    assert ex.step("Idle", "S1") == 0
    ex.call()
    assert ex.step("Idle", "S0") == 0
    assert ex.step("Run", "S1") == 0
    ex.call({"I 0.1": 1})
    assert ex.step("Run", "S0") == 1
    assert ex.step("Idle", "S1") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_event_rows_act_once(kind: str) -> None:
    ex = make(kind, chain("S1 S M 1.0", "S0 S M 1.1", "S1 R M 1.2"))
    ex.call({"M 1.2": 1})
    ex.call({"I 0.0": 1})
    assert (ex.bit("M 1.0"), ex.bit("M 1.1"), ex.bit("M 1.2")) == (1, 0, 0)
    ex.call({"M 1.0": 0, "M 1.2": 1})  # not written again while the step stays
    assert (ex.bit("M 1.0"), ex.bit("M 1.2")) == (0, 1)
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.bit("M 1.1") == 1
    assert ex.bit("M 1.0") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_s1_n_writes_once_and_is_reset_when_the_step_is_left(kind: str) -> None:
    ex = make(kind, chain("S1 N Q 1.2", "S0 N Q 1.3"))
    enter_run(ex)
    assert (ex.bit("Q 1.2"), ex.bit("Q 1.3")) == (1, 0)
    ex.call({"Q 1.2": 0})
    assert ex.bit("Q 1.2") == 0
    ex.call({"Q 1.2": 1})
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert (ex.bit("Q 1.2"), ex.bit("Q 1.3")) == (0, 1)
    ex.call()
    assert ex.bit("Q 1.3") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_v1_v0_and_a1_rows(kind: str) -> None:
    rows = ("V1 S M 1.4", "V0 S M 1.5", "A1 S M 1.6")
    ex = make(kind, chain(*rows, supervision=cond(c("I 0.6"))))
    enter_run(ex)
    ex.call({"I 0.6": 1})
    assert ex.step("Run", "V1") == 1
    assert ex.step("Run", "VA") == 1
    assert (ex.bit("M 1.4"), ex.bit("M 1.5"), ex.bit("M 1.6")) == (1, 0, 0)
    ex.call({"I 0.6": 0, "M 1.4": 0})
    assert ex.step("Run", "V1") == 0
    assert ex.bit("M 1.4") == 0
    ex.call({"ACK_EF": 1})
    assert (ex.step("Run", "V0"), ex.step("Run", "A1")) == (1, 1)
    assert (ex.bit("M 1.5"), ex.bit("M 1.6")) == (1, 1)
    ex.call()
    assert (ex.step("Run", "V0"), ex.step("Run", "A1")) == (0, 0)


@pytest.mark.parametrize("kind", KINDS)
def test_r1_rows_never_fire(kind: str) -> None:
    ex = make(kind, chain("R1 S M 1.7", "R1 N Q 1.7"))
    enter_run(ex)
    for _ in range(3):
        ex.call()
    assert ex.step("Run", "R1") == 0
    assert (ex.bit("M 1.7"), ex.bit("Q 1.7")) == (0, 0)

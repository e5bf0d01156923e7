"""SEMANTICS §2 phase 5, the interlock (marker C): while its condition is false the step is
disturbed (LA, event L1, also in the call the step is activated), its C rows do not run (an
``N C`` bit is 0), ERR_FLT is on and U stops counting; when the condition is true again, L0.
By default an interlock error does not block the step's transitions; with
``interlock_blocks`` it does."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, cond, enter_run, make

from nasaq.lang.graph.model import Settings

ROWS = ("N C Q 0.4", "N Q 0.5", "S C M 2.2", "L1 S M 2.0", "L0 S M 2.1")


@pytest.mark.parametrize("kind", KINDS)
def test_an_interlock_false_at_activation_raises_l1_at_once(kind: str) -> None:
    ex = make(kind, chain(*ROWS, interlock=cond(c("I 0.5"))))
    enter_run(ex)
    assert ex.step("Run", "LA") == 1
    assert ex.step("Run", "L1") == 1
    assert (ex.bit("Q 0.4"), ex.bit("Q 0.5"), ex.bit("M 2.2")) == (0, 1, 0)
    assert ex.bit("M 2.0") == 1
    assert ex.out("ERR_FLT") == 1
    ex.call()
    assert ex.step("Run", "L1") == 0
    assert ex.step("Run", "LA") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_the_interlock_becoming_true_raises_l0_and_runs_the_c_rows(kind: str) -> None:
    ex = make(kind, chain(*ROWS, interlock=cond(c("I 0.5"))))
    enter_run(ex)
    ex.call({"I 0.5": 1})
    assert ex.step("Run", "LA") == 0
    assert ex.step("Run", "L0") == 1
    assert (ex.bit("Q 0.4"), ex.bit("M 2.2"), ex.bit("M 2.1")) == (1, 1, 1)
    assert ex.out("ERR_FLT") == 0
    ex.call({"I 0.5": 0})  # goes away again: L1, N C off
    assert ex.step("Run", "L1") == 1
    assert ex.bit("Q 0.4") == 0
    assert ex.bit("Q 0.5") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_an_interlock_true_at_activation_raises_nothing(kind: str) -> None:
    ex = make(kind, chain(*ROWS, interlock=cond(c("I 0.5"))))
    ex.call({"I 0.5": 1})
    ex.call({"I 0.0": 1})
    assert ex.step("Run", "LA") == 0
    assert ex.step("Run", "L1") == 0
    assert ex.step("Run", "L0") == 0
    assert ex.bit("Q 0.4") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_u_does_not_count_while_the_step_is_disturbed(kind: str) -> None:
    ex = make(kind, chain(interlock=cond(c("I 0.5"))))
    enter_run(ex)  # LA from this call on
    ex.call()
    assert (ex.step("Run", "T"), ex.step("Run", "U")) == (100, 0)
    ex.call({"I 0.5": 1})  # LA was still set at the start of this call
    assert (ex.step("Run", "T"), ex.step("Run", "U")) == (200, 0)
    ex.call()
    assert (ex.step("Run", "T"), ex.step("Run", "U")) == (300, 100)


@pytest.mark.parametrize("kind", KINDS)
def test_an_interlock_error_does_not_block_switching_by_default(kind: str) -> None:
    ex = make(kind, chain(interlock=cond(c("I 0.5"))))
    enter_run(ex)
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_interlock_blocks_switching_when_set_so(kind: str) -> None:
    settings = Settings(interlock_blocks=True)
    ex = make(kind, chain(interlock=cond(c("I 0.5")), settings=settings))
    enter_run(ex)
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.step("Run") == 1
    ex.call({"I 0.5": 1})  # LA cleared in phase 5 of this call: the switch waits for the next
    assert ex.step("Run") == 1
    assert ex.step("Run", "LA") == 0
    ex.call()
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_a_step_without_interlock_is_never_disturbed(kind: str) -> None:
    ex = make(kind, chain("N C Q 0.4"))
    enter_run(ex)
    assert ex.step("Run", "LA") == 0
    assert ex.bit("Q 0.4") == 1
    assert ex.out("ERR_FLT") == 0

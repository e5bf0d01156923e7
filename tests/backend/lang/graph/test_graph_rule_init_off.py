"""SEMANTICS §2 phase 1: the first call activates the initial steps; INIT_SQ (a level) leaves
every other step and activates the initial ones, and while it is held no transition fires;
OFF_SQ (a level, it wins over INIT_SQ) switches every step off, and the sequencer stays off
when it is released until INIT_SQ or an ON starts it again."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, cond, enter_run, make


@pytest.mark.parametrize("kind", KINDS)
def test_all_steps_start_off_and_the_first_call_activates_the_initial_ones(
    kind: str,
) -> None:
    ex = make(kind, chain("N Q 0.0", idle_actions=("N Q 0.1",)))
    ex.call({"I 0.0": 1})  # no transition fires in the initialising call
    assert ex.step("Idle") == 1
    assert ex.step("Idle", "S1") == 1
    assert ex.step("Run") == 0
    assert ex.bit("Q 0.1") == 1
    assert ex.bit("Q 0.0") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_init_sq_returns_to_the_initial_step_and_holds_it(kind: str) -> None:
    ex = make(kind, chain("N Q 0.0"))
    enter_run(ex)
    ex.call({"INIT_SQ": 1})
    assert ex.step("Run") == 0
    assert ex.step("Run", "S0") == 1
    assert ex.bit("Q 0.0") == 0
    assert ex.step("Idle") == 1
    assert ex.step("Idle", "S1") == 1
    ex.call()  # held, I 0.0 still true: no switching
    assert ex.step("Idle") == 1
    assert ex.step("Run") == 0
    assert ex.step("Idle", "S1") == 0
    ex.call({"INIT_SQ": 0})
    assert ex.step("Run") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_init_sq_keeps_an_active_initial_step_and_clears_errors(kind: str) -> None:
    ex = make(kind, chain(supervision=cond(c("I 0.6"))))
    enter_run(ex)
    ex.call({"I 0.6": 1})
    assert ex.out("ERR_FLT") == 1
    ex.call({"INIT_SQ": 1})
    assert ex.step("Run", "VA") == 0
    assert ex.out("ERR_FLT") == 0
    ex.call()
    assert ex.step("Idle", "S1") == 0
    assert ex.step("Idle", "T") == 100


@pytest.mark.parametrize("kind", KINDS)
def test_off_sq_switches_everything_off_while_held_and_after(kind: str) -> None:
    ex = make(kind, chain("N Q 0.0"))
    enter_run(ex)
    ex.call({"OFF_SQ": 1})
    assert ex.step("Run") == 0
    assert ex.step("Run", "S0") == 1
    assert ex.bit("Q 0.0") == 0
    assert ex.step("Idle") == 0
    ex.call({"INIT_SQ": 1})  # OFF_SQ wins
    assert ex.step("Idle") == 0
    assert ex.step("Run") == 0
    ex.call({"INIT_SQ": 0, "OFF_SQ": 0})
    ex.call()
    assert ex.step("Idle") == 0
    assert ex.step("Run") == 0
    ex.call({"INIT_SQ": 1})
    assert ex.step("Idle") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_man_cannot_switch_while_init_sq_is_held(kind: str) -> None:
    """MAN's S_ON/S_OFF belong to phase 4, which phase 1 skips: held INIT_SQ wins."""
    ex = make(kind, chain())
    ex.call({"SW_MAN": 1})
    ex.call({"INIT_SQ": 1})
    ex.call({"S_SEL": 1, "S_OFF": 1})
    assert ex.step("Idle") == 1
    assert ex.step("Idle", "S0") == 0
    ex.call({"S_SEL": 2, "S_ON": 1})
    assert ex.step("Run") == 0

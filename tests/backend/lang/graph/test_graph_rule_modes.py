"""SEMANTICS §2 phases 0, 4 and 6, the modes: AUTO (1) switches on the condition; MAN (2)
never switches, S_ON/S_OFF rising edges switch step S_SEL on/off; TAP (3) switches on the
condition and a T_PUSH rising edge; TOP (4) on the condition or a T_PUSH edge (decision (d):
one switch per push). The SW_* inputs act on their rising edge and the mode is kept in the
instance DB; AUTO_ON/MAN_ON/TAP_ON/TOP_ON show it. SW_TOP is in the user-defined set only."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, chain, enter_run, make

from nasaq.lang.graph.model import Settings

USER = Settings(parameters="USER_DEFINED")


@pytest.mark.parametrize("kind", KINDS)
def test_auto_is_the_initial_mode(kind: str) -> None:
    ex = make(kind, chain())
    ex.call()
    assert ex.mode() == 1
    assert ex.out("AUTO_ON") == 1
    assert ex.out("MAN_ON") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_man_never_switches_and_the_mode_is_kept(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"SW_MAN": 1})
    ex.call({"SW_MAN": 0, "I 0.0": 1})
    assert ex.mode() == 2
    assert ex.out("MAN_ON") == 1
    assert ex.out("AUTO_ON") == 0
    assert ex.step("Idle") == 1
    assert ex.step("Run") == 0
    assert ex.tt("Trans1") == 1  # computed for display
    ex.call({"SW_AUTO": 1})
    assert ex.mode() == 1
    assert ex.step("Run") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_man_s_on_and_s_off_act_on_the_selected_step(kind: str) -> None:
    ex = make(kind, chain("N Q 3.0"))
    ex.call({"SW_MAN": 1})
    ex.call({"S_SEL": 2, "S_ON": 1})
    assert ex.step("Run") == 1
    assert ex.step("Run", "S1") == 1
    assert ex.bit("Q 3.0") == 1
    assert ex.step("Idle") == 1
    assert ex.out("S_NO") == 2
    assert ex.out("S_ACTIVE") == 1
    ex.call()  # S_ON held: no new edge
    assert ex.step("Run", "S1") == 0
    ex.call({"S_ON": 0, "S_SEL": 1, "S_OFF": 1})
    assert ex.step("Idle") == 0
    assert ex.step("Idle", "S0") == 1
    assert ex.out("S_NO") == 1
    assert ex.out("S_ACTIVE") == 0
    ex.call({"S_OFF": 0, "S_SEL": 2})
    ex.call({"S_OFF": 1})
    assert ex.step("Run") == 0
    assert ex.bit("Q 3.0") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_tap_switches_on_condition_and_push_edge(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"SW_TAP": 1})
    assert ex.mode() == 3
    assert ex.out("TAP_ON") == 1
    ex.call({"I 0.0": 1})
    assert ex.step("Run") == 0
    ex.call({"T_PUSH": 1})
    assert ex.step("Run") == 1
    ex.call({"I 0.1": 1})  # T_PUSH held: no new push
    assert ex.step("Run") == 1
    ex.call({"T_PUSH": 0})
    ex.call({"T_PUSH": 1})
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_tap_push_without_condition_does_nothing(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"SW_TAP": 1})
    ex.call({"T_PUSH": 1})
    assert ex.step("Idle") == 1
    assert ex.step("Run") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_top_switches_on_condition_or_push(kind: str) -> None:
    ex = make(kind, chain(settings=USER))
    ex.call({"SW_TOP": 1})
    assert ex.mode() == 4
    assert ex.out("TOP_ON") == 1
    ex.call({"T_PUSH": 1})  # no condition, pushed
    assert ex.step("Run") == 1
    ex.call()
    assert ex.step("Run") == 1
    ex.call({"I 0.1": 1})  # condition, no push
    assert ex.step("Idle") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_the_last_mode_input_in_order_wins(kind: str) -> None:
    """AUTO, TAP, TOP, MAN are checked in this order: MAN wins over AUTO in one call."""
    ex = make(kind, chain())
    ex.call({"SW_AUTO": 1, "SW_MAN": 1})
    assert ex.mode() == 2
    ex.call({"SW_AUTO": 0, "SW_MAN": 0})
    ex.call({"SW_AUTO": 1, "SW_TAP": 1})
    assert ex.mode() == 3


@pytest.mark.parametrize("kind", KINDS)
def test_a_held_mode_input_selects_only_once(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"SW_MAN": 1})
    ex.call({"SW_TAP": 1})
    assert ex.mode() == 3
    ex.call()
    assert ex.mode() == 3


@pytest.mark.parametrize("kind", KINDS)
def test_s_no_shows_the_active_step_in_auto(kind: str) -> None:
    ex = make(kind, chain())
    ex.call()
    assert ex.out("S_NO") == 1
    assert ex.out("S_ACTIVE") == 1
    assert ex.out("S_MORE") == 0
    enter_run(ex)
    assert ex.out("S_NO") == 2

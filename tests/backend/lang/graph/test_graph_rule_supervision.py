"""SEMANTICS §2 phase 3 and decision (c), supervision (marker V): a true supervision condition
of a step active before the call is an error (VA, V1, ERR_FLT) that blocks the step's
transitions, also when both become true in the same call; with ``acknowledge_required`` (the
default) it stays until an ACK_EF rising edge (V0, A1), and is raised again in the next call
while the condition is still true; without, it clears by itself when the condition is false."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, cmp, cond, enter_run, make

from nasaq.lang.graph.model import Settings

WATCH = cond(c("I 0.6"))


@pytest.mark.parametrize("kind", KINDS)
def test_a_supervision_error_blocks_the_transition_true_in_the_same_call(
    kind: str,
) -> None:
    ex = make(kind, chain(supervision=WATCH))
    enter_run(ex)
    ex.call({"I 0.6": 1, "I 0.1": 1})
    assert ex.step("Run") == 1
    assert ex.step("Run", "VA") == 1
    assert ex.step("Run", "V1") == 1
    assert ex.out("ERR_FLT") == 1
    assert ex.tt("Trans2") == 1  # the condition is true, the switch is blocked


@pytest.mark.parametrize("kind", KINDS)
def test_the_error_stays_until_acknowledged_then_the_step_switches(kind: str) -> None:
    ex = make(kind, chain(supervision=WATCH))
    enter_run(ex)
    ex.call({"I 0.6": 1})
    ex.call({"I 0.6": 0, "I 0.1": 1})
    assert ex.step("Run") == 1
    assert ex.step("Run", "VA") == 1
    assert ex.step("Run", "V0") == 0
    ex.call({"ACK_EF": 1})  # acknowledged in phase 3, switched in phase 4 of the same call
    assert ex.step("Run", "VA") == 0
    assert ex.step("Run", "V0") == 1
    assert ex.step("Run", "A1") == 1
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 1
    assert ex.out("ERR_FLT") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_acknowledgement_acts_on_the_rising_edge_and_a_true_error_comes_back(
    kind: str,
) -> None:
    ex = make(kind, chain(supervision=WATCH))
    enter_run(ex)
    ex.call({"I 0.6": 1})
    ex.call({"ACK_EF": 1})
    assert ex.step("Run", "VA") == 0
    assert ex.step("Run", "A1") == 1
    ex.call()  # still true: raised again
    assert ex.step("Run", "VA") == 1
    assert ex.step("Run", "V1") == 1
    ex.call({"I 0.6": 0})  # ACK_EF still held: no new edge
    assert ex.step("Run", "VA") == 1
    ex.call({"ACK_EF": 0})
    ex.call({"ACK_EF": 1})
    assert ex.step("Run", "VA") == 0
    ex.call()
    assert ex.step("Run", "VA") == 0
    assert ex.out("ERR_FLT") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_without_acknowledge_required_the_error_clears_itself(kind: str) -> None:
    ex = make(kind, chain(supervision=WATCH, settings=Settings(acknowledge_required=False)))
    enter_run(ex)
    ex.call({"I 0.6": 1, "I 0.1": 1})
    assert ex.step("Run") == 1
    assert ex.step("Run", "VA") == 1
    ex.call({"I 0.6": 0})  # cleared in phase 3, switched in phase 4
    assert ex.step("Run", "V0") == 1
    assert ex.step("Run", "A1") == 0
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_a_step_time_supervision(kind: str) -> None:
    """``Run.T > T#250MS``: T is 300 ms in the third call after the activation."""
    watch = cond(cmp(">", "Run.T", "T#250MS"))
    ex = make(kind, chain(supervision=watch))
    enter_run(ex)
    ex.call()
    ex.call()
    assert ex.step("Run", "VA") == 0
    ex.call()
    assert ex.step("Run", "VA") == 1
    assert ex.step("Run", "V1") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_a_step_is_not_supervised_in_the_call_it_is_activated(kind: str) -> None:
    ex = make(kind, chain(supervision=WATCH))
    ex.call({"I 0.6": 1})
    ex.call({"I 0.0": 1})
    assert ex.step("Run") == 1
    assert ex.step("Run", "VA") == 0
    ex.call()
    assert ex.step("Run", "VA") == 1

"""SEMANTICS §2 phase 4, Skip Step: with ``skip_steps`` (or EN_SSKIP in the user-defined set),
a step whose outgoing transition is already true when it would be activated is passed: not
activated (no S1, no actions), and that transition fires instead. Without it the step is
activated and its actions run for one call (a step activated in a call is not left in it)."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, fb, make, seq, step, trans

from nasaq.lang.graph.model import GraphBlock, Settings


def block(settings: Settings) -> GraphBlock:
    return fb(
        seq(
            "Line",
            [
                step("A", 1, initial=True),
                step("B", 2, "N Q 0.0", "S1 S M 3.0"),
                step("C", 3, "N Q 0.1"),
            ],
            [
                trans(1, "A", "B", c("I 0.0")),
                trans(2, "B", "C", c("I 0.1")),
                trans(3, "C", "A", c("I 0.2")),
            ],
        ),
        settings=settings,
    )


@pytest.mark.parametrize("kind", KINDS)
def test_without_skip_the_step_is_activated_for_a_call(kind: str) -> None:
    ex = make(kind, block(Settings()))
    ex.call()
    ex.call({"I 0.0": 1, "I 0.1": 1})
    assert ex.step("B") == 1
    assert ex.bit("Q 0.0") == 1
    assert ex.bit("M 3.0") == 1
    ex.call()
    assert ex.step("B") == 0
    assert ex.step("C") == 1
    assert ex.bit("Q 0.0") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_with_skip_the_step_is_passed(kind: str) -> None:
    ex = make(kind, block(Settings(skip_steps=True)))
    ex.call()
    ex.call({"I 0.0": 1, "I 0.1": 1})
    assert (ex.step("A"), ex.step("B"), ex.step("C")) == (0, 0, 1)
    assert ex.step("B", "S1") == 0
    assert ex.step("C", "S1") == 1
    assert ex.bit("Q 0.0") == 0
    assert ex.bit("M 3.0") == 0
    assert ex.bit("Q 0.1") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_with_skip_a_step_whose_next_transition_is_false_is_activated(
    kind: str,
) -> None:
    ex = make(kind, block(Settings(skip_steps=True)))
    ex.call()
    ex.call({"I 0.0": 1})
    assert ex.step("B") == 1
    assert ex.bit("M 3.0") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_en_sskip_switches_skipping_on(kind: str) -> None:
    ex = make(kind, block(Settings(parameters="USER_DEFINED")))
    ex.call({"EN_SSKIP": 1})
    ex.call({"I 0.0": 1, "I 0.1": 1})
    assert (ex.step("B"), ex.step("C")) == (0, 1)

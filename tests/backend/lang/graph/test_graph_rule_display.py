"""SEMANTICS §2 phase 6, the display outputs: S_MORE when more than one step is active; S_NO
the number of the displayed active step (0 if none) and S_ACTIVE; S_NEXT/S_PREV rising edges
move the display through the active steps in step order, wrapping round."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, fb, make, seq, step, trans

from nasaq.lang.graph.model import GraphBlock


def three() -> GraphBlock:
    steps = [step("A", 1, initial=True), step("B", 4), step("C", 7), step("D", 9)]
    transitions = [
        trans(1, "A", ["B", "C", "D"], c("I 0.0")),
        trans(2, ["B", "C", "D"], "A", c("I 0.1")),
    ]
    return fb(seq("Three", steps, transitions))


@pytest.mark.parametrize("kind", KINDS)
def test_s_next_and_s_prev_walk_through_the_active_steps(kind: str) -> None:
    ex = make(kind, three())
    ex.call()
    ex.call({"I 0.0": 1})
    assert ex.out("S_MORE") == 1
    assert ex.out("S_NO") == 4
    assert ex.out("S_ACTIVE") == 1
    shown = []
    for edge in ("S_NEXT", "S_NEXT", "S_NEXT", "S_PREV", "S_PREV"):
        ex.call({edge: 1})
        shown.append(ex.out("S_NO"))
        ex.call({edge: 0})
    assert shown == [7, 9, 4, 9, 7]


@pytest.mark.parametrize("kind", KINDS)
def test_s_prev_without_active_steps_leaves_the_display_usable(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"OFF_SQ": 1})
    assert ex.out("S_NO") == 0
    assert ex.out("S_ACTIVE") == 0
    ex.call({"S_PREV": 1})
    ex.call({"OFF_SQ": 0, "S_PREV": 0, "INIT_SQ": 1})
    assert ex.step("Idle") == 1
    assert ex.out("S_NO") == 1
    assert ex.out("S_ACTIVE") == 1

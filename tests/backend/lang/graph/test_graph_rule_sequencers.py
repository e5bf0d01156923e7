"""SEMANTICS §2, several sequencers in one FB: all run in every call, each from its own
initial step; a supervision error in one blocks only its own transitions; step numbers and
S_MORE span the FB."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, cond, fb, make, seq, step, trans

from nasaq.lang.graph.model import GraphBlock


def two() -> GraphBlock:
    first = seq(
        "Left",
        [
            step("L1", 1, initial=True),
            step("L2", 2, "N Q 4.0", supervision=cond(c("I 1.0"))),
        ],
        [trans(1, "L1", "L2", c("I 0.0")), trans(2, "L2", "L1", c("I 0.1"))],
    )
    second = seq(
        "Right",
        [step("R1", 11, initial=True), step("R2", 12, "N Q 4.1")],
        [trans(11, "R1", "R2", c("I 0.0")), trans(12, "R2", "R1", c("I 0.1"))],
    )
    return fb(first, second)


@pytest.mark.parametrize("kind", KINDS)
def test_both_sequencers_start_and_switch_in_the_same_call(kind: str) -> None:
    ex = make(kind, two())
    ex.call()
    assert (ex.step("L1"), ex.step("R1")) == (1, 1)
    assert ex.out("S_MORE") == 1
    ex.call({"I 0.0": 1})
    assert (ex.step("L2"), ex.step("R2")) == (1, 1)
    assert (ex.bit("Q 4.0"), ex.bit("Q 4.1")) == (1, 1)


@pytest.mark.parametrize("kind", KINDS)
def test_a_supervision_error_stops_only_its_own_sequencer(kind: str) -> None:
    ex = make(kind, two())
    ex.call()
    ex.call({"I 0.0": 1})
    ex.call({"I 0.0": 0, "I 1.0": 1, "I 0.1": 1})
    assert ex.step("L2") == 1
    assert ex.step("L2", "VA") == 1
    assert ex.step("R1") == 1
    assert ex.step("R2") == 0
    assert ex.out("ERR_FLT") == 1

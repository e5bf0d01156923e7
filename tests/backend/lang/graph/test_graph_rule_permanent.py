"""SEMANTICS §2, the permanent instructions: the pre-networks run after the inputs are read
and before the sequencer (a transition sees what they wrote in the same call), the
post-networks after the actions (they see this call's action results)."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, fb, make, seq, step, trans

from nasaq.lang.graph.model import GraphBlock
from nasaq.lang.lad.model import Coil, CoilKind, Network, Output, Series


def rung(contact: str, coil: str, kind: CoilKind = "=") -> Network:
    return Network(
        logic=Series(elements=[c(contact)]),
        outputs=[Output(target=Coil(coil=kind, operand=coil))],
    )


def block() -> GraphBlock:
    steps = [step("Idle", 1, initial=True), step("Run", 2, "N Q 0.0")]
    transitions = [
        trans(1, "Idle", "Run", c("M 30.0")),
        trans(2, "Run", "Idle", c("I 0.1")),
    ]
    return fb(
        seq("Loop", steps, transitions),
        pre=[rung("I 0.2", "M 30.0")],
        post=[rung("Q 0.0", "Q 0.7"), rung("I 0.3", "Q 0.6", "S")],
    )


@pytest.mark.parametrize("kind", KINDS)
def test_pre_networks_run_before_the_transitions(kind: str) -> None:
    ex = make(kind, block())
    ex.call()
    ex.call({"I 0.2": 1})
    assert ex.bit("M 30.0") == 1
    assert ex.step("Run") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_post_networks_see_this_calls_actions(kind: str) -> None:
    ex = make(kind, block())
    ex.call()
    ex.call({"I 0.2": 1})
    assert ex.bit("Q 0.0") == 1
    assert ex.bit("Q 0.7") == 1
    ex.call({"I 0.2": 0, "I 0.1": 1, "I 0.3": 1})
    assert ex.bit("Q 0.0") == 0
    assert ex.bit("Q 0.7") == 0
    assert ex.bit("Q 0.6") == 1

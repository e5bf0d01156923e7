"""SEMANTICS §2 phase 5 and decision (b), ON and OFF: they change the other step's X at once
and raise its S1/S0 in the next call (so its event rows run exactly once); OFF S_ALL switches
off every step but its own; an OFF after an ON of the same step in the same call wins.

``Aux`` (3) sits in a second sequencer without an initial step, so only ON starts it."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, fb, make, seq, step, trans

from nasaq.lang.graph.model import GraphBlock


def block(run: tuple[str, ...], idle: tuple[str, ...] = ()) -> GraphBlock:
    return fb(
        seq(
            "Loop",
            [step("Idle", 1, *idle, initial=True), step("Run", 2, *run)],
            [trans(1, "Idle", "Run", c("I 0.0")), trans(2, "Run", "Idle", c("I 0.1"))],
        ),
        seq(
            "Other",
            [step("Aux", 3, "N Q 2.0", "S1 S Q 2.1", "S0 S Q 2.2")],
            [trans(3, "Aux", None, c("I 0.7"))],
        ),
    )


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("target", ["S3", "Aux"])
def test_on_activates_at_once_and_raises_s1_in_the_next_call(kind: str, target: str) -> None:
    ex = make(kind, block(run=(f"S1 ON {target}",)))
    ex.call()
    assert ex.step("Aux") == 0
    ex.call({"I 0.0": 1})
    # Aux comes after Run in step order: its plain rows already ran in this call.
    assert ex.step("Aux") == 1
    assert ex.bit("Q 2.0") == 1
    assert ex.step("Aux", "S1") == 0
    assert ex.bit("Q 2.1") == 0
    assert ex.step("Aux", "T") == 0
    ex.call()
    assert ex.step("Aux", "S1") == 1
    assert ex.bit("Q 2.1") == 1
    ex.call()
    assert ex.step("Aux", "S1") == 0
    assert ex.step("Aux", "T") == 100


@pytest.mark.parametrize("kind", KINDS)
def test_off_deactivates_at_once_and_raises_s0_in_the_next_call(kind: str) -> None:
    ex = make(kind, block(run=("S1 OFF S3",), idle=("S1 ON S3",)))
    ex.call()
    ex.call()
    assert ex.step("Aux") == 1
    assert ex.bit("Q 2.0") == 1
    ex.call({"I 0.0": 1})
    assert ex.step("Aux") == 0
    assert ex.step("Aux", "S0") == 0
    ex.call()
    assert ex.step("Aux", "S0") == 1
    assert ex.bit("Q 2.0") == 0
    assert ex.bit("Q 2.2") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_off_s_all_leaves_only_its_own_step(kind: str) -> None:
    ex = make(kind, block(run=("S1 OFF S_ALL",), idle=("S1 ON S3",)))
    ex.call()
    ex.call({"I 0.0": 1})
    assert (ex.step("Idle"), ex.step("Run"), ex.step("Aux")) == (0, 1, 0)
    ex.call()
    assert ex.step("Run") == 1
    assert ex.step("Aux", "S0") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_an_off_after_an_on_in_the_same_call_wins(kind: str) -> None:
    ex = make(kind, block(run=("S1 ON S3", "S1 OFF S3")))
    ex.call()
    ex.call({"I 0.0": 1})
    assert ex.step("Aux") == 0
    ex.call()
    assert ex.step("Aux") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_on_of_an_active_step_does_not_restart_it(kind: str) -> None:
    ex = make(kind, block(run=("S1 ON S3",), idle=("S1 ON S3",)))
    ex.call()
    ex.call()
    ex.call()
    assert ex.step("Aux", "T") == 100
    ex.call({"I 0.0": 1})
    assert ex.step("Aux") == 1
    assert ex.step("Aux", "T") == 200
    ex.call()
    assert ex.step("Aux", "S1") == 0

"""SEMANTICS §2 phase 5, the counter qualifiers CS (set to a preset), CU (+1), CD (-1) and CR
(reset), event actions that act once per event: entering the step three times counts three."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, Executor, chain, make


def around(ex: Executor, times: int) -> None:
    """Enters Run and goes back to Idle ``times`` times (one transition per call)."""
    for _ in range(times):
        ex.call({"I 0.0": 1, "I 0.1": 0})
        ex.call({"I 0.0": 0, "I 0.1": 1})


@pytest.mark.parametrize("kind", KINDS)
def test_cu_counts_every_activation_once(kind: str) -> None:
    ex = make(kind, chain("S1 CU C 1"))
    ex.call()
    around(ex, 3)
    ex.call()
    assert ex.counter(1) == 3


@pytest.mark.parametrize("kind", KINDS)
def test_cs_presets_and_cd_counts_down(kind: str) -> None:
    ex = make(kind, chain("S1 CS C 2, C#26", "S0 CD C 2"))
    ex.call()
    ex.call({"I 0.0": 1})
    assert ex.counter(2) == 26
    ex.call()
    assert ex.counter(2) == 26
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.counter(2) == 25


@pytest.mark.parametrize("kind", KINDS)
def test_cr_resets_the_counter(kind: str) -> None:
    ex = make(kind, chain("S1 CU C 3", idle_actions=("S1 CR C 3",)))
    ex.call()
    ex.call({"I 0.0": 1})
    assert ex.counter(3) == 1
    ex.call({"I 0.0": 0, "I 0.1": 1})
    assert ex.step("Idle") == 1
    assert ex.counter(3) == 0


@pytest.mark.parametrize("kind", KINDS)
def test_cd_stops_at_zero(kind: str) -> None:
    ex = make(kind, chain("S1 CD C 4"))
    ex.call()
    around(ex, 2)
    assert ex.counter(4) == 0

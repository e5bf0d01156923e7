"""SEMANTICS §2 phase 5, the timer qualifiers: TL starts an S5 timer as an extended pulse (STL
SE: its bit is 1 for the time, whatever the step does), TD as a retentive on-delay (STL SS: its
bit becomes 1 after the time and stays until reset), TR resets it. The timers are read after a
call, at that call's time (the CPU's clock stands still in these tests between the calls)."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, chain, make


@pytest.mark.parametrize("kind", KINDS)
def test_tl_is_an_extended_pulse_that_outlives_the_step(kind: str) -> None:
    ex = make(kind, chain("S1 TL T 1, S5T#500MS"))
    ex.call()
    ex.call({"I 0.0": 1})  # started at this call
    assert ex.timer(1) == 1
    ex.call({"I 0.0": 0, "I 0.1": 1})  # Run left after 100 ms: the pulse goes on
    assert ex.step("Run") == 0
    assert ex.timer(1) == 1
    ex.call(dt=300)  # 400 ms
    assert ex.timer(1) == 1
    ex.call(dt=150)  # 550 ms
    assert ex.timer(1) == 0


@pytest.mark.parametrize("kind", KINDS)
def test_td_switches_on_after_its_time_and_stays_until_tr(kind: str) -> None:
    ex = make(kind, chain("S1 TD T 2, S5T#300MS", idle_actions=("S1 TR T 2",)))
    ex.call()
    ex.call({"I 0.0": 1})
    assert ex.timer(2) == 0
    ex.call(dt=150)
    assert ex.timer(2) == 0
    ex.call(dt=200)  # 350 ms
    assert ex.timer(2) == 1
    ex.call(dt=500)
    assert ex.timer(2) == 1
    ex.call({"I 0.0": 0, "I 0.1": 1})  # Idle entered: S1 TR
    assert ex.step("Idle") == 1
    assert ex.timer(2) == 0


@pytest.mark.parametrize("kind", KINDS)
def test_tl_runs_once_per_activation(kind: str) -> None:
    """The event starts the timer once; it is not restarted while the step stays active."""
    ex = make(kind, chain("S1 TL T 3, S5T#300MS"))
    ex.call()
    ex.call({"I 0.0": 1})
    for _ in range(3):
        ex.call()
    assert ex.step("Run") == 1
    assert ex.timer(3) == 0

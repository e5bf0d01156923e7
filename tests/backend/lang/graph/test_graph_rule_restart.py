"""SEMANTICS §3, retention: the sequencer state and the mode are in the instance DB, so after
STOP and a warm restart the FB resumes where it was (no initialisation, the active step keeps
its time) in the mode it was in; OB 100 calling it with INIT_SQ is how a user restarts it."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, chain, enter_run, make


@pytest.mark.parametrize("kind", KINDS)
def test_a_warm_restart_resumes_at_the_active_step(kind: str) -> None:
    ex = make(kind, chain("N Q 0.0"))
    enter_run(ex)
    ex.call()
    ex.restart()
    ex.call()
    assert ex.step("Run") == 1
    assert ex.step("Idle") == 0
    assert ex.step("Run", "S1") == 0
    assert ex.step("Idle", "S1") == 0
    assert ex.step("Run", "T") == 200
    assert ex.bit("Q 0.0") == 1  # written again by the active step


@pytest.mark.parametrize("kind", KINDS)
def test_a_warm_restart_keeps_the_mode(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"SW_TAP": 1})
    ex.restart()
    ex.call({"SW_TAP": 0, "I 0.0": 1})
    assert ex.mode() == 3
    assert ex.out("TAP_ON") == 1
    assert ex.step("Run") == 0

"""SEMANTICS §4, the Control Sequencer mailbox: a session writes G7_CMD_STEP then G7_CMD into
the instance DB; the next call acts as if the matching input had a rising edge (or INIT_SQ /
OFF_SQ were set for that one call) and clears G7_CMD."""

from __future__ import annotations

import pytest
from graph_harness import KINDS, c, chain, cond, enter_run, make


@pytest.mark.parametrize("kind", KINDS)
def test_mode_commands_and_the_mailbox_is_cleared(kind: str) -> None:
    ex = make(kind, chain())
    ex.call()
    for command, mode in ((2, 2), (3, 3), (4, 4), (1, 1)):
        ex.command(command)
        ex.call()
        assert ex.mode() == mode
        assert ex.out("G7_CMD") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_step_on_and_off_in_man(kind: str) -> None:
    ex = make(kind, chain("N Q 3.0"))
    ex.call()
    ex.command(6, 2)  # not in MAN: ignored
    ex.call()
    assert ex.step("Run") == 0
    ex.command(2)
    ex.call()
    ex.command(6, 2)
    ex.call()
    assert ex.step("Run") == 1
    assert ex.step("Run", "S1") == 1
    assert ex.bit("Q 3.0") == 1
    ex.command(7, 1)
    ex.call()
    assert ex.step("Idle") == 0
    assert ex.step("Idle", "S0") == 1
    assert ex.step("Run") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_push_in_tap(kind: str) -> None:
    ex = make(kind, chain())
    ex.call({"I 0.0": 1})
    ex.command(3)
    ex.call()
    assert ex.step("Run") == 0
    ex.command(8)
    ex.call()
    assert ex.step("Run") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_acknowledge(kind: str) -> None:
    ex = make(kind, chain(supervision=cond(c("I 0.6"))))
    enter_run(ex)
    ex.call({"I 0.6": 1})
    ex.call({"I 0.6": 0})
    assert ex.step("Run", "VA") == 1
    ex.command(5)
    ex.call()
    assert ex.step("Run", "VA") == 0
    assert ex.step("Run", "A1") == 1


@pytest.mark.parametrize("kind", KINDS)
def test_init_and_off_last_one_call(kind: str) -> None:
    ex = make(kind, chain())
    enter_run(ex)
    ex.command(9)
    ex.call()
    assert ex.step("Idle") == 1
    assert ex.step("Run") == 0
    ex.call()  # INIT for one call only: I 0.0 switches again
    assert ex.step("Run") == 1
    ex.command(10)
    ex.call()
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 0
    ex.call()
    assert ex.step("Run") == 0
    assert ex.step("Idle") == 0


@pytest.mark.parametrize("kind", KINDS)
def test_interlock_and_supervision_switches(kind: str) -> None:
    ex = make(
        kind,
        chain("N C Q 3.1", interlock=cond(c("I 0.5")), supervision=cond(c("I 0.6"))),
    )
    enter_run(ex)
    assert ex.step("Run", "LA") == 1
    assert ex.bit("Q 3.1") == 0
    ex.command(12)  # interlock off: the condition no longer counts
    ex.call()
    assert ex.step("Run", "LA") == 0
    assert ex.step("Run", "L0") == 1
    assert ex.bit("Q 3.1") == 1
    ex.command(11)
    ex.call()
    assert ex.step("Run", "LA") == 1
    ex.command(14)  # supervision off
    ex.call({"I 0.6": 1})
    assert ex.step("Run", "VA") == 0
    ex.command(13)
    ex.call()
    assert ex.step("Run", "VA") == 1

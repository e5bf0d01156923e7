"""Breakpoints on a step's activation and single step by transition, on real ``.graph`` FBs in a
session: the CPU holds before the step becomes active however that happens (a transition, the
initial step at INIT_SQ, MAN's step on, an ON action), the hold says which step of which FB,
a single step runs to the next firing (past the other targets of a simultaneous branch, and
through the clock a step time needs), and bad requests get their MON62x codes."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from graph_session import Cpu

from nasaq.ir import BlockKind
from nasaq.lang.stl import SourceFile
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import CLIENT_MESSAGE, HoldState, SetBreakpoint, Step

SCENARIOS = Path(__file__).resolve().parents[2] / "scenarios" / "graph"
FB1 = (BlockKind.FB, 1)


def scenario(*names: str) -> list[SourceFile]:
    return [SourceFile(name, (SCENARIOS / name).read_text()) for name in names]


class Debugged(Cpu):
    """A paused session whose clock runs fast when it runs (a step single-stepped through a
    5 s step time takes no 5 s), with the debugger's messages as a client sends them."""

    def __init__(self, sources: list[SourceFile]) -> None:
        super().__init__(sources)
        self.run(lambda: self.session.do_set_time("fast", None))
        self.run(lambda: self.session.do_set_time("pause", None))

    def breakpoint(self, **location: Any) -> dict[str, Any]:
        message = CLIENT_MESSAGE.validate_python({"type": "set_breakpoint", "location": location})
        assert isinstance(message, SetBreakpoint)
        found: dict[str, Any] = self.run(
            lambda: self.session.do_set_breakpoint(message.location, message.condition)
        )
        return found

    def step_by_transition(self) -> None:
        message = CLIENT_MESSAGE.validate_python({"type": "step", "by": "transition"})
        assert isinstance(message, Step)
        self.run(lambda: self.session.do_step(message.by, message.into))

    def held(self, start: Callable[[], Any] | None = None) -> HoldState:
        """Calls ``start`` (by default: run a few scans) and waits for the hold."""
        session = self.session
        if start is None:
            self.run(lambda: session.do_run_scans(20))
        else:
            start()
        deadline = time.monotonic() + 5
        while session.hold_view is None:
            assert time.monotonic() < deadline, "the CPU did not hold"
            time.sleep(0.005)
        return session.hold_view

    def go_on(self) -> None:
        """Continues from the hold and waits until the scan is done."""
        session = self.session
        self.run(session.do_continue)
        deadline = time.monotonic() + 5
        while session.held is not None:
            assert time.monotonic() < deadline, "the CPU still holds"
            time.sleep(0.005)
        self.run(lambda: session.do_set_time("pause", None))
        self.run(lambda: None)

    def clear(self) -> None:
        self.run(lambda: self.session.do_clear_breakpoint(None))


@pytest.fixture(scope="module")
def conveyors() -> Iterator[Debugged]:
    cpu = Debugged(scenario("g17_conveyors.graph", "g17_conveyors.awl", "g17_conveyors.sdf"))
    cpu.scans(2)
    yield cpu
    cpu.session.close()


def test_a_step_breakpoint_holds_before_the_transition_switches_the_step_on(
    conveyors: Debugged,
) -> None:
    session = conveyors.session
    conveyors.run(lambda: session.do_open_block(1, '"Conveyors"'))
    set_ = conveyors.breakpoint(block='"Conveyors"', step=2)
    assert (set_["block"], set_["where"]) == ("FB1", "FB1 step 2")
    assert conveyors.breakpoint(block='"Conveyors"', step=2)["id"] == set_["id"]  # the same one
    conveyors.write({"I0.0": True})
    hold = conveyors.held()
    assert (hold.reason, hold.breakpoint) == ("breakpoint", set_["id"])
    assert (hold.graph_step, hold.graph_block) == (2, "FB1")
    assert hold.location.block == "FB1"
    assert [frame.block for frame in hold.call_stack] == ["FB1", "OB1"]
    # about to become active: Trans2 left Idle, B_on is not on yet, nor is belt B
    assert conveyors.read("IDB_Conveyors.B_on.X") == 0
    assert conveyors.read("IDB_Conveyors.Idle.X") == 0
    assert conveyors.read("Q0.1") == 0
    # the chart at the hold: the FB's instance as it is now, no step active
    status = conveyors.run(lambda: session.snapshot and session.snapshot.blocks.get(FB1))
    assert status is not None
    assert status.graph is not None
    assert [s.state for s in status.graph.steps] == ["inactive"] * 6
    state = conveyors.run(session.do_session_state)
    assert state["breakpoints"][0]["location"] == {"block": '"Conveyors"', "step": 2}
    conveyors.write({"I0.0": False})
    conveyors.go_on()
    assert conveyors.read("IDB_Conveyors.B_on.X") == 1
    assert conveyors.read("Q0.1") == 1
    conveyors.run(lambda: session.do_open_block(1, None))
    conveyors.clear()


def test_single_step_by_transition_runs_to_each_next_firing(
    conveyors: Debugged,
) -> None:
    """From B_on (waiting 5 s for A_on) the steps go: A_on after its 5 s, then Idle (the empty
    transition), each a hold of reason step saying the step."""
    assert conveyors.read("IDB_Conveyors.B_on.X") == 1
    hold = conveyors.held(conveyors.step_by_transition)
    assert (hold.reason, hold.breakpoint, hold.graph_step, hold.graph_block) == (
        "step",
        None,
        3,
        "FB1",
    )
    assert conveyors.read("IDB_Conveyors.B_on.T") >= 5000  # the clock ran for the step time
    assert conveyors.read("IDB_Conveyors.A_on.X") == 0
    hold = conveyors.held(conveyors.step_by_transition)  # from the hold: the next firing
    assert (hold.reason, hold.graph_step) == ("step", 1)
    assert conveyors.read("IDB_Conveyors.A_on.X") == 0  # Trans6 left A_on for Idle
    conveyors.go_on()
    assert conveyors.read("IDB_Conveyors.Idle.X") == 1
    assert conveyors.read("Q0.0") == 1


def test_continue_drops_a_step_still_waiting_for_its_transition(conveyors: Debugged) -> None:
    session = conveyors.session
    assert conveyors.read("IDB_Conveyors.Idle.X") == 1  # waits for Start, Stop or Emergency
    conveyors.step_by_transition()
    conveyors.run(lambda: None)
    time.sleep(0.05)  # the clock runs (fast), nothing fires
    assert session.hold_view is None
    assert conveyors.run(lambda: session.debugger.step) is not None
    conveyors.run(session.do_continue)
    assert conveyors.run(lambda: session.debugger.active) is False
    conveyors.run(lambda: session.do_set_time("pause", None))
    conveyors.write({"I0.1": True})  # Stop: A_off becomes active, and nothing holds
    conveyors.scans(2)
    conveyors.write({"I0.1": False})
    assert session.hold_view is None
    assert conveyors.read("IDB_Conveyors.A_off.X") == 1
    conveyors.write({"I0.2": True})  # back to Idle by way of Emergency
    conveyors.scans(2)
    conveyors.write({"I0.2": False})
    conveyors.scans(2)
    assert conveyors.read("IDB_Conveyors.Idle.X") == 1


def test_the_initial_step_at_init_and_a_step_switched_on_in_man(
    conveyors: Debugged,
) -> None:
    set_ = conveyors.breakpoint(file="g17_conveyors.graph", step=1)
    assert set_["where"] == "FB1 step 1"
    conveyors.control("IDB_Conveyors", "off")
    conveyors.control("IDB_Conveyors", "init")
    hold = conveyors.held()  # the call that initialises switches Idle on again
    assert (hold.reason, hold.graph_step) == ("breakpoint", 1)
    assert conveyors.read("IDB_Conveyors.Idle.X") == 0
    conveyors.go_on()
    assert conveyors.read("IDB_Conveyors.Idle.X") == 1
    conveyors.clear()

    conveyors.breakpoint(block="FB1", step=5)
    conveyors.control("IDB_Conveyors", "man")
    conveyors.control("IDB_Conveyors", "step_on", 5)
    hold = conveyors.held()
    assert (hold.reason, hold.graph_step) == ("breakpoint", 5)
    conveyors.go_on()
    assert conveyors.read("IDB_Conveyors.B_off.X") == 1
    conveyors.clear()
    conveyors.control("IDB_Conveyors", "step_off", 5)
    conveyors.control("IDB_Conveyors", "auto")
    conveyors.scans(3)
    assert conveyors.read("IDB_Conveyors.B_off.X") == 0


def test_bad_step_breakpoints_and_steps_get_their_codes(conveyors: Debugged) -> None:
    cases: list[tuple[dict[str, Any], str]] = [
        ({"block": "OB1", "step": 1}, "MON624"),
        ({"block": "FB1", "step": 99}, "MON625"),
        ({"block": "FB1", "step": 1, "line": 3}, "MON626"),
        ({"block": "FB1", "step": 1, "instruction": 0}, "MON626"),
        ({"file": "g17_conveyors.awl", "step": 1}, "MON627"),
        ({"file": "other.graph", "step": 1}, "MON627"),
        ({"block": "FB7", "step": 1}, "MON613"),
        ({"step": 1}, "MON604"),
    ]
    for location, code in cases:
        with pytest.raises(MonitorError) as raised:
            conveyors.breakpoint(**location)
        assert raised.value.code == code, location
    with pytest.raises(MonitorError) as raised:
        conveyors.breakpoint(block="FB1", step=99)
    assert "S1, S2, S3, S4, S5, S6" in str(raised.value)
    with pytest.raises(ValueError, match="greater than or equal to 1"):
        conveyors.breakpoint(block="FB1", step=0)  # a step number is 1 or more
    assert conveyors.run(conveyors.session.do_session_state)["breakpoints"] == []

    plain = Cpu(
        [
            SourceFile(
                "ob1.awl",
                "ORGANIZATION_BLOCK OB 1\nBEGIN\n      NOP 0;\nEND_ORGANIZATION_BLOCK\n",
            )
        ]
    )
    try:
        with pytest.raises(MonitorError) as raised:
            plain.run(lambda: plain.session.do_step("transition", False))
        assert raised.value.code == "MON629"
    finally:
        plain.session.close()


def test_a_simultaneous_firing_is_one_step_and_an_on_action_activates() -> None:
    """g02c: Trans1 switches Step2 and Step6 on together; the step after the hold at Step2 does
    not stop at Step6 but at Step7 (Trans6, I 0.4). The file holds two Graph FBs: by file alone
    the breakpoint is ambiguous (MON628)."""
    cpu = Debugged(scenario("g02c_simultaneous.graph", "g02c_simultaneous.awl"))
    try:
        cpu.scans(2)
        with pytest.raises(MonitorError) as raised:
            cpu.breakpoint(file="g02c_simultaneous.graph", step=2)
        assert raised.value.code == "MON628"
        assert "FB1, FB2" in str(raised.value)
        cpu.breakpoint(block="FB1", step=2)
        cpu.write({"I0.0": True})
        assert cpu.held().graph_step == 2
        cpu.clear()
        cpu.step_by_transition()
        cpu.run(lambda: None)
        deadline = time.monotonic() + 5
        while cpu.read("DB1.Step6.X") != 1:  # Step6 came in the same firing: no hold there
            assert time.monotonic() < deadline, "Step6 did not become active"
            time.sleep(0.005)
        time.sleep(0.05)  # many fast scans: still no hold, the step waits for Trans6
        assert cpu.session.hold_view is None
        assert cpu.read("DB1.Step2.X") == 1
        cpu.write({"I0.4": True})
        hold = cpu.held(lambda: None)  # the step is still pending
        assert (hold.reason, hold.graph_step, hold.graph_block) == ("step", 7, "FB1")
        cpu.go_on()
    finally:
        cpu.session.close()

    cpu = Debugged(scenario("g08_on_off.graph", "g08_on_off.awl"))
    try:
        cpu.scans(2)
        cpu.breakpoint(block="FB1", step=9)
        cpu.write({"I0.2": True})  # Step1 -> Step4 -> Step3 (G8's path without the OFF)
        cpu.scans(2)
        cpu.write({"I0.2": False, "I0.4": True})
        hold = cpu.held()  # Step3 became active; its S1 ON S9 switches the lamp sequencer on
        assert (hold.reason, hold.graph_step) == ("breakpoint", 9)
        assert cpu.read("DB1.Step3.X") == 1
        assert cpu.read("DB1.Step9.X") == 0
        cpu.go_on()
        assert cpu.read("DB1.Step9.X") == 1
    finally:
        cpu.session.close()

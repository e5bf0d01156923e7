"""Breakpoints, holds and single steps over the monitoring socket of a real server."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    CALC_SCL,
    LOOP_PROGRAM,
    PLANT_PROGRAM,
    LiveServer,
    Monitor,
    line_of,
    plant_sources,
    running_server,
    source,
)

FC1_LOAD_MW10 = line_of(LOOP_PROGRAM, "L     MW    10")  # FC1, instruction 0
OB1_CALL = line_of(LOOP_PROGRAM, "CALL FC 1")  # OB1, instruction 6


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


def _client(live: LiveServer, sources: list[dict[str, str]]) -> Iterator[Monitor]:
    session_id = live.create(sources)["id"]
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        yield client
    live.delete(session_id)


@pytest.fixture
def loop(live: LiveServer) -> Iterator[Monitor]:
    """The LOOP program (OB1 calls FC1 three times; MW10 = 6 after each scan), in STOP."""
    yield from _client(live, [source("prog.awl", LOOP_PROGRAM)])


@pytest.fixture
def plant(live: LiveServer) -> Iterator[Monitor]:
    yield from _client(live, plant_sources())


@pytest.fixture
def calc(live: LiveServer) -> Iterator[Monitor]:
    yield from _client(live, [source("calc.scl", CALC_SCL)])


def _frame(block: str, instruction: int, line: int, network: int, file: str) -> dict[str, Any]:
    return {
        "block": block,
        "instruction": instruction,
        "line": line,
        "file": file,
        "network": network,
    }


def _fc1(instruction: int) -> dict[str, Any]:
    return _frame("FC1", instruction, FC1_LOAD_MW10 + instruction, 1, "prog.awl")


def _breakpoint(client: Monitor, condition: str | None = None, **location: Any) -> dict[str, Any]:
    fields: dict[str, Any] = {"location": location}
    if condition is not None:
        fields["condition"] = condition
    result: dict[str, Any] = client.ok("set_breakpoint", **fields)
    return result


def _held(client: Monitor, what: str, **expected: Any) -> dict[str, Any]:
    """Waits for a hold whose location has the ``expected`` fields (``accu1=`` compares the
    register): a frame may still repeat the previous hold (it is sent again after every
    command carried out at a hold), so the new one is told by where it is."""
    accu1 = expected.pop("accu1", None)

    def matches(m: Monitor) -> dict[str, Any] | None:
        hold = m.hold
        if hold is None or any(hold["location"][k] != v for k, v in expected.items()):
            return None
        if accu1 is not None and hold["registers"]["accu1"] != accu1:
            return None
        return hold

    held: dict[str, Any] = client.until(matches, what)
    return held


# -- the scenario: a breakpoint in an FC called from a loop -------------------------------------


def test_hold_in_an_fc_called_from_a_loop_step_modify_a_local_and_continue(
    loop: Monitor,
) -> None:
    loop.ok("watch", entries=["MW10", "#t", "#step"])
    loop.ok("trend", entries=["MW10"])
    set_ = _breakpoint(loop, file="prog.awl", line=FC1_LOAD_MW10)
    assert set_["block"] == "FC1"
    assert set_["instructions"] == [0]
    assert set_["where"] == f"prog.awl line {FC1_LOAD_MW10}"

    loop.ok("run")
    hold = loop.until_held()
    assert hold["reason"] == "breakpoint"
    assert hold["breakpoint"] == set_["id"]
    assert hold["location"] == _fc1(0)
    # Called from OB1's CALL in network 2 (instruction 6), innermost first.
    assert hold["call_stack"] == [_fc1(0), _frame("OB1", 6, OB1_CALL, 2, "prog.awl")]
    # OB1 loaded the loop counter 3 before the call; the FC has not run yet.
    assert hold["registers"]["accu1"] == 3
    assert loop.local("step") == 2
    loop.until(lambda m: m.state("mode") == "HOLD", "mode HOLD")
    assert loop.cpu is not None
    assert loop.cpu["scans"] == 0
    loop.until(lambda m: m.value("#step") == 2 and m.value("MW10") == 0, "the held values")

    # Step through the FC: L MW10 (0), L #step (2), +I, T #t.
    hold = loop.step("instruction")
    assert hold["location"] == _fc1(1)
    assert (hold["registers"]["accu1"], hold["registers"]["accu2"]) == (0, 3)
    hold = loop.step("instruction")
    assert hold["location"] == _fc1(2)
    assert (hold["registers"]["accu1"], hold["registers"]["accu2"]) == (2, 0)
    hold = loop.step("instruction")
    assert hold["location"] == _fc1(3)
    assert hold["registers"]["accu1"] == 2
    hold = loop.step("instruction")
    assert hold["location"] == _fc1(4)  # before L #t
    assert loop.local("t") == 2
    assert hold["call_stack"][1]["block"] == "OB1"
    assert loop.cpu is not None
    assert loop.cpu["mode"] == "HOLD"

    # Modify the local the next instruction reads: MW10 := #t = 100 (then +2, +2).
    loop.ok("modify", target="#t", value=100)
    loop.until(lambda m: m.hold and m.local("t") == 100, "the hold to show #t = 100")
    loop.until(lambda m: m.value("#t") == 100, "the watch to show #t = 100")

    loop.ok("clear_breakpoint")
    loop.ok("continue")
    loop.until(lambda m: m.hold is None and m.released, "the hold to be released")
    loop.until_mode("RUN")
    # The scan that held ends with MW10 = 100 + 2 + 2; the following ones compute 6 again.
    loop.until(lambda m: len(m.trend) >= 3, "three samples")
    assert loop.trend[0]["scan"] == 1
    assert loop.trend[0]["values"] == [104]
    assert [s["values"] for s in loop.trend[1:3]] == [[6], [6]]
    assert loop.cpu is not None
    assert loop.cpu["mode"] == "RUN"


def test_a_marker_modified_at_a_breakpoint_is_what_the_fc_reads(loop: Monitor) -> None:
    loop.ok("watch", entries=["MW10"])
    loop.ok("trend", entries=["MW10"])
    _breakpoint(loop, file="prog.awl", line=FC1_LOAD_MW10)
    loop.ok("run")
    loop.until_held()
    loop.ok("modify", target="MW10", value=50)
    loop.until_value("MW10", 50)

    # The breakpoint holds again at the second call (loop counter 2): FC1 added 2 to the
    # modified marker.
    loop.ok("continue")
    hold = _held(loop, "the second call", block="FC1", instruction=0, accu1=2)
    assert hold["location"] == _fc1(0)
    assert hold["call_stack"][1]["instruction"] == 6
    loop.until_value("MW10", 52)
    assert loop.cpu is not None
    assert loop.cpu["mode"] == "HOLD"

    loop.ok("clear_breakpoint")
    loop.ok("run")  # run while holding continues, as continue does
    loop.until_mode("RUN")
    loop.until(lambda m: m.trend, "the first sample")
    assert loop.trend[0] == {"scan": 1, "time_ms": 10, "values": [56]}


# -- where breakpoints go -----------------------------------------------------------------------


def test_breakpoints_by_block_and_instruction_and_by_network(loop: Monitor) -> None:
    by_network = _breakpoint(loop, block="OB1", network=2)
    assert by_network["instructions"] == [2]  # L 0, the first instruction of network 2
    assert by_network["where"] == "OB1 network 2"
    loop.ok("run")
    hold = loop.until_held()
    assert hold["breakpoint"] == by_network["id"]
    assert hold["location"] == _frame("OB1", 2, line_of(LOOP_PROGRAM, "L     0"), 2, "prog.awl")
    assert [f["block"] for f in hold["call_stack"]] == ["OB1"]

    loop.ok("clear_breakpoint", id=by_network["id"])
    by_instruction = _breakpoint(loop, block="FC1", instruction=3)
    loop.ok("continue")
    hold = _held(loop, "FC1 instruction 3", block="FC1", instruction=3)
    assert hold["breakpoint"] == by_instruction["id"]
    assert hold["location"] == _fc1(3)

    # A block and a line of its source.
    by_line = _breakpoint(loop, block="FC1", line=FC1_LOAD_MW10 + 5)
    assert by_line["instructions"] == [5]
    loop.ok("clear_breakpoint", id=by_instruction["id"])
    loop.ok("continue")
    hold = _held(loop, "FC1 instruction 5", block="FC1", instruction=5)
    assert hold["breakpoint"] == by_line["id"]
    assert hold["location"] == _fc1(5)
    loop.fails("clear_breakpoint", "MON607", id=by_instruction["id"])


def test_a_condition_holds_only_at_the_right_loop_count(loop: Monitor) -> None:
    loop.ok("watch", entries=["MW10", "#n"])
    # OB1's loop counter #n counts 3, 2, 1: hold before the third call only.
    _breakpoint(loop, "#n = 1", file="prog.awl", line=OB1_CALL)
    loop.ok("run")
    hold = loop.until_held()
    assert hold["location"]["block"] == "OB1"
    assert hold["location"]["instruction"] == 6
    assert loop.local("n") == 1
    loop.until_value("MW10", 4)  # two calls done

    # A condition on a marker, in the called FC: the third call sees MW10 = 4.
    loop.ok("clear_breakpoint")
    _breakpoint(loop, "MW10 >= 4", block="FC1", instruction=0)
    loop.ok("step", by="scan")  # finish this scan: FC1's third call holds there
    hold = _held(loop, "FC1 with MW10 >= 4", block="FC1")
    assert hold["location"] == _fc1(0)
    assert hold["registers"]["accu1"] == 1  # the loop counter
    loop.until_value("MW10", 4)


def test_bad_conditions_are_mon612(loop: Monitor) -> None:
    error = loop.fails(
        "set_breakpoint", "MON612", location={"block": "FC1", "instruction": 0}, condition="blah"
    )
    assert "blah" in error["message"]
    loop.fails(
        "set_breakpoint",
        "MON612",
        location={"block": "FC1", "instruction": 0},
        condition="#nosuch = 1",
    )
    loop.fails(
        "set_breakpoint",
        "MON612",
        location={"block": "FC1", "instruction": 0},
        condition="MW10 > many",
    )


def test_an_scl_breakpoint_by_file_and_line_steps_by_statement(calc: Monitor) -> None:
    calc.ok("watch", entries=["#i", "#total", "DB2.total"])
    body = line_of(CALC_SCL, "total := total + i;")
    head = line_of(CALC_SCL, "FOR i := 1 TO limit DO")
    _breakpoint(calc, "i = 3", file="calc.scl", line=body)
    calc.ok("run")
    hold = calc.until_held()
    assert hold["location"]["block"] == "FB2"
    assert hold["location"]["line"] == body
    assert hold["location"]["file"] == "calc.scl"
    assert [f["block"] for f in hold["call_stack"]] == ["FB2", "OB1"]
    assert hold["call_stack"][1]["line"] == line_of(CALC_SCL, "FB2.DB2(limit := 4);")
    # The FB's parameter and statics, and its temp i: 1 + 2 summed so far.
    assert (calc.local("limit"), calc.local("total"), calc.local("i")) == (4, 3, 3)
    calc.until(lambda m: m.value("#i") == 3 and m.value("#total") == 3, "the watched locals")

    calc.ok("clear_breakpoint")
    hold = calc.step("statement")  # to the FOR's step (i := i + 1)
    assert hold["location"]["line"] == head
    assert calc.local("total") == 6
    hold = calc.step("statement")  # the loop body again, i = 4
    assert hold["location"]["line"] == body
    assert (calc.local("i"), calc.local("total")) == (4, 6)
    hold = calc.step("statement")
    hold = calc.step("statement")  # the FOR's test ends the loop: runs := runs + 1
    assert calc.local("total") == 10
    calc.ok("continue")
    calc.until_mode("RUN")
    calc.until_value("DB2.total", 10)


# -- steps --------------------------------------------------------------------------------------


def test_step_over_and_into_a_call(loop: Monitor) -> None:
    loop.ok("watch", entries=["MW10"])
    _breakpoint(loop, block="OB1", instruction=6)  # the CALL
    loop.ok("run")
    loop.until_held()
    loop.until_value("MW10", 0)

    hold = loop.step("instruction")  # over: FC1 runs, the hold is after the CALL
    assert hold["location"] == _frame("OB1", 7, OB1_CALL + 1, 2, "prog.awl")
    assert [f["block"] for f in hold["call_stack"]] == ["OB1"]
    loop.until_value("MW10", 2)

    loop.ok("continue")  # the breakpoint holds at the second CALL (loop counter 2)
    hold = _held(loop, "the second CALL", block="OB1", instruction=6, accu1=2)
    hold = loop.step("instruction", into=True)
    assert hold["location"] == _fc1(0)
    assert [f["block"] for f in hold["call_stack"]] == ["FC1", "OB1"]
    assert hold["call_stack"][1]["instruction"] == 6
    # Stepping out of the FC's last instruction returns after the CALL.
    loop.ok("clear_breakpoint")
    for k in range(1, 6):
        assert loop.step("instruction")["location"] == _fc1(k)
    assert loop.step("instruction")["location"]["block"] == "OB1"
    loop.until_value("MW10", 4)


def test_step_by_network_and_into_an_fb(plant: Monitor) -> None:
    _breakpoint(plant, block="OB1", network=1)
    plant.ok("run")
    hold = plant.until_held()
    assert hold["location"]["network"] == 1
    plant.ok("clear_breakpoint")
    lines = {n: line_of(PLANT_PROGRAM, text) for n, text in ((2, "DB1.DBW"), (3, "A     M"))}
    hold = plant.step("network")
    assert (hold["location"]["network"], hold["location"]["line"]) == (2, lines[2])
    hold = plant.step("network")
    assert (hold["location"]["network"], hold["location"]["line"]) == (3, lines[3])
    assert plant.cpu is not None
    assert plant.cpu["scans"] == 0
    hold = plant.step("network")  # past OB1's end: network 1 of the next scan
    assert hold["location"]["network"] == 1
    assert hold["location"]["instruction"] == 0
    assert plant.cpu is not None
    assert plant.cpu["scans"] == 1

    hold = plant.step("instruction", into=True)  # into FB1 with its instance DB5
    assert hold["location"]["block"] == "FB1"
    assert [f["block"] for f in hold["call_stack"]] == ["FB1", "OB1"]
    assert (plant.local("inc"), plant.local("count")) == (1, 1)


def test_step_by_scan_from_a_hold_and_from_a_pause(loop: Monitor) -> None:
    _breakpoint(loop, block="OB1", instruction=0)
    loop.ok("run")
    loop.until_held()
    loop.ok("clear_breakpoint")
    loop.ok("step", by="scan")
    state = loop.until(
        lambda m: m.cpu if m.state("scans") == 1 and m.state("time_mode") == "pause" else None,
        "the scan to end in a pause",
    )
    assert state["mode"] == "RUN"
    assert loop.hold is None
    loop.ok("step", by="scan")
    loop.until(lambda m: m.state("scans") == 2, "one more scan")
    loop.drain(0.2)
    assert loop.cpu is not None
    assert loop.cpu["scans"] == 2


def test_a_step_while_running_holds_at_the_next_instruction(loop: Monitor) -> None:
    loop.ok("run")
    loop.until_scans(3)
    hold = loop.step("instruction")
    # The next instruction the CPU runs: the start of OB1 in the next scan.
    assert hold["reason"] == "step"
    assert hold["location"]["block"] == "OB1"
    assert hold["location"]["instruction"] == 0
    loop.until_mode("HOLD")
    loop.ok("continue")
    loop.until_mode("RUN")


def test_stop_while_holding_abandons_the_scan(live: LiveServer, loop: Monitor) -> None:
    _breakpoint(loop, file="prog.awl", line=FC1_LOAD_MW10)
    loop.ok("run")
    loop.until_held()
    loop.ok("stop")
    state = loop.until_mode("STOP")
    assert state["stop_code"] == "SIM527"
    loop.until(lambda m: m.hold is None and m.released, "the hold to be released")
    codes = [
        e["code"] for e in live.http.get(f"/api/sessions/{loop.session_id}/diagnostics").json()
    ]
    assert "SIM527" in codes
    # Run again: the breakpoint is still set and holds again.
    loop.ok("run")
    assert loop.until_held()["location"] == _fc1(0)


def test_another_session_runs_on_while_one_holds(live: LiveServer, loop: Monitor) -> None:
    _breakpoint(loop, block="FC1", instruction=0)
    loop.ok("run")
    loop.until_held()
    other = live.create_stl()
    try:
        with live.monitor(other) as client:
            client.ok("subscribe_cpu")
            client.ok("run")
            client.until_scans(10)
    finally:
        live.delete(other)
    assert loop.cpu is not None
    assert loop.cpu["mode"] == "HOLD"


def test_continue_after_a_short_hold_keeps_the_virtual_pace(loop: Monitor) -> None:
    """Held for 0.7 s, the CPU resumes one scan per 10 ms cycle; it does not run the 70 cycles
    it spent holding back to back."""
    loop.ok("run")
    loop.until_scans(3)
    _breakpoint(loop, block="OB1", instruction=0)
    loop.until_held()
    time.sleep(0.7)
    loop.ok("clear_breakpoint")
    loop.drain(0.05)
    assert loop.cpu is not None
    start = loop.cpu["scans"]
    loop.ok("continue")
    loop.drain(0.25)
    ran = loop.cpu["scans"] - start
    assert ran <= 45, f"{ran} scans in 0.25 s after the hold (virtual, 10 ms a cycle)"


# -- a LAD block ---------------------------------------------------------------------------------

LAD_OB1 = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = count the scans
RUNG Box(ADD_I, IN1 := MW 20, IN2 := 1, OUT => MW 20) END_RUNG
NETWORK
TITLE = the lamp
RUNG Contact(I 0.0) Coil(Q 0.0) END_RUNG
NETWORK
TITLE = the latch
RUNG
  PARALLEL
    BRANCH Contact(I 0.1) END_BRANCH
    BRANCH Contact(M 1.0) END_BRANCH
  END_PARALLEL
  ContactNC(I 0.2)
  Coil(M 1.0)
END_RUNG
END_ORGANIZATION_BLOCK
"""


@pytest.fixture
def ladder(live: LiveServer) -> Iterator[Monitor]:
    yield from _client(live, [source("main.lad", LAD_OB1)])


def test_a_lad_block_holds_at_a_network_and_steps_by_network(ladder: Monitor) -> None:
    """The graphical editors' breakpoints: a network of a LAD block, a step to the next network,
    continue; with a condition the hold waits for it."""
    set_ = _breakpoint(ladder, block="OB1", network=2)
    assert set_["where"] == "OB1 network 2"
    ladder.ok("run")
    hold = ladder.until_held()
    assert hold["breakpoint"] == set_["id"]
    assert (hold["location"]["block"], hold["location"]["network"]) == ("OB1", 2)
    assert hold["location"]["file"] == "main.lad"
    ladder.ok("clear_breakpoint")
    hold = ladder.step("network")
    assert (hold["location"]["block"], hold["location"]["network"]) == ("OB1", 3)
    assert ladder.cpu is not None
    scans = ladder.cpu["scans"]
    ladder.ok("continue")
    ladder.until(lambda m: m.released and m.hold is None, "the release")
    ladder.until_scans(scans + 3)

    # With a condition the hold waits for it: scans go on while the input is off.
    conditioned = _breakpoint(ladder, "I0.0 = 1", block="OB1", network=2)
    ladder.until_scans(ladder.cpu["scans"] + 5)
    assert ladder.hold is None
    ladder.ok("set_input", address="I0.0", value=True)
    hold = _held(ladder, "network 2 with I0.0 on", block="OB1", network=2)
    assert hold["breakpoint"] == conditioned["id"]
    ladder.ok("clear_breakpoint")
    ladder.ok("continue")
    ladder.until(lambda m: m.released and m.hold is None, "the release")

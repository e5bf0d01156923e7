"""Commands on the monitoring socket of a real server: run, stop, restart, the time modes,
inputs, modify, force, and running a number of scans."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    LOOP_PROGRAM,
    PLANT_SYMBOLS,
    LiveServer,
    Monitor,
    plant_sources,
    running_server,
    source,
    wait_for,
)


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


@pytest.fixture
def plant(live: LiveServer) -> Iterator[Monitor]:
    """A client (subscribed to the CPU) on a new session of the plant program, in STOP."""
    session_id = live.create(plant_sources())["id"]
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        yield client
    live.delete(session_id)


@pytest.fixture
def lamp(live: LiveServer) -> Iterator[Monitor]:
    """A client (subscribed to the CPU) on the LOOP program (Q0.0 = I0.0, symbols Start and
    Lamp), in STOP."""
    sources = [source("prog.awl", LOOP_PROGRAM), source("io.sdf", PLANT_SYMBOLS)]
    session_id = live.create(sources)["id"]
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        yield client
    live.delete(session_id)


def _scans_during(client: Monitor, seconds: float) -> int:
    """How many scans the frames report during ``seconds`` from now."""
    assert client.cpu is not None
    start = client.cpu["scans"]
    client.drain(seconds)
    assert client.cpu is not None
    return int(client.cpu["scans"]) - start


def _paused(client: Monitor) -> dict[str, Any]:
    state: dict[str, Any] = client.until(
        lambda m: m.cpu if m.cpu and m.state("time_mode") == "pause" else None, "time mode pause"
    )
    return state


# -- run, stop, restart -------------------------------------------------------------------------


def test_run_stop_and_restart_with_ob100(plant: Monitor) -> None:
    plant.ok("watch", entries=["M1.0", "MW30"])
    assert plant.until(lambda m: m.cpu, "the CPU state")["mode"] == "STOP"
    plant.ok("run")  # from STOP: a warm restart, OB100 sets M1.0
    plant.until_mode("RUN")
    plant.until_value("M1.0", True)
    plant.until_scans(3)

    # run while running restarts nothing.
    plant.ok("modify", target="M1.0", value=False)
    plant.until_value("M1.0", False)
    plant.ok("run")
    scans = plant.until_scans(1)["scans"]
    plant.until_scans(scans + 5)
    assert plant.value("M1.0") is False

    # stop: no more scans.
    plant.ok("stop")
    stopped = plant.until_mode("STOP")
    assert stopped["stop_code"] is None
    plant.drain(0.2)
    assert plant.cpu is not None
    assert plant.cpu["scans"] == stopped["scans"]
    counter = plant.value("MW30")
    assert counter == stopped["scans"]

    # restart (warm): OB100 again, then RUN; the counter in M memory goes on.
    plant.ok("restart")
    plant.until_value("M1.0", True)
    plant.until_mode("RUN")
    plant.until(lambda m: m.value("MW30") > counter, "MW30 to count on")

    # a warm restart while running runs OB100 too.
    plant.ok("modify", target="M1.0", value=False)
    plant.until_value("M1.0", False)
    plant.ok("restart")
    plant.until_value("M1.0", True)


def test_a_cold_restart_runs_ob102_not_ob100(plant: Monitor) -> None:
    plant.ok("watch", entries=["M1.0"])
    plant.ok("restart", cold=True)
    plant.until_mode("RUN")
    scans = plant.until_scans(1)["scans"]
    plant.until_scans(scans + 3)
    plant.until(lambda m: "M1.0" in m.watch, "M1.0")
    assert plant.value("M1.0") is False  # the plant has no OB102; OB100 did not run


# -- time modes ---------------------------------------------------------------------------------


def test_fast_runs_far_more_scans_than_virtual_and_keeps_virtual_time(plant: Monitor) -> None:
    plant.ok("run")
    plant.until_scans(2)
    virtual = _scans_during(plant, 0.3)
    assert 15 <= virtual <= 45, f"{virtual} scans in 0.3 s at 10 ms a cycle"

    plant.ok("set_time", mode="fast")
    plant.until(lambda m: m.state("time_mode") == "fast", "time mode fast")
    fast = _scans_during(plant, 0.3)
    assert fast > 5 * virtual, f"fast: {fast} scans, virtual: {virtual}"
    assert plant.cpu is not None
    assert plant.cpu["time_ms"] == plant.cpu["scans"] * 10  # still 10 ms per scan

    plant.ok("set_time", mode="virtual")
    plant.until(lambda m: m.state("time_mode") == "virtual", "time mode virtual")
    plant.drain(0.05)
    again = _scans_during(plant, 0.3)
    assert again <= 45, f"{again} scans in 0.3 s after fast"


def test_pause_stops_the_scans_and_the_clock(plant: Monitor) -> None:
    plant.ok("run")
    plant.until_scans(3)
    plant.ok("set_time", mode="pause")
    paused = _paused(plant)
    assert paused["mode"] == "RUN"
    plant.drain(0.3)
    assert plant.cpu is not None
    assert (plant.cpu["scans"], plant.cpu["time_ms"]) == (paused["scans"], paused["time_ms"])

    # continue resumes the time mode it was in.
    plant.ok("continue")
    plant.until(lambda m: m.state("time_mode") == "virtual", "time mode virtual")
    plant.until_scans(paused["scans"] + 5)


def test_real_time_follows_the_wall_clock(plant: Monitor) -> None:
    plant.ok("set_time", mode="real", cycle_ms=20)
    plant.ok("run")
    start = plant.until_scans(2)
    began = time.monotonic()
    plant.drain(0.6)
    assert plant.cpu is not None
    assert plant.cpu["time_mode"] == "real"
    elapsed_ms = (time.monotonic() - began) * 1000
    advanced = plant.cpu["time_ms"] - start["time_ms"]
    scans = plant.cpu["scans"] - start["scans"]
    assert abs(advanced - elapsed_ms) < 200, f"{advanced} ms simulated in {elapsed_ms:.0f} ms"
    assert 15 <= scans <= 45, f"{scans} scans of 20 ms in 0.6 s"


def test_set_time_changes_the_cycle_of_virtual_time(plant: Monitor) -> None:
    plant.ok("run")
    before = plant.until_scans(2)
    plant.ok("set_time", mode="virtual", cycle_ms=50)
    state = plant.until(
        lambda m: (
            m.cpu if m.state("cycle_ms") == 50 and m.state("scans") > before["scans"] + 3 else None
        ),
        "scans of 50 ms",
    )
    # Every scan since the change adds 50 ms.
    later = plant.until_scans(state["scans"] + 2)
    assert later["time_ms"] - state["time_ms"] == (later["scans"] - state["scans"]) * 50


# -- inputs, modify, force ----------------------------------------------------------------------


def test_set_input_drives_the_program_and_the_output_shows_in_a_frame(lamp: Monitor) -> None:
    lamp.ok("watch", entries=["I0.0", "Q0.0", "Lamp"])
    lamp.ok("run")
    lamp.until_value("Q0.0", False)
    lamp.ok("set_input", address="I0.0", value=True)
    lamp.until_value("Q0.0", True)
    assert lamp.value("I0.0") is True
    lamp.until_value("Lamp", True)
    # By symbol, with a string value as users type it.
    lamp.ok("set_input", address='"Start"', value="FALSE")
    lamp.until_value("Q0.0", False)
    lamp.until_value("Lamp", False)


def test_set_input_refuses_what_is_not_an_input(lamp: Monitor) -> None:
    error = lamp.fails("set_input", "MON603", address="Q0.0", value=True)
    assert error["params"]["target"] == "Q0.0"
    lamp.fails("set_input", "MON603", address="Lamp", value=True)
    lamp.fails("set_input", "MON606", address="I0.0", value=7)


def test_modify_writes_memory_and_db_members_once(plant: Monitor) -> None:
    plant.ok("watch", entries=["MW20", "MW30", "DB1.level", "DB1.speed", "M1.2", "DB5.count"])
    plant.ok("run")
    plant.until_value("M1.2", True)
    plant.until(lambda m: (m.value("MW30") or 0) >= 3, "MW30 to count")

    # A DB member: the program copies it to MW20 from the next scan on.
    plant.ok("modify", target="DB1.level", value=42)
    plant.until_value("MW20", 42)
    plant.ok("modify", target='"Tank".level', value="-7")
    plant.until_value("MW20", 65529)  # MW20 is a WORD: -7 as 16#FFF9
    assert plant.value("DB1.level") == -7
    plant.ok("modify", target="DB1.speed", value="2.5")
    plant.until_value("DB1.speed", 2.5)

    # Memory, once: the counter goes on counting from the modified value.
    plant.ok("modify", target="MW30", value=1000)
    plant.until(lambda m: 1000 <= m.value("MW30") < 1100, "MW30 to count on from 1000")
    plant.until(lambda m: m.value("MW30") > 1002, "MW30 to count on")
    # ...and an instance DB member likewise.
    plant.ok("modify", target="DB5.count", value=-100)
    plant.until(lambda m: -100 <= m.value("DB5.count") < 0, "DB5.count to count from -100")

    # A bit the logic reads: AN M1.1 makes M1.2 false.
    plant.ok("modify", target="M1.1", value=True)
    plant.until_value("M1.2", False)

    # Values that do not fit the target are refused.
    assert (
        plant.fails("modify", "MON606", target="DB1.level", value=40000)["params"]["target"]
        == "DB1.level"
    )
    plant.fails("modify", "MON606", target="M1.1", value="maybe")
    plant.fails("modify", "MON603", target="DB9.DBW0", value=1)


def test_a_forced_input_wins_over_set_input_and_unforce_releases_it(lamp: Monitor) -> None:
    lamp.ok("watch", entries=["I0.0", "Q0.0"])
    lamp.ok("run")
    lamp.until_value("Q0.0", False)

    lamp.ok("force", address="I0.0", value=True)
    lamp.until_value("Q0.0", True)
    lamp.until(lambda m: m.watch["I0.0"] == {"value": True, "forced": True, "error": None}, "I0.0")
    assert lamp.cpu is not None
    lamp.until(lambda m: m.state("forced") == [{"address": "I0.0", "value": 1}], "cpu.forced")
    assert lamp.watch["Q0.0"]["forced"] is False

    # The process says 0, the force says 1: the program keeps seeing 1.
    lamp.ok("set_input", address="I0.0", value=False)
    scans = lamp.cpu["scans"]
    lamp.until_scans(scans + 5)
    assert lamp.value("Q0.0") is True
    assert lamp.value("I0.0") is True

    # unforce: the input follows the process again.
    lamp.ok("unforce", address="I0.0")
    lamp.until_value("Q0.0", False)
    lamp.until(lambda m: m.watch["I0.0"] == {"value": False, "forced": False, "error": None}, "I0")
    lamp.until(lambda m: m.state("forced") == [], "no forces")


def test_unforce_without_an_address_removes_every_force(lamp: Monitor) -> None:
    lamp.ok("watch", entries=["Q0.0", "PQB0"])
    lamp.ok("run")
    lamp.ok("force", address="I0.0", value=1)
    lamp.ok("force", address="Q0.1", value=True)
    lamp.until(
        lambda m: (
            m.state("forced") == [{"address": "I0.0", "value": 1}, {"address": "Q0.1", "value": 1}]
        ),
        "two forces",
    )
    # A forced output reaches the peripheral outputs: Q0.0 from the program, Q0.1 forced.
    lamp.until_value("PQB0", 0b11)
    lamp.ok("unforce")
    lamp.until(lambda m: m.state("forced") == [], "no forces")
    lamp.until_value("PQB0", 0)
    lamp.fails("force", "MON603", address="MW20", value=1)


# -- running a number of scans ------------------------------------------------------------------


def test_run_scans_runs_exactly_n_more_scans_then_pauses(live: LiveServer, plant: Monitor) -> None:
    plant.ok("trend", entries=["MW30"])
    plant.ok("run")
    plant.until_scans(3)
    plant.ok("set_time", mode="pause")
    start = _paused(plant)["scans"]
    session = live.session(plant.session_id)
    wait_for(lambda: session.cpu.scans == start, "the CPU to show the paused scan count")

    plant.ok("run_scans", count=40)
    # The CPU runs them (not paced) ...
    wait_for(lambda: session.cpu.scans >= start + 40, "the 40 scans to run")
    time.sleep(0.2)
    assert session.cpu.scans == start + 40
    # ... and the client sees where it stopped: 40 more scans, time mode pause.
    state = plant.until(
        lambda m: m.cpu if m.state("scans") == start + 40 else None,
        f"a frame with scans = {start + 40} (the CPU ran them)",
        timeout=2,
    )
    assert state["time_mode"] == "pause"
    assert state["time_ms"] == (start + 40) * 10
    plant.until(lambda m: m.trend and m.trend[-1]["scan"] == start + 40, "the last sample")


def test_continue_after_run_scans_resumes_at_the_virtual_pace(plant: Monitor) -> None:
    plant.ok("run")
    plant.until_scans(3)
    plant.ok("run_scans", count=300)
    plant.until(lambda m: m.state("time_mode") == "pause", "time mode pause")
    plant.drain(0.2)
    plant.ok("continue")
    plant.until(lambda m: m.state("time_mode") == "virtual", "time mode virtual")
    ran = _scans_during(plant, 0.5)
    assert ran >= 25, f"only {ran} scans in 0.5 s after continue (virtual, 10 ms a cycle)"


def test_continue_after_a_single_scan_step_does_not_catch_up(plant: Monitor) -> None:
    """Paused for 0.7 s after ``step by scan``, the CPU resumes one scan per cycle; it does not
    run the 70 scans of the pause back to back."""
    plant.ok("run")
    plant.until_scans(3)
    plant.ok("step", by="scan")
    _paused(plant)
    time.sleep(0.7)
    plant.drain(0.05)
    plant.ok("continue")
    ran = _scans_during(plant, 0.25)
    assert ran <= 45, f"{ran} scans in 0.25 s after continue (virtual, 10 ms a cycle)"


def test_run_scans_and_step_need_a_running_cpu(plant: Monitor) -> None:
    plant.fails("run_scans", "MON607", count=3)
    plant.fails("step", "MON607", by="scan")
    plant.fails("continue", "MON607")
    plant.ok("run")
    plant.until_mode("RUN")
    plant.fails("continue", "MON607")

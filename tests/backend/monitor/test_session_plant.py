"""A simulation session with a virtual plant (a project's ``.plant`` file): the program fills the
tank in closed loop, the frames carry the plant, the operator panel and fault injection work over
the socket, and a bad plant file is refused with its file and line."""

from __future__ import annotations

import json
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from nasaq.monitor import protocol as p
from nasaq.monitor.frames import merge

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import LiveServer, Monitor, running_server, source

# The pump latch of the course's tank lesson: the pump button starts the pump, the NC stop
# button or the full switch stops it; the alarm shows the full switch.
PUMP_PROGRAM = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = pump: start, self-holding, stop (NC) or full stops it
      A(    ;
      O     I      0.0;
      O     Q      4.0;
      )     ;
      A     I      0.1;
      AN    I      0.3;
      =     Q      4.0;
NETWORK
TITLE = alarm = full
      A     I      0.3;
      =     Q      4.1;
END_ORGANIZATION_BLOCK
"""

TANK_PLANT = """\
kind: tank
wiring:
  pump_pb: I0.0
  stop_pb: I0.1
  ls_low: I0.2
  ls_high: I0.3
  level: IW64
  pump: Q4.0
  alarm: Q4.1
params: {initial: 10, pump_rate: 20}
"""


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        # The first session starts the worker processes: on a busy machine that takes longer
        # than the tests' usual deadline, so it is made here, with time to spare.
        warm = server.http.post(
            "/api/sessions", json={"sources": [source("OB1.awl", PUMP_PROGRAM)]}, timeout=60
        )
        assert warm.status_code == 201, warm.text
        server.delete(warm.json()["id"])
        yield server


def plant_of(monitor: Monitor) -> dict[str, Any] | None:
    """The plant as the frames received so far show it (frames carry it when it changed)."""
    found: dict[str, Any] | None = None
    for frame in monitor.frames:
        if frame.get("plant_removed"):
            found = None
        if frame.get("plant") is not None:
            found = frame["plant"]
    return found


def until_plant(monitor: Monitor, test: Any, what: str) -> dict[str, Any]:
    def check(m: Monitor) -> dict[str, Any] | None:
        plant = plant_of(m)
        return plant if plant is not None and test(plant) else None

    found: dict[str, Any] = monitor.until(check, what, timeout=10)
    return found


@pytest.fixture
def tank(live: LiveServer) -> Iterator[Monitor]:
    created = live.create(
        [source("OB1.awl", PUMP_PROGRAM), source("tank.plant", TANK_PLANT)], time_mode="fast"
    )
    with live.monitor(created["id"]) as client:
        client.ok("subscribe_cpu")
        yield client
    live.delete(created["id"])


def test_the_program_fills_the_tank_in_closed_loop_and_frames_carry_the_plant(
    tank: Monitor,
) -> None:
    first = until_plant(tank, lambda p: True, "the first frame with the plant")
    assert first["kind"] == "tank"
    assert first["state"]["level"] == 10.0
    assert first["signals"]["stop_pb"] == 1  # NC: closed while not pressed
    assert first["wiring"]["level"] == "IW64"
    assert first["faults"] == []
    tank.ok("watch", entries=["IW64", "Q4.0"])
    tank.ok("run")
    tank.ok("plant_operate", control="pump_pb", value=1)
    rising = until_plant(tank, lambda p: p["signals"]["pump"] == 1, "the pump to run")
    tank.ok("plant_operate", control="pump_pb", value=0)
    # The program keeps the pump on (self-holding) until the full switch trips at 90 %.
    full = until_plant(tank, lambda p: p["signals"]["ls_high"] == 1, "the full switch")
    assert full["state"]["level"] >= 90.0
    assert full["time_ms"] > rising["time_ms"]
    stopped = until_plant(tank, lambda p: p["signals"]["pump"] == 0, "the pump to stop")
    assert stopped["signals"]["alarm"] == 1
    assert stopped["faults"] == []
    # The transmitter's word reached the PLC: 90 % of 27648.
    tank.until(lambda m: (m.value("IW64") or 0) >= 24883, "IW64 >= 90 %")


def test_a_stuck_full_switch_overflows_the_tank_and_a_reset_restores_it(tank: Monitor) -> None:
    until_plant(tank, lambda p: True, "the plant")
    tank.ok("plant_fault", fault="ls_high_stuck", on=True)
    tank.ok("run")
    tank.ok("plant_operate", control="pump_pb", value=1)
    # A press shorter than a scan is not seen (as on a real PLC): release it once it ran.
    until_plant(tank, lambda p: p["signals"]["pump"] == 1, "the pump to run")
    tank.ok("plant_operate", control="pump_pb", value=0)
    over = until_plant(tank, lambda p: "overflow" in p["faults"], "the overflow")
    assert over["state"]["level"] == 100.0
    assert over["signals"]["ls_high"] == 0  # the stuck switch never said full
    assert set(over["faults"]) == {"overflow", "ls_high_stuck"}
    tank.ok("stop")
    tank.ok("plant_reset")
    back = until_plant(tank, lambda p: p["faults"] == [], "the reset plant")
    assert back["state"]["level"] == 10.0


def test_the_stop_button_is_pressed_as_the_level_its_nc_contact_gives(live: LiveServer) -> None:
    # Virtual time, one scan per 10 ms of the wall clock, and a slow pump: the tank takes 16 s
    # to reach the full switch, so it is the stop button that stops the pump.
    slow = TANK_PLANT.replace("pump_rate: 20", "pump_rate: 5")
    created = live.create([source("OB1.awl", PUMP_PROGRAM), source("tank.plant", slow)])
    with live.monitor(created["id"]) as tank:
        tank.ok("run")
        tank.ok("plant_operate", control="pump_pb", value=1)
        until_plant(tank, lambda p: p["signals"]["pump"] == 1, "the pump to run")
        tank.ok("plant_operate", control="pump_pb", value=0)
        tank.ok("plant_operate", control="stop_pb", value=0)  # pressed: the NC contact opens
        stopped = until_plant(tank, lambda p: p["signals"]["pump"] == 0, "the stop to win")
        assert stopped["signals"]["stop_pb"] == 0
        assert 10.0 < stopped["state"]["level"] < 90.0
        assert stopped["signals"]["ls_high"] == 0
    live.delete(created["id"])


def test_bad_plant_commands_are_answered_with_their_codes(tank: Monitor) -> None:
    until_plant(tank, lambda p: True, "the plant")
    unknown = tank.fails("plant_operate", "PLT014", control="start", value=1)
    assert "pump_pb" in unknown["params"]["known"]
    too_big = tank.fails("plant_operate", "PLT016", control="stop_pb", value=2)
    assert too_big["params"]["high"] == 1
    no_fault = tank.fails("plant_fault", "PLT018", fault="overflow", on=True)  # raised only
    assert no_fault["params"]["known"] == "ls_high_stuck, level_wire_break"
    tank.fails("plant_operate", "MON601", control="pump_pb")  # no value


def test_a_session_without_a_plant_says_so(live: LiveServer) -> None:
    session_id = live.create_stl(PUMP_PROGRAM)
    with live.monitor(session_id) as client:
        client.fails("plant_reset", "PLT017")
        client.ok("subscribe_cpu")
        client.until(lambda m: m.cpu is not None, "a frame")
        assert plant_of(client) is None
    live.delete(session_id)


def test_a_bad_plant_file_is_refused_with_its_file_and_line(live: LiveServer) -> None:
    bad = TANK_PLANT.replace("ls_high: I0.3", "ls_high: Q0.3")
    response = live.http.post(
        "/api/sessions",
        json={"sources": [source("OB1.awl", PUMP_PROGRAM), source("tank.plant", bad)]},
    )
    assert response.status_code == 422, response.text
    error = response.json()["error"]
    assert error["code"] == "PLT004"
    assert error["params"]["file"] == "tank.plant"
    assert error["params"]["line"] == 6
    assert "Q0.3" in error["message"]
    broken = live.http.post(
        "/api/sessions",
        json={"sources": [source("OB1.awl", PUMP_PROGRAM), source("a.plant", "kind: [tank\n")]},
    )
    assert broken.status_code == 422
    assert broken.json()["error"]["code"] == "PLT001"


def test_a_download_replaces_the_plant_and_one_without_a_plant_file_removes_it(
    live: LiveServer, tank: Monitor
) -> None:
    until_plant(tank, lambda p: p["state"]["level"] == 10.0, "the plant")
    program = source("OB1.awl", PUMP_PROGRAM)
    fuller = source("tank.plant", TANK_PLANT.replace("initial: 10", "initial: 50"))
    response = live.http.put(
        f"/api/sessions/{tank.session_id}/program", json={"sources": [program, fuller]}
    )
    assert response.status_code == 200, response.text
    until_plant(tank, lambda p: p["state"]["level"] == 50.0, "the new plant")
    refused = live.http.put(
        f"/api/sessions/{tank.session_id}/program",
        json={"sources": [program, source("tank.plant", "kind: boiler\n")]},
    )
    assert refused.status_code == 422
    assert refused.json()["error"]["code"] == "PLT002"
    response = live.http.put(
        f"/api/sessions/{tank.session_id}/program", json={"sources": [program]}
    )
    assert response.status_code == 200, response.text
    tank.until(lambda m: any(f.get("plant_removed") for f in m.frames), "the plant to go")
    assert plant_of(tank) is None


def test_waiting_frames_merge_to_the_newest_plant_or_its_removal() -> None:
    def plant(level: float) -> p.PlantFrame:
        return p.PlantFrame(
            kind="tank", time_ms=10, state={"level": level}, signals={}, faults=[], wiring={}
        )

    def frame(seq: int, **fields: Any) -> str:
        return p.Frame(seq=seq, **fields).model_dump_json()

    newest = json.loads(merge([frame(1, plant=plant(10)), frame(2), frame(3, plant=plant(12))]))
    assert newest["plant"]["state"] == {"level": 12}
    assert newest["plant_removed"] is False
    removed = json.loads(merge([frame(1, plant=plant(10)), frame(2, plant_removed=True)]))
    assert removed["plant"] is None
    assert removed["plant_removed"] is True
    again = json.loads(merge([frame(1, plant_removed=True), frame(2, plant=plant(50))]))
    assert again["plant"]["state"] == {"level": 50}
    assert again["plant_removed"] is False
    p.SERVER_MESSAGE.validate_python(again)

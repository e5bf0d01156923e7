"""``GET /api/plants``: the catalogue the plant drawings, the plant file editor and the lesson
authors read: every kind with its signals, faults, parameters and usual wiring."""

from __future__ import annotations

from fastapi.testclient import TestClient
from project_helpers import make_project


def test_the_catalogue_lists_every_kind_with_its_signals_faults_and_wiring(
    client: TestClient,
) -> None:
    response = client.get("/api/plants")
    assert response.status_code == 200
    kinds = {entry["kind"]: entry for entry in response.json()}
    assert {"panel", "motor", "tank", "bottle_conveyor", "traffic_light", "drill"} <= set(kinds)
    assert {"mixer", "car_park", "bcd_panel"} <= set(kinds)
    tank = kinds["tank"]
    assert tank["title"]
    signals = {s["name"]: s for s in tank["signals"]}
    assert signals["stop_pb"] == {
        "name": "stop_pb",
        "direction": "control",
        "kind": "bool",
        "normally_closed": True,
        "description": "stop push button, NC",
    }
    assert signals["level"]["kind"] == "word"
    assert signals["level"]["direction"] == "sensor"
    assert signals["pump"]["direction"] == "actuator"
    faults = {f["code"]: f["injectable"] for f in tank["faults"]}
    assert faults == {"overflow": False, "ls_high_stuck": True, "level_wire_break": True}
    assert tank["defaults"]["pump_rate"] == 5.0
    assert tank["default_wiring"]["level"] == "IW64"
    motor = {s["name"]: s for s in kinds["motor"]["signals"]}
    assert motor["overload"]["normally_closed"] is True


def test_a_plant_file_is_checked_with_its_line(client: TestClient) -> None:
    good = client.post(
        "/api/plants/check",
        json={"name": "tank.plant", "text": "kind: tank\nwiring: {pump: Q4.0}\n"},
    )
    assert good.status_code == 200
    assert good.json()["config"]["wiring"] == {"pump": "Q4.0"}
    assert good.json()["diagnostics"] == []
    bad = client.post(
        "/api/plants/check",
        json={"name": "tank.plant", "text": "kind: tank\nwiring:\n  pump: I4.0\n"},
    )
    assert bad.status_code == 200
    assert bad.json()["config"] is None
    [problem] = bad.json()["diagnostics"]
    assert problem["code"] == "PLT005"
    assert problem["span"]["line"] == 3
    assert problem["key"] == "plant_wire_output"


def test_a_project_lists_its_plant_file_problem_and_refuses_to_run_it(
    client: TestClient,
) -> None:
    """A project's .plant file is a project file: its problem shows among the project's
    problems (file and line, for the editor) and a download of the project is refused."""
    program = (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n A I 0.0;\n = Q 4.0;\nEND_ORGANIZATION_BLOCK\n"
    )
    plant = "kind: motor\nwiring:\n  start: I0.0\n  contactor: I4.0\n"
    project_id = make_project(client, "Plant", {"OB1.awl": program, "motor.plant": plant})
    files = client.get(f"/api/projects/{project_id}/files").json()
    assert {f["name"]: f["language"] for f in files}["motor.plant"] == "plant"
    build = client.get(f"/api/projects/{project_id}/blocks").json()
    [problem] = [d for d in build["diagnostics"] if d["code"].startswith("PLT")]
    assert problem["code"] == "PLT005"
    assert problem["span"]["file"] == "motor.plant"
    assert problem["span"]["line"] == 4
    refused = client.post(f"/api/projects/{project_id}/sessions")
    assert refused.status_code == 422
    assert refused.json()["error"]["code"] == "PLT005"
    fixed = plant.replace("I4.0", "Q4.0")
    saved = client.put(f"/api/projects/{project_id}/files/motor.plant", json={"text": fixed})
    assert saved.status_code in (200, 201), saved.text
    build = client.get(f"/api/projects/{project_id}/blocks").json()
    assert [d for d in build["diagnostics"] if d["code"].startswith("PLT")] == []

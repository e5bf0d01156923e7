"""A project's ``cpu.properties`` through the API: checked for the page, applied by downloads."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

# M 100.5 (1 Hz clock bit) copied to Q 4.0; OB102 marks a cold restart in MW 20.
PROGRAM = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     M    100.5;
      =     Q      4.0;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK OB 102
BEGIN
NETWORK
      L     102;
      T     MW    20;
END_ORGANIZATION_BLOCK
"""
PROPERTIES = "clock_memory = MB100\ncycle_time = 25\nstartup = cold\n"


def _watch_after_run(client: TestClient, session: dict[str, Any]) -> tuple[set[bool], int]:
    """RUN over the socket; the values Q 4.0 takes in the frames and the last MW 20."""
    seen: set[bool] = set()
    mw20 = 0
    with client.websocket_connect(session["websocket"]) as socket:
        assert socket.receive_json()["type"] == "hello"
        socket.send_json({"type": "set_time", "mode": "fast", "cycle_ms": None, "ref": 1})
        socket.send_json({"type": "watch", "entries": ["Q4.0", "MW20"], "ref": 2})
        socket.send_json({"type": "run", "ref": 3})
        for _ in range(400):
            message = socket.receive_json()
            assert message["type"] != "error", message
            watched = message.get("watch") if message["type"] == "frame" else None
            if watched and "Q4.0" in watched:
                seen.add(watched["Q4.0"]["value"])
            if watched and "MW20" in watched:
                mw20 = watched["MW20"]["value"]
            if len(seen) == 2 and mw20:
                break
    return seen, mw20


def test_check_reads_the_text_with_values_and_problems_by_line(
    client: TestClient,
) -> None:
    response = client.post("/api/cpu-properties/check", json={"text": PROPERTIES})
    assert response.status_code == 200, response.text
    body = response.json()
    assert body["diagnostics"] == []
    assert body["properties"] == {
        "profile": "S7-300",
        "cycle_monitoring_time": 150,
        "cycle_time": 25,
        "clock_memory": 100,
        "retentive_markers": 16,
        "retentive_timers": 0,
        "retentive_counters": 8,
        "startup": "cold",
    }
    bad = client.post("/api/cpu-properties/check", json={"text": "cycle_time = fast\n"}).json()
    assert [(d["code"], d["span"]["line"], d["params"]["key"]) for d in bad["diagnostics"]] == [
        ("PRJ904", 1, "cycle_time")
    ]
    assert bad["properties"]["cycle_time"] == 10


def test_a_download_applies_the_projects_properties(client: TestClient) -> None:
    project_id = make_project(client, "Clock", {"OB1.awl": PROGRAM, "cpu.properties": PROPERTIES})
    blocks = client.get(f"/api/projects/{project_id}/blocks").json()
    assert blocks["diagnostics"] == []  # the compiler skips the properties file
    response = client.post(f"/api/projects/{project_id}/sessions")
    assert response.status_code == 201, response.text
    session = response.json()
    try:
        assert session["cpu"]["cycle_ms"] == 25  # the file's cycle time
        seen, mw20 = _watch_after_run(client, session)
        assert seen == {True, False}  # M 100.5 toggles: the clock memory byte is MB 100
        assert mw20 == 102  # RUN made the file's startup, a cold restart (OB102)
    finally:
        client.delete(f"/api/sessions/{session['id']}")
    explicit = client.post(f"/api/projects/{project_id}/sessions", json={"cycle_ms": 40})
    assert explicit.status_code == 201, explicit.text
    try:
        assert explicit.json()["cpu"]["cycle_ms"] == 40  # an option sent explicitly wins
    finally:
        client.delete(f"/api/sessions/{explicit.json()['id']}")


def test_a_file_with_errors_refuses_the_download_with_its_line(
    client: TestClient,
) -> None:
    project_id = make_project(
        client,
        "Bad CPU",
        {"OB1.awl": PROGRAM, "cpu.properties": "cycle_time = 20\nstartup = hot\n"},
    )
    response = client.post(f"/api/projects/{project_id}/sessions")
    assert response.status_code == 422
    error = error_of(response)
    assert error["code"] == "PRJ908"
    assert error["params"] == {"file": "cpu.properties", "line": 2, "problem": "PRJ906"}
    sources = [{"name": "OB1.awl", "text": PROGRAM}]
    good = client.post("/api/sessions", json={"sources": sources})
    assert good.status_code == 201, good.text
    try:
        bad = [*sources, {"name": "cpu.properties", "text": "colour = red\n"}]
        refused = client.put(f"/api/sessions/{good.json()['id']}/program", json={"sources": bad})
        assert error_of(refused)["code"] == "PRJ908"
    finally:
        client.delete(f"/api/sessions/{good.json()['id']}")

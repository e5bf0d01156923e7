"""A project's session outlives its browser tabs: a reloaded page, a second tab or another browser
finds it by project and attaches to it with its CPU state, forces, breakpoints and trend history;
a session whose last client left is closed after the idle time, counted from that moment."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    PLANT_PROGRAM,
    PLANT_SYMBOLS,
    LiveServer,
    line_of,
    running_server,
    wait_for,
)

IDLE_SECONDS = 1.0  # the reaper looks every IDLE_SECONDS / 2


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server(session_idle_seconds=IDLE_SECONDS) as server:
        yield server


def _project(live: LiveServer, name: str) -> int:
    response = live.http.post("/api/projects", json={"name": name})
    assert response.status_code == 201, response.text
    project_id: int = response.json()["id"]
    for file, text in (("plant.awl", PLANT_PROGRAM), ("plant.sdf", PLANT_SYMBOLS)):
        saved = live.http.put(f"/api/projects/{project_id}/files/{file}", json={"text": text})
        assert saved.status_code in (200, 201), saved.text
    return project_id


def _download(live: LiveServer, project_id: int) -> dict[str, Any]:
    # Compiling may take longer than one wait on a busy machine.
    response = live.http.post(f"/api/projects/{project_id}/sessions", json={}, timeout=60)
    assert response.status_code == 201, response.text
    body: dict[str, Any] = response.json()
    return body


def _of_project(live: LiveServer, project_id: int) -> list[dict[str, Any]]:
    response = live.http.get("/api/sessions", params={"project_id": project_id})
    assert response.status_code == 200, response.text
    found: list[dict[str, Any]] = response.json()
    return found


def _exists(live: LiveServer, session_id: str) -> bool:
    return live.http.get(f"/api/sessions/{session_id}").status_code == 200


def test_a_project_session_is_found_by_project_with_its_name_mode_and_age(
    live: LiveServer,
) -> None:
    mixer = _project(live, "Mixer line")
    other = _project(live, "Other line")
    made = _download(live, mixer)
    try:
        assert made["project_id"] == mixer
        assert made["project_name"] == "Mixer line"
        found = _of_project(live, mixer)
        assert [s["id"] for s in found] == [made["id"]]
        assert found[0]["cpu"]["mode"] == "STOP"
        assert found[0]["profile"] == "S7-300"
        assert 0 <= found[0]["age_seconds"] < 60
        assert _of_project(live, other) == []
        everything = live.http.get("/api/sessions").json()
        assert made["id"] in [s["id"] for s in everything]
    finally:
        live.delete(made["id"])
    assert _of_project(live, mixer) == []


def test_a_new_download_of_the_project_replaces_its_running_session(
    live: LiveServer,
) -> None:
    project_id = _project(live, "Replaced line")
    first = _download(live, project_id)
    with live.monitor(first["id"]) as watcher:
        second = _download(live, project_id)
        # The old CPU's clients learn that it was closed (and look the project up again).
        watcher.until(
            lambda m: any(e.get("code") == "MON614" for e in m.unsolicited),
            "MON614 for the old",
        )
    try:
        assert [s["id"] for s in _of_project(live, project_id)] == [second["id"]]
        assert not _exists(live, first["id"])
    finally:
        live.delete(second["id"])


def test_a_client_attaching_after_the_first_left_finds_cpu_forces_breakpoints_and_trend(
    live: LiveServer,
) -> None:
    project_id = _project(live, "Reattached line")
    session_id = _download(live, project_id)["id"]
    line = line_of(PLANT_PROGRAM, "T     MW    20;")
    try:
        with live.monitor(session_id) as first:
            first.ok("subscribe_cpu", on=True)
            first.ok("force", address="I0.0", value=True)
            first.ok("trend", entries=["MW30"])
            first.ok("run")
            first.until_scans(5)
            bp = first.ok("set_breakpoint", location={"file": "plant.awl", "line": line})
            first.until_held()
            first.until(lambda m: len(m.trend) > 0, "trend samples")

        # The first client is gone (a reload); the page finds the session by its project, and
        # once the server has seen the socket close (it may list the client a moment longer),
        # with no client.
        def left() -> dict[str, Any] | None:
            (session,) = _of_project(live, project_id)
            return session if session["clients"] == [] else None

        found = wait_for(left, "the first client to leave the session")
        assert found["id"] == session_id
        with live.monitor(session_id) as second:
            second.ok("subscribe_cpu", on=True)
            state = second.until_mode("HOLD")
            assert state["forced"] == [{"address": "I0.0", "value": True}]
            kept = second.ok("session_state")
            assert kept["trend"] == ["MW30"]
            (breakpoint,) = kept["breakpoints"]
            assert breakpoint["id"] == bp["id"]
            assert breakpoint["location"] == {"file": "plant.awl", "line": line}
            assert breakpoint["file"] == "plant.awl"
            assert breakpoint["condition"] is None
            # The reloaded page sets the project's breakpoints again: the same one, no duplicate.
            again = second.ok("set_breakpoint", location={"file": "plant.awl", "line": line})
            assert again["id"] == bp["id"]
            assert len(second.ok("session_state")["breakpoints"]) == 1
            # Asking for the same trend starts with the samples recorded before the reload.
            second.ok("trend", entries=["MW30"])
            history = second.until(lambda m: len(m.trend) > 0, "the trend history")
            assert history
            assert second.trend[0]["scan"] < state["scans"]
            # The breakpoint still holds: continue, and the CPU holds there again.
            before = state["scans"]
            second.ok("continue")
            second.until(
                lambda m: m.hold is not None and m.cpu is not None and m.cpu["scans"] > before,
                "the next hold at the same breakpoint",
            )
            second.ok("clear_breakpoint", id=None)
            assert second.ok("session_state")["breakpoints"] == []
    finally:
        live.delete(session_id)


def test_a_second_tab_gets_the_trend_history_of_the_first(live: LiveServer) -> None:
    session_id = _download(live, _project(live, "Two tabs line"))["id"]
    try:
        with live.monitor(session_id) as first, live.monitor(session_id) as second:
            first.ok("trend", entries=["MW30"])
            first.ok("run")
            first.until(lambda m: len(m.trend) >= 5, "five samples")
            second.ok("trend", entries=["MW30"])
            second.until(lambda m: len(m.trend) >= 5, "the history in the second tab")
            assert second.trend[0]["scan"] <= first.trend[0]["scan"] + 1
            # A different trend in a tab starts empty and leaves the other tab's alone.
            second.ok("trend", entries=["MW20"])
            second.drain(0.2)
            assert all(sample["scan"] > first.trend[0]["scan"] for sample in second.trend)
            assert first.ok("session_state")["trend"] in (["MW30"], ["MW20"])
    finally:
        live.delete(session_id)


def test_a_session_whose_last_client_left_is_closed_after_the_idle_time(
    live: LiveServer,
) -> None:
    project_id = _project(live, "Idle line")
    session_id = _download(live, project_id)["id"]
    with live.monitor(session_id) as client:
        client.ok("run")
        time.sleep(2 * IDLE_SECONDS)  # connected: never idle, however long
        assert _exists(live, session_id)
    left = time.monotonic()
    wait_for(lambda: not _exists(live, session_id), "the idle session to close", timeout=5)
    assert time.monotonic() - left >= IDLE_SECONDS * 0.9
    assert _of_project(live, project_id) == []  # its slot is free


def test_a_reload_does_not_lose_the_session_when_the_old_socket_closes_first(
    live: LiveServer,
) -> None:
    """The old page's socket closes, the reloaded page attaches a moment later: the idle time
    counts from the last client leaving, not from the last command."""
    project_id = _project(live, "Reload race line")
    session_id = _download(live, project_id)["id"]
    try:
        with live.monitor(session_id) as old:
            old.ok("run")
            time.sleep(2 * IDLE_SECONDS)  # no command for longer than the idle time
        # Several reaper rounds pass before the new page attaches.
        time.sleep(0.6 * IDLE_SECONDS)
        assert _exists(live, session_id)
        with live.monitor(session_id) as new:
            new.ok("subscribe_cpu", on=True)
            assert new.until_mode("RUN")["scans"] > 0
            time.sleep(1.5 * IDLE_SECONDS)
            assert _exists(live, session_id)
    finally:
        live.delete(session_id)

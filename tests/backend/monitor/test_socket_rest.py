"""The session REST API on a real server: create, list, get, download, diagnostics, trend CSV,
delete, and the session limit, as the IDE uses them around its monitoring socket."""

from __future__ import annotations

import csv
import io
import sys
from collections.abc import Iterator
from pathlib import Path

import httpx2
import pytest
from websockets.exceptions import ConnectionClosed, InvalidStatus
from websockets.sync.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    AREA_ERROR_PROGRAM,
    LOOP_PROGRAM,
    PLANT_PROGRAM,
    TIMEOUT,
    LiveServer,
    line_of,
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
def created(live: LiveServer) -> Iterator[list[str]]:
    """Ids of the sessions a test creates; deleted afterwards."""
    ids: list[str] = []
    yield ids
    for session_id in ids:
        live.delete(session_id)


def _refused(url: str) -> None:
    """A socket at ``url`` is refused at the handshake, or closed before it hears anything."""
    try:
        with connect(url, open_timeout=TIMEOUT) as ws:
            message = ws.recv(timeout=TIMEOUT)
    except (InvalidStatus, ConnectionClosed):
        return
    raise AssertionError(f"{url} accepted the socket and sent {message!r}")


def _error(response: httpx2.Response) -> dict[str, object]:
    """The catalogue diagnostic of an API error answer."""
    body = response.json()
    assert set(body) == {"error"}, body
    error: dict[str, object] = body["error"]
    return error


# -- create, list, get ------------------------------------------------------------------------


def test_create_answers_201_with_the_blocks_the_cpu_in_stop_and_the_socket(
    live: LiveServer, created: list[str]
) -> None:
    response = live.http.post(
        "/api/sessions", json={"sources": [source("prog.awl", LOOP_PROGRAM)], "cycle_ms": 20}
    )
    assert response.status_code == 201, response.text
    body = response.json()
    created.append(body["id"])
    assert body["blocks"] == ["FC1", "OB1"]
    assert body["websocket"] == f"/api/sessions/{body['id']}/ws"
    cpu = body["cpu"]
    assert cpu["mode"] == "STOP"
    assert cpu["scans"] == 0
    assert cpu["time_ms"] == 0
    assert cpu["cycle_ms"] == 20
    assert cpu["time_mode"] == "virtual"
    assert cpu["forced"] == []
    # The socket the answer names is the session's.
    with live.monitor(body["id"]) as client:
        assert client.hello["session"] == body["id"]
        assert client.hello["protocol"] == 1
        assert client.hello["max_watch_entries"] == 500


def test_a_program_that_does_not_compile_is_422_mon611_naming_file_and_line(
    live: LiveServer,
) -> None:
    broken = LOOP_PROGRAM.replace("      +I    ;", "      XYZ   MW 4;")
    before = {s["id"] for s in live.http.get("/api/sessions").json()}
    response = live.http.post("/api/sessions", json={"sources": [source("broken.awl", broken)]})
    assert response.status_code == 422, response.text
    error = _error(response)
    assert error["code"] == "MON611"
    line = line_of(broken, "XYZ")
    assert f"broken.awl:{line}:" in str(error["message"]), error
    # Nothing was created.
    assert {s["id"] for s in live.http.get("/api/sessions").json()} == before


def test_an_scl_compile_error_names_the_scl_file(live: LiveServer) -> None:
    broken = "FUNCTION FC1 : VOID\nBEGIN\n  MW10 := ;\nEND_FUNCTION\n"
    response = live.http.post("/api/sessions", json={"sources": [source("bad.scl", broken)]})
    assert response.status_code == 422, response.text
    error = _error(response)
    assert error["code"] == "MON611"
    assert "bad.scl:3:" in str(error["message"]), error


def test_list_and_get_show_each_session_with_its_cpu(live: LiveServer, created: list[str]) -> None:
    first = live.create_stl()
    second = live.create(plant_sources())["id"]
    created += [first, second]
    listed = {s["id"]: s for s in live.http.get("/api/sessions").json()}
    assert {first, second} <= set(listed)
    assert listed[second]["blocks"] == ["DB1", "DB5", "FB1", "OB1", "OB100"]

    with live.monitor(second) as client:
        client.ok("subscribe_cpu")
        client.ok("run")
        client.until_scans(3)
    got = live.http.get(f"/api/sessions/{second}")
    assert got.status_code == 200
    body = got.json()
    assert body["id"] == second
    assert body["cpu"]["mode"] == "RUN"
    assert body["cpu"]["scans"] >= 3
    assert live.http.get(f"/api/sessions/{first}").json()["cpu"]["mode"] == "STOP"


# -- delete ------------------------------------------------------------------------------------


def test_delete_closes_the_sockets_and_forgets_the_session(live: LiveServer) -> None:
    session_id = live.create_stl()
    client = live.connect(session_id)
    client.ok("subscribe_cpu")
    client.ok("run")
    client.until_scans(2)

    assert live.http.delete(f"/api/sessions/{session_id}").status_code == 204

    # The open socket is told (MON614) and closed normally.
    closed = client.closed()
    assert any(e["code"] == "MON614" for e in client.unsolicited), client.unsolicited
    assert closed.rcvd is not None
    assert closed.rcvd.code == 1000

    for response in (
        live.http.get(f"/api/sessions/{session_id}"),
        live.http.delete(f"/api/sessions/{session_id}"),
        live.http.get(f"/api/sessions/{session_id}/diagnostics"),
        live.http.put(
            f"/api/sessions/{session_id}/program",
            json={"sources": [source("prog.awl", LOOP_PROGRAM)]},
        ),
    ):
        assert response.status_code == 404, response.text
        assert _error(response)["code"] == "MON609"
    assert session_id not in {s["id"] for s in live.http.get("/api/sessions").json()}

    # A new socket on the deleted session is refused.
    _refused(f"{live.ws_base}/api/sessions/{session_id}/ws")


def test_a_socket_on_an_unknown_session_is_refused(live: LiveServer) -> None:
    _refused(f"{live.ws_base}/api/sessions/nosuchsession/ws")
    response = live.http.get("/api/sessions/nosuchsession")
    assert response.status_code == 404
    assert _error(response)["code"] == "MON609"


# -- download ----------------------------------------------------------------------------------


def test_a_download_in_stop_lists_the_changed_blocks_and_keeps_unchanged_data(
    live: LiveServer, created: list[str]
) -> None:
    session_id = live.create(plant_sources())["id"]
    created.append(session_id)
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        client.ok("watch", entries=["DB1.level", "DB5.count", "MW20", "MW22", "MW30"])
        client.ok("run")
        client.until_scans(3)
        client.ok("modify", target="DB1.level", value=42)
        client.until_value("MW20", 42)
        client.ok("stop")
        client.until_mode("STOP")
        counted = client.value("DB5.count")
        assert counted >= 3
        assert client.value("MW30") == counted

        # OB1 now copies the level to MW22: only OB1 changes.
        changed_ob1 = PLANT_PROGRAM.replace("T     MW    20;", "T     MW    22;")
        response = live.http.put(
            f"/api/sessions/{session_id}/program",
            json={"sources": [source("plant.awl", changed_ob1)]},
        )
        assert response.status_code == 200, response.text
        assert response.json() == {"changed": ["OB1"]}
        # Data blocks with the same layout and the memory markers keep their values.
        assert live.http.get(f"/api/sessions/{session_id}").json()["cpu"]["mode"] == "STOP"
        client.ok("watch", entries=["DB1.level", "DB5.count", "MW20", "MW22", "MW30"])
        client.until_value("DB1.level", 42)
        assert client.value("DB5.count") == counted
        assert client.value("MW30") == counted
        client.ok("run")
        client.until_value("MW22", 42)
        client.until(lambda m: m.value("DB5.count") > counted, "FB1 to count on")

        # A DB whose layout changes starts again from its initial values.
        client.ok("stop")
        client.until_mode("STOP")
        retyped = changed_ob1.replace("    speed : REAL := 1.5;", "    speed : DINT := 9;")
        response = live.http.put(
            f"/api/sessions/{session_id}/program",
            json={"sources": [source("plant.awl", retyped)]},
        )
        assert response.status_code == 200, response.text
        assert response.json() == {"changed": ["DB1"]}
        client.ok("watch", entries=["DB1.level", "DB1.speed", "DB5.count"])
        client.until_value("DB1.level", 5)
        client.until_value("DB1.speed", 9)
        assert client.value("DB5.count") > counted


def test_a_download_lists_only_blocks_whose_content_changed(
    live: LiveServer, created: list[str]
) -> None:
    """Inserting a line into DB1 moves the blocks below it down the file; their code is the
    same, so they are not "changed" blocks (the IDE shows this list to the user)."""
    session_id = live.create(plant_sources())["id"]
    created.append(session_id)
    grown = PLANT_PROGRAM.replace(
        "    speed : REAL := 1.5;", "    speed : REAL := 1.5;\n    extra : INT := 7;"
    )
    response = live.http.put(
        f"/api/sessions/{session_id}/program", json={"sources": [source("plant.awl", grown)]}
    )
    assert response.status_code == 200, response.text
    assert response.json() == {"changed": ["DB1"]}


def test_a_download_in_run_is_409_mon607_and_changes_nothing(
    live: LiveServer, created: list[str]
) -> None:
    session_id = live.create(plant_sources())["id"]
    created.append(session_id)
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        client.ok("watch", entries=["MW20"])
        client.ok("run")
        client.until_value("MW20", 5)
        changed = PLANT_PROGRAM.replace("T     MW    20;", "T     MW    22;")
        response = live.http.put(
            f"/api/sessions/{session_id}/program",
            json={"sources": [source("plant.awl", changed)]},
        )
        assert response.status_code == 409, response.text
        assert _error(response)["code"] == "MON607"
        # Still the old program, still running.
        scans = client.until_scans(1)["scans"]
        client.until_scans(scans + 3)
        assert client.cpu is not None
        assert client.cpu["mode"] == "RUN"
        assert live.http.get(f"/api/sessions/{session_id}").json()["blocks"] == [
            "DB1",
            "DB5",
            "FB1",
            "OB1",
            "OB100",
        ]


def test_a_download_that_does_not_compile_is_422_and_keeps_the_old_program(
    live: LiveServer, created: list[str]
) -> None:
    session_id = live.create_stl()
    created.append(session_id)
    broken = LOOP_PROGRAM.replace("LOOP  next;", "LOOP  nowhere;")
    response = live.http.put(
        f"/api/sessions/{session_id}/program", json={"sources": [source("prog.awl", broken)]}
    )
    assert response.status_code == 422, response.text
    error = _error(response)
    assert error["code"] == "MON611"
    assert f"prog.awl:{line_of(broken, 'nowhere')}:" in str(error["message"])
    with live.monitor(session_id) as client:
        client.ok("watch", entries=["MW10"])
        client.ok("run")
        client.until_value("MW10", 6)


# -- diagnostics -------------------------------------------------------------------------------


def test_the_diagnostic_buffer_shows_an_area_length_error_with_block_network_and_line(
    live: LiveServer, created: list[str]
) -> None:
    session_id = live.create_stl(AREA_ERROR_PROGRAM, name="area.awl")
    created.append(session_id)
    assert live.http.get(f"/api/sessions/{session_id}/diagnostics").json() == []
    line = line_of(AREA_ERROR_PROGRAM, "DB3.DBW")
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        client.ok("run")
        # The socket tells about the entry as it is made ...
        client.until(lambda m: m.diagnostics, "a diagnostics entry in a frame")
        state = client.until_mode("STOP")
        assert state["stop_code"] == "SIM503"
        assert f"line {line}" in state["stop_reason"]
        entry = client.diagnostics[0]
        assert entry["code"] == "SIM503"
        assert (entry["block"], entry["network"], entry["line"]) == ("OB1", 2, line)
        assert "DB3.DBW 10" in entry["message"]

    # ... and the REST API keeps the buffer, oldest first.
    response = live.http.get(f"/api/sessions/{session_id}/diagnostics")
    assert response.status_code == 200
    entries = response.json()
    assert entries[0] == entry
    assert set(entry) == {
        "time_ms",
        "code",
        "message",
        "block",
        "network",
        "line",
        "key",
        "params",
    }
    # The IDE says the entry in its language from the catalogue key and the params.
    assert entry["key"] == "sim_area_length_read"
    assert entry["params"]["address"] in entry["message"]


# -- trend CSV ---------------------------------------------------------------------------------


def test_the_trend_csv_holds_each_clients_own_samples(live: LiveServer, created: list[str]) -> None:
    session_id = live.create(plant_sources())["id"]
    created.append(session_id)
    with live.monitor(session_id) as one, live.monitor(session_id) as two:
        assert one.client_id != two.client_id
        one.ok("trend", entries=["MW30"])
        two.ok("trend", entries=["DB5.count", "DB1.level", "M1.0"])
        one.ok("run")
        one.until(lambda m: len(m.trend) >= 10, "10 trend samples")
        two.until(lambda m: len(m.trend) >= 10, "10 trend samples")

        first = live.http.get(
            f"/api/sessions/{session_id}/trend.csv", params={"client": one.client_id}
        )
        assert first.status_code == 200
        assert first.headers["content-type"].startswith("text/csv")
        rows = list(csv.reader(io.StringIO(first.text)))
        assert rows[0] == ["scan", "time_ms", "MW30"]
        data = [[int(cell) for cell in row] for row in rows[1:]]
        assert len(data) >= 10
        for scan, time_ms, counter in data:
            assert time_ms == scan * 10
            assert counter == scan  # MW30 counts the scans
        assert [row[0] for row in data] == list(range(data[0][0], data[0][0] + len(data)))

        second = live.http.get(
            f"/api/sessions/{session_id}/trend.csv", params={"client": two.client_id}
        )
        rows = list(csv.reader(io.StringIO(second.text)))
        assert rows[0] == ["scan", "time_ms", "DB5.count", "DB1.level", "M1.0"]
        assert len(rows) > 10
        scan, time_ms, count, level, flag = rows[-1]
        assert int(count) == int(scan)
        assert level == "5"
        assert flag == "True"

    # The CSV exists while its client is connected: once the server has seen the socket close
    # (it may answer one request more before it has), the client's samples are gone.
    url = f"/api/sessions/{session_id}/trend.csv"

    def closed() -> httpx2.Response | None:
        response = live.http.get(url, params={"client": one.client_id})
        return response if response.status_code == 404 else None

    gone = wait_for(closed, "the closed client's trend to go")
    assert _error(gone)["code"] == "MON603"


# -- the session limit -------------------------------------------------------------------------


def test_more_sessions_than_max_sessions_is_503_mon610() -> None:
    with running_server(max_sessions=2) as small:
        first = small.create_stl()
        small.create_stl()
        response = small.http.post(
            "/api/sessions", json={"sources": [source("prog.awl", LOOP_PROGRAM)]}
        )
        assert response.status_code == 503, response.text
        error = _error(response)
        assert error["code"] == "MON610"
        assert "2" in str(error["message"])
        assert len(small.http.get("/api/sessions").json()) == 2
        # Closing one makes room again.
        small.delete(first)
        wait_for(lambda: len(small.http.get("/api/sessions").json()) == 1, "the session to go")
        small.create_stl()

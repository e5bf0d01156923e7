"""Bad input on the monitoring socket of a real server: every case is answered with its catalogue
code (the ref echoed when the message has one), and the connection, the session, the other
sessions and the server carry on."""

from __future__ import annotations

import base64
import json
import logging
import os
import socket
import struct
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import (
    CALC_SCL,
    COUNTER_PROGRAM,
    LOOP_PROGRAM,
    TIMEOUT,
    LiveServer,
    Monitor,
    line_of,
    running_server,
    source,
    wait_for,
)

RAW_REF = 9000  # refs of hand-written messages, far from the ones Monitor.send counts


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


@pytest.fixture(scope="module")
def control(live: LiveServer) -> Iterator[Monitor]:
    """Another session, running, that every bad input must leave alone."""
    session_id = live.create_stl()
    with live.monitor(session_id) as client:
        client.ok("subscribe_cpu")
        client.ok("run")
        client.until_scans(1)
        yield client
    live.delete(session_id)


@pytest.fixture
def client(live: LiveServer, control: Monitor) -> Iterator[Monitor]:
    """A client on a new running LOOP session. Each test checks at its end that its own
    connection and session carry on; afterwards, whatever happened, the control session and
    the server must still work."""
    session_id = live.create([source("prog.awl", LOOP_PROGRAM)])["id"]
    with live.monitor(session_id) as monitor:
        monitor.ok("subscribe_cpu")
        monitor.ok("watch", entries=["MW10"])
        monitor.ok("run")
        monitor.until_value("MW10", 6)
        yield monitor
    live.delete(session_id)
    _carries_on(live, control)


def _carries_on(live: LiveServer, monitor: Monitor) -> None:
    """The server answers, ``monitor``'s session runs and its connection answers."""
    health = live.http.get("/api/health")
    assert health.status_code == 200
    assert health.json()["status"] == "ok"
    monitor.drain(0.05)
    assert monitor.cpu is not None
    assert monitor.cpu["mode"] == "RUN", monitor.cpu
    monitor.until_scans(monitor.cpu["scans"] + 3, timeout=2)
    monitor.ok("subscribe_cpu")  # the connection still answers


# -- messages the server cannot read ------------------------------------------------------------


def test_malformed_json_is_mon601(live: LiveServer, client: Monitor) -> None:
    client.send_raw("{not json")
    error = client.next_unsolicited()
    assert error["code"] == "MON601"
    assert error["key"] == "mon_malformed_message"
    assert error["ref"] is None
    assert "JSON" in error["message"]
    client.send_raw('{"type": "run", "ref": 5')  # cut short: no ref can be read
    assert client.next_unsolicited()["code"] == "MON601"
    client.send_raw("")
    assert client.next_unsolicited()["code"] == "MON601"
    client.send_raw("[1, 2]")
    assert client.next_unsolicited()["code"] == "MON601"
    _carries_on(live, client)


def test_a_binary_frame_is_mon601(live: LiveServer, client: Monitor) -> None:
    client.send_raw(b"\x00\x01\x02binary")
    error = client.next_unsolicited()
    assert error["code"] == "MON601"
    assert "JSON text" in error["message"]
    # Even a binary frame holding valid JSON.
    client.send_raw(json.dumps({"type": "run", "ref": RAW_REF}).encode())
    assert client.next_unsolicited()["code"] == "MON601"
    assert RAW_REF not in client.answers
    _carries_on(live, client)


def test_an_unknown_message_type_is_mon601_with_its_ref(live: LiveServer, client: Monitor) -> None:
    client.send_raw(json.dumps({"type": "explode", "ref": RAW_REF}))
    error = client.answer(RAW_REF)
    assert error["type"] == "error"
    assert error["code"] == "MON601"
    assert "explode" in error["message"]
    client.send_raw(json.dumps({"ref": RAW_REF + 1}))  # no type at all
    assert client.answer(RAW_REF + 1)["code"] == "MON601"


_WRONG_TYPES: list[tuple[dict[str, Any], str]] = [
    ({"type": "watch", "entries": "MW10"}, "watch.entries"),
    ({"type": "watch", "entries": [10, 12]}, "watch.entries.0"),
    ({"type": "trend", "entries": None}, "trend.entries"),
    ({"type": "open_block", "block": 1}, "open_block.block"),
    ({"type": "set_time", "mode": "warp"}, "set_time.mode"),
    ({"type": "set_time", "mode": "fast", "cycle_ms": 0}, "set_time.cycle_ms"),
    ({"type": "set_input", "address": ["I0.0"], "value": 1}, "set_input.address"),
    ({"type": "modify", "target": "MW10"}, "modify.value"),
    ({"type": "modify", "target": "MW10", "value": [1]}, "modify.value"),
    ({"type": "restart", "cold": [1]}, "restart.cold"),
    ({"type": "subscribe_cpu", "on": "maybe"}, "subscribe_cpu.on"),
    ({"type": "step", "by": "line"}, "step.by"),
    ({"type": "run_scans", "count": "many"}, "run_scans.count"),
    ({"type": "run_scans", "count": 0}, "run_scans.count"),
    ({"type": "set_breakpoint", "location": {"file": "prog.awl", "line": 0}}, "location.line"),
    ({"type": "set_breakpoint", "location": "prog.awl:12"}, "set_breakpoint.location"),
    (
        {"type": "set_breakpoint", "location": {"file": "prog.awl", "line": 12, "column": 3}},
        "location.column",
    ),
    ({"type": "clear_breakpoint", "id": "all"}, "clear_breakpoint.id"),
    ({"type": "run", "extra": 1}, "run.extra"),
]


@pytest.mark.parametrize(("message", "field"), _WRONG_TYPES, ids=[f for _, f in _WRONG_TYPES])
def test_a_field_of_the_wrong_type_is_mon601_naming_the_field(
    live: LiveServer, client: Monitor, message: dict[str, Any], field: str
) -> None:
    client.send_raw(json.dumps({**message, "ref": RAW_REF}))
    error = client.answer(RAW_REF)
    assert error["type"] == "error", error
    assert error["code"] == "MON601", error
    assert field in error["params"]["reason"], error
    _carries_on(live, client)


def test_a_ref_of_the_wrong_type_is_mon601_without_a_ref(live: LiveServer, client: Monitor) -> None:
    client.send_raw(json.dumps({"type": "run", "ref": "seven"}))
    error = client.next_unsolicited()
    assert error["code"] == "MON601"
    assert "ref" in error["params"]["reason"]
    _carries_on(live, client)


def test_a_message_over_64_kib_is_mon602(live: LiveServer, client: Monitor) -> None:
    huge = json.dumps({"type": "watch", "entries": ["M0.0"] * 20_000, "ref": RAW_REF})
    assert len(huge) > 64 * 1024
    client.send_raw(huge)
    error = client.next_unsolicited()
    assert error["code"] == "MON602"
    assert error["params"]["limit"] == 64 * 1024
    assert error["params"]["size"] >= len(huge)
    assert RAW_REF not in client.answers
    # The old watch list stands.
    assert client.ok("watch", entries=["MW10"])["entries"] == [{"entry": "MW10", "type": "WORD"}]
    _carries_on(live, client)


# -- messages that ask for something that does not exist ------------------------------------------


def test_unknown_addresses_are_mon603(live: LiveServer, client: Monitor) -> None:
    for kind, fields in (
        ("set_input", {"address": "IX", "value": 1}),
        ("set_input", {"address": "Q0.0", "value": 1}),  # not an input
        ("modify", {"target": "DB9.DBW0", "value": 1}),
        ("modify", {"target": '"NoSuchSymbol"', "value": 1}),
        ("force", {"address": "MW20", "value": 1}),  # not an input or output
        ("unforce", {"address": "MB4"}),
        ("trend", {"entries": ["MW10", "QQ7"]}),
    ):
        error = client.fails(kind, "MON603", **fields)
        assert error["params"]["target"], error
    # A watch list takes the good entries and reports the unknown ones.
    ack = client.ok("watch", entries=["MW10", "QQ7", "DB9.DBW0"])
    assert [e.get("code") for e in ack["entries"]] == [None, "MON603", "MON603"]
    client.until(lambda m: "QQ7" in m.watch, "the unknown entry in a frame")
    assert client.watch["QQ7"]["value"] is None
    assert client.watch["QQ7"]["error"]
    _carries_on(live, client)


@contextmanager
def _contained(live: LiveServer, session_id: str) -> Iterator[None]:
    """For a test that may break its session: on failure the session is closed at once (a
    session thread that failed in a loop would go on logging tracebacks while pytest reports,
    and Python 3.11 formats tracebacks with ``ast``, which is not thread-safe), and only the
    first of its repeated log records are kept."""
    logger = logging.getLogger("nasaq.monitor.session")
    kept = 0

    def first_few(record: logging.LogRecord) -> bool:
        nonlocal kept
        kept += 1
        return kept <= 3

    logger.addFilter(first_few)
    try:
        yield
    except BaseException:
        live.delete(session_id)
        raise
    finally:
        logger.removeFilter(first_few)


@pytest.mark.parametrize("entry", ["MW99999", "T9999"])
def test_watching_an_address_beyond_the_cpus_memory_is_reported_and_the_cpu_runs_on(
    live: LiveServer, client: Monitor, entry: str
) -> None:
    """The S7-300 has MB0..MB2047 and T0..T255: the entry is an error of its own (MON603 in
    the ack, or an error in the frames), the rest of the watch list and the CPU carry on."""
    with _contained(live, client.session_id):
        _watch_beyond_memory(live, client, entry)


def _watch_beyond_memory(live: LiveServer, client: Monitor, entry: str) -> None:
    ack = client.ok("watch", entries=["MW10", entry, "MW12"])
    assert client.cpu is not None
    scans = client.cpu["scans"]
    client.ok("modify", target="MW12", value=77)
    client.until(
        lambda m: m.value("MW12") == 77 and m.state("scans") >= scans + 5,
        f"frames with MW12 = 77 and 5 more scans after watching {entry}",
        timeout=1,
    )
    assert client.cpu is not None
    assert client.cpu["mode"] == "RUN"
    reported = {e["entry"]: e for e in ack["entries"]}[entry]
    if "code" not in reported:
        client.until(lambda m: entry in m.watch, f"{entry} in a frame", timeout=2)
        assert client.watch[entry]["error"], client.watch[entry]
    else:
        assert reported["code"] == "MON603"
    _carries_on(live, client)


def test_trending_an_address_beyond_the_cpus_memory_is_mon603(
    live: LiveServer, client: Monitor
) -> None:
    with _contained(live, client.session_id):
        _trend_beyond_memory(live, client)


def _trend_beyond_memory(live: LiveServer, client: Monitor) -> None:
    error = client.request("trend", entries=["MW10", "MW99999"])
    assert client.cpu is not None
    scans = client.cpu["scans"]
    client.until(
        lambda m: m.state("mode") != "RUN" or m.state("scans") >= scans + 5,
        "5 more scans (or a STOP)",
        timeout=2,
    )
    assert client.cpu is not None
    assert client.cpu["mode"] == "RUN", client.cpu
    assert error["type"] == "error", error
    assert error["code"] == "MON603"
    _carries_on(live, client)


@pytest.mark.parametrize(
    ("kind", "address"), [("set_input", "I9999.0"), ("force", "I9999.0"), ("force", "Q9999.0")]
)
def test_driving_an_io_bit_beyond_the_cpus_image_is_mon603(
    live: LiveServer, client: Monitor, kind: str, address: str
) -> None:
    """The S7-300's process images are 2048 bytes: I9999.0 does not exist."""
    error = client.request(kind, address=address, value=True)
    assert error["type"] == "error", error
    assert error["code"] == "MON603", error
    client.drain(0.05)
    assert client.cpu is not None
    assert client.cpu["forced"] == []
    _carries_on(live, client)


def test_unknown_blocks_are_mon613(live: LiveServer, client: Monitor) -> None:
    client.fails("open_block", "MON613", block="FC99")
    client.fails("set_breakpoint", "MON613", location={"block": "FB7", "instruction": 0})
    _carries_on(live, client)


def test_bad_values_are_mon606(live: LiveServer, client: Monitor) -> None:
    client.fails("modify", "MON606", target="MW10", value="lots")
    client.fails("modify", "MON606", target="MW10", value=70000)
    client.fails("modify", "MON606", target="MW10", value=None)
    client.fails("set_input", "MON606", address="I0.0", value=2)
    _carries_on(live, client)


# -- breakpoints where there is no code ---------------------------------------------------------


def test_a_breakpoint_on_a_line_without_code_is_mon604_naming_the_next_line(
    live: LiveServer,
    client: Monitor,
) -> None:
    blank = line_of(LOOP_PROGRAM, "TITLE = add")  # FC1's network title
    code = line_of(LOOP_PROGRAM, "L     MW    10")
    error = client.fails("set_breakpoint", "MON604", location={"file": "prog.awl", "line": blank})
    assert f"the next line with code is {code}" in error["message"], error
    assert error["params"]["next_line"] == code  # for the editor's "move it there"
    assert f"line {blank}" in error["message"]
    # Past the last line with code there is no next line to name.
    last = len(LOOP_PROGRAM.splitlines())
    error = client.fails("set_breakpoint", "MON604", location={"file": "prog.awl", "line": last})
    assert "next line" not in error["message"]
    client.fails("set_breakpoint", "MON604", location={"file": "other.awl", "line": code})
    client.fails("set_breakpoint", "MON604", location={"block": "FC1", "network": 9})
    client.fails("set_breakpoint", "MON604", location={"block": "FC1", "instruction": 99})
    client.fails("set_breakpoint", "MON604", location={"block": "FC1"})
    _carries_on(live, client)


def test_an_scl_breakpoint_on_a_blank_line_names_the_next_statement(live: LiveServer) -> None:
    session_id = live.create([source("calc.scl", CALC_SCL)])["id"]
    try:
        with live.monitor(session_id) as scl:
            blank = line_of(CALC_SCL, "total := 0;") + 1
            assert CALC_SCL.splitlines()[blank - 1] == ""
            error = scl.fails(
                "set_breakpoint", "MON604", location={"file": "calc.scl", "line": blank}
            )
            nxt = line_of(CALC_SCL, "FOR i := 1 TO limit DO")
            assert f"the next line with code is {nxt}" in error["message"]
    finally:
        live.delete(session_id)


# -- limits -------------------------------------------------------------------------------------


def test_a_watch_of_thousands_of_entries_is_mon605(live: LiveServer, client: Monitor) -> None:
    entries = [f"MW{2 * k}" for k in range(5000)]
    client.send_raw(json.dumps({"type": "watch", "entries": entries, "ref": RAW_REF}))
    error = client.answer(RAW_REF)
    assert error["code"] == "MON605", error
    assert error["params"]["limit"] == client.hello["max_watch_entries"] == 500
    assert error["params"]["count"] == 5000
    client.fails("watch", "MON605", entries=entries[:501])
    assert len(client.ok("watch", entries=entries[:500])["entries"]) == 500
    client.fails("trend", "MON605", entries=entries[:33])
    assert len(client.ok("trend", entries=entries[:32])["entries"]) == 32
    client.ok("trend", entries=[])
    client.ok("watch", entries=["MW10"])
    _carries_on(live, client)


def test_a_seventeenth_socket_on_a_session_is_mon605(live: LiveServer, client: Monitor) -> None:
    others = [live.connect(client.session_id) for _ in range(15)]  # 16 with ``client``
    try:
        with connect(
            f"{live.ws_base}/api/sessions/{client.session_id}/ws", open_timeout=TIMEOUT
        ) as ws:
            error = json.loads(ws.recv(timeout=TIMEOUT))
            assert error["type"] == "error"
            assert error["code"] == "MON605"
            with pytest.raises(ConnectionClosed) as closed:
                ws.recv(timeout=TIMEOUT)
            assert closed.value.rcvd is not None
            assert closed.value.rcvd.code == 1008
        # The sixteen go on.
        others[-1].ok("subscribe_cpu")
    finally:
        for other in others:
            other.close()
    # Once one leaves, a new one is welcome.
    with live.monitor(client.session_id) as again:
        again.ok("subscribe_cpu")
    _carries_on(live, client)


# -- commands the CPU's state does not allow ----------------------------------------------------


def test_commands_the_cpu_state_does_not_allow_are_mon607(
    live: LiveServer, client: Monitor
) -> None:
    client.fails("continue", "MON607")  # running, not held, not paused
    client.fails("modify", "MON607", target="#n", value=1)  # locals only at a hold
    client.fails("clear_breakpoint", "MON607", id=42)
    client.ok("stop")
    client.until_mode("STOP")
    client.fails("continue", "MON607")
    client.fails("step", "MON607", by="instruction")
    client.fails("run_scans", "MON607", count=5)
    client.ok("run")
    client.until_mode("RUN")
    _carries_on(live, client)


# -- a client that never reads ------------------------------------------------------------------


class _RawSocket:
    """A WebSocket client by hand, with a tiny receive buffer, that reads only when asked."""

    def __init__(self, live: LiveServer, session_id: str) -> None:
        self.sock = socket.socket()
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        self.sock.settimeout(TIMEOUT)
        self.sock.connect(("127.0.0.1", live.port))
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall(
            (
                f"GET /api/sessions/{session_id}/ws HTTP/1.1\r\n"
                f"Host: 127.0.0.1:{live.port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n"
            ).encode()
        )
        head = b""
        while b"\r\n\r\n" not in head:
            head += self._exactly(1)
        assert head.startswith(b"HTTP/1.1 101"), head

    def _exactly(self, count: int) -> bytes:
        data = b""
        while len(data) < count:
            chunk = self.sock.recv(count - len(data))
            if not chunk:
                raise EOFError("the server closed the connection")
            data += chunk
        return data

    def receive(self) -> tuple[int, bytes]:
        first, second = self._exactly(2)
        size = second & 0x7F
        if size == 126:
            size = struct.unpack(">H", self._exactly(2))[0]
        elif size == 127:
            size = struct.unpack(">Q", self._exactly(8))[0]
        return first & 0x0F, self._exactly(size)

    def send(self, message: dict[str, Any]) -> None:
        data = json.dumps(message).encode()
        mask = os.urandom(4)
        if len(data) < 126:
            head = bytes([0x81, 0x80 | len(data)])
        else:
            head = bytes([0x81, 0x80 | 126]) + struct.pack(">H", len(data))
        self.sock.sendall(head + mask + bytes(b ^ mask[k % 4] for k, b in enumerate(data)))

    def close(self) -> None:
        self.sock.close()


def test_a_client_that_never_reads_is_dropped_and_nobody_else_notices() -> None:
    with running_server(slow_client_seconds=1) as live:
        slow_session = live.create_stl(COUNTER_PROGRAM, name="counter.awl")
        other_session = live.create_stl()
        raw = _RawSocket(live, slow_session)
        try:
            opcode, payload = raw.receive()
            hello = json.loads(payload)
            assert hello["type"] == "hello"
            client_id = hello["client"]
            session = live.session(slow_session)
            assert client_id in session.clients
            entries = ["MD0", "MD4", *[f"MB{100 + k}" for k in range(30)]]
            for ref, message in enumerate(
                [
                    {"type": "watch", "entries": entries},
                    {"type": "trend", "entries": entries},
                    {"type": "subscribe_cpu"},
                    {"type": "set_time", "mode": "fast"},
                    {"type": "run"},
                ],
                start=1,
            ):
                raw.send({**message, "ref": ref})

            # From now on the raw client reads nothing. Another client on another session
            # keeps getting its frames, and the server keeps answering.
            with live.monitor(other_session) as other:
                other.ok("subscribe_cpu")
                other.ok("run")
                began = time.monotonic()
                while client_id in session.clients:
                    assert time.monotonic() - began < 20, "the slow client was never dropped"
                    scans = other.until_scans(1)["scans"]
                    other.until_scans(scans + 2, timeout=2)
                    assert live.http.get("/api/health").status_code == 200
                scans = other.cpu["scans"] if other.cpu else 0
                other.until_scans(scans + 5, timeout=2)
                assert live.http.get("/api/health").status_code == 200
            # The slow session itself runs on (fast), without its client.
            counted = session.cpu.scans
            wait_for(lambda: session.cpu.scans > counted + 100, "the slow session to run on")

            # What the dropped client finds when it finally reads: frames, then the close
            # with MON608 (policy violation 1008), or a connection already gone.
            raw.sock.settimeout(TIMEOUT)
            close: tuple[int, bytes] | None = None
            try:
                while close is None:
                    opcode, payload = raw.receive()
                    if opcode == 0x8:
                        close = struct.unpack(">H", payload[:2])[0], payload[2:]
            except (EOFError, ConnectionResetError):
                pass
            if close is not None:
                assert close[0] == 1008
                assert b"did not read" in close[1]
        finally:
            raw.close()

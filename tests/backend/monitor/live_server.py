"""A real Nasaq server on a free localhost port, in a thread, and monitoring clients for it.

The socket tests talk to the server the way the IDE does: HTTP for the sessions, one WebSocket
per client. ``LiveServer`` runs uvicorn (lifespan included) in a daemon thread; ``Monitor`` wraps
one WebSocket and keeps what its frames said (frames carry only changes, so the client merges
them, as the front end does). Every wait has a deadline, so a broken server fails a test rather
than hanging it.
"""

from __future__ import annotations

import itertools
import json
import socket
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import httpx2
import uvicorn
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import ClientConnection, connect

from nasaq.api.app import create_app
from nasaq.settings import Settings

TIMEOUT = 5.0  # seconds any single wait may take before the test fails

# -- programs the tests download ----------------------------------------------------------------

# OB1 calls FC1 three times from a LOOP; FC1 adds its input ``step`` to MW10 through a temp.
# OB1 also copies I0.0 to Q0.0. Each scan ends with MW10 = 3 * 2 = 6.
LOOP_PROGRAM = """\
FUNCTION FC 1 : VOID
TITLE = add one
VAR_INPUT
  step : INT;
END_VAR
VAR_TEMP
  t : INT;
END_VAR
BEGIN
NETWORK
TITLE = add
      L     MW    10;
      L     #step;
      +I    ;
      T     #t;
      L     #t;
      T     MW    10;
END_FUNCTION

ORGANIZATION_BLOCK OB 1
VAR_TEMP
  info : ARRAY[0..19] OF BYTE;
  n : INT;
END_VAR
BEGIN
NETWORK
TITLE = lamp
      A     I      0.0;
      =     Q      0.0;
NETWORK
TITLE = loop
      L     0;
      T     MW    10;
      L     3;
next: T     #n;
      CALL FC 1 (step := 2);
      L     #n;
      LOOP  next;
END_ORGANIZATION_BLOCK
"""


# OB1 of the plant: network 1 counts the scans in the instance DB5 of FB1, network 2 copies
# DB1.level to MW20 and counts the scans in MW30 too, network 3 is bit logic on M1.0/M1.1.
# OB100 (warm restart) sets M1.0. After scan n, MW30 = DB5.count = n.
PLANT_PROGRAM = """\
DATA_BLOCK DB 1
  STRUCT
    level : INT := 5;
    speed : REAL := 1.5;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

FUNCTION_BLOCK FB 1
VAR_INPUT
  inc : INT;
END_VAR
VAR
  count : INT;
END_VAR
BEGIN
NETWORK
TITLE = count
      L     #count;
      L     #inc;
      +I    ;
      T     #count;
END_FUNCTION_BLOCK

DATA_BLOCK DB 5
  FB 1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 100
BEGIN
NETWORK
      SET   ;
      =     M      1.0;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = count scans
      CALL FB 1 , DB 5 (inc := 1);
NETWORK
TITLE = copy level
      L     DB1.DBW    0;
      T     MW    20;
      L     MW    30;
      +     1;
      T     MW    30;
NETWORK
TITLE = logic
      A     M      1.0;
      AN    M      1.1;
      =     M      1.2;
END_ORGANIZATION_BLOCK
"""

PLANT_SYMBOLS = """\
"Lamp","Q 0.0","BOOL","the lamp"
"Counter","MW 30","INT","scans counted by OB1"
"Tank","DB 1","DB 1","tank data"
"Start","I 0.0","BOOL","start button"
"""

# SCL: FB2 sums 1..limit in a FOR loop into its static ``total`` and counts its runs; FC3
# squares its input into a temp and returns the square + 1. OB1: MW40 = 2 * total (20),
# MW42 = FC3(total) (101).
CALC_SCL = """\
FUNCTION_BLOCK FB2
VAR_INPUT
  limit : INT;
END_VAR
VAR
  total : INT;
  runs : INT;
END_VAR
VAR_TEMP
  i : INT;
END_VAR
BEGIN
  total := 0;

  FOR i := 1 TO limit DO
    total := total + i;
  END_FOR;
  runs := runs + 1;
END_FUNCTION_BLOCK

DATA_BLOCK DB2 FB2
BEGIN
END_DATA_BLOCK

FUNCTION FC3 : INT
VAR_INPUT
  a : INT;
END_VAR
VAR_TEMP
  sq : INT;
END_VAR
BEGIN
  sq := a * a;
  FC3 := sq + 1;
END_FUNCTION

ORGANIZATION_BLOCK OB1
VAR_TEMP
  x : INT;
  y : INT;
END_VAR
BEGIN
  FB2.DB2(limit := 4);
  x := DB2.total;
  y := FC3(a := x);
  MW40 := INT_TO_WORD(x * 2);
  MW42 := INT_TO_WORD(y);
END_ORGANIZATION_BLOCK
"""

# Network 2 reads beyond the end of DB3 (2 bytes long): an area length error, the CPU goes to
# STOP in its first scan.
AREA_ERROR_PROGRAM = """\
DATA_BLOCK DB 3
  STRUCT
    a : INT;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = fine
      L     1;
      T     MW     2;
NETWORK
TITLE = too far
      L     DB3.DBW   10;
      T     MW     4;
END_ORGANIZATION_BLOCK
"""

# MD0 counts scans, MD4 = MD0 + 3: values that change in every scan.
COUNTER_PROGRAM = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      L     MD     0;
      +     L#1;
      T     MD     0;
      +     L#3;
      T     MD     4;
END_ORGANIZATION_BLOCK
"""


def line_of(text: str, needle: str, occurrence: int = 1) -> int:
    """The 1-based number of the line of ``text`` holding ``needle`` (its n-th occurrence)."""
    hits = [k + 1 for k, line in enumerate(text.splitlines()) if needle in line]
    assert len(hits) >= occurrence, f"{needle!r} is not in the program {occurrence} times"
    return hits[occurrence - 1]


def source(name: str, text: str) -> dict[str, str]:
    return {"name": name, "text": text}


def plant_sources() -> list[dict[str, str]]:
    return [source("plant.awl", PLANT_PROGRAM), source("plant.sdf", PLANT_SYMBOLS)]


# -- the server ---------------------------------------------------------------------------------


class LiveServer:
    """uvicorn serving ``create_app(settings)`` on 127.0.0.1 until ``stop``."""

    def __init__(self, settings: Settings) -> None:
        self.settings = settings
        self.app = create_app(settings)
        # uvicorn serves on this socket, bound here: no race for a free port.
        self.socket = socket.socket()
        self.socket.bind(("127.0.0.1", 0))
        self.port: int = self.socket.getsockname()[1]
        self.base = f"http://127.0.0.1:{self.port}"
        self.ws_base = f"ws://127.0.0.1:{self.port}"
        config = uvicorn.Config(
            self.app, host="127.0.0.1", port=self.port, log_level="warning", lifespan="on"
        )
        self.server = uvicorn.Server(config)
        self.thread = threading.Thread(
            target=self.server.run,
            kwargs={"sockets": [self.socket]},
            name="live-uvicorn",
            daemon=True,
        )
        self.http = httpx2.Client(base_url=self.base, timeout=TIMEOUT)

    def start(self) -> LiveServer:
        self.thread.start()
        wait_for(
            lambda: self.server.started or not self.thread.is_alive(),
            what="the server to start",
            timeout=10,
        )
        assert self.server.started, "the server did not start (see its log)"
        return self

    def stop(self) -> None:
        self.http.close()
        self.server.should_exit = True
        self.thread.join(timeout=15)
        self.socket.close()
        assert not self.thread.is_alive(), "the server did not stop"

    # REST helpers -------------------------------------------------------------------------------
    def create(self, sources: list[dict[str, str]], **options: Any) -> dict[str, Any]:
        """POST /api/sessions; asserts 201 and returns the session."""
        response = self.http.post("/api/sessions", json={"sources": sources, **options})
        assert response.status_code == 201, response.text
        body: dict[str, Any] = response.json()
        return body

    def create_stl(self, text: str = LOOP_PROGRAM, name: str = "prog.awl", **options: Any) -> str:
        return str(self.create([source(name, text)], **options)["id"])

    def delete(self, session_id: str) -> None:
        response = self.http.delete(f"/api/sessions/{session_id}")
        assert response.status_code in (204, 404), response.text

    def session(self, session_id: str) -> RemoteSession:
        """The session as the REST API shows it (it runs in a worker process)."""
        return RemoteSession(self, session_id)

    def connect(self, session_id: str, **options: Any) -> Monitor:
        return Monitor(self, session_id, **options)

    @contextmanager
    def monitor(self, session_id: str, **options: Any) -> Iterator[Monitor]:
        client = self.connect(session_id, **options)
        try:
            yield client
        finally:
            client.close()


class RemoteSession:
    """Reads a session's state through ``GET /api/sessions/{id}`` on each access."""

    def __init__(self, live: LiveServer, session_id: str) -> None:
        self.live = live
        self.session_id = session_id

    def _info(self) -> dict[str, Any]:
        response = self.live.http.get(f"/api/sessions/{self.session_id}")
        assert response.status_code == 200, response.text
        found: dict[str, Any] = response.json()
        return found

    @property
    def clients(self) -> list[int]:
        return list(self._info()["clients"])

    @property
    def cpu(self) -> SimpleNamespace:
        return SimpleNamespace(**self._info()["cpu"])


@contextmanager
def running_server(**settings: Any) -> Iterator[LiveServer]:
    """A started server with its own data folder; ``settings`` override the defaults (e.g.
    ``max_sessions=2``, ``slow_client_seconds=1``)."""
    with tempfile.TemporaryDirectory(prefix="nasaq-live-") as folder:
        root = Path(folder)
        live = LiveServer(
            Settings(data_dir=root / "data", frontend_dist=root / "no-dist", **settings)
        ).start()
        try:
            yield live
        finally:
            live.stop()


def wait_for(
    condition: Callable[[], Any], what: str, timeout: float = TIMEOUT, interval: float = 0.01
) -> Any:
    """Polls ``condition`` until it returns something truthy; fails after ``timeout``."""
    deadline = time.monotonic() + timeout
    while True:
        result = condition()
        if result:
            return result
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(interval)


# -- a monitoring client ------------------------------------------------------------------------


class Monitor:
    """One WebSocket client. ``cpu``, ``watch``, ``block``, ``hold``, ``trend`` and
    ``diagnostics`` hold what the frames received so far said."""

    def __init__(self, live: LiveServer, session_id: str, **options: Any) -> None:
        self.live = live
        self.session_id = session_id
        self._exit = ExitStack()
        self.ws: ClientConnection = self._exit.enter_context(
            connect(
                f"{live.ws_base}/api/sessions/{session_id}/ws",
                open_timeout=TIMEOUT,
                close_timeout=2,
                **options,
            )
        )
        self._refs = itertools.count(1)
        self.answers: dict[int, dict[str, Any]] = {}
        self.unsolicited: list[dict[str, Any]] = []  # errors without a ref
        self.frames: list[dict[str, Any]] = []
        self.cpu: dict[str, Any] | None = None
        self.watch: dict[str, dict[str, Any]] = {}
        self.block: dict[str, Any] | None = None
        self.hold: dict[str, Any] | None = None
        self.released = 0
        self.trend: list[dict[str, Any]] = []
        self.diagnostics: list[dict[str, Any]] = []
        self.hello = self.receive()
        assert self.hello["type"] == "hello", self.hello
        self.client_id: int = self.hello["client"]

    def close(self) -> None:
        self._exit.close()

    # receiving ----------------------------------------------------------------------------------
    def receive(self, timeout: float = TIMEOUT) -> dict[str, Any]:
        """The next message, merged into this client's state."""
        raw = self.ws.recv(timeout=timeout)
        assert isinstance(raw, str), f"the server sent a binary frame: {raw!r}"
        message: dict[str, Any] = json.loads(raw)
        kind = message.get("type")
        if kind == "frame":
            self._merge(message)
        elif kind in ("ack", "error"):
            ref = message.get("ref")
            if ref is None:
                self.unsolicited.append(message)
            else:
                self.answers[ref] = message
        return message

    def _replaced(self, kind: str) -> None:
        """A new watch list, trend list or open block replaces the old one: forget what the
        frames said about the old one. (Frames already on their way may still bring some.)"""
        if kind == "watch":
            self.watch = {}
        elif kind == "trend":
            self.trend = []
        elif kind == "open_block":
            self.block = None

    def _merge(self, frame: dict[str, Any]) -> None:
        self.frames.append(frame)
        if frame.get("cpu") is not None:
            self.cpu = frame["cpu"]
        if frame.get("watch"):
            self.watch.update(frame["watch"])
        if frame.get("block") is not None:
            self.block = frame["block"]
        if frame.get("released"):
            self.hold = None
            self.released += 1
        if frame.get("hold") is not None:
            self.hold = frame["hold"]
        if frame.get("trend"):
            self.trend.extend(frame["trend"])
        if frame.get("diagnostics"):
            self.diagnostics.extend(frame["diagnostics"])

    def until(
        self, condition: Callable[[Monitor], Any], what: str, timeout: float = TIMEOUT
    ) -> Any:
        """Receives until ``condition(self)`` is truthy (checked first); returns its result."""
        deadline = time.monotonic() + timeout
        while True:
            result = condition(self)
            if result:
                return result
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError(
                    f"timed out after {timeout} s waiting for {what}; cpu={self.cpu} "
                    f"hold={_short(self.hold)} watch={_short(self.watch)}"
                )
            try:
                self.receive(timeout=left)
            except TimeoutError:
                continue

    def state(self, field: str) -> Any:
        """A field of the CPU state the frames showed last (None before the first)."""
        return None if self.cpu is None else self.cpu[field]

    def value(self, entry: str) -> Any:
        return self.watch[entry]["value"] if entry in self.watch else None

    def until_value(self, entry: str, expected: Any, timeout: float = TIMEOUT) -> None:
        self.until(
            lambda m: entry in m.watch and m.watch[entry]["value"] == expected,
            f"{entry} = {expected!r}",
            timeout,
        )

    def until_mode(self, mode: str, timeout: float = TIMEOUT) -> dict[str, Any]:
        state: dict[str, Any] = self.until(
            lambda m: m.cpu if m.cpu is not None and m.cpu["mode"] == mode else None,
            f"CPU mode {mode}",
            timeout,
        )
        return state

    def until_held(self, timeout: float = TIMEOUT) -> dict[str, Any]:
        held: dict[str, Any] = self.until(lambda m: m.hold, "a hold", timeout)
        return held

    def until_scans(self, scans: int, timeout: float = TIMEOUT) -> dict[str, Any]:
        state: dict[str, Any] = self.until(
            lambda m: m.cpu if m.cpu is not None and m.cpu["scans"] >= scans else None,
            f"{scans} scans",
            timeout,
        )
        return state

    def drain(self, seconds: float) -> None:
        """Receives (and merges) whatever arrives during ``seconds``."""
        deadline = time.monotonic() + seconds
        while (left := deadline - time.monotonic()) > 0:
            try:
                self.receive(timeout=left)
            except TimeoutError:
                break

    def local(self, name: str) -> Any:
        """The value of a local variable of the held block, as the hold shows it."""
        assert self.hold is not None, "the CPU does not hold"
        found = [v["value"] for v in self.hold["locals"] if v["name"] == name]
        assert found, f"{name} is not among the locals {self.hold['locals']}"
        return found[0]

    def step(self, by: str, into: bool = False) -> dict[str, Any]:
        """Steps from a hold (or a running CPU) and returns the hold the step ends in."""
        before = None
        if self.hold is not None and self.cpu is not None:
            before = (self.hold["location"], self.cpu["scans"])

        def moved(m: Monitor) -> dict[str, Any] | None:
            hold = m.hold
            if hold is None or hold["reason"] != "step" or m.cpu is None:
                return None
            return hold if (hold["location"], m.cpu["scans"]) != before else None

        self.ok("step", by=by, into=into)
        held: dict[str, Any] = self.until(moved, f"the step by {by} to end in a hold")
        return held

    # sending ------------------------------------------------------------------------------------
    def send(self, kind: str, **fields: Any) -> int:
        ref = next(self._refs)
        self._replaced(kind)
        self.ws.send(json.dumps({"type": kind, "ref": ref, **fields}))
        return ref

    def send_raw(self, data: str | bytes) -> None:
        self.ws.send(data)

    def answer(self, ref: int, timeout: float = TIMEOUT) -> dict[str, Any]:
        found: dict[str, Any] = self.until(
            lambda m: m.answers.get(ref), f"the answer to ref {ref}", timeout
        )
        return found

    def request(self, kind: str, **fields: Any) -> dict[str, Any]:
        """Sends a message and returns its ack or error."""
        return self.answer(self.send(kind, **fields))

    def ok(self, kind: str, **fields: Any) -> Any:
        """Sends a message, asserts it is acknowledged, returns the ack's result."""
        answer = self.request(kind, **fields)
        assert answer["type"] == "ack", f"{kind} {fields}: {answer}"
        return answer["result"]

    def fails(self, kind: str, code: str, **fields: Any) -> dict[str, Any]:
        """Sends a message and asserts the server answers it with error ``code``."""
        answer = self.request(kind, **fields)
        assert answer["type"] == "error", f"{kind} {fields} was accepted: {answer}"
        assert answer["code"] == code, answer
        return answer

    def next_unsolicited(self, timeout: float = TIMEOUT) -> dict[str, Any]:
        """The next error that carries no ref (answers to messages the server could not read)."""
        count = len(self.unsolicited)
        self.until(lambda m: len(m.unsolicited) > count, "an error without ref", timeout)
        return self.unsolicited[count]

    def closed(self, timeout: float = TIMEOUT) -> ConnectionClosed:
        """Reads until the server closes the connection; returns how it closed."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                self.receive(timeout=max(0.01, deadline - time.monotonic()))
            except TimeoutError:
                continue
            except ConnectionClosed as closed:
                return closed
        raise AssertionError(f"the server did not close the connection within {timeout} s")


def _short(value: object, limit: int = 400) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit] + "..."

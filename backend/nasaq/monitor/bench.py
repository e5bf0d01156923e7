"""Monitoring benchmark: ``python -m nasaq.monitor.bench [--quick]``.

Prints three figures, each with its target (the report exits 0 when a target is missed; it
exits 1 only when something breaks: the server does not start, a session gets no frames):

(a) latency from ``set_input`` to the first frame that shows the changed output: one session
    at a 10 ms cycle (virtual time), one client watching ``Q0.0``, p50/p95 over 200 toggles.
    The server is ``uvicorn`` in a subprocess; this process is the client.
(b) 100 sessions, each running an OB1 of 1,000 STL instructions (executed per scan) at a 10 ms
    cycle with one WebSocket subscriber (CPU state + a few watched values): the scan rate each
    session achieves (from ``cpu.scans``) and the frames each subscriber receives per second,
    over 10 s after a warm-up. One asyncio client process serves the 100 sockets.
(c) the slowdown of a CPU running flat out (time mode ``fast``) while a client monitors its open
    block, against the same CPU unmonitored (in-process: a ``Session`` and a thread that builds
    the frames as a connection would); the same with a breakpoint that never fires (every block
    runs instrumented) as an informational figure.

``--quick`` runs a short version of all three (a smoke test for the test suite).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import math
import os
import random
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from fastapi import FastAPI
    from websockets.asyncio.client import ClientConnection


CYCLE_MS = 10.0
INSTRUCTIONS = 1000
LATENCY_P95_TARGET_MS = 30.0
SCAN_RATE_TARGET = 1000.0 / CYCLE_MS  # scans/s: the session keeps its cycle
SCAN_RATE_TOLERANCE = 0.99  # measured over a window: allow 1 % for the window's edges
FRAMES_TARGET = 10.0  # frames/s per subscriber
SLOWDOWN_TARGET = 3.0
WATCHED = ["Q0.0", "MW100", "MW102", "DB1.DBW2", "M0.2"]
PARENT_ENV = "NASAQ_MONITOR_BENCH_PARENT"
TOGGLE_TIMEOUT_S = 5.0
BUSY_WARNING = 0.3  # cores busy before the bench starts: other work competes for the CPUs


class BenchError(Exception):
    """Something broke: the figures cannot be measured."""


@dataclass(frozen=True, slots=True)
class Plan:
    toggles: int
    sessions: int
    warmup_s: float
    window_s: float
    phase_s: float
    settle_s: float


FULL = Plan(toggles=200, sessions=100, warmup_s=3.0, window_s=10.0, phase_s=5.0, settle_s=1.0)
QUICK = Plan(toggles=20, sessions=8, warmup_s=1.0, window_s=2.0, phase_s=1.0, settle_s=0.3)


# -- the program ----------------------------------------------------------------------------------


def program_source(instructions: int = INSTRUCTIONS) -> str:
    """STL source of DB1 and an OB1 that executes exactly ``instructions`` instructions per scan:
    bit logic (A/AN/O/=/S/R on I, Q, M), word loads, transfers, compares and INT arithmetic on MW
    and DB1 words, and branches whose two paths have the same length. ``I0.0`` drives ``Q0.0``
    (the first network, for the latency figure); ``MW100`` counts the scans."""
    networks: list[tuple[str, list[str]]] = [
        ("lamp", ["A     I      0.0", "=     Q      0.0"]),
        ("scan counter", ["L     MW   100", "L     1", "+I", "T     MW   100"]),
    ]
    count = sum(len(code) for _, code in networks)
    makers = (_bits, _latch, _compare, _math, _branch, _divide)
    k = 0
    while True:
        title, code, executed = makers[k % len(makers)](k)
        if count + executed > instructions:
            break
        networks.append((title, code))
        count += executed
        k += 1
    pad: list[str] = []
    while count + 2 <= instructions:
        pad += [f"A     M  {60 + k % 4}.{k % 8}", f"=     M  {56 + k % 4}.{k % 8}"]
        count += 2
        k += 1
    if count < instructions:
        pad.append("NOP   0")
        count += 1
    if pad:
        networks.append(("padding", pad))
    lines = [
        "DATA_BLOCK DB 1",
        "  STRUCT",
        "    w : ARRAY[0..63] OF INT;",
        "  END_STRUCT",
        "BEGIN",
        "END_DATA_BLOCK",
        "",
        "ORGANIZATION_BLOCK OB 1",
        "TITLE = monitor bench",
        "VAR_TEMP",
        "  info : ARRAY[0..19] OF BYTE;",
        "END_VAR",
        "BEGIN",
    ]
    for title, code in networks:
        lines += ["NETWORK", f"TITLE = {title}"]
        lines += [_statement(line) for line in code]
    lines.append("END_ORGANIZATION_BLOCK")
    return "\n".join(lines) + "\n"


def _statement(line: str) -> str:
    label, sep, rest = line.partition(":")
    if sep:
        return f"{label + ':':6s}{rest.strip()};"
    return f"      {line};"


def _ibit(k: int) -> str:
    return f"I  {k % 8}.{(k * 3 + 1) % 8}"


def _mbit(k: int) -> str:
    return f"M  {k % 48}.{(k * 5 + 2) % 8}"


def _qbit(k: int) -> str:
    return f"Q  {1 + k % 7}.{(k * 7) % 8}"


def _mw(k: int) -> str:
    return f"MW {104 + 2 * (k % 48)}"


def _dbw(k: int) -> str:
    return f"DB1.DBW {2 * (k % 64)}"


def _bits(k: int) -> tuple[str, list[str], int]:
    code = [f"A     {_ibit(k)}", f"AN    {_ibit(k + 1)}", f"O     {_mbit(k)}", f"=     {_qbit(k)}"]
    return "bit logic", code, 4


def _latch(k: int) -> tuple[str, list[str], int]:
    code = [
        f"A     {_ibit(k + 2)}",
        f"A     {_mbit(k + 1)}",
        f"S     {_mbit(k + 2)}",
        f"A     {_ibit(k + 3)}",
        f"AN    {_mbit(k + 3)}",
        f"R     {_mbit(k + 2)}",
    ]
    return "latch", code, 6


def _compare(k: int) -> tuple[str, list[str], int]:
    code = [
        f"L     {_mw(k)}",
        f"L     {_dbw(k)}",
        ">I" if k % 2 else "<>I",
        f"=     {_mbit(k + 4)}",
        f"A     {_mbit(k + 4)}",
        f"=     {_qbit(k + 1)}",
    ]
    return "compare", code, 6


def _math(k: int) -> tuple[str, list[str], int]:
    code = [
        f"L     {_mw(k)}",
        f"L     {_dbw(k + 1)}",
        "+I",
        f"T     {_mw(k + 1)}",
        f"L     {_mw(k + 1)}",
        "L     3",
        "*I",
        f"T     {_dbw(k + 2)}",
    ]
    return "integer math", code, 8


def _branch(k: int) -> tuple[str, list[str], int]:
    # Both paths run 3 instructions between the JC and the label y<k>: 11 in all, every scan.
    code = [
        "L     MW   100",
        f"L     {(k * 37) % 1000}",
        "<I",
        f"JC    x{k:03d}",
        "L     1",
        f"T     {_mw(k + 2)}",
        f"JU    y{k:03d}",
        f"x{k:03d}: L     2",
        f"T     {_mw(k + 2)}",
        "NOP   0",
        f"y{k:03d}: L     {_mw(k + 2)}",
        f"L     {_dbw(k + 3)}",
        "-I",
        f"T     {_dbw(k + 3)}",
    ]
    return "branch", code, 11


def _divide(k: int) -> tuple[str, list[str], int]:
    code = [f"L     {_dbw(k + 4)}", f"L     {3 + k % 5}", "/I", "T     MW   102"]
    return "division", code, 4


def executed_per_scan(source: str, scans: int = 5) -> int:
    """Compiles ``source`` and runs a few scans: the instructions each scan executed (they must
    all be the same)."""
    from nasaq.cpu import Cpu, Profile
    from nasaq.monitor.download import compile_download

    program = compile_download(_sources(source))
    cpu = Cpu(program, Profile.S7_300, CYCLE_MS)
    cpu.start()
    counts = set()
    for _ in range(scans):
        before = cpu.instructions_executed
        cpu.scan()
        counts.add(cpu.instructions_executed - before)
    if cpu.mode != "RUN":
        raise BenchError(f"the bench program stopped the CPU: {cpu.stop_reason}")
    if len(counts) != 1:
        raise BenchError(f"the bench program executes a varying count per scan: {sorted(counts)}")
    return counts.pop()


def _sources(source: str) -> list[Any]:
    from nasaq.lang.stl import SourceFile

    return [SourceFile(name="bench.awl", text=source)]


# -- the server process ---------------------------------------------------------------------------


def server_app() -> FastAPI:
    """The uvicorn app factory of the server subprocess (settings from ``NASAQ_*``). It exits
    when the bench that started it is gone, however the bench ended."""
    from nasaq.api.app import create_app
    from nasaq.settings import Settings

    parent = os.environ.get(PARENT_ENV)
    if parent is not None:
        threading.Thread(target=_exit_with_parent, args=(int(parent),), daemon=True).start()
    return create_app(Settings())


def _exit_with_parent(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(0.5)
    os._exit(3)


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port: int = probe.getsockname()[1]
        return port


@contextmanager
def running_server(
    max_sessions: int, app: str = "nasaq.monitor.bench:server_app"
) -> Iterator[Server]:
    """``python -m uvicorn`` serving the app factory ``app`` in a subprocess with a fresh data
    folder; terminated on leaving."""
    import httpx2

    with tempfile.TemporaryDirectory(prefix="nasaq-monitor-bench-") as folder:
        root = Path(folder)
        port = _free_port()
        package_root = str(Path(__file__).resolve().parents[2])
        env = dict(os.environ)
        env.update(
            {
                "NASAQ_DATA_DIR": str(root / "data"),
                "NASAQ_MAX_SESSIONS": str(max_sessions),
                "NASAQ_LOG_LEVEL": "warning",
                "NASAQ_SESSION_IDLE_SECONDS": "3600",
                PARENT_ENV: str(os.getpid()),
                "PYTHONPATH": os.pathsep.join(
                    p for p in (package_root, env.get("PYTHONPATH")) if p
                ),
            }
        )
        command = [
            sys.executable,
            "-m",
            "uvicorn",
            app,
            "--factory",
            "--host",
            "127.0.0.1",
            "--port",
            str(port),
            "--log-level",
            "warning",
            "--no-access-log",
        ]
        log_path = root / "server.log"
        with open(log_path, "wb") as log:
            process = subprocess.Popen(
                command, cwd=root, env=env, stdout=log, stderr=subprocess.STDOUT
            )
        server = Server(process, f"http://127.0.0.1:{port}", f"ws://127.0.0.1:{port}", log_path)
        try:
            deadline = time.monotonic() + 60.0
            with httpx2.Client(trust_env=False, timeout=2.0) as http:
                while True:
                    if process.poll() is not None:
                        raise BenchError(
                            f"the server exited with {process.returncode}:\n{server.log_tail()}"
                        )
                    try:
                        if http.get(server.http + "/api/health").status_code == 200:
                            break
                    except httpx2.TransportError:
                        pass
                    if time.monotonic() > deadline:
                        raise BenchError(f"the server did not start in 60 s:\n{server.log_tail()}")
                    time.sleep(0.1)
            yield server
        finally:
            server.stop()


@dataclass
class Server:
    process: subprocess.Popen[bytes]
    http: str
    ws: str
    log_path: Path

    def log_tail(self, lines: int = 30) -> str:
        try:
            text = self.log_path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            return "(no server log)"
        return "\n".join(text.splitlines()[-lines:]) or "(empty server log)"

    def cpu_seconds(self) -> float | None:
        """User + system CPU seconds of the server process so far (Linux), else None."""
        try:
            fields = Path(f"/proc/{self.process.pid}/stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            return None
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def stop(self) -> None:
        process = self.process
        if process.poll() is None:
            process.terminate()
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait(timeout=10)


# -- (a) latency ----------------------------------------------------------------------------------


@dataclass
class Latency:
    samples_ms: list[float]

    def percentile(self, q: float) -> float:
        return percentile(self.samples_ms, q)


def percentile(values: Sequence[float], q: float) -> float:
    """Nearest-rank percentile (q in 0..100)."""
    ordered = sorted(values)
    if not ordered:
        return math.nan
    rank = max(1, math.ceil(q / 100 * len(ordered)))
    return ordered[rank - 1]


async def _create_session(http: Any, server: Server, source: str, mode: str = "virtual") -> str:
    response = await http.post(
        server.http + "/api/sessions",
        json={
            "sources": [{"name": "bench.awl", "text": source}],
            "cycle_ms": CYCLE_MS,
            "time_mode": mode,
        },
    )
    if response.status_code != 201:
        raise BenchError(f"POST /api/sessions: {response.status_code} {response.text[:300]}")
    session_id: str = response.json()["id"]
    return session_id


def _connect(server: Server, session_id: str) -> Any:
    from websockets.asyncio.client import connect

    # compression: like a browser, the client offers permessage-deflate.
    return connect(
        f"{server.ws}/api/sessions/{session_id}/ws",
        proxy=None,
        max_size=2**24,
        open_timeout=30,
        close_timeout=5,
    )


async def _send(ws: ClientConnection, message: dict[str, Any]) -> None:
    await ws.send(json.dumps(message))


async def _wait_output(ws: ClientConnection, address: str, expected: bool, timeout: float) -> None:
    deadline = time.perf_counter() + timeout
    while True:
        left = deadline - time.perf_counter()
        if left <= 0:
            raise BenchError(f"no frame showed {address} = {expected} within {timeout} s")
        try:
            raw = await asyncio.wait_for(ws.recv(), left)
        except TimeoutError:
            continue
        message = json.loads(raw)
        kind = message.get("type")
        if kind == "error":
            raise BenchError(f"the server answered with an error: {message}")
        if kind == "frame":
            found = (message.get("watch") or {}).get(address)
            if found is not None and found.get("value") is expected:
                return


async def measure_latency(server: Server, http: Any, source: str, toggles: int) -> Latency:
    session_id = await _create_session(http, server, source)
    rng = random.Random(20240611)
    samples: list[float] = []
    try:
        async with _connect(server, session_id) as ws:
            await _send(ws, {"type": "watch", "entries": ["Q0.0"], "ref": 1})
            await _send(ws, {"type": "set_input", "address": "I0.0", "value": 0, "ref": 2})
            await _send(ws, {"type": "run", "ref": 3})
            await _wait_output(ws, "Q0.0", False, 30.0)
            await asyncio.sleep(0.5)  # the first scans compiled the program
            for toggle in range(toggles):
                # A random pause puts the command at a random point of the 10 ms cycle.
                await asyncio.sleep(rng.uniform(0.0, 2 * CYCLE_MS / 1000))
                value = toggle % 2 == 0
                started = time.perf_counter()
                await _send(
                    ws,
                    {
                        "type": "set_input",
                        "address": "I0.0",
                        "value": int(value),
                        "ref": 10 + toggle,
                    },
                )
                await _wait_output(ws, "Q0.0", value, TOGGLE_TIMEOUT_S)
                samples.append((time.perf_counter() - started) * 1000)
    finally:
        await http.delete(f"{server.http}/api/sessions/{session_id}")
    return Latency(samples)


# -- (b) many sessions ----------------------------------------------------------------------------


@dataclass
class Subscriber:
    """One WebSocket on one session: subscribes to the CPU state and a few values, starts the
    CPU, and notes when each frame arrived and the scan count it showed."""

    session_id: str
    frames: list[float] = field(default_factory=list)  # perf_counter of each frame received
    scans: list[tuple[float, int]] = field(default_factory=list)  # frames with the CPU state
    errors: list[str] = field(default_factory=list)
    extensions: str = ""
    ready: asyncio.Event = field(default_factory=asyncio.Event)
    done: asyncio.Event = field(default_factory=asyncio.Event)

    async def run(self, server: Server) -> None:
        from websockets.exceptions import ConnectionClosed

        async with _connect(server, self.session_id) as ws:
            if ws.response is not None:
                self.extensions = ws.response.headers.get("Sec-WebSocket-Extensions", "")
            await _send(ws, {"type": "subscribe_cpu", "ref": 1})
            await _send(ws, {"type": "watch", "entries": WATCHED, "ref": 2})
            await _send(ws, {"type": "run", "ref": 3})
            try:
                while not self.done.is_set():
                    try:
                        raw = await asyncio.wait_for(ws.recv(), 0.5)
                    except TimeoutError:
                        continue
                    now = time.perf_counter()
                    message = json.loads(raw)
                    kind = message.get("type")
                    if kind == "frame":
                        self.frames.append(now)
                        cpu = message.get("cpu")
                        if cpu is not None and cpu.get("mode") == "RUN":
                            self.scans.append((now, int(cpu["scans"])))
                            self.ready.set()
                    elif kind == "error":
                        self.errors.append(str(raw)[:300])
            except ConnectionClosed as closed:
                if not self.done.is_set():
                    self.errors.append(f"connection closed: {closed}")

    def scan_rate(self, start: float, end: float) -> float:
        """Scans per second from the last frame at or before ``start`` to the first at or after
        ``end`` (or the last one received, if none came after ``end``); NaN without two."""
        before = [sample for sample in self.scans if sample[0] <= start]
        after = [sample for sample in self.scans if sample[0] >= end]
        first = before[-1] if before else None
        last = after[0] if after else (self.scans[-1] if self.scans else None)
        if first is None or last is None or last[0] <= first[0]:
            return math.nan
        return (last[1] - first[1]) / (last[0] - first[0])


@dataclass
class Load:
    sessions: int
    window_s: float
    scan_rates: list[float]
    frame_rates: list[float]
    cycle_avg_ms: list[float]
    server_cpu: float | None  # share of one core during the window
    client_cpu: float
    extensions: str
    rest_s: float  # how long GET /api/sessions took right after the window
    others: float | None  # cores other processes used during the window


async def _session_list(http: Any, server: Server, ids: set[str]) -> tuple[float, dict[str, Any]]:
    started = time.perf_counter()
    response = await http.get(server.http + "/api/sessions")
    took = time.perf_counter() - started
    if response.status_code != 200:
        raise BenchError(f"GET /api/sessions: {response.status_code}")
    return took, {s["id"]: s["cpu"] for s in response.json() if s["id"] in ids}


async def measure_load(server: Server, http: Any, source: str, plan: Plan) -> Load:
    limit = asyncio.Semaphore(4)

    async def create() -> str:
        async with limit:
            return await _create_session(http, server, source)

    ids = await asyncio.gather(*(create() for _ in range(plan.sessions)))
    subscribers = [Subscriber(session_id) for session_id in ids]
    tasks = [asyncio.create_task(s.run(server)) for s in subscribers]
    try:
        deadline = time.monotonic() + 60.0
        while not all(s.ready.is_set() for s in subscribers):
            for task, subscriber in zip(tasks, subscribers, strict=True):
                if task.done():
                    why = task.exception() or "; ".join(subscriber.errors) or "?"
                    raise BenchError(f"a subscriber ended before its first frame: {why!r}")
            if time.monotonic() > deadline:
                missing = sum(1 for s in subscribers if not s.ready.is_set())
                raise BenchError(f"{missing} of {plan.sessions} subscribers got no frame in 60 s")
            await asyncio.sleep(0.05)
        await asyncio.sleep(plan.warmup_s)
        start = time.perf_counter()
        server_before = server.cpu_seconds()
        client_before = time.process_time()
        system_before = system_busy_seconds()
        await asyncio.sleep(plan.window_s)
        end = time.perf_counter()
        server_after = server.cpu_seconds()
        client_cpu = (time.process_time() - client_before) / (end - start)
        system_after = system_busy_seconds()
        # Every session's rate ends at its first frame after the window (waiting at most 10 s).
        deadline = time.monotonic() + 10.0
        while time.monotonic() < deadline and not all(
            s.scans and s.scans[-1][0] >= end for s in subscribers
        ):
            await asyncio.sleep(0.05)
        rest_s, final = await _session_list(http, server, set(ids))
    finally:
        for s in subscribers:
            s.done.set()
        results = await asyncio.gather(*tasks, return_exceptions=True)
    for result in results:
        if isinstance(result, BaseException):
            raise BenchError(f"a subscriber failed: {result!r}")
    errors = [e for s in subscribers for e in s.errors]
    if errors:
        raise BenchError(f"{len(errors)} errors from the server, the first: {errors[0]}")
    elapsed = end - start
    cycle_avg = []
    for s in subscribers:
        state = final.get(s.session_id)
        if state is None:
            raise BenchError(f"session {s.session_id} disappeared")
        if state["mode"] != "RUN":
            raise BenchError(f"session {s.session_id} left RUN: {state['stop_reason']}")
        if state.get("cycle"):
            cycle_avg.append(float(state["cycle"]["avg_ms"]))
    server_cpu = (
        None
        if server_before is None or server_after is None
        else (server_after - server_before) / elapsed
    )
    others = (
        None
        if server_cpu is None or system_before is None or system_after is None
        else max(0.0, (system_after - system_before) / elapsed - server_cpu - client_cpu)
    )
    return Load(
        sessions=plan.sessions,
        window_s=elapsed,
        scan_rates=[s.scan_rate(start, end) for s in subscribers],
        frame_rates=[sum(1 for t in s.frames if start <= t < end) / elapsed for s in subscribers],
        cycle_avg_ms=cycle_avg,
        server_cpu=server_cpu,
        client_cpu=client_cpu,
        extensions=subscribers[0].extensions,
        rest_s=rest_s,
        others=others,
    )


async def client_figures(plan: Plan, source: str) -> tuple[Latency, Load]:
    import httpx2

    with running_server(plan.sessions + 10) as server:
        async with httpx2.AsyncClient(trust_env=False, timeout=120.0) as http:
            latency = await measure_latency(server, http, source, plan.toggles)
            load = await measure_load(server, http, source, plan)
        if server.process.poll() is not None:
            raise BenchError(f"the server died:\n{server.log_tail()}")
    return latency, load


# -- (c) monitoring slowdown (in-process) ---------------------------------------------------------


@dataclass
class Phase:
    name: str
    scans_per_s: float
    cpu_ms_per_scan: float
    frames_per_s: float
    frame_kb: float
    others: float | None = None  # cores other processes used meanwhile
    seconds: float = 0.0  # how long it was measured


class FrameSink:
    """Counts the frames the session builds and serialises for its client (what the worker
    would forward to the socket)."""

    def __init__(self) -> None:
        self.frames = 0
        self.block_frames = 0
        self.bytes = 0

    def __call__(self, client: int, text: str) -> None:
        self.bytes += len(text)
        self.frames += 1
        self.block_frames += '"block":null' not in text


def measure_monitoring(source: str, plan: Plan) -> tuple[Phase, list[Phase]]:
    """The bare CPU's scan rate (informational) and the session's phases: unmonitored, the open
    block monitored, debugging (a breakpoint that never fires, with the block open)."""
    from nasaq.cpu import Cpu, Profile
    from nasaq.monitor.download import compile_download
    from nasaq.monitor.protocol import Location
    from nasaq.monitor.session import ClientView, Session

    # cpu_share=1.0: the session's CPU-share limiter must not cap the fast mode's scan rate.
    session = Session("bench", _sources(source), Profile.S7_300, CYCLE_MS, "virtual", cpu_share=1.0)
    bare = Cpu(compile_download(_sources(source)), Profile.S7_300, CYCLE_MS)
    bare.start()
    for _ in range(100):
        bare.scan()
    started, cpu_started, scans = time.perf_counter(), time.process_time(), bare.scans
    while time.perf_counter() - started < plan.phase_s:
        bare.scan()
    elapsed = time.perf_counter() - started
    done = bare.scans - scans
    bare_phase = Phase(
        "bare Cpu.scan() loop",
        done / elapsed,
        (time.process_time() - cpu_started) * 1000 / max(done, 1),
        0.0,
        0.0,
    )

    client = 1
    view = ClientView(cpu=True)
    sink = FrameSink()
    session.emit = sink
    session.clients[client] = view
    session.start()
    phases: list[Phase] = []
    try:

        def command(action: Any) -> Any:
            return session.submit(action).result(timeout=30)

        command(lambda: session.do_watch(client, WATCHED))
        command(lambda: session.do_set_time("fast", None))
        command(session.do_run)

        def phase(name: str, monitored: bool) -> Phase:
            time.sleep(plan.settle_s)
            cpu = session.cpu
            frames, size, blocks = sink.frames, sink.bytes, sink.block_frames
            started, cpu_started, scans = time.perf_counter(), time.process_time(), cpu.scans
            system_started = system_busy_seconds()
            time.sleep(plan.phase_s)
            elapsed = time.perf_counter() - started
            done = cpu.scans - scans
            own = time.process_time() - cpu_started
            system = system_busy_seconds()
            others = (
                None
                if system is None or system_started is None
                else max(0.0, system - system_started - own) / elapsed
            )
            if cpu.mode != "RUN" or session.held is not None:
                raise BenchError(f"the session left RUN in phase {name!r}: {cpu.stop_reason}")
            if done <= 0:
                raise BenchError(f"no scans in phase {name!r}")
            sent = sink.frames - frames
            if sent <= 0:
                raise BenchError(f"no frames in phase {name!r}")
            if monitored and sink.block_frames == blocks:
                raise BenchError(f"no block status in phase {name!r}")
            return Phase(
                name,
                done / elapsed,
                own * 1000 / done,
                sent / elapsed,
                (sink.bytes - size) / sent / 1024,
                others,
                elapsed,
            )

        phases.append(phase("unmonitored", False))
        command(lambda: session.do_open_block(client, "OB1"))
        phases.append(phase("OB1 monitored", True))
        command(
            lambda: session.do_set_breakpoint(Location(block="OB1", instruction=0), "MW100 > 70000")
        )
        phases.append(phase("debugging", True))
    finally:
        session.close()
    return bare_phase, phases


# -- the report -----------------------------------------------------------------------------------


def _verdict(passed: bool) -> str:
    return "PASS" if passed else "FAIL"


def report(
    latency: Latency, load: Load, bare: Phase, phases: list[Phase], out: Any = sys.stdout
) -> int:
    """Prints the figures; returns how many targets were met (of 4)."""
    met = 0
    p50, p95 = latency.percentile(50), latency.percentile(95)
    ok = p95 < LATENCY_P95_TARGET_MS
    met += ok
    print(
        f"(a) set_input -> frame latency    1 session, {CYCLE_MS:g} ms virtual cycle, "
        f"{len(latency.samples_ms)} toggles",
        file=out,
    )
    print(
        f"    p50 {p50:6.1f} ms   p95 {p95:6.1f} ms   max {max(latency.samples_ms):6.1f} ms"
        f"      target p95 < {LATENCY_P95_TARGET_MS:g} ms          {_verdict(ok)}",
        file=out,
    )
    print(
        f"(b) {load.sessions} sessions x {INSTRUCTIONS} instructions, {CYCLE_MS:g} ms virtual "
        f"cycle, 1 subscriber each, {load.window_s:.1f} s window",
        file=out,
    )
    floor = SCAN_RATE_TARGET * SCAN_RATE_TOLERANCE
    measured = [rate for rate in load.scan_rates if not math.isnan(rate)]
    unmeasured = len(load.scan_rates) - len(measured)
    low = min(measured) if measured and not unmeasured else math.nan
    mid = statistics.median(measured) if measured else math.nan
    ok = low >= floor
    met += ok
    print(
        f"    scan rate  min {low:6.1f}/s  median {mid:6.1f}/s"
        f"      target {SCAN_RATE_TARGET:g}/s per session (>= {floor:g})  {_verdict(ok)}",
        file=out,
    )
    if unmeasured:
        print(f"    ({unmeasured} sessions sent too few CPU frames for a scan rate)", file=out)
    low, mid = min(load.frame_rates), statistics.median(load.frame_rates)
    ok = low >= FRAMES_TARGET
    met += ok
    print(
        f"    frames     min {low:6.1f}/s  median {mid:6.1f}/s"
        f"      target >= {FRAMES_TARGET:g}/s per subscriber      {_verdict(ok)}",
        file=out,
    )
    server_cpu = "?" if load.server_cpu is None else f"{load.server_cpu * 100:.0f}%"
    others = "?" if load.others is None else f"{load.others:.2f}"
    cycle = f"{statistics.median(load.cycle_avg_ms):.2f} ms" if load.cycle_avg_ms else "?"
    print(
        f"    (CPU: server process {server_cpu} of one core, client process "
        f"{load.client_cpu * 100:.0f}%, other processes {others} cores; median scan {cycle};",
        file=out,
    )
    print(
        f"     GET /api/sessions under this load took {load.rest_s:.2f} s; "
        f"compression: {load.extensions.split(';')[0] or 'none'})",
        file=out,
    )
    base = phases[0]
    print(
        f"(c) open-block monitoring slowdown   1 session in fast mode, {INSTRUCTIONS} "
        f"instructions/scan, {base.seconds:.0f} s per phase",
        file=out,
    )
    print(
        f"    {'':22s} {'scans/s':>8s} {'CPU ms/scan':>12s} {'frames/s':>9s} {'KB/frame':>9s}"
        f" {'slowdown':>9s}",
        file=out,
    )
    print(
        f"    {bare.name:22s} {bare.scans_per_s:8.0f} {bare.cpu_ms_per_scan:12.3f} {'-':>9s}"
        f" {'-':>9s} {'-':>9s}   (no session, informational)",
        file=out,
    )
    cpu_ratios = []
    for index, phase in enumerate(phases):
        ratio = base.scans_per_s / phase.scans_per_s
        line = (
            f"    {phase.name:22s} {phase.scans_per_s:8.0f} {phase.cpu_ms_per_scan:12.3f}"
            f" {phase.frames_per_s:9.0f} {phase.frame_kb:9.1f} {ratio:8.2f}x"
        )
        if index == 1:
            ok = ratio < SLOWDOWN_TARGET
            met += ok
            line += f"   target < {SLOWDOWN_TARGET:g}x   {_verdict(ok)}"
        elif index > 1:
            line += "   (informational)"
        if index:
            cpu_ratios.append(f"{phase.name} {phase.cpu_ms_per_scan / base.cpu_ms_per_scan:.2f}x")
        print(line, file=out)
    competing = [phase.others for phase in phases if phase.others is not None]
    print(
        f"    (slowdown by CPU time per scan: {', '.join(cpu_ratios)}"
        + (f"; other processes used up to {max(competing):.2f} cores)" if competing else ")"),
        file=out,
    )
    return met


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m nasaq.monitor.bench", description=__doc__)
    parser.add_argument("--quick", action="store_true", help="a short run (smoke test)")
    parser.add_argument("--sessions", type=int, help="sessions of figure (b)")
    parser.add_argument("--toggles", type=int, help="input toggles of figure (a)")
    parser.add_argument("--window", type=float, help="seconds measured in figure (b)")
    parser.add_argument("--phase", type=float, help="seconds per phase of figure (c)")
    args = parser.parse_args(argv)
    plan = QUICK if args.quick else FULL
    plan = Plan(
        toggles=args.toggles or plan.toggles,
        sessions=args.sessions or plan.sessions,
        warmup_s=plan.warmup_s,
        window_s=args.window or plan.window_s,
        phase_s=args.phase or plan.phase_s,
        settle_s=plan.settle_s,
    )
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, _terminated)
    print(
        f"Nasaq monitor bench{' (quick)' if args.quick else ''}: {os.cpu_count()} CPUs, "
        f"load average {_load_average()}{_busy_note('before the start')}",
        flush=True,
    )
    try:
        source = program_source()
        executed = executed_per_scan(source)
        print(f"program: DB1 + OB1 of {executed} STL instructions executed per scan", flush=True)
        latency, load = asyncio.run(client_figures(plan, source))
        bare, phases = measure_monitoring(source, plan)
    except BenchError as error:
        print(f"monitor bench FAILED: {error}", file=sys.stderr)
        return 1
    met = report(latency, load, bare, phases)
    print(f"{met} of 4 targets met; load average {_load_average()} at the end", flush=True)
    return 0


def _terminated(signum: int, frame: FrameType | None) -> None:
    raise SystemExit(128 + signum)


def system_busy_seconds() -> float | None:
    """CPU seconds all processes of the machine have used (Linux ``/proc/stat``), else None."""
    try:
        with open("/proc/stat", encoding="ascii") as stat:
            fields = stat.readline().split()
    except OSError:
        return None
    if not fields or fields[0] != "cpu":
        return None
    # user nice system idle iowait irq softirq steal: all but idle and iowait
    busy = sum(int(fields[k]) for k in (1, 2, 3, 6, 7, 8))
    return busy / os.sysconf("SC_CLK_TCK")


def busy_cores(seconds: float = 1.0) -> float | None:
    """Cores busy over the next ``seconds`` (this process sleeps meanwhile)."""
    before = system_busy_seconds()
    time.sleep(seconds)
    after = system_busy_seconds()
    return None if before is None or after is None else (after - before) / seconds


def _busy_note(when: str) -> str:
    busy = busy_cores()
    if busy is None:
        return ""
    note = f"; {busy:.2f} cores busy {when}"
    if busy > BUSY_WARNING:
        note += " (WARNING: other processes compete for the CPUs, the figures may be low)"
    return note


def _load_average() -> str:
    try:
        return "{:.2f} {:.2f} {:.2f}".format(*os.getloadavg())
    except OSError:
        return "?"


if __name__ == "__main__":
    raise SystemExit(main())

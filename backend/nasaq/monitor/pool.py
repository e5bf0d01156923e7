"""The server's side of the worker processes: where each session runs, requests to it, and the
routing of its frames and answers to the sockets (``nasaq.monitor.worker`` is the other side).

A session is pinned to the worker with the fewest sessions when it is created. One thread per
worker reads what the worker sends and hands it to the event loop. A session made from a project
is tagged with it (``project_of``, ``ids(project_id)``), so that a reloaded page, a second tab or
another browser finds the project's running session and attaches to it. Sessions nobody has been
connected to for ``idle_seconds`` (counted from the last client leaving) are closed by ``reap``.
"""

from __future__ import annotations

import asyncio
import contextlib
import itertools
import logging
import os
import secrets
import socket
import subprocess
import sys
import threading
from dataclasses import dataclass, field
from multiprocessing.connection import Connection
from typing import Any, Protocol

from nasaq.diagnostics.phrases import phrase
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import TimeModeName

log = logging.getLogger(__name__)
MAX_CLIENTS = 16  # sockets on one session (a student, a teacher looking on, a second tab)


class Client(Protocol):
    """A socket of a session: it gets the worker's frames and answers as JSON text."""

    def deliver(self, kind: str, text: str) -> None: ...


@dataclass
class _Worker:
    name: str
    process: subprocess.Popen[bytes]
    connection: Connection
    lock: threading.Lock = field(default_factory=threading.Lock)
    sessions: set[str] = field(default_factory=set)

    def send(self, item: tuple[Any, ...]) -> None:
        with self.lock:
            self.connection.send(item)


class WorkerPool:
    def __init__(
        self, workers: int | None = None, max_sessions: int = 200, idle_seconds: float = 900.0
    ) -> None:
        self.size = workers or os.cpu_count() or 1
        self.max_sessions = max_sessions
        self.idle_seconds = idle_seconds
        self._workers: list[_Worker] = []
        self._where: dict[str, _Worker] = {}
        self._projects: dict[str, int | None] = {}  # session: the project it was made from
        self._clients: dict[tuple[str, int], Client] = {}
        self._requests: dict[int, tuple[asyncio.Future[Any], _Worker]] = {}
        self._ids = itertools.count(1)
        self._client_ids = itertools.count(1)
        self._loop: asyncio.AbstractEventLoop | None = None

    # -- life -----------------------------------------------------------------------------------
    def start(self, loop: asyncio.AbstractEventLoop) -> None:
        self._loop = loop
        for _ in range(self.size):
            self._spawn()

    def _spawn(self) -> None:
        """A fresh interpreter (never a fork of this threaded server) running
        ``nasaq.monitor.worker``, connected by a socket pair; it ends when its socket closes."""
        name = f"nasaq-sim-{next(self._ids)}"
        ours, theirs = socket.socketpair()
        process = subprocess.Popen(
            [sys.executable, "-m", "nasaq.monitor.worker", str(theirs.fileno())],
            pass_fds=[theirs.fileno()],
        )
        theirs.close()
        worker = _Worker(name, process, Connection(ours.detach()))
        self._workers.append(worker)
        threading.Thread(
            target=self._read, args=(worker,), name=f"{name}-reader", daemon=True
        ).start()

    def stop(self) -> None:
        """Closes every session, then ends the workers. A worker without a session has nothing
        to close: it is terminated at once rather than waited for (one still starting would
        first finish its imports, a second or more of CPU for nothing)."""
        workers, self._workers = self._workers, []
        for worker in workers:
            if not worker.sessions:
                worker.process.terminate()
                continue
            with contextlib.suppress(OSError):
                worker.send(("shutdown",))
        for worker in workers:
            try:
                worker.process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                worker.process.kill()
                worker.process.wait()
            worker.connection.close()

    # -- requests -------------------------------------------------------------------------------
    async def _request(self, worker: _Worker, kind: str, *args: Any) -> Any:
        loop = asyncio.get_running_loop()
        req = next(self._ids)
        future: asyncio.Future[Any] = loop.create_future()
        self._requests[req] = (future, worker)
        try:
            worker.send((kind, req, *args))
        except OSError:
            self._requests.pop(req, None)
            raise MonitorError("MON614") from None
        return await future

    async def create(
        self,
        sources: list[tuple[str, str]],
        profile: str = "S7-300",
        cycle_ms: float = 10,
        time_mode: TimeModeName = "virtual",
        project_id: int | None = None,
    ) -> dict[str, Any]:
        if len(self._where) >= self.max_sessions:
            raise MonitorError("MON610", limit=self.max_sessions)
        worker = min(self._workers, key=lambda w: len(w.sessions))
        session_id = secrets.token_hex(8)
        worker.sessions.add(session_id)  # reserved while it compiles
        self._where[session_id] = worker
        self._projects[session_id] = project_id
        try:
            found: dict[str, Any] = await self._request(
                worker, "create", session_id, sources, profile, cycle_ms, time_mode, project_id
            )
        except BaseException:
            worker.sessions.discard(session_id)
            self._where.pop(session_id, None)
            self._projects.pop(session_id, None)
            raise
        return found

    async def call(self, session_id: str, op: str, *args: Any) -> Any:
        worker = self._where.get(session_id)
        if worker is None:
            raise MonitorError("MON609", id=session_id)
        return await self._request(worker, "call", session_id, op, args)

    def ids(self, project_id: int | None = None) -> list[str]:
        """Every session, or those made from project ``project_id``; oldest first."""
        if project_id is None:
            return list(self._where)
        return [sid for sid in self._where if self._projects.get(sid) == project_id]

    def exists(self, session_id: str) -> bool:
        return session_id in self._where

    async def delete(self, session_id: str) -> None:
        await self.call(session_id, "close")
        self._forget(session_id)

    async def reap(self) -> list[str]:
        closed: list[str] = []
        for worker in list(self._workers):
            ids: list[str] = await self._request(worker, "reap", self.idle_seconds)
            for session_id in ids:
                self._forget(session_id)
            closed += ids
        return closed

    def _forget(self, session_id: str) -> None:
        worker = self._where.pop(session_id, None)
        self._projects.pop(session_id, None)
        if worker is not None:
            worker.sessions.discard(session_id)

    # -- sockets --------------------------------------------------------------------------------
    def attach(self, session_id: str, client: Client) -> int:
        """Registers a socket of ``session_id``; its number. MON609 for no such session,
        MON605 when the session has all the sockets it may have."""
        worker = self._where.get(session_id)
        if worker is None:
            raise MonitorError("MON609", id=session_id)
        count = sum(1 for sid, _ in self._clients if sid == session_id)
        if count >= MAX_CLIENTS:
            raise MonitorError(
                "MON605", what=phrase("what_clients"), count=count + 1, limit=MAX_CLIENTS
            )
        number = next(self._client_ids)
        self._clients[(session_id, number)] = client
        worker.send(("attach", session_id, number))
        return number

    def detach(self, session_id: str, number: int) -> None:
        self._clients.pop((session_id, number), None)
        worker = self._where.get(session_id)
        if worker is not None:
            with contextlib.suppress(OSError):
                worker.send(("detach", session_id, number))

    def forward(self, session_id: str, number: int, text: str) -> None:
        """A client message (JSON text the server validated) for the session's CPU thread."""
        worker = self._where.get(session_id)
        if worker is None:
            raise MonitorError("MON614")
        worker.send(("message", session_id, number, text))

    # -- the reader threads ---------------------------------------------------------------------
    def _read(self, worker: _Worker) -> None:
        loop = self._loop
        assert loop is not None
        while True:
            try:
                item = worker.connection.recv()
            except (EOFError, OSError):
                item = ("died", worker)
            try:
                loop.call_soon_threadsafe(self._dispatch, item)
            except RuntimeError:  # the event loop is closed: the server is stopping
                break
            if item[0] == "died":
                break

    def _dispatch(self, item: tuple[Any, ...]) -> None:
        kind = item[0]
        if kind == "result":
            _, req, ok, payload = item
            found = self._requests.pop(req, None)
            if found is None or found[0].done():
                return
            future = found[0]
            if ok:
                future.set_result(payload)
            else:
                code, params = payload
                future.set_exception(MonitorError(code, **params))
        elif kind in ("reply", "frame"):
            _, session_id, number, text = item
            client = self._clients.get((session_id, number))
            if client is not None:
                client.deliver(kind, text)
        elif kind == "closed":
            self._closed(item[1])
        elif kind == "died":
            self._died(item[1])

    def _closed(self, session_id: str) -> None:
        self._forget(session_id)
        for (sid, _number), client in list(self._clients.items()):
            if sid == session_id:
                client.deliver("closed", "")

    def _died(self, worker: _Worker) -> None:
        """A worker process ended (killed, crashed): its sessions are gone; nothing waits."""
        if worker not in self._workers:
            return  # stopped on purpose
        log.error(
            "monitor worker %s ended; its %d sessions are closed", worker.name, len(worker.sessions)
        )
        worker.process.poll()
        self._workers.remove(worker)
        for session_id in list(worker.sessions):
            self._closed(session_id)
        for req, (future, owner) in list(self._requests.items()):
            if owner is worker:
                del self._requests[req]
                if not future.done():
                    future.set_exception(MonitorError("MON614"))
        self._spawn()

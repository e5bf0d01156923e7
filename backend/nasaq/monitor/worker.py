"""A worker process: it runs simulation sessions, each CPU in its own thread.

Python runs one thread at a time per process, so the server spreads sessions over worker
processes (one per core by default, ``nasaq.monitor.pool``) and keeps its own process for the
web: a busy classroom's CPUs never slow the sockets and the REST API, and the sessions use every
core. The server talks to a worker over a pipe with tuples:

server → worker: ``("create", req, id, sources, profile, cycle_ms, time_mode, project_id)``,
``("attach", id, client)``, ``("detach", id, client)``, ``("message", id, client, json)``,
``("call", req, id, op, args)`` with op ``info``, ``download``, ``diagnostics``, ``trend_csv``
or ``close``, ``("reap", req, idle_seconds)``, ``("shutdown",)``.

worker → server: ``("result", req, ok, payload)`` (payload: the result, or ``(code, params)`` of
a MonitorError), ``("reply", id, client, json)`` (an ack or error), ``("frame", id, client,
json)``, ``("closed", id)``.
"""

from __future__ import annotations

import contextlib
import csv
import io
import logging
import signal
import sys
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future
from multiprocessing.connection import Connection
from typing import Any

from pydantic import ValidationError

from nasaq.cpu import Profile
from nasaq.diagnostics.phrases import phrase
from nasaq.diagnostics.validation import validation_reason
from nasaq.lang.stl import SourceFile
from nasaq.monitor import protocol as p
from nasaq.monitor.commands import command
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.scheduler import Scheduler
from nasaq.monitor.session import ClientView, Session

log = logging.getLogger(__name__)


class Worker:
    def __init__(self, connection: Connection) -> None:
        self.connection = connection
        self.sessions: dict[str, Session] = {}
        self.scheduler = Scheduler()
        self._lock = threading.Lock()

    def send(self, item: tuple[Any, ...]) -> None:
        # The server may be gone: the worker then ends with it (its next recv fails).
        with self._lock, contextlib.suppress(OSError, ValueError):
            self.connection.send(item)

    def run(self) -> None:
        while True:
            try:
                item = self.connection.recv()
            except (EOFError, OSError):
                break
            if item[0] == "shutdown":
                break
            try:
                self.handle(item)
            except Exception:  # a bug: log it, keep serving the other sessions
                log.exception("monitor worker: %r failed", item[0])
        for session in list(self.sessions.values()):
            session.close()
        self.scheduler.stop()

    def handle(self, item: tuple[Any, ...]) -> None:
        kind = item[0]
        if kind == "create":
            threading.Thread(target=self.create, args=item[1:], daemon=True).start()
        elif kind == "attach":
            _, session_id, client = item
            session = self.sessions.get(session_id)
            if session is None:
                self.send(("closed", session_id))
                return
            session.clients[client] = ClientView()
            session.submit(lambda: None)  # publishes a first snapshot for the newcomer
        elif kind == "detach":
            _, session_id, client = item
            found = self.sessions.get(session_id)
            if found is not None:
                view = found.clients.pop(client, None)
                if view is not None:
                    found.client_left(view)
        elif kind == "message":
            self.message(*item[1:])
        elif kind == "call":
            self.call(*item[1:])
        elif kind == "reap":
            _, req, idle_seconds = item
            self.send(("result", req, True, self.reap(idle_seconds)))

    # -- sessions -------------------------------------------------------------------------------
    def create(
        self,
        req: int,
        session_id: str,
        sources: list[tuple[str, str]],
        profile: str,
        cycle_ms: float,
        time_mode: p.TimeModeName,
        project_id: int | None = None,
    ) -> None:
        try:
            files = [SourceFile(name=name, text=text) for name, text in sources]
            session = Session(
                session_id, files, Profile(profile), cycle_ms, time_mode, project_id=project_id
            )
        except MonitorError as error:
            self.send(("result", req, False, (error.code, error.params)))
            return
        except Exception:
            log.exception("monitor worker: creating a session failed")
            self.send(("result", req, False, ("MON616", {"reason": "internal error"})))
            return

        def emit(client: int, text: str) -> None:
            self.send(("frame", session_id, client, text))

        session.emit = emit
        self.sessions[session_id] = session
        session.start(self.scheduler)
        self.send(("result", req, True, info(session)))

    def message(self, session_id: str, client: int, text: str) -> None:
        session = self.sessions.get(session_id)
        ref: int | None = None
        try:
            if session is None:
                raise MonitorError("MON614")
            message = p.CLIENT_MESSAGE.validate_json(text)
            ref = message.ref
            future = session.submit(command(session, client, message))
        except MonitorError as error:
            self.send(("reply", session_id, client, error_json(ref, error)))
            return
        except ValidationError as error:  # the server validated it: this is not expected
            self.send(("reply", session_id, client, error_json(None, malformed(error))))
            return

        def done(finished: Future[Any]) -> None:
            self.send(("reply", session_id, client, answer_json(ref, finished)))

        future.add_done_callback(done)

    def call(self, req: int, session_id: str, op: str, args: tuple[Any, ...]) -> None:
        session = self.sessions.get(session_id)
        if session is None:
            self.send(("result", req, False, ("MON609", {"id": session_id})))
            return
        if op == "close":
            self.sessions.pop(session_id, None)
            threading.Thread(target=self._close, args=(req, session), daemon=True).start()
            return
        action: Callable[[], Any] = {
            "info": lambda: info(session),
            "download": lambda: session.do_download(
                [SourceFile(name=n, text=t) for n, t in args[0]]
            ),
            "diagnostics": lambda: diagnostics(session),
            "trend_csv": lambda: trend_csv(session, int(args[0])),
        }[op]

        def done(finished: Future[Any]) -> None:
            error = finished.exception()
            if error is None:
                self.send(("result", req, True, finished.result()))
            elif isinstance(error, MonitorError):
                self.send(("result", req, False, (error.code, error.params)))
            else:
                log.error("monitor worker: %s failed", op, exc_info=error)
                self.send(("result", req, False, ("MON616", {"reason": "internal error"})))

        session.submit(action).add_done_callback(done)

    def _close(self, req: int, session: Session) -> None:
        session.close()
        self.send(("closed", session.id))
        self.send(("result", req, True, None))

    def reap(self, idle_seconds: float) -> list[str]:
        now = time.monotonic()
        idle = [
            s.id
            for s in list(self.sessions.values())
            if not s.clients and now - s.last_activity > idle_seconds
        ]
        for session_id in idle:
            session = self.sessions.pop(session_id)
            threading.Thread(target=session.close, daemon=True).start()
        return idle


def info(session: Session) -> dict[str, Any]:
    return {
        "id": session.id,
        "blocks": sorted(f"{k.value}{n}" for k, n in session.program.blocks),
        "cpu": session.cpu_state().model_dump(mode="json"),
        "clients": sorted(session.clients),
        "project_id": session.project_id,
        "profile": session.profile.value,
        "started_at": session.started_at,
    }


def diagnostics(session: Session) -> list[dict[str, Any]]:
    return [
        p.DiagnosticEntry.of(e).model_dump(mode="json")
        for e in list(session.engine.diagnostic_buffer)
    ]


def trend_csv(session: Session, client: int) -> str:
    view = session.clients.get(client)
    if view is None:
        raise MonitorError(
            "MON603",
            target=phrase("client_n", client=client),
            reason=phrase("no_such_client"),
        )
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["scan", "time_ms", *(t.text for t in view.trend)])
    reals = [t.type == "REAL" for t in view.trend]
    for sample in list(view.history):
        values = [_real_text(v) if r else v for v, r in zip(sample.values, reals, strict=False)]
        writer.writerow([sample.scan, sample.time_ms, *values])
    return out.getvalue()


def _real_text(value: object) -> object:
    """A REAL as the watch table and the trend show it: seven significant digits (a REAL's
    precision), so ``42.4`` is not written as the double ``42.400001525878906``."""
    return format(value, ".7g") if isinstance(value, float) else value


def error_json(ref: int | None, error: MonitorError) -> str:
    return p.ProtocolError(
        ref=ref,
        code=error.code,
        key=error.key,
        message=str(error),
        params=error.diagnostic.params,
    ).model_dump_json()


def answer_json(ref: int | None, future: Future[Any]) -> str:
    error = future.exception()
    if error is None:
        return p.Ack(ref=ref, result=future.result()).model_dump_json()
    if isinstance(error, MonitorError):
        return error_json(ref, error)
    log.error("monitor worker: a command failed", exc_info=error)
    return error_json(
        ref, MonitorError("MON607", action=phrase("act_command"), reason=phrase("internal_error"))
    )


def malformed(error: ValidationError) -> MonitorError:
    first = error.errors()[0]
    where = ".".join(str(part) for part in first.get("loc", ()))
    reason = validation_reason(first)
    if where:
        return MonitorError("MON601", reason=phrase("field_reason", field=where, reason=reason))
    return MonitorError("MON601", reason=reason)


def main(connection: Connection) -> None:
    """The worker process's entry point."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl+C is the server's to handle
    logging.basicConfig(level=logging.WARNING)
    Worker(connection).run()


if __name__ == "__main__":
    main(Connection(int(sys.argv[1])))

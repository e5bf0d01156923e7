"""One client's WebSocket on a session, on the server's side of the worker pipe.

The reader checks each message against the protocol (an unreadable one is answered at once) and
forwards it to the worker, which carries it out in the session's CPU thread and answers. The
writer sends the answers, then the frames that came meanwhile merged into one (``frames.merge``),
so a slow client gets fewer, fuller frames and costs nobody else anything; the frames waiting for a
client that does not read at all are folded every ``MAX_WAITING_FRAMES``. A client that takes
no data for ``send_timeout`` seconds, or leaves more than ``MAX_PENDING`` messages unanswered, is
disconnected with MON608.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
from collections import deque
from typing import Any

from pydantic import ValidationError
from starlette.websockets import WebSocket, WebSocketDisconnect

from nasaq.diagnostics.phrases import phrase
from nasaq.monitor import protocol as p
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.frames import merge
from nasaq.monitor.pool import WorkerPool
from nasaq.monitor.session import MAX_WATCH
from nasaq.monitor.worker import error_json, malformed

MAX_MESSAGE_BYTES = 64 * 1024
MAX_PENDING = 256
MAX_WAITING_FRAMES = 64
CLOSE_POLICY = 1008


class Connection:
    def __init__(
        self, socket: WebSocket, pool: WorkerPool, session_id: str, send_timeout: float = 10.0
    ) -> None:
        self.socket = socket
        self.pool = pool
        self.session_id = session_id
        self.send_timeout = send_timeout
        self.client = 0
        self.wake = asyncio.Event()
        self.replies: deque[str] = deque()
        self.frames: list[str] = []  # waiting to be sent, merged into one when sent
        self.pending = 0  # messages forwarded and not answered yet
        self.closing: tuple[int, str] | None = None
        self.session_closed = False

    async def serve(self) -> None:
        await self.socket.accept()
        try:
            self.client = self.pool.attach(self.session_id, self)
        except MonitorError as error:
            await self.socket.send_text(error_json(None, error))
            await self.socket.close(CLOSE_POLICY, str(error)[:120])
            return
        hello = p.Hello(
            session=self.session_id,
            client=self.client,
            max_frames_per_second=30,
            max_watch_entries=MAX_WATCH,
        )
        self.replies.append(hello.model_dump_json())
        self.wake.set()
        reader = asyncio.create_task(self._read())
        writer = asyncio.create_task(self._write())
        try:
            await asyncio.wait({reader, writer}, return_when=asyncio.FIRST_COMPLETED)
        finally:
            reader.cancel()
            writer.cancel()
            self.pool.detach(self.session_id, self.client)
            if self.closing is not None:
                code, reason = self.closing
                # The peer may be gone or stuck: then there is nothing more to tell it.
                with contextlib.suppress(Exception):
                    await asyncio.wait_for(self.socket.close(code, reason[:120]), 2)

    def deliver(self, kind: str, text: str) -> None:
        """From the worker (in the event loop): an answer, a frame, or the session's end."""
        if kind == "reply":
            self.pending -= 1
            self.replies.append(text)
        elif kind == "frame":
            self.frames.append(text)
            if len(self.frames) >= MAX_WAITING_FRAMES:  # a client that does not read: fold
                self.frames = [merge(self.frames)]
        else:
            self.session_closed = True
            self.replies.append(error_json(None, MonitorError("MON614")))
        self.wake.set()

    # -- reading --------------------------------------------------------------------------------
    async def _read(self) -> None:
        socket = self.socket
        while True:
            try:
                message = await socket.receive()
            except (WebSocketDisconnect, RuntimeError):
                return
            if message["type"] == "websocket.disconnect":
                return
            text = message.get("text")
            if text is None:
                self._error(None, MonitorError("MON601", reason=phrase("frames_json")))
                continue
            size = len(text) if len(text) * 4 <= MAX_MESSAGE_BYTES else len(text.encode())
            if size > MAX_MESSAGE_BYTES:
                self._error(None, MonitorError("MON602", size=size, limit=MAX_MESSAGE_BYTES))
                continue
            try:
                p.CLIENT_MESSAGE.validate_json(text)
            except ValidationError as error:
                self._error(_ref_of(text), malformed(error))
                continue
            if self.pending >= MAX_PENDING or len(self.replies) > MAX_PENDING:
                self._drop("MON608", seconds=self.send_timeout)
                return
            try:
                self.pool.forward(self.session_id, self.client, text)
            except (MonitorError, OSError):
                self.deliver("closed", "")
                return
            self.pending += 1

    # -- writing --------------------------------------------------------------------------------
    def _error(self, ref: int | None, error: MonitorError) -> None:
        self.replies.append(error_json(ref, error))
        self.wake.set()

    def _drop(self, code: str, **params: Any) -> None:
        self.closing = (CLOSE_POLICY, str(MonitorError(code, **params)))

    async def _write(self) -> None:
        while True:
            await self.wake.wait()
            self.wake.clear()
            while self.replies:
                if not await self._send(self.replies.popleft()):
                    return
            if self.frames:
                frames, self.frames = self.frames, []
                if not await self._send(merge(frames)):
                    return
            if self.session_closed:
                self.closing = (1000, "session closed")
                return

    async def _send(self, text: str) -> bool:
        try:
            await asyncio.wait_for(self.socket.send_text(text), self.send_timeout)
        except TimeoutError:
            self._drop("MON608", seconds=self.send_timeout)
            return False
        except (WebSocketDisconnect, RuntimeError, OSError):
            return False
        return True


def _ref_of(text: str) -> int | None:
    try:
        data = json.loads(text)
    except ValueError:
        return None
    ref = data.get("ref") if isinstance(data, dict) else None
    return ref if isinstance(ref, int) and not isinstance(ref, bool) else None

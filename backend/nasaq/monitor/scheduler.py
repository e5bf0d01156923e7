"""One thread that runs the scans of many sessions.

A thread per session would cost a thread wake-up per scan: 100 sessions at 10 ms are 10,000
wake-ups a second, which costs more than the programs themselves. The scheduler wakes at most
about once a millisecond and runs every scan due by then. A session that may hold in the middle of
a scan (a breakpoint, a step) moves to its own thread, since a hold blocks the thread it is on,
and comes back when nothing can hold it any more (``Session.tick``, ``Session._main``).
"""

from __future__ import annotations

import logging
import threading
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from nasaq.monitor.session import Session

log = logging.getLogger(__name__)
IDLE_S = 0.1  # the longest sleep when no session has a scan due


class Scheduler:
    def __init__(self) -> None:
        self._sessions: list[Session] = []
        self._signal = threading.Event()
        self._stopped = False
        self._thread = threading.Thread(target=self._run, name="nasaq-scheduler", daemon=True)
        self._thread.start()

    def add(self, session: Session) -> None:
        self._sessions = [*self._sessions, session]
        self.wake()

    def remove(self, session: Session) -> None:
        self._sessions = [s for s in self._sessions if s is not session]

    def wake(self) -> None:
        self._signal.set()

    def stop(self) -> None:
        self._stopped = True
        self.wake()
        self._thread.join(timeout=5)

    def _run(self) -> None:
        while not self._stopped:
            self._signal.clear()
            wake_at = time.perf_counter() + IDLE_S
            for session in self._sessions:
                if session.owner != "scheduler" or session.closed:
                    continue
                due = session.tick()
                if due is not None and due < wake_at:
                    wake_at = due
            pause = wake_at - time.perf_counter()
            if pause > 0:
                self._signal.wait(pause)

"""The three time modes of a running CPU.

- ``virtual``: every scan advances the clock by exactly ``cycle_ms``; nothing waits for the wall
  clock, so results are the same on any machine (tests, lessons, ``nasaq run``). A session that
  shows a running CPU paces virtual scans 1:1 with the wall clock when nobody asks for speed.
- ``real``: scans are paced to the wall clock: scan k starts ``k * cycle_ms`` after the first. When
  a scan takes longer than the cycle (a heavy program), the next starts at once and the schedule
  moves on from there, as a real CPU's cycle time simply grows; it never races to catch up.
- ``fast``: as fast as the machine goes, each scan still ``cycle_ms`` of virtual time
  (fast-forward through a long timer).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from enum import StrEnum

from nasaq.cpu.api import Cpu


class TimeMode(StrEnum):
    VIRTUAL = "virtual"
    REAL = "real"
    FAST = "fast"


class Pacer:
    def __init__(
        self,
        mode: TimeMode,
        clock: Callable[[], float] = time.monotonic,
        sleep: Callable[[float], None] = time.sleep,
    ) -> None:
        self.mode = mode
        self._clock = clock
        self._sleep = sleep
        self._due: float | None = None

    def run(self, cpu: Cpu, scans: int, before_scan: Callable[[int], None] | None = None) -> int:
        """Runs up to ``scans`` scans (fewer if the CPU stops); returns how many ran.

        ``before_scan(k)`` is called before scan k (1-based), e.g. to change inputs."""
        ran = 0
        for number in range(1, scans + 1):
            if cpu.mode != "RUN":
                break
            if self.mode is TimeMode.REAL:
                self._wait_for_slot(cpu.cycle_ms)
            if before_scan is not None:
                before_scan(number)
            cpu.scan()
            ran = number
        return ran

    def _wait_for_slot(self, cycle_ms: float) -> None:
        now = self._clock()
        if self._due is None:
            self._due = now
        elif self._due > now:
            self._sleep(self._due - now)
        else:
            self._due = now  # overrun: start at once, keep the rhythm from here
        self._due += cycle_ms / 1000.0

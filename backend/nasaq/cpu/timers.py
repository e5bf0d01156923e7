"""S5 timers (SP SE SD SS SF, FR, R, L/LC) evaluated against the virtual clock.

A timer is started with an S5TIME value (3 BCD digits and a time base of 10 ms, 100 ms, 1 s or
10 s) and decrements by one unit per time base. Because the virtual clock stands still during a
scan, the state is computed when it is looked at: the remaining units are
``value - (now - start) // base``, and the timer has elapsed when ``now - start >= value * base``.
"""

from __future__ import annotations

from typing import Protocol

from nasaq.cpu.bcd import bcd_to_int, int_to_bcd
from nasaq.cpu.errors import CpuError

BASES_MS = (10, 100, 1000, 10000)

# What Q becomes when the time elapses
_Q_ON_ELAPSE = {"SP": 0, "SE": 0, "SD": 1, "SS": 1, "SF": 0}


class Clock(Protocol):
    now: int


class Timers:
    """All timers of a CPU as parallel lists, indexed by timer number."""

    def __init__(self, count: int, clock: Clock) -> None:
        self.count = count
        self.clock = clock
        self.clear()

    def clear(self, keep: int = 0) -> None:
        """Reset timers ``keep`` and up (warm restart keeps the retentive ones)."""
        n = self.count
        if keep == 0:
            self.q = [0] * n
            self.running = [False] * n
            self.start_ms = [0] * n
            self.base = [10] * n  # ms per unit
            self.units = [0] * n  # value at start, or the value held while stopped
            self.on_elapse = [0] * n
            self.edge = [0] * n  # RLO of the last start instruction (edge memory)
            self.fr_edge = [0] * n
            return
        for k in range(keep, n):
            self.q[k] = 0
            self.running[k] = False
            self.units[k] = 0
            self.edge[k] = 0
            self.fr_edge[k] = 0

    def check(self, number: int) -> int:
        if not 0 <= number < self.count:
            raise CpuError("SIM516", number=number, last=self.count - 1)
        return number

    # -- state ------------------------------------------------------------------------------
    def _update(self, n: int) -> None:
        if self.running[n]:
            elapsed = self.clock.now - self.start_ms[n]
            if elapsed >= self.units[n] * self.base[n]:
                self.running[n] = False
                self.units[n] = 0
                self.q[n] = self.on_elapse[n]

    def status(self, n: int) -> int:
        self.check(n)
        self._update(n)
        return self.q[n]

    def remaining_units(self, n: int) -> int:
        self._update(n)
        if self.running[n]:
            return self.units[n] - (self.clock.now - self.start_ms[n]) // self.base[n]
        return self.units[n]

    def remaining_ms(self, n: int) -> int:
        self._update(n)
        if self.running[n]:
            return max(0, self.start_ms[n] + self.units[n] * self.base[n] - self.clock.now)
        return self.units[n] * self.base[n]

    def load(self, n: int) -> int:
        """``L T n``: remaining time in units of the time base, binary."""
        self.check(n)
        return self.remaining_units(n)

    def load_bcd(self, n: int) -> int:
        """``LC T n``: remaining time as S5TIME (BCD value with its time base in bits 12-13)."""
        self.check(n)
        units = self.remaining_units(n)
        return int_to_bcd(units, 3) | (BASES_MS.index(self.base[n]) << 12)

    # -- instructions -------------------------------------------------------------------------
    def _start(self, n: int, kind: str, s5time: int, op: str) -> None:
        units = bcd_to_int(s5time & 0xFFF, 3, op)
        self.base[n] = BASES_MS[(s5time >> 12) & 3]
        self.units[n] = units
        self.start_ms[n] = self.clock.now
        self.running[n] = True
        self.on_elapse[n] = _Q_ON_ELAPSE[kind]

    def start(self, kind: str, n: int, rlo: int, s5time: int) -> None:
        """SP SE SD SS SF with the RLO and ACCU1 (the time value) of the instruction."""
        self.check(n)
        rising = rlo and not self.edge[n]
        falling = not rlo and self.edge[n]
        self.edge[n] = rlo
        self._update(n)
        op = f"{kind} T {n}"
        if kind == "SP":
            if rising:
                self._start(n, kind, s5time, op)
                self.q[n] = 1
            elif not rlo and self.running[n]:
                self._stop(n)
        elif kind == "SE":
            if rising:
                self._start(n, kind, s5time, op)
                self.q[n] = 1
        elif kind == "SD":
            if rising:
                self._start(n, kind, s5time, op)
                self.q[n] = 0
                self._update(n)
            elif not rlo:
                self._stop(n)
                self.q[n] = 0
        elif kind == "SS":
            if rising:
                self._start(n, kind, s5time, op)
                self._update(n)
        elif kind == "SF":
            if rising:
                self._stop(n)
                self.q[n] = 1
            elif falling:
                self._start(n, kind, s5time, op)
                self.q[n] = 1
                self._update(n)

    def _stop(self, n: int) -> None:
        if self.running[n]:
            self.units[n] = self.remaining_units(n)
            self.running[n] = False
        self.q[n] = 0

    def reset(self, n: int, rlo: int) -> None:
        """``R T n``: with RLO 1 the timer stops, Q and the time value become 0."""
        self.check(n)
        if rlo:
            self.running[n] = False
            self.units[n] = 0
            self.q[n] = 0

    def enable(self, n: int, rlo: int) -> None:
        """``FR T n``: a rising RLO clears the start edge memory, so a start with RLO 1 restarts."""
        self.check(n)
        if rlo and not self.fr_edge[n]:
            self.edge[n] = 0
        self.fr_edge[n] = rlo

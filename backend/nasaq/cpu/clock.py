"""The CPU's time-of-day clock, which SFC 1 READ_CLK reads (and through it TIA's RD_SYS_T and
RD_LOC_T, ``nasaq.lang.scl.lower.instructions``).

*Nasaq*: the clock is set from the PC's local time the first time the program reads it, and
from then on runs with the CPU's own clock (the virtual clock of the scans, ``Machine.now``), so
two reads differ by exactly the time the CPU ran between them, at any simulation speed, and a
held or single-stepped CPU does not see the PC's time jump. An S7-300/400's clock is set to the
local time by convention; Nasaq has no time zone setting, so RD_SYS_T (the system time) and
RD_LOC_T (the local time) read the same clock.

READ_CLK writes the DATE_AND_TIME (8 BCD bytes, ``nasaq.cpu.iec_library.dt_bytes``) to its
output CDT; RET_VAL is 0 and BR 1.
"""

from __future__ import annotations

import datetime

from nasaq.cpu.iec_library import MS_PER_DAY, dt_bytes

_EPOCH = datetime.datetime(1990, 1, 1)
_LAST = (datetime.datetime(2090, 1, 1) - _EPOCH).days * MS_PER_DAY - 1


def pc_ms() -> int:
    """The PC's local time now, in ms since 1990-01-01 00:00 (DATE_AND_TIME's epoch)."""
    now = datetime.datetime.now()
    delta = now - _EPOCH
    return delta.days * MS_PER_DAY + delta.seconds * 1000 + delta.microseconds // 1000


class Clock:
    """The time of day of one CPU: ``ms(now)`` for the virtual time ``now`` (ms since start)."""

    def __init__(self) -> None:
        self.base: int | None = None  # the clock's time at virtual time 0, once read

    def ms(self, now: int) -> int:
        if self.base is None:
            self.base = pc_ms() - now
        return min(max(self.base + now, 0), _LAST)

    def date_and_time(self, now: int) -> bytes:
        return dt_bytes(self.ms(now))

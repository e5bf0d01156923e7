"""Which organization blocks the operating system runs, and when, per profile.

S7-300/400 (unchanged since the first simulator): OB1 every cycle, OB35 on its cyclic interrupt
(100 ms unless configured), OB100 at a warm and OB102 at a cold restart, OB121/OB122 on errors.

S7-1200/1500 (TIA Portal's rules): the program-cycle OBs are OB1 and every further OB numbered
123 and up that TIA would file under "Program cycle" (its name is no other event's: TIA names a
second one "Main_1", a freely named one counts too); they run each cycle in number order, OB1
first. The startup OBs are OB100 and the OBs from 123 named "Startup_<n>"; both restarts run them
all in number order (an S7-1500 knows no OB102). The cyclic interrupt OBs are OB30-OB38 and the
ones from 123 named "Cyclic interrupt_<n>"; each has its own period, 100 ms by default (the cycle
time TIA proposes for a new cyclic interrupt OB, whatever its number). OBs of events the
simulator has no source for (hardware interrupts, time of day ...) are loaded but never run.
The event of an OB from 123 up is read from its name (``nasaq.lang.tia_names``), the only place
a TIA source keeps it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from nasaq.cpu.profile import Profile
from nasaq.ir import BlockKind, Program
from nasaq.lang.tia_names import FIRST_FREE_OB, LAST_OB, ob_event

DEFAULT_PERIOD_MS = 100  # OB35 on S7-300/400; every cyclic interrupt OB on S7-1200/1500
MAX_PERIOD_MS = 60000  # the longest cycle time STEP 7 and TIA accept for a cyclic interrupt
CLASSIC_CYCLIC = (35,)  # the one cyclic interrupt OB the S7-300/400 profiles run
S7_1500_CYCLIC = tuple(range(30, 39))

EVENT_CYCLE, EVENT_CYCLIC, EVENT_STARTUP = 0x11, 0x11, 0x13
# (event class, priority) of the start information; cyclic interrupts as STEP 7's defaults
START_INFO: dict[int, tuple[int, int]] = {
    1: (EVENT_CYCLE, 1),
    **{30 + k: (EVENT_CYCLIC, 7 + k) for k in range(9)},
    100: (EVENT_STARTUP, 27),
    102: (EVENT_STARTUP, 27),
    121: (0x25, 1),
    122: (0x29, 1),
}


@dataclass(frozen=True, slots=True)
class ObPlan:
    cycle: tuple[int, ...]  # program-cycle OBs, in the order each scan runs them
    warm: tuple[int, ...]  # startup OBs of a warm restart, in order
    cold: tuple[int, ...]  # ... of a cold restart
    cyclic: tuple[tuple[int, int], ...]  # (OB number, period in ms)
    start_info: dict[int, tuple[int, int]]  # OB number: (event class, priority)


def check_periods(periods: Mapping[int, int], profile: Profile) -> None:
    """Raises ValueError for a period of an OB that is no cyclic interrupt of ``profile`` or out
    of 1 to 60000 ms (``Cpu``'s check; ``cpu.properties`` reports the same as diagnostics)."""
    for number, ms in periods.items():
        if not is_cyclic_number(number, profile):
            raise ValueError(f"OB {number} is no cyclic interrupt OB of the {profile.value}")
        if not 1 <= ms <= MAX_PERIOD_MS:
            raise ValueError(f"OB {number}: the cycle time must be 1 to {MAX_PERIOD_MS} ms")


def is_cyclic_number(number: int, profile: Profile) -> bool:
    """Whether a cycle time may be set for OB ``number`` under ``profile``."""
    if profile is Profile.S7_1500:
        return number in S7_1500_CYCLIC or FIRST_FREE_OB <= number <= LAST_OB
    return number in CLASSIC_CYCLIC


def plan(program: Program, profile: Profile, periods: Mapping[int, int]) -> ObPlan:
    """The OBs ``program`` has that the operating system of ``profile`` runs."""
    if profile is not Profile.S7_1500:
        ms = periods.get(35, DEFAULT_PERIOD_MS)
        return ObPlan((1,), (100,), (102,), ((35, ms),), START_INFO)
    cycle, startup, cyclic = [1], [100], []
    info = dict(START_INFO)
    for kind, number in sorted(program.blocks):
        if kind is not BlockKind.OB:
            continue
        if number in S7_1500_CYCLIC:
            cyclic.append((number, periods.get(number, DEFAULT_PERIOD_MS)))
        if number < FIRST_FREE_OB:
            continue
        event = ob_event(program.blocks[(kind, number)].name)
        key = event.key if event is not None else "program_cycle"
        if key == "program_cycle":
            cycle.append(number)
        elif key == "startup":
            startup.append(number)
            info[number] = START_INFO[100]
        elif key == "cyclic_interrupt":
            cyclic.append((number, periods.get(number, DEFAULT_PERIOD_MS)))
            info[number] = (EVENT_CYCLIC, 8)  # TIA's default priority of a cyclic interrupt
    return ObPlan(tuple(cycle), tuple(startup), tuple(startup), tuple(cyclic), info)

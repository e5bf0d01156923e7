"""Organization blocks named by their event, as TIA Portal names and numbers them.

TIA Portal's "Generate source from blocks" writes an OB by its symbolic name only
(``ORGANIZATION_BLOCK "Startup"``): the number lives in the project, not in the source. When
TIA adds an OB it names it after its event ("Main", "Startup", "Cyclic interrupt" ...) and gives
it the event's first free number; a second OB of the same event is called ``<event>_1``,
``<event>_2`` ... So the name tells the number (shared by the SCL and the STL front ends):

- a name that carries its number as TIA lists it (``"Main [OB1]"``) has that number;
- an event name (case-insensitive, blanks and underscores optional: ``CyclicInterrupt``, an
  ``ob`` prefix allowed, optionally followed by ``_<n>``) takes the first free number
  of its event's range (``EVENTS``); on the S7-1200/1500 family, once the range is used up, the
  first free number from 123 up (TIA's rule for further OBs of any event);
- STEP 7 Classic's standard OB symbols (``CYCL_EXC``, ``CYC_INT5``, ``COMPLETE RESTART`` ...)
  name exactly one OB, whatever is free;
- on the S7-1200/1500 family an OB with any other name is a further program-cycle OB, numbered
  from 123 up as TIA does; on S7-300/400 every OB number is an event and such an OB has no
  number (the caller reports it).

Decision: on S7-300/400 "Cyclic interrupt" is OB 35 first (the one cyclic interrupt every S7-300
CPU has, and the one Nasaq's CPU runs), then OB 30..38; on S7-1200/1500 it is OB 30 first, TIA's
default there. The OB number an absolute name (``OB35``) or the symbol table gives always wins;
callers ask this module only for OBs those leave unnumbered.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from dataclasses import dataclass

from nasaq.lang.profiles import is_s7_1500

FIRST_FREE_OB = 123  # S7-1200/1500: OBs beyond an event's own numbers, and extra cycle OBs
LAST_OB = 32767


@dataclass(frozen=True, slots=True)
class ObEvent:
    """One OB event: TIA's default name(s) and the numbers it owns, in the order TIA takes them."""

    key: str  # stable identifier, e.g. "cyclic_interrupt"
    names: tuple[str, ...]  # TIA's default name first, then accepted spellings
    classic: tuple[int, ...]  # S7-300/400
    s7_1500: tuple[int, ...]  # S7-1200/1500 (then 123 up)


EVENTS: tuple[ObEvent, ...] = (
    ObEvent("program_cycle", ("Main", "Program cycle"), (1,), (1,)),
    ObEvent("startup", ("Startup",), (100,), (100,)),
    ObEvent("time_of_day", ("Time of day",), tuple(range(10, 18)), tuple(range(10, 18))),
    ObEvent("time_delay", ("Time delay interrupt",), tuple(range(20, 24)), tuple(range(20, 24))),
    ObEvent(
        "cyclic_interrupt",
        ("Cyclic interrupt",),
        (35, 30, 31, 32, 33, 34, 36, 37, 38),
        tuple(range(30, 39)),
    ),
    ObEvent(
        "hardware_interrupt", ("Hardware interrupt",), tuple(range(40, 48)), tuple(range(40, 48))
    ),
    ObEvent("status", ("Status",), (55,), (55,)),
    ObEvent("update", ("Update",), (56,), (56,)),
    ObEvent("profile", ("Profile",), (57,), (57,)),
    ObEvent("synchronous_cycle", ("Synchronous Cycle",), (61, 62, 63, 64), (61, 62, 63, 64)),
    ObEvent("mc_preservo", ("MC-PreServo",), (), (67,)),
    ObEvent("time_error", ("Time error interrupt", "Time error"), (80,), (80,)),
    ObEvent("diagnostic_error", ("Diagnostic error interrupt",), (82,), (82,)),
    ObEvent("pull_or_plug", ("Pull or plug of modules",), (83,), (83,)),
    ObEvent("rack_failure", ("Rack or station failure",), (86,), (86,)),
    ObEvent("mc_servo", ("MC-Servo",), (), (91,)),
    ObEvent("mc_interpolator", ("MC-Interpolator",), (), (92,)),
    ObEvent("mc_postservo", ("MC-PostServo",), (), (95,)),
    ObEvent("programming_error", ("Programming error",), (121,), (121,)),
    ObEvent("io_access_error", ("I/O access error", "IO access error"), (122,), (122,)),
)

# STEP 7 Classic's standard library symbols of the OBs: each names exactly one OB.
CLASSIC_SYMBOLS: dict[str, int] = {
    "cycl_exc": 1,
    **{f"tod_int{k}": 10 + k for k in range(8)},
    **{f"del_int{k}": 20 + k for k in range(4)},
    **{f"cyc_int{k}": 30 + k for k in range(9)},
    **{f"hw_int{k}": 40 + k for k in range(8)},
    "cycl_flt": 80,
    "ps_flt": 81,
    "i/o_flt1": 82,
    "i/o_flt2": 83,
    "cpu_flt": 84,
    "obnl_flt": 85,
    "rack_flt": 86,
    "comm_flt": 87,
    "backgrnd": 90,
    "complete restart": 100,
    "restart": 101,
    "cold restart": 102,
    "prog_err": 121,
    "mod_err": 122,
    "background": 90,
    "multi_int": 60,
    **{f"sync_{k}": 60 + k for k in range(1, 5)},
    # The OB comments of STEP 7's standard symbol table, which Classic sources also use as the
    # OBs' symbols ("Cycle Execution", "Cyclic Interrupt 5" ...).
    "cycle execution": 1,
    **{f"time of day interrupt {k}": 10 + k for k in range(8)},
    **{f"time delay interrupt {k}": 20 + k for k in range(4)},
    **{f"cyclic interrupt {k}": 30 + k for k in range(9)},
    **{f"hardware interrupt {k}": 40 + k for k in range(8)},
    "multicomputing interrupt": 60,
    **{f"dp synchronous interrupt {k}": 60 + k for k in range(1, 5)},
    "cycle time fault": 80,
    "power supply fault": 81,
    "i/o point fault 1": 82,
    "i/o point fault 2": 83,
    "cpu fault": 84,
    "ob not loaded fault": 85,
    "loss of rack fault": 86,
    "communication fault": 87,
    "background cycle": 90,
    "module access error": 122,
}

_SUFFIX = re.compile(r"^(.*?)_\d+$")
_NUMBERED = re.compile(r"\[\s*OB\s*(\d+)\s*\]\s*$", re.IGNORECASE)  # "Main [OB1]", as TIA lists it


def _compact(text: str) -> str:
    """Letters and digits only: "CyclicInterrupt", "cyclic_interrupt" read as "Cyclic interrupt"."""
    return re.sub(r"[^0-9a-z]", "", text.casefold())


_BY_NAME: dict[str, ObEvent] = {name.casefold(): event for event in EVENTS for name in event.names}
_BY_COMPACT: dict[str, ObEvent] = {
    _compact(name): event for event in EVENTS for name in event.names
}


def ob_event(name: str) -> ObEvent | None:
    """The event an OB name stands for, or None: ``"Cyclic interrupt_2"``, ``"CyclicInterrupt"``
    and ``"obCyclicInterrupt"`` are the cyclic interrupt."""
    key = name.strip().casefold()
    match = _SUFFIX.match(key)
    for candidate in (key, match.group(1)) if match is not None else (key,):
        compact = _compact(candidate)
        found = (
            _BY_NAME.get(candidate)
            or _BY_COMPACT.get(compact)
            or (_BY_COMPACT.get(compact[2:]) if compact.startswith("ob") else None)
        )
        if found is not None:
            return found
    return None


def ob_number(name: str, taken: Collection[int], profile: str) -> int | None:
    """The number TIA gives a new OB called ``name`` when ``taken`` OB numbers are used, or
    None where there is none (S7-300/400: not an event name, or the event's numbers used up).
    A Classic symbol (``CYC_INT5``) gives its own number even if taken (a duplicate)."""
    numbered = _NUMBERED.search(name)
    if numbered is not None:
        return int(numbered.group(1))
    key = name.strip().casefold()
    exact = CLASSIC_SYMBOLS.get(key)
    if exact is not None:
        return exact
    event = ob_event(name)
    modern = is_s7_1500(profile)
    if event is not None:
        for number in event.s7_1500 if modern else event.classic:
            if number not in taken:
                return number
    if not modern:
        return None
    for number in range(FIRST_FREE_OB, LAST_OB + 1):
        if number not in taken:
            return number
    return None

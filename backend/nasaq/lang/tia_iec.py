"""TIA Portal's IEC counters and timers of the other types (S7-1200/1500 only): CTU, CTD and
CTUD counting in SINT, USINT, UINT, DINT, UDINT, LINT or ULINT (``CTU_DINT``, ``CTD_UDINT``,
``CTUD_LINT`` ..., and the counter types ``IEC_SCOUNTER`` ... ``IEC_ULCOUNTER`` laid out as
their CTUD), and TP, TON, TOF of an LTIME (``TP_LTIME``, ``TON_LTIME``, ``TOF_LTIME``,
``IEC_LTIMER`` laid out as TON_LTIME). The INT counters and TIME timers are SFB 0-5.

No S7-300/400 has them: Nasaq numbers them SFB 1200-1223 (``COMPATIBILITY.md``, "64-bit
values in watch and monitor (longs)"). The parameters are TIA's for these CPUs: ``CU``, ``CD``,
``R``, ``LD`` (load; SFB 1/2 of the S7-300/400 call it ``LOAD``), ``PV``, ``Q``/``QU``/``QD``,
``CV``; ``IN``, ``PT``, ``Q``, ``ET``. The static members after them are Nasaq's (edge
memories, the timer's state and its start time), as for SFB 0-5. Bodies: ``nasaq.cpu.tia_iec``.
"""

from __future__ import annotations

FIRST = 1200
COUNTER_TYPES = ("SINT", "USINT", "UINT", "DINT", "UDINT", "LINT", "ULINT")
# The counter types TIA gives each integer (its CTUD layout), by the integer.
COUNTER_TYPE_NAMES = {
    "SINT": "IEC_SCOUNTER",
    "USINT": "IEC_USCOUNTER",
    "UINT": "IEC_UCOUNTER",
    "DINT": "IEC_DCOUNTER",
    "UDINT": "IEC_UDCOUNTER",
    "LINT": "IEC_LCOUNTER",
    "ULINT": "IEC_ULCOUNTER",
}
COUNTERS = ("CTU", "CTD", "CTUD")
TIMERS = ("TP", "TON", "TOF")
# The classic SFB of each instruction (what ``x.CTU(...)`` names after its dot).
CLASSIC = {"CTU": 0, "CTD": 1, "CTUD": 2, "TP": 3, "TON": 4, "TOF": 5}
_LTIMER_FIRST = FIRST + len(COUNTER_TYPES) * len(COUNTERS)  # 1221


def counter_number(instruction: str, kind: str) -> int:
    """The SFB number of ``instruction`` (CTU, CTD, CTUD) counting in ``kind``."""
    return FIRST + COUNTER_TYPES.index(kind) * len(COUNTERS) + COUNTERS.index(instruction)


def timer_number(instruction: str) -> int:
    """The SFB number of ``instruction`` (TP, TON, TOF) of an LTIME."""
    return _LTIMER_FIRST + TIMERS.index(instruction)


def _counter(instruction: str, kind: str) -> list[tuple[str, str, str]]:
    if instruction == "CTU":
        return [
            ("IN", "CU", "BOOL"),
            ("IN", "R", "BOOL"),
            ("IN", "PV", kind),
            ("OUT", "Q", "BOOL"),
            ("OUT", "CV", kind),
            ("STAT", "CUO", "BOOL"),
        ]
    if instruction == "CTD":
        return [
            ("IN", "CD", "BOOL"),
            ("IN", "LD", "BOOL"),
            ("IN", "PV", kind),
            ("OUT", "Q", "BOOL"),
            ("OUT", "CV", kind),
            ("STAT", "CDO", "BOOL"),
        ]
    return [
        ("IN", "CU", "BOOL"),
        ("IN", "CD", "BOOL"),
        ("IN", "R", "BOOL"),
        ("IN", "LD", "BOOL"),
        ("IN", "PV", kind),
        ("OUT", "QU", "BOOL"),
        ("OUT", "QD", "BOOL"),
        ("OUT", "CV", kind),
        ("STAT", "CUO", "BOOL"),
        ("STAT", "CDO", "BOOL"),
    ]


_LTIMER = [
    ("IN", "IN", "BOOL"),
    ("IN", "PT", "LTIME"),
    ("OUT", "Q", "BOOL"),
    ("OUT", "ET", "LTIME"),
    ("STAT", "STATE", "BYTE"),
    ("STAT", "STIME", "TIME"),
    ("STAT", "ATIME", "TIME"),
]

NAMES: dict[int, str] = {}
INTERFACES: dict[int, list[tuple[str, str, str]]] = {}
KINDS: dict[int, tuple[str, str]] = {}  # number -> (instruction, type)
for _kind in COUNTER_TYPES:
    for _name in COUNTERS:
        _number = counter_number(_name, _kind)
        NAMES[_number] = f"{_name}_{_kind}"
        INTERFACES[_number] = _counter(_name, _kind)
        KINDS[_number] = (_name, _kind)
for _name in TIMERS:
    _number = timer_number(_name)
    NAMES[_number] = f"{_name}_LTIME"
    INTERFACES[_number] = _LTIMER
    KINDS[_number] = (_name, "LTIME")

# TIA's instance type names that stand for one of these layouts.
INSTANCE_TYPES: dict[str, int] = {
    name: counter_number("CTUD", kind) for kind, name in COUNTER_TYPE_NAMES.items()
}
INSTANCE_TYPES["IEC_LTIMER"] = timer_number("TON")
_RENAMED = {"CTU": {"Q": "QU"}, "CTD": {"Q": "QD"}}


def paired(have: int, run: int) -> tuple[int, int, dict[str, str]] | None:
    """How the instruction of classic SFB ``run`` (``x.CTU(...)``: 0) runs on an instance of
    SFB ``have`` (one of these): (the SFB whose parameters the call takes, the SFB that runs,
    the parameters whose name in the instance differs); None when it cannot (a CTU on a
    CTD_DINT, a timer on a counter)."""
    found = KINDS.get(have)
    wanted = next((name for name, number in CLASSIC.items() if number == run), None)
    if found is None or wanted is None:
        return None
    instruction, kind = found
    if kind == "LTIME":
        if wanted not in TIMERS:
            return None
        number = timer_number(wanted)  # TP, TON and TOF of an LTIME share one layout
        return number, number, {}
    if wanted not in COUNTERS:
        return None
    number = counter_number(wanted, kind)
    if instruction == wanted:
        return number, number, {}
    if instruction == "CTUD" and wanted in _RENAMED:  # IEC_DCOUNTER.CTU: CTUD, Q from QU
        return number, have, _RENAMED[wanted]
    return None

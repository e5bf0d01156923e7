"""Interfaces of the system blocks: the system function blocks a program may instantiate (IEC
counters and timers), so their instance DBs and multi-instances get the S7-300/400 layout, and
the system functions the CPU runs, so a LAD/FBD call box shows their parameters.

Only the interface is here (what layout, CALL checks and the editors need); what the blocks do
belongs to the CPU. Other SFBs/SFCs are accepted in CALLs without parameter checks.
"""

from __future__ import annotations

_IEC_TIMER = [
    ("IN", "IN", "BOOL"),
    ("IN", "PT", "TIME"),
    ("OUT", "Q", "BOOL"),
    ("OUT", "ET", "TIME"),
    ("STAT", "STATE", "BYTE"),
    ("STAT", "STIME", "TIME"),
    ("STAT", "ATIME", "TIME"),
]

# IEC 61131-3's edge detectors R_TRIG and F_TRIG, which TIA Portal offers for every CPU family
# (S7-300/400 too) but which no S7-300/400 CPU has as a numbered SFB: Nasaq runs them as SFB 1000
# and SFB 1001, numbers no S7-300/400 system block uses (backend/nasaq/cpu/COMPATIBILITY.md).
R_TRIG_SFB = 1000
F_TRIG_SFB = 1001
_EDGE = [("IN", "CLK", "BOOL"), ("OUT", "Q", "BOOL"), ("STAT", "M", "BOOL")]

SFB_NAMES: dict[int, str] = {
    0: "CTU",
    1: "CTD",
    2: "CTUD",
    3: "TP",
    4: "TON",
    5: "TOF",
    R_TRIG_SFB: "R_TRIG",
    F_TRIG_SFB: "F_TRIG",
}

SFB_INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    0: [  # CTU
        ("IN", "CU", "BOOL"),
        ("IN", "R", "BOOL"),
        ("IN", "PV", "INT"),
        ("OUT", "Q", "BOOL"),
        ("OUT", "CV", "INT"),
        ("STAT", "CUO", "BOOL"),
    ],
    1: [  # CTD
        ("IN", "CD", "BOOL"),
        ("IN", "LOAD", "BOOL"),
        ("IN", "PV", "INT"),
        ("OUT", "Q", "BOOL"),
        ("OUT", "CV", "INT"),
        ("STAT", "CDO", "BOOL"),
    ],
    2: [  # CTUD
        ("IN", "CU", "BOOL"),
        ("IN", "CD", "BOOL"),
        ("IN", "R", "BOOL"),
        ("IN", "LOAD", "BOOL"),
        ("IN", "PV", "INT"),
        ("OUT", "QU", "BOOL"),
        ("OUT", "QD", "BOOL"),
        ("OUT", "CV", "INT"),
        ("STAT", "CUO", "BOOL"),
        ("STAT", "CDO", "BOOL"),
    ],
    3: _IEC_TIMER,  # TP
    4: _IEC_TIMER,  # TON
    5: _IEC_TIMER,  # TOF
    R_TRIG_SFB: _EDGE,
    F_TRIG_SFB: _EDGE,
}

# The system functions the CPU runs (``nasaq.cpu.calls``): their names and parameters.
SFC_NAMES: dict[int, str] = {1: "READ_CLK", 43: "RE_TRIGR", 46: "STP", 64: "TIME_TCK"}
SFC_INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    1: [("OUT", "RET_VAL", "INT"), ("OUT", "CDT", "DATE_AND_TIME")],
    43: [],  # retrigger the cycle monitoring: nothing to do in the simulator (COMPATIBILITY.md)
    46: [],
    64: [("OUT", "RET_VAL", "TIME")],
}

# Nasaq's numbers from 1100 up are for instructions of the S7-1200/1500 family only.
S7_1500_FROM = 1100


def sfb_number(name: str) -> int | None:
    """The SFB a system block's name (any case) stands for, None for other names."""
    if len(_BY_NAME) != len(SFB_NAMES):  # filled at first use, after every merge below
        _BY_NAME.update({n.upper(): number for number, n in SFB_NAMES.items()})
    return _BY_NAME.get(name.upper())


def s7_1500_only(number: int) -> bool:
    """Whether SFB ``number`` exists on S7-1200/1500 CPUs only (SCL500 under S7-300/400)."""
    return number >= S7_1500_FROM and number not in CLASSIC_TOO


# Blocks numbered from 1100 that S7-300/400 have too (as library FBs: TCON FB 65 ...).
CLASSIC_TOO: set[int] = set()


_BY_NAME: dict[str, int] = {}

# -- merge points: each module that brings system blocks adds its line here (no cycles: those
# modules import neither this one nor ``system_types``) --------------------------------------------
from nasaq.lang import tia_control  # noqa: E402  (sysfb: PID_Compact, CTRL_HSC)

SFB_NAMES.update(tia_control.NAMES)
SFB_INTERFACES.update(tia_control.INTERFACES)
SFC_NAMES.update(tia_control.SFC_NAMES)
SFC_INTERFACES.update(tia_control.SFC_INTERFACES)
from nasaq.lang import tia_comm  # noqa: E402  (syscomm: TCON ..., GET/PUT, data logs, RD_SINFO)

SFB_NAMES.update(tia_comm.NAMES)
SFB_INTERFACES.update(tia_comm.INTERFACES)
SFC_NAMES.update(tia_comm.SFC_NAMES)
SFC_INTERFACES.update(tia_comm.SFC_INTERFACES)
CLASSIC_TOO.update(tia_comm.CLASSIC)
from nasaq.lang import tia_iec  # noqa: E402  (longs: CTU_DINT ..., TON_LTIME ...)

SFB_NAMES.update(tia_iec.NAMES)
SFB_INTERFACES.update(tia_iec.INTERFACES)
from nasaq.lang import tia_filters  # noqa: E402  (filters: Filter_PT1, Filter_DT1, Filter_PT2)

SFB_NAMES.update(tia_filters.NAMES)
SFB_INTERFACES.update(tia_filters.INTERFACES)

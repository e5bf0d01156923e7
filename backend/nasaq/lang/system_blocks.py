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
SFC_NAMES: dict[int, str] = {1: "READ_CLK", 46: "STP", 64: "TIME_TCK"}
SFC_INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    1: [("OUT", "RET_VAL", "INT"), ("OUT", "CDT", "DATE_AND_TIME")],
    46: [],
    64: [("OUT", "RET_VAL", "TIME")],
}

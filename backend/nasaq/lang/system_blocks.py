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

SFB_NAMES: dict[int, str] = {0: "CTU", 1: "CTD", 2: "CTUD", 3: "TP", 4: "TON", 5: "TOF"}

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
}

# The system functions the CPU runs (``nasaq.cpu.calls``): their names and parameters.
SFC_NAMES: dict[int, str] = {46: "STP", 64: "TIME_TCK"}
SFC_INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    46: [],
    64: [("OUT", "RET_VAL", "TIME")],
}

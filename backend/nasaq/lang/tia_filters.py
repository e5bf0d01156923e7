"""Interfaces of TIA Portal's filter instructions of the "basic functions for controllers"
(S7-1500, LibVersion 1.0): Filter_PT1 (first-order lag), Filter_DT1 (derivative with a
first-order lag) and Filter_PT2 (second-order lag), numbered by Nasaq SFB 1130-1132 (no
S7-300/400 has them, so SCL500 there). What they compute is ``nasaq.cpu.tia_filters``.

As in TIA, the parameters that change rarely are static members of the instance, written
before the call (``#f.Lag := 2.0;``): Gain, Lag (PT2: TimeConstant, Damping) and the cycle
time ``CycleTime.Value`` (seconds) with ``CycleTime.EnableMeasurement`` (TRUE: measured from
the CPU's clock at every call). Members ending in ``_N`` are Nasaq's own state of the filter.

The tables follow the contract of ``nasaq.lang.system_types`` and are merged into
``system_blocks``/``system_types`` at the bottom of those modules; this module imports neither.
"""

from __future__ import annotations

from nasaq.lang.types import Elementary, Field, StructType

FILTER_PT1 = 1130
FILTER_DT1 = 1131
FILTER_PT2 = 1132

CYCLE_TIME = "Filter_CycleTime"

TYPES: dict[str, StructType] = {
    CYCLE_TIME: StructType(
        (
            Field("Value", Elementary("REAL"), 0.1),
            Field("EnableMeasurement", Elementary("BOOL"), True),
        )
    ),
}

NAMES: dict[int, str] = {
    FILTER_PT1: "Filter_PT1",
    FILTER_DT1: "Filter_DT1",
    FILTER_PT2: "Filter_PT2",
}

_COMMON_IN = [
    ("IN", "Input", "REAL"),
    ("IN", "SubstituteOutput", "REAL"),
    ("IN", "SubstituteOutputActive", "BOOL"),
    ("IN", "Reset", "BOOL"),
]
_COMMON_OUT = [
    ("OUT", "Output", "REAL"),
    ("OUT", "ErrorBits", "DWORD"),
    ("OUT", "Error", "BOOL"),
]
# Nasaq's state: the CPU time (ms) of the previous call and whether one has been made.
_STATE = [("STAT", "Tick_N", "DINT"), ("STAT", "Started_N", "BOOL")]

INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    FILTER_PT1: [
        *_COMMON_IN,
        *_COMMON_OUT,
        ("STAT", "Gain", "REAL := 1.0"),
        ("STAT", "Lag", "REAL := 1.0"),
        ("STAT", "CycleTime", CYCLE_TIME),
        *_STATE,
    ],
    FILTER_DT1: [
        *_COMMON_IN,
        *_COMMON_OUT,
        ("STAT", "Gain", "REAL := 1.0"),
        ("STAT", "Lag", "REAL := 1.0"),
        ("STAT", "CycleTime", CYCLE_TIME),
        *_STATE,
        ("STAT", "InputOld_N", "REAL"),  # the input of the previous call
    ],
    FILTER_PT2: [
        *_COMMON_IN,
        *_COMMON_OUT,
        ("STAT", "Gain", "REAL := 1.0"),
        ("STAT", "TimeConstant", "REAL := 1.0"),
        ("STAT", "Damping", "REAL := 1.0"),
        ("STAT", "CycleTime", CYCLE_TIME),
        *_STATE,
        ("STAT", "Slope_N", "REAL"),  # the output's rate of change (per second)
    ],
}

"""Interfaces of the TIA Portal control and counting system blocks Nasaq runs (S7-1200/1500):
PID_Compact (V1.x, as its instance DBs and ``#pid.sRet.r_Ctrl_Gain`` name its members) and
CTRL_HSC, numbered by Nasaq from SFB 1100 (no S7-300/400 has them), and the system data
type HW_HSC. What the blocks do is ``nasaq.cpu.tia_control``; the instruction-like functions
RUNTIME, RESET_TIMER and PRESET_TIMER are ``nasaq.lang.tia_timing``.

The tables follow the contract of ``nasaq.lang.system_types``: ``NAMES``, ``INTERFACES``
(``(section, name, type_text)``) and ``TYPES`` are merged into ``system_blocks`` and
``system_types`` at the bottom of those modules. This module imports neither.

PID_Compact V1.x (S7-1200/1500 PID control manual, "PID_Compact V1"): the parameters Setpoint,
Input, Input_PER, ManualEnable, ManualValue, Reset; ScaledInput, Output, Output_PER,
Output_PWM, SetpointLimit_H/L, InputWarning_H/L, State, Error; and the static members the
manual lists (sb_RunModeByStartup, sBackUp, sPid_Calc, sPid_Cmpt, sParamCalc, sRet ...),
with the manual's initial values. Members named ``..._N`` at the end of ``sPid_Calc`` are
Nasaq's own state of its PID algorithm (COMPATIBILITY.md, "sysfb").
"""

from __future__ import annotations

from nasaq.lang.types import Elementary, Field, StructType

PID_COMPACT = 1100
CTRL_HSC = 1101

REAL_MAX = 3.402822e38


def _struct(*members: tuple[str, str, object]) -> StructType:
    return StructType(
        tuple(Field(name, Elementary(kind), initial) for name, kind, initial in members)
    )


PID_BACKUP = _struct(
    ("r_Gain", "REAL", 1.0),
    ("r_Ti", "REAL", 20.0),
    ("r_Td", "REAL", 0.0),
    ("r_A", "REAL", 0.0),
    ("r_B", "REAL", 0.0),
    ("r_C", "REAL", 0.0),
    ("r_Cycle", "REAL", 1.0),
)
PID_CALC = _struct(
    ("r_Cycle", "REAL", 0.1),
    ("b_RunIn", "BOOL", False),
    ("b_CalcParamSUT", "BOOL", False),
    ("b_CalcParamTIR", "BOOL", False),
    ("i_CtrlTypeSUT", "INT", 0),
    ("i_CtrlTypeTIR", "INT", 0),
    ("r_Isum_N", "REAL", 0.0),  # Nasaq: the integral action (in output units)
    ("r_Dpart_N", "REAL", 0.0),  # Nasaq: the filtered derivative action
    ("r_PvOld_N", "REAL", 0.0),  # Nasaq: the process value of the previous sample
    ("d_Tick_N", "DINT", 0),  # Nasaq: the system time (ms) of the previous call
    ("i_ModeOld_N", "INT", -1),  # Nasaq: sRet.i_Mode at the previous call (edge detection)
    ("b_First_N", "BOOL", True),  # Nasaq: no sample yet since the start
    ("b_ResetOld_N", "BOOL", False),  # Nasaq: Reset at the previous call
    ("i_Auto_N", "INT", 0),  # Nasaq: the mode without ManualEnable (returned to after it)
)
PID_CMPT = _struct(
    ("r_Sp_Hlm", "REAL", REAL_MAX),
    ("r_Sp_Llm", "REAL", -REAL_MAX),
    ("r_Pv_Norm_IN_1", "REAL", 0.0),
    ("r_Pv_Norm_IN_2", "REAL", 27648.0),
    ("r_Pv_Norm_OUT_1", "REAL", 0.0),
    ("r_Pv_Norm_OUT_2", "REAL", 100.0),
    ("r_Lmn_Hlm", "REAL", 100.0),
    ("r_Lmn_Llm", "REAL", 0.0),
    ("b_Input_PER_On", "BOOL", True),
    ("b_LoadBackUp", "BOOL", False),
    ("b_InvCtrl", "BOOL", False),
    ("r_Lmn_Pwm_PPTm", "REAL", 0.0),
    ("r_Lmn_Pwm_PBTm", "REAL", 0.0),
    ("r_Pv_Hlm", "REAL", 120.0),
    ("r_Pv_Llm", "REAL", 0.0),
    ("r_Pv_HWrn", "REAL", REAL_MAX),
    ("r_Pv_LWrn", "REAL", -REAL_MAX),
)
PID_PARAM_CALC = _struct(("i_Event_SUT", "INT", 0), ("i_Event_TIR", "INT", 0))
PID_RET = _struct(
    ("i_Mode", "INT", 0),
    ("r_Ctrl_Gain", "REAL", 1.0),
    ("r_Ctrl_Ti", "REAL", 20.0),
    ("r_Ctrl_Td", "REAL", 0.0),
    ("r_Ctrl_A", "REAL", 0.0),
    ("r_Ctrl_B", "REAL", 0.0),
    ("r_Ctrl_C", "REAL", 0.0),
    ("r_Ctrl_Cycle", "REAL", 1.0),
)

TYPES: dict[str, StructType] = {
    "PID_Compact_BackUp": PID_BACKUP,
    "PID_Compact_Calc": PID_CALC,
    "PID_Compact_Cmpt": PID_CMPT,
    "PID_Compact_ParamCalc": PID_PARAM_CALC,
    "PID_Compact_Ret": PID_RET,
}
# System data types that are a hardware identifier: a number the CPU gives each hardware object
# (HW_HSC: a high-speed counter), a WORD in the instance (TIA: HW_ANY, a UINT-sized identifier).
ALIASES: dict[str, str] = {"HW_HSC": "WORD"}

NAMES: dict[int, str] = {PID_COMPACT: "PID_Compact", CTRL_HSC: "CTRL_HSC"}

INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    PID_COMPACT: [
        ("IN", "Setpoint", "REAL"),
        ("IN", "Input", "REAL"),
        ("IN", "Input_PER", "WORD"),
        ("IN", "ManualEnable", "BOOL"),
        ("IN", "ManualValue", "REAL"),
        ("IN", "Reset", "BOOL"),
        ("OUT", "ScaledInput", "REAL"),
        ("OUT", "Output", "REAL"),
        ("OUT", "Output_PER", "WORD"),
        ("OUT", "Output_PWM", "BOOL"),
        ("OUT", "SetpointLimit_H", "BOOL"),
        ("OUT", "SetpointLimit_L", "BOOL"),
        ("OUT", "InputWarning_H", "BOOL"),
        ("OUT", "InputWarning_L", "BOOL"),
        ("OUT", "State", "INT"),
        ("OUT", "Error", "DWORD"),
        ("STAT", "sb_GetCycleTime", "BOOL"),
        ("STAT", "sb_EnCyclEstimation", "BOOL := TRUE"),
        ("STAT", "sb_EnCyclMonitoring", "BOOL := TRUE"),
        ("STAT", "sb_RunModeByStartup", "BOOL := TRUE"),
        ("STAT", "sby_EsData_1", "BYTE"),
        ("STAT", "sby_EsData_2", "BYTE"),
        ("STAT", "si_Unit", "INT"),
        ("STAT", "si_Type", "INT"),
        ("STAT", "sd_Warning", "DWORD"),
        ("STAT", "sBackUp", "PID_Compact_BackUp"),
        ("STAT", "sPid_Calc", "PID_Compact_Calc"),
        ("STAT", "sPid_Cmpt", "PID_Compact_Cmpt"),
        ("STAT", "sParamCalc", "PID_Compact_ParamCalc"),
        ("STAT", "sRet", "PID_Compact_Ret"),
    ],
    CTRL_HSC: [
        ("IN", "HSC", "HW_HSC"),
        ("IN", "DIR", "BOOL"),
        ("IN", "CV", "BOOL"),
        ("IN", "RV", "BOOL"),
        ("IN", "PERIOD", "BOOL"),
        ("IN", "NEW_DIR", "INT"),
        ("IN", "NEW_CV", "DINT"),
        ("IN", "NEW_RV", "DINT"),
        ("IN", "NEW_PERIOD", "INT"),
        ("OUT", "BUSY", "BOOL"),
        ("OUT", "STATUS", "WORD"),
    ],
}

# System functions without an instance, numbered by Nasaq in its sysfb range (no S7-300/400 has
# them): RUNTIME measures the time between two calls (``MEM``: the time stamp of the previous
# call, in seconds of the CPU's system time; the value: the seconds since then).
RUNTIME_SFC = 780
SFC_NAMES: dict[int, str] = {RUNTIME_SFC: "RUNTIME"}
SFC_INTERFACES: dict[int, list[tuple[str, str, str]]] = {
    RUNTIME_SFC: [("IN_OUT", "MEM", "LREAL"), ("OUT", "RET_VAL", "LREAL")],
}

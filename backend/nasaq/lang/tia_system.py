"""TIA Portal's (and STEP 7's) system blocks, system data types and system instructions that
Nasaq does not simulate, so that a source using them is told so by name (``SCL920``) rather
than "unknown data type" (``SCL202``) or "not declared" (``SCL201``). TIA writes them unquoted;
a block, symbol or variable of the program with the same name is that, not the system one
(only names nothing declares end here). The IEC timers and counters are not here: Nasaq runs
them.

Not complete: what real projects use most (communication, PID, motion, counting, diagnostics,
data logging, VARIANT handling, runtime measurement).
"""

from __future__ import annotations

_NAMES = (
    # communication
    "TUSEND", "TURCV", "TMAIL_C",
    "BSEND", "BRCV", "USEND", "URCV", "MB_CLIENT",
    "MB_SERVER", "MB_MASTER", "MB_SLAVE", "MB_COMM_LOAD", "RDREC", "WRREC", "RALRM",
    "DPRD_DAT", "DPWR_DAT", "PNIO_SEND", "PNIO_RECV",
    # system data types
    "ErrorStruct",
    # control, counting, motion
    "PID_3Step", "PID_Temp", "CONT_C", "CONT_S", "PULSEGEN", "TCONT_CP",
    "CTRL_HSC_EXT", "CTRL_PWM", "CTRL_PTO", "High_Speed_Counter", "MC_Power",
    "MC_Home", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity", "MC_MoveJog",
    "MC_Halt", "MC_Reset", "TO_PositioningAxis", "TO_SpeedAxis", "TO_Axis",
    "TO_CommandTable",
    # diagnostics, block information, runtime
    "GET_ERROR", "GET_ERR_ID", "GetSymbolName",
    "GetInstanceName", "GetSymbolPath", "GetInstancePath", "GET_DIAG", "GEN_DIAG",
    "DeviceStates", "ModuleStates", "LED", "Get_IM_Data", "RD_DPARA",
    # strings, VARIANT, memory
    "S_CONV",
    "POKE_BLK", "BLKMOV", "UBLKMOV", "FILL",
    # timers and clock
    "WR_SYS_T", "WR_LOC_T", "SET_TIMEZONE", "SET_CLK",
    # data logging and recipes
    "RecipeExport", "RecipeImport", "Program_Alarm", "Get_AlarmState", "Gen_UsrMsg",
    # more the corpus declares (issue 20, gaps): serial and Modbus, technology objects, types
    "Modbus_Comm_Load", "Modbus_Master", "Modbus_Slave", "Send_P2P", "Receive_P2P",
    "Port_Config", "Send_Config", "Receive_Config", "USS_Port_Scan", "USS_Drive_Control",
    "TO_SynchronousAxis", "TO_ExternalEncoder", "TO_Axis_PTO", "TO_CommandTable_PTO",
    "TO_OutputCam", "TO_MeasuringInput", "TO_Cam", "TO_Kinematics", "MC_CommandTable",
    "MC_ChangeDynamic", "MC_WriteParam", "MC_ReadParam", "MC_GearIn", "MC_MoveSuperimposed",
    "TCON_QDN", "TADDR_Send_QDN", "HW_PWM", "HW_PTO", "EVENT_ANY",
    "EVENT_ATT", "EVENT_HWINT", "OB_ANY", "OB_DELAY", "OB_TOD", "OB_CYCLIC", "OB_ATT",
    "OB_PCYCLE", "OB_HWINT", "OB_DIAG", "OB_TIMEERROR", "OB_STARTUP", "PORT", "RTM", "PIP",
    "DB_WWW", "AOM_IDENT", "GEOADDR", "GetStationInfo", "D_ACT_DP",
)  # fmt: skip
_SPELLING = {name.upper(): name for name in _NAMES}
SYSTEM_NAMES = frozenset(_SPELLING)


def tia_system(name: str) -> str | None:
    """The system block, type or instruction ``name`` (any case) stands for, spelt as TIA
    spells it; None when it is none of them."""
    return _SPELLING.get(name.upper())

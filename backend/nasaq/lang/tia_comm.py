"""Interfaces of the communication, data logging and block information instructions
(``syscomm``): Open User Communication (TCON, TDISCON, TSEND, TRCV, TSEND_C, TRCV_C), S7
communication (GET, PUT), the CP blocks AG_SEND/AG_RECV, the data logs of the S7-1200/1500
(DataLogCreate ... DataLogDelete), RD_SINFO, and the system data types they use.

Interfaces as Siemens documents them (System Software for S7-300/400, System and Standard
Functions, "Open Communication via Industrial Ethernet" and "S7 Communication"; S7-1200 and
S7-1500 system manuals, "Open user communication", "Data logs"). The STAT members of each block
are Nasaq's own (a real CPU keeps its job state where the manuals do not say): they carry the
previous REQ for the edge and the job's step.

Numbers (``backend/nasaq/cpu/COMPATIBILITY.md``, "Communication and data logging"):
- GET SFB 14, PUT SFB 15, RD_SINFO SFC 6: the S7-300/400 numbers.
- TCON, TDISCON, TSEND, TRCV are FB 65, 66, 63, 64 of STEP 7's Standard Library on S7-300/400:
  FBs, which would take numbers of the program's own FBs, and SFB 63-65 are other blocks (the
  31xC point-to-point SFBs), so Nasaq runs them as SFB 1150-1153; they exist on both families
  (``CLASSIC``). TSEND_C/TRCV_C (1154, 1155) and the data logs (1160-1166) are S7-1200/1500 only.
- AG_SEND (FC 5), AG_RECV (FC 6) and AG_CNTRL (FC 10) of the SIMATIC NET CP library run as
  system functions SFC 750-752 (called by name; a program's own FC 5, 6, 10 keep theirs).

No import of ``system_blocks`` or ``system_types`` here: those modules merge these tables.
"""

from __future__ import annotations

from nasaq.lang.types import ArrayType, Elementary, Field, StringType, StructType

TCON, TDISCON, TSEND, TRCV, TSEND_C, TRCV_C = 1150, 1151, 1152, 1153, 1154, 1155
GET, PUT = 14, 15
LOG_CREATE, LOG_OPEN, LOG_WRITE, LOG_CLOSE, LOG_NEW_FILE, LOG_DELETE, LOG_CLEAR = range(1160, 1167)
RD_SINFO = 6

NAMES: dict[int, str] = {
    GET: "GET",
    PUT: "PUT",
    TCON: "TCON",
    TDISCON: "TDISCON",
    TSEND: "TSEND",
    TRCV: "TRCV",
    TSEND_C: "TSEND_C",
    TRCV_C: "TRCV_C",
    LOG_CREATE: "DataLogCreate",
    LOG_OPEN: "DataLogOpen",
    LOG_WRITE: "DataLogWrite",
    LOG_CLOSE: "DataLogClose",
    LOG_NEW_FILE: "DataLogNewFile",
    LOG_DELETE: "DataLogDelete",
    LOG_CLEAR: "DataLogClear",
}
# Blocks that also exist on S7-300/400 (GET/PUT as SFBs, TCON ... as library FBs).
CLASSIC = frozenset({GET, PUT, TCON, TDISCON, TSEND, TRCV})

Interface = list[tuple[str, str, str]]

# TIA's VARIANT parameters: laid out as an ANY (10 bytes) until the interface parser gives
# VARIANT its descriptor (``nasaq.lang.scl.descriptor``); the bodies do not read them.
_VARIANT = "ANY"

_RESULT = [("OUT", "DONE", "BOOL"), ("OUT", "BUSY", "BOOL"), ("OUT", "ERROR", "BOOL")]
_STATUS = [("OUT", "STATUS", "WORD")]
# Nasaq's job state: the previous REQ (edge), the step, a second key (the log or connection).
_JOB = [("STAT", "REQ_OLD", "BOOL"), ("STAT", "STEP", "BYTE"), ("STAT", "KEY", "DWORD")]


def _get_put(request: str) -> Interface:
    first = [("IN", "REQ", "BOOL"), ("IN", "ID", "WORD")]
    outs = [("OUT", "NDR" if request == "RD" else "DONE", "BOOL"), ("OUT", "ERROR", "BOOL")]
    areas = [("IN_OUT", f"ADDR_{i}", "ANY") for i in range(1, 5)]
    areas += [("IN_OUT", f"{request}_{i}", "ANY") for i in range(1, 5)]
    return first + outs + _STATUS + areas + _JOB


INTERFACES: dict[int, Interface] = {
    GET: _get_put("RD"),
    PUT: _get_put("SD"),
    TCON: [
        ("IN", "REQ", "BOOL"),
        ("IN", "ID", "WORD"),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "CONNECT", "ANY"),
        *_JOB,
    ],
    TDISCON: [("IN", "REQ", "BOOL"), ("IN", "ID", "WORD"), *_RESULT, *_STATUS, *_JOB],
    TSEND: [
        ("IN", "REQ", "BOOL"),
        ("IN", "ID", "WORD"),
        ("IN", "LEN", "INT"),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "DATA", "ANY"),
        *_JOB,
    ],
    TRCV: [
        ("IN", "EN_R", "BOOL"),
        ("IN", "ID", "WORD"),
        ("IN", "LEN", "INT"),
        ("IN", "ADHOC", "BOOL"),
        ("OUT", "NDR", "BOOL"),
        ("OUT", "BUSY", "BOOL"),
        ("OUT", "ERROR", "BOOL"),
        *_STATUS,
        ("OUT", "RCVD_LEN", "INT"),
        ("IN_OUT", "DATA", "ANY"),
        *_JOB,
    ],
    TSEND_C: [
        ("IN", "REQ", "BOOL"),
        ("IN", "CONT", "BOOL"),
        ("IN", "LEN", "UDINT"),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "CONNECT", _VARIANT),
        ("IN_OUT", "DATA", _VARIANT),
        ("IN_OUT", "ADDR", _VARIANT),
        ("IN_OUT", "COM_RST", "BOOL"),
        *_JOB,
    ],
    TRCV_C: [
        ("IN", "EN_R", "BOOL"),
        ("IN", "CONT", "BOOL"),
        ("IN", "LEN", "UDINT"),
        ("IN", "ADHOC", "BOOL"),
        *_RESULT,
        *_STATUS,
        ("OUT", "RCVD_LEN", "UDINT"),
        ("IN_OUT", "CONNECT", _VARIANT),
        ("IN_OUT", "DATA", _VARIANT),
        ("IN_OUT", "ADDR", _VARIANT),
        ("IN_OUT", "COM_RST", "BOOL"),
        *_JOB,
    ],
    LOG_CREATE: [
        ("IN", "REQ", "BOOL"),
        ("IN", "RECORDS", "UDINT"),
        ("IN", "FORMAT", "UINT"),
        ("IN", "TIMESTAMP", "UINT"),
        ("IN", "NAME", _VARIANT),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "ID", "DWORD"),
        ("IN_OUT", "HEADER", _VARIANT),
        ("IN_OUT", "DATA", _VARIANT),
        *_JOB,
    ],
    LOG_OPEN: [
        ("IN", "REQ", "BOOL"),
        ("IN", "MODE", "UINT"),
        ("IN", "NAME", _VARIANT),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "ID", "DWORD"),
        ("IN_OUT", "DATA", _VARIANT),
        *_JOB,
    ],
    LOG_WRITE: [("IN", "REQ", "BOOL"), *_RESULT, *_STATUS, ("IN_OUT", "ID", "DWORD"), *_JOB],
    LOG_CLOSE: [("IN", "REQ", "BOOL"), *_RESULT, *_STATUS, ("IN_OUT", "ID", "DWORD"), *_JOB],
    LOG_NEW_FILE: [
        ("IN", "REQ", "BOOL"),
        ("IN", "RECORDS", "UDINT"),
        ("IN", "NAME", _VARIANT),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "ID", "DWORD"),
        ("IN_OUT", "DATA", _VARIANT),
        *_JOB,
    ],
    LOG_DELETE: [
        ("IN", "REQ", "BOOL"),
        ("IN", "NAME", _VARIANT),
        ("IN", "DelFile", "BOOL"),
        *_RESULT,
        *_STATUS,
        ("IN_OUT", "ID", "DWORD"),
        *_JOB,
    ],
    LOG_CLEAR: [("IN", "REQ", "BOOL"), *_RESULT, *_STATUS, ("IN_OUT", "ID", "DWORD"), *_JOB],
}

# The start information RD_SINFO (SFC 6) reads: TIA's SI_classic, the S7-300/400 layout.
SI_MEMBERS = (
    ("EV_CLASS", "BYTE"),
    ("EV_NUM", "BYTE"),
    ("PRIORITY", "BYTE"),
    ("NUM", "BYTE"),
    ("TYP2_3", "BYTE"),
    ("TYP1", "BYTE"),
    ("ZI1", "WORD"),
    ("ZI2_3", "DWORD"),
)
# AG_SEND (FC 5) and AG_RECV (FC 6) of the SIMATIC NET CP library run as system functions,
# with Nasaq's numbers SFC 750 and 751 (a program's own FC 5 and FC 6 keep theirs).
AG_SEND, AG_RECV, AG_CNTRL = 750, 751, 752  # AG_CNTRL is FC 10 there
SFC_NAMES: dict[int, str] = {
    RD_SINFO: "RD_SINFO",
    AG_SEND: "AG_SEND",
    AG_RECV: "AG_RECV",
    AG_CNTRL: "AG_CNTRL",
}
SFC_INTERFACES: dict[int, Interface] = {
    RD_SINFO: [
        ("OUT", "RET_VAL", "INT"),
        ("OUT", "TOP_SI", "SI_classic"),
        ("OUT", "START_UP_SI", "SI_classic"),
    ],
    AG_SEND: [
        ("IN", "ACT", "BOOL"),
        ("IN", "ID", "INT"),
        ("IN", "LADDR", "WORD"),
        ("IN", "SEND", "ANY"),
        ("IN", "LEN", "INT"),
        ("OUT", "DONE", "BOOL"),
        ("OUT", "ERROR", "BOOL"),
        ("OUT", "STATUS", "WORD"),
    ],
    AG_RECV: [
        ("IN", "ID", "INT"),
        ("IN", "LADDR", "WORD"),
        ("IN", "RECV", "ANY"),
        ("OUT", "NDR", "BOOL"),
        ("OUT", "ERROR", "BOOL"),
        ("OUT", "STATUS", "WORD"),
        ("OUT", "LEN", "INT"),
    ],
    AG_CNTRL: [
        ("IN", "ACT", "BOOL"),
        ("IN", "ID", "INT"),
        ("IN", "LADDR", "WORD"),
        ("IN", "CMD", "INT"),
        ("OUT", "DONE", "BOOL"),
        ("OUT", "ERROR", "BOOL"),
        ("OUT", "STATUS", "WORD"),
        ("OUT", "RESULT1", "DWORD"),
        ("OUT", "RESULT2", "DWORD"),
    ],
}
# The system functions SCL calls by name: name -> SFC number (their parameters: SFC_INTERFACES;
# a structured one, the start information, takes any variable of its layout).
SYSTEM_FUNCTIONS: dict[str, int] = {name: number for number, name in SFC_NAMES.items()}


# Formal types that take any variable (checked by the CPU, as STEP 7's ANY).
ANY_VARIABLE = frozenset({"ANY", "SI_classic"})
# GetBlockName (S7-1200/1500): the name of the block that calls it, as a WSTRING of at most SIZE
# characters; the compiler knows it, so the value is a constant of the calling block.
GET_BLOCK_NAME = "GETBLOCKNAME"
BLOCK_NAME_TYPE = StringType(254, wide=True)
S7_1500_ONLY = frozenset({GET_BLOCK_NAME})
SPELLING = {GET_BLOCK_NAME: "GetBlockName"}


def function_parameters(name: str) -> tuple[int, list[tuple[str, str, str]], str | None]:
    """SFC number, ``(formal, section, type text)`` without RET_VAL, and RET_VAL's type text
    (None: no value) of the system function ``name`` (upper case, in SYSTEM_FUNCTIONS)."""
    number = SYSTEM_FUNCTIONS[name]
    formals = [(n, s, text) for s, n, text in SFC_INTERFACES[number] if n != "RET_VAL"]
    result = next((text for _s, n, text in SFC_INTERFACES[number] if n == "RET_VAL"), None)
    return number, formals, result


# Elementary types TIA names after their use (hardware identifiers, connection IDs).
_WORD_ALIASES = (
    "HW_ANY",
    "HW_IO",
    "HW_DEVICE",
    "HW_SUBMODULE",
    "HW_INTERFACE",
    "HW_IEPORT",
    "HW_MODULE",
    "HW_DPSLAVE",
    "HW_IOSYSTEM",
    "CONN_ANY",
    "CONN_OUC",
    "CONN_PRG",
)
ALIASES: dict[str, str] = {**dict.fromkeys(_WORD_ALIASES, "WORD"), "CONN_R_ID": "DWORD"}


def _struct(*members: tuple[str, object]) -> StructType:
    fields = []
    for name, kind in members:
        data_type = Elementary(ALIASES.get(kind, kind)) if isinstance(kind, str) else kind
        fields.append(Field(name, data_type))  # type: ignore[arg-type]
    return StructType(tuple(fields))


def _bytes(low: int, high: int, element: str = "BYTE") -> ArrayType:
    return ArrayType(((low, high),), Elementary(element))


_IP_V4 = _struct(("ADDR", _bytes(1, 4)))
_T_SELECTOR = _struct(("TSelLength", "USINT"), ("TSel", _bytes(1, 32)))
TYPES: dict[str, StructType] = {
    "IP_V4": _IP_V4,
    "TSelector": _T_SELECTOR,
    "TCON_IP_v4": _struct(
        ("InterfaceId", "HW_ANY"),
        ("ID", "CONN_OUC"),
        ("ConnectionType", "BYTE"),
        ("ActiveEstablished", "BOOL"),
        ("RemoteAddress", _IP_V4),
        ("RemotePort", "UINT"),
        ("LocalPort", "UINT"),
    ),
    "TCON_IP_RFC": _struct(
        ("InterfaceId", "HW_ANY"),
        ("ID", "CONN_OUC"),
        ("ConnectionType", "BYTE"),
        ("ActiveEstablished", "BOOL"),
        ("RemoteAddress", _IP_V4),
        ("RemoteTSelector", _T_SELECTOR),
        ("LocalTSelector", _T_SELECTOR),
    ),
    "TCON_Param": _struct(  # 64 bytes, as the S7-300/400 connection description
        ("block_length", "WORD"),
        ("id", "WORD"),
        ("connection_type", "BYTE"),
        ("active_est", "BOOL"),
        ("local_device_id", "BYTE"),
        ("local_tsap_id_len", "BYTE"),
        ("rem_subnet_id_len", "BYTE"),
        ("rem_staddr_len", "BYTE"),
        ("rem_tsap_id_len", "BYTE"),
        ("next_staddr_len", "BYTE"),
        ("local_tsap_id", _bytes(1, 16)),
        ("rem_subnet_id", _bytes(1, 6)),
        ("rem_staddr", _bytes(1, 6)),
        ("rem_tsap_id", _bytes(1, 16)),
        ("next_staddr", _bytes(1, 6)),
        ("spare", "WORD"),
    ),
    "TADDR_Param": _struct(
        ("REM_IP_ADDR", _bytes(1, 4, "USINT")), ("REM_PORT_NR", "UINT"), ("RESERVED", "WORD")
    ),
    "SI_classic": _struct(*SI_MEMBERS),
}

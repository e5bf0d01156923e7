"""Operands of STL IR instructions, resolved down to what the CPU addresses.

Conventions (STEP 7 semantics, so the CPU needs no symbol knowledge):
- ``#temp`` of any block is a :class:`Direct` in area ``L`` at the variable's offset in the block's
  local stack frame.
- ``#var`` of an FB (IN, OUT, IN_OUT, STAT) is a :class:`RegisterIndirect` in area ``DI``
  through AR2 (``DIX [AR2, P#x.y]``), as STEP 7 compiles it: that is what makes multi-instances
  work.
- ``#param`` of an FC is a :class:`ParamRef`: FC parameters are passed by reference, the CPU
  resolves them through the current call frame.
- ``"DB".member`` and ``DB5.DBW2`` are :class:`Direct` with ``db`` set: the CPU opens that DB first
  (it overwrites the DB register, as on a real CPU).
- Constants carry the 32-bit pattern ``L`` puts into ACCU1 (see :class:`Constant`).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum, StrEnum

from nasaq.ir.fast_init import fast_init


class Area(StrEnum):
    I = "I"  # noqa: E741 - the S7 area name
    Q = "Q"
    M = "M"
    L = "L"  # local stack of the running block
    V = "V"  # local stack of the calling block (previous frame)
    DB = "DB"  # the DB opened in the DB register
    DI = "DI"  # the DB opened in the DI register (instance DB)
    PI = "PI"  # peripheral inputs (bypass the process image)
    PQ = "PQ"  # peripheral outputs


class Width(IntEnum):
    """Access width in bits."""

    BIT = 1
    BYTE = 8
    WORD = 16
    DWORD = 32


@fast_init
@dataclass(frozen=True, slots=True)
class Direct:
    """``I 0.0``, ``MW 10``, ``DBX 2.1``, ``DB5.DBW 4`` (``db=5``), ``L 0.0``, ``PIW 256``."""

    area: Area
    width: Width
    byte: int
    bit: int = 0
    db: int | None = None


@fast_init
@dataclass(frozen=True, slots=True)
class MemoryIndirect:
    """``I [MD 2]``, ``DBW [#ptr]``: the address comes from a DWORD area pointer at ``pointer``.

    For timers, counters, DBs and blocks (``SP T [MW 4]``, ``OPN DB [MW 2]``, ``UC FC [MW 6]``) the
    pointer is a WORD holding the number, and ``target`` says what kind of thing it numbers.
    """

    width: Width | None
    area: Area | None
    pointer: Direct | RegisterIndirect
    target: str | None = None  # None for memory; "T", "C", "DB", "DI", "FC", "FB", "SFC"


@fast_init
@dataclass(frozen=True, slots=True)
class RegisterIndirect:
    """``DBX [AR1, P#0.0]`` (area given, area-internal) or ``[AR1, P#2.0]`` (area-crossing:
    ``area`` is None and the area comes from AR's area bits). ``offset_bits`` = byte * 8 + bit."""

    width: Width
    area: Area | None
    register: int  # 1 or 2
    offset_bits: int


class ConstType(StrEnum):
    BOOL = "BOOL"
    BYTE = "BYTE"
    WORD = "WORD"
    DWORD = "DWORD"
    INT = "INT"
    DINT = "DINT"
    REAL = "REAL"
    S5TIME = "S5TIME"
    TIME = "TIME"
    DATE = "DATE"
    TOD = "TIME_OF_DAY"
    CHAR = "CHAR"
    POINTER = "POINTER"  # P#...: a 32-bit area pointer (area-crossing when it names an area)
    BYTES = "BYTES"  # B#(1, 2) / B#(1, 2, 3, 4)
    COUNTER = "COUNTER"  # C#123 (BCD)
    # DT#1990-1-1-0:0:0.0: the 8 BCD bytes of a DATE_AND_TIME as one 64-bit ``pattern`` (first
    # byte highest). Never loaded into ACCU1: only an actual parameter (FC/FB IN) or a DB value.
    DATE_AND_TIME = "DATE_AND_TIME"
    # 'more than 4 characters' (or any character constant passed to a STRING parameter): the
    # characters as one big-endian ``pattern`` of ``value`` bytes. Only a STRING actual parameter.
    STRING = "STRING"


@fast_init
@dataclass(frozen=True, slots=True)
class Constant:
    """``pattern`` is the unsigned 32-bit value ``L`` loads into ACCU1 (INT constants are 16-bit
    immediates with ACCU1-H = 0, REAL as IEEE 754 bits, S5TIME/C# in BCD, P# an area pointer).
    ``value`` keeps the value as written (int or float) for display, checks and ``+ n`` /
    ``INC n`` style operands.
    DATE_AND_TIME and STRING constants are the exceptions: no accumulator values but actual
    parameters, their ``pattern`` as long as they are (see ``ConstType``)."""

    type: ConstType
    pattern: int
    value: int | float
    text: str = ""


@fast_init
@dataclass(frozen=True, slots=True)
class TimerRef:
    number: int


@fast_init
@dataclass(frozen=True, slots=True)
class CounterRef:
    number: int


class BlockKind(StrEnum):
    OB = "OB"
    FB = "FB"
    FC = "FC"
    SFB = "SFB"
    SFC = "SFC"
    DB = "DB"
    DI = "DI"  # OPN DI n
    UDT = "UDT"


@fast_init
@dataclass(frozen=True, slots=True)
class BlockRef:
    kind: BlockKind
    number: int


@fast_init
@dataclass(frozen=True, slots=True)
class LabelRef:
    name: str


class StatusCondition(StrEnum):
    """Operands of ``A ==0``, ``O OV``, ``AN BR`` ...: bits and results of the status word."""

    EQ0 = "==0"
    NE0 = "<>0"
    GT0 = ">0"
    LT0 = "<0"
    GE0 = ">=0"
    LE0 = "<=0"
    OV = "OV"
    OS = "OS"
    BR = "BR"
    UO = "UO"


@fast_init
@dataclass(frozen=True, slots=True)
class Register:
    """``L STW`` / ``T STW``, ``L DBNO``, ``L DBLG``, ``L DINO``, ``L DILG``, ``LAR1 AR2``.

    The test pseudo-ops (``--test-ops``) add ``ACCU1``..``ACCU4`` (``__ACCU n``) and one status
    bit each ``STW.FC STW.RLO STW.STA STW.OR STW.OS STW.OV STW.CC0 STW.CC1 STW.BR`` (``__STW bit``);
    ``__AR n`` is ``AR1``/``AR2`` and ``__DBR 1``/``__DBR 2`` is ``DBNO``/``DINO``.
    """

    name: str


@fast_init
@dataclass(frozen=True, slots=True)
class ParamRef:
    """A formal parameter of the running FC, accessed by reference through the call frame."""

    index: int
    name: str
    width: Width | None  # None for parameters that are not elementary (ANY, POINTER, STRUCT)
    bit_offset: int = 0  # into the parameter, for member access of a struct parameter


@fast_init
@dataclass(frozen=True, slots=True)
class MultiInstance:
    """``CALL #Motor1``: an FB instance inside the calling FB's instance data at ``offset_bits``."""

    offset_bits: int
    name: str


@fast_init
@dataclass(frozen=True, slots=True)
class CallArg:
    name: str  # formal parameter name
    value: Operand  # actual parameter, resolved like any operand


@fast_init
@dataclass(frozen=True, slots=True)
class CallInfo:
    """``CALL FB 1, DB 10 (IN := I 0.0, ...)``; ``CALL FC 2 (...)``; ``CALL #inst (...)``."""

    block: BlockRef
    instance: BlockRef | MultiInstance | None
    args: tuple[CallArg, ...]


Operand = (
    Direct
    | MemoryIndirect
    | RegisterIndirect
    | Constant
    | TimerRef
    | CounterRef
    | BlockRef
    | LabelRef
    | StatusCondition
    | Register
    | ParamRef
)

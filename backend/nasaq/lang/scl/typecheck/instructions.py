"""The formal parameters and result types of the built-in instructions SCL code calls by name,
as TIA Portal (and S7-SCL Classic) declare them, so their calls are checked like an FC's:
unknown parameter names (``SCL223``), a parameter twice (``SCL228``), wrong input types
(``SCL213``/``214``/``218``), missing inputs (``SCL227``). Every call also takes ``EN`` and
``ENO``. Inputs may be given without names, in interface order (``MAX(a, b)``,
``INT_TO_WORD(i)``), as both dialects allow.

- conversions ``X_TO_Y``: ``IN`` of type X; ``ROUND``/``TRUNC``/``CEIL``/``FLOOR`` and the REAL
  functions ``IN`` REAL;
- ``MAX``/``MIN``: ``IN1`` .. ``IN32`` (at least two), ``LIMIT``: ``MN``, ``IN``, ``MX``;
  ``SEL``: ``G``, ``IN0``, ``IN1``; ``MUX``: ``K``, ``IN0`` .. ``IN31`` (at least two), ``ELSE``;
  the result has the common type of the values (``operators``' implicit widening); values of
  two types that neither widens to are ``SCL214`` at the second;
- ``SCALE_X``: ``MIN``, ``VALUE`` (REAL), ``MAX``; the result has the type of MIN/MAX (TIA: OUT,
  MIN and MAX have one type); ``NORM_X``: ``MIN``, ``VALUE``, ``MAX`` of one type, result REAL;
- ``MOVE_BLK``/``UMOVE_BLK``: ``IN`` (the first source element), ``COUNT``, ``OUT =>`` (the
  first target element), the same element type; ``FILL_BLK``: ``IN`` (the value), ``COUNT``,
  ``OUT =>``. They are statements (no value).
- ``RD_SYS_T``/``RD_LOC_T`` ``(OUT => t)``, and S7-SCL Classic's ``READ_CLK`` (SFC 1) ``(CDT =>
  t)``: t a DATE_AND_TIME, or a DTL (S7-1200/1500); the value is RET_VAL, an INT.
- ``TIME_TCK()`` (SFC 64): the system time in ms, a TIME.
- ``T_ADD``/``T_SUB`` ``(IN1 := point or duration, IN2 := duration)``: IN1's type (TIME,
  TIME_OF_DAY, DATE_AND_TIME, DTL); ``T_DIFF (IN1, IN2)`` of one type: a TIME;
  ``T_COMBINE (IN1 := DATE, IN2 := TIME_OF_DAY)``: a DATE_AND_TIME.
- ``DTL_TO_TOD``/``DTL_TO_DATE`` ``(IN := a DTL)``: its TIME_OF_DAY, its DATE.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

from nasaq.lang import tia_comm, tia_timing
from nasaq.lang.dtl import DTL
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.signatures import BOOL, Param, Signature
from nasaq.lang.scl.typecheck.types import (
    CONVERSIONS,
    LONG,
    IntConst,
    Type,
    Verdict,
    assignable,
    describe,
    is_silent,
    scalar,
    wider,
)
from nasaq.lang.types import DataType, Elementary, StringType

_E = Elementary
INT, DINT, REAL = _E("INT"), _E("DINT"), _E("REAL")
NUMBERS: tuple[DataType, ...] = (INT, DINT, REAL)
ORDERED: tuple[DataType, ...] = (
    *NUMBERS,
    _E("TIME"),
    _E("DATE"),
    _E("TIME_OF_DAY"),
    _E("BYTE"),
    _E("WORD"),
    _E("DWORD"),
    _E("CHAR"),
)
ANY_VALUE: tuple[DataType, ...] = (*ORDERED, BOOL, _E("S5TIME"))
BLOCK_ELEMENTS: tuple[DataType, ...] = ORDERED  # TIA: bit strings, integers, REAL, times, CHAR
MANY = 32  # inputs of MAX/MIN/MUX (TIA's boxes go to 32)
# S7-1200/1500: the 8-byte types MIN/MAX/LIMIT/SEL (and the REAL functions, LREAL) take too
LREAL = _E("LREAL")
LONG_ORDERED: tuple[DataType, ...] = (_E("LINT"), _E("ULINT"), LREAL, _E("LTIME"))

REAL_INPUT = frozenset(
    ["ROUND", "TRUNC", "CEIL", "FLOOR", "SQR", "SQRT", "EXP", "EXPD", "LN", "LOG", "SIN"]
) | frozenset(["COS", "TAN", "ASIN", "ACOS", "ATAN"])
BCD = {  # the BCD conversions' input types
    "BCD_TO_INT": "WORD",
    "WORD_BCD_TO_INT": "WORD",
    "BCD16_TO_INT": "WORD",
    "BYTE_BCD_TO_INT": "BYTE",
    "INT_TO_BCD": "INT",
    "INT_TO_BCD_WORD": "INT",
    "INT_TO_BCD16": "INT",
    "INT_TO_BCD_BYTE": "INT",
    "DWORD_BCD_TO_DINT": "DWORD",
    "BCD32_TO_DINT": "DWORD",
    "DINT_TO_BCD_DWORD": "DINT",
    "DINT_TO_BCD32": "DINT",
}
SELECTIONS = frozenset(["MAX", "MIN", "LIMIT", "SEL", "MUX", "SCALE_X", "NORM_X"])
BLOCK_MOVES = frozenset(["MOVE_BLK", "UMOVE_BLK", "FILL_BLK"])
CLOCKS = {"RD_SYS_T": "OUT", "RD_LOC_T": "OUT", "READ_CLK": "CDT"}  # their output's name
TIME_FUNCTIONS = frozenset(["T_ADD", "T_SUB", "T_DIFF", "T_COMBINE"])
# TIA's conversions of a DTL (S7-1200/1500): its time of day, its date
DTL_CONVERSIONS = {"DTL_TO_TOD": "TIME_OF_DAY", "DTL_TO_DATE": "DATE"}
NAMES = SELECTIONS | BLOCK_MOVES | CLOCKS.keys() | TIME_FUNCTIONS | {"TIME_TCK"}
NAMES |= DTL_CONVERSIONS.keys()
# RE_TRIGR (SFC 43, retrigger the cycle monitoring): no parameters, nothing to simulate
NAMES |= {"RE_TRIGR"}
# TIA's typed forms of the overloaded instructions (``SCALE_X_REAL``, ``NORM_X_REAL``, ``MIN_INT``):
# the suffix names the data type TIA's box was given; Nasaq runs the untyped instruction, whose
# type comes from its values (``typed_form``)
TYPED_BASES = frozenset(["SCALE_X", "NORM_X", "MIN", "MAX", "LIMIT", "SEL", "MUX"])
_SUFFIXES = frozenset(
    ["SINT", "USINT", "INT", "UINT", "DINT", "UDINT", "LINT", "ULINT", "REAL", "LREAL"]
) | frozenset(["BYTE", "WORD", "DWORD", "LWORD", "TIME", "LTIME", "CHAR", "DATE", "TOD"])


def typed_form(name: str) -> str:
    """The instruction a typed form names (``SCALE_X_REAL``: ``SCALE_X``), else ``name``."""
    base, _, suffix = name.upper().rpartition("_")
    return base if base in TYPED_BASES and suffix in _SUFFIXES else name


NAMES |= tia_timing.NAMES
NAMES |= tia_comm.SYSTEM_FUNCTIONS.keys() | {tia_comm.GET_BLOCK_NAME}
TIME, TOD, DATE, DT = _E("TIME"), _E("TIME_OF_DAY"), _E("DATE"), _E("DATE_AND_TIME")
LTIME = _E("LTIME")
# the inputs that take part in the common type of a selection (the others are K, G, VALUE ...)
VALUES = {
    "MAX": None,
    "MIN": None,
    "LIMIT": None,
    "SEL": ("IN0", "IN1"),
    "MUX": None,
    "SCALE_X": ("MIN", "MAX"),
    "NORM_X": None,
}
_SKIP = {"SEL": ("G",), "MUX": ("K",), "SCALE_X": ("VALUE",)}


def _signature(name: str, params: list[Param], result: DataType | None = None) -> Signature:
    found = {param.name.casefold(): param for param in params}
    found["en"] = Param("EN", "IN", (BOOL,))
    found["eno"] = Param("ENO", "OUT", (BOOL,))
    return Signature(name, "STANDARD", found, result)


def _numbered(prefix: str, first: int, required: int, types: tuple[DataType, ...]) -> list[Param]:
    return [
        Param(f"{prefix}{n}", "IN", types, n < first + required) for n in range(first, first + MANY)
    ]


@cache  # one signature per name, shared (read, never changed)
def signature(name: str) -> Signature | None:
    """The formal parameters of the built-in ``name`` (upper case); None for the others."""
    if name in CONVERSIONS:
        source = name.split("_TO_", 1)[0]
        if source in ("BLOCK_DB", "STRING"):
            return None  # BLOCK_DB_TO_WORD takes a DB; STRING_TO_CHAR is the strings' own
        return _signature(name, [Param("IN", "IN", (_E(LONG.get(source, source)),), True)])
    if name in BCD:
        return _signature(name, [Param("IN", "IN", (_E(BCD[name]),), True)])
    if name in REAL_INPUT:
        return _signature(name, [Param("IN", "IN", (REAL, LREAL), True)])
    if name in ("MAX", "MIN"):
        return _signature(name, _numbered("IN", 1, 2, (*ORDERED, *LONG_ORDERED)))
    if name == "LIMIT":
        ordered = (*ORDERED, *LONG_ORDERED)
        return _signature(name, [Param(n, "IN", ordered, True) for n in ("MN", "IN", "MX")])
    if name == "SEL":
        params = [Param("G", "IN", (BOOL,), True)]
        values = (*ANY_VALUE, *LONG_ORDERED, _E("LWORD"))
        return _signature(name, params + [Param(n, "IN", values, True) for n in ("IN0", "IN1")])
    if name == "MUX":
        params = [Param("K", "IN", (INT, DINT), True), *_numbered("IN", 0, 2, ANY_VALUE)]
        return _signature(name, [*params, Param("ELSE", "IN", ANY_VALUE)])
    if name in ("SCALE_X", "NORM_X"):
        value = (REAL,) if name == "SCALE_X" else NUMBERS
        params = [Param("MIN", "IN", NUMBERS, True), Param("VALUE", "IN", value, True)]
        return _signature(name, [*params, Param("MAX", "IN", NUMBERS, True)])
    if name in ("T_ADD", "T_SUB"):  # an LTIME +/- an LTIME or a TIME (``ltime_operands``)
        first = Param("IN1", "IN", (TIME, TOD, DT, DTL, LTIME), True)
        return _signature(name, [first, Param("IN2", "IN", (TIME, LTIME), True)])
    if name == "T_DIFF":
        return _signature(
            name, [Param(n, "IN", (TOD, DATE, DT, TIME, DTL), True) for n in ("IN1", "IN2")]
        )
    if name == "T_COMBINE":
        params = [Param("IN1", "IN", (DATE,), True), Param("IN2", "IN", (TOD,), True)]
        return _signature(name, params, DT)
    if name == "TIME_TCK":
        return _signature(name, [], _E("TIME"))
    if name in DTL_CONVERSIONS:
        return _signature(name, [Param("IN", "IN", (DTL,), True)], _E(DTL_CONVERSIONS[name]))
    if name in tia_timing.PARAMETERS:  # RUNTIME, RESET_TIMER, PRESET_TIMER
        formals, returns = tia_timing.PARAMETERS[name]
        return _signature(name, [Param(n, s, types, True) for n, s, types in formals], returns)
    if name in tia_comm.SYSTEM_FUNCTIONS:  # RD_SINFO, AG_SEND, AG_RECV (``nasaq.lang.tia_comm``)
        return _system_function(name)
    if name == tia_comm.GET_BLOCK_NAME:  # the calling block's name (``tia_comm``)
        sizes = tuple(_E(kind) for kind in ("UINT", "USINT", "UDINT", "INT", "DINT", "SINT"))
        label = tia_comm.SPELLING[name]
        return _signature(label, [Param("SIZE", "IN", sizes, True)], tia_comm.BLOCK_NAME_TYPE)
    if name in CLOCKS:
        return _signature(name, [Param(CLOCKS[name], "OUT", (_E("ANY"),), True)], INT)
    if name in BLOCK_MOVES:
        moves = [
            Param("IN", "IN", BLOCK_ELEMENTS, True),
            Param("COUNT", "IN", (INT, DINT), True),
            Param("OUT", "OUT", (_E("ANY"),), True),
        ]
        return _signature(name, moves)
    return None


def _system_function(name: str) -> Signature:
    """A system function's parameters; a structured one takes any variable (the start
    information of RD_SINFO: the program declares its own STRUCT of that layout)."""
    from nasaq.lang.system_types import parse

    _number, formals, result = tia_comm.function_parameters(name)
    params = [
        Param(formal, section, (_E("ANY") if text in tia_comm.ANY_VARIABLE else parse(text),), True)
        for formal, section, text in formals
    ]
    return _signature(name, params, None if result is None else parse(result))


def arguments(node: ast.Call, name: str) -> list[ast.Arg]:
    """The arguments that hold the values a selection chooses from (in order)."""
    wanted = VALUES.get(name)
    skip = _SKIP.get(name, ())
    found: list[ast.Arg] = []
    inputs = signature(name)
    order = [p.name for p in inputs.inputs()] if inputs is not None else []
    position = 0
    for arg in node.args:
        if arg.name is None:
            formal = order[position] if position < len(order) else ""
            position += 1
        else:
            formal = arg.name.upper()
        if formal in ("EN", "ENO") or formal in skip or arg.output:
            continue
        if wanted is None or formal in wanted:
            found.append(arg)
    return found


def common(values: list[Type]) -> tuple[Type | None, int | None]:
    """The type values of a selection share: (type, None), or (None, the index of the first
    value that fits no common type). Untyped constants take the type of the typed values."""
    typed = [v for v in values if not isinstance(v, IntConst) and scalar(v) is not None]
    found: str | None = None
    for position, value in enumerate(values):
        if value not in typed and typed:
            continue
        kind = scalar(value)
        if kind is None:
            continue
        if found is None:
            found = kind
            continue
        joined = wider(found, kind)
        if joined is None:
            return None, position
        found = joined
    return (Elementary(found) if found is not None else None), None


def result(name: str, values: list[Type]) -> Type | tuple[int, Verdict] | None:
    """The result type of a selection (``values``: the types of ``arguments``), or (position,
    verdict) for the first value that does not fit, or None when it cannot be told (silent)."""
    if any(is_silent(v) for v in values):
        return None
    if name == "NORM_X":
        return REAL
    found, wrong = common(values)
    if wrong is not None:
        first = common(values[:wrong])[0]
        expected = describe(first) if first is not None else describe(values[0])
        return wrong, Verdict("SCL214", {"actual": describe(values[wrong]), "expected": expected})
    if found is None:
        return None
    if name == "SCALE_X" and scalar(found) not in ("INT", "DINT", "REAL"):
        return 0, Verdict("SCL214", {"actual": describe(found), "expected": "REAL"})
    return found


def block_move(
    name: str, node: ast.Call, type_of: Callable[[ast.Expr], Type]
) -> tuple[ast.Expr, Verdict] | None:
    """MOVE_BLK/UMOVE_BLK: IN and OUT elements of one type; FILL_BLK: IN fits OUT's element.
    OUT must be an element of the types ``BLOCK_ELEMENTS`` names. The first problem, if any."""
    given = {(arg.name or "").upper(): arg.value for arg in node.args if arg.name}
    for formal, arg in zip(("IN", "COUNT", "OUT"), node.args, strict=False):
        if arg.name is None:  # unnamed, in their order
            given.setdefault(formal, arg.value)
    target, source = given.get("OUT"), given.get("IN")
    if target is None or source is None:
        return None  # reported as missing
    goal, value = type_of(target), type_of(source)
    if is_silent(goal) or is_silent(value):
        return None
    if not isinstance(goal, Elementary) or goal not in BLOCK_ELEMENTS:
        return target, Verdict("SCL214", {"actual": describe(goal), "expected": "INT"})
    if name == "FILL_BLK":
        verdict = assignable(value, goal)
        return (source, verdict) if verdict.code is not None else None
    if scalar(value) != scalar(goal):
        return source, Verdict("SCL214", {"actual": describe(value), "expected": describe(goal)})
    return None


def ltime_operands(
    name: str, node: ast.Call, type_of: Callable[[ast.Expr], Type]
) -> tuple[ast.Expr, Verdict] | None:
    """T_ADD/T_SUB take an LTIME duration (IN2) only for an LTIME (IN1), as TIA Portal's
    S7-1200/1500 variants do: a TIME, TIME_OF_DAY, DATE_AND_TIME or DTL takes a TIME."""
    if name not in ("T_ADD", "T_SUB"):
        return None
    values = {
        (arg.name or ("IN1", "IN2")[position]).upper(): arg.value
        for position, arg in enumerate(node.args[:2])
    } | {(arg.name or "").upper(): arg.value for arg in node.args if arg.name}
    first, second = values.get("IN1"), values.get("IN2")
    if first is None or second is None:
        return None
    have, duration = type_of(first), type_of(second)
    if is_silent(have) or is_silent(duration) or scalar(duration) != "LTIME":
        return None
    if scalar(have) == "LTIME":
        return None
    verdict = {"actual": "LTIME", "expected": "TIME", "function": "LTIME_TO_TIME"}
    return second, Verdict("SCL213", verdict)


def clock_output(name: str, node: ast.Call, type_of: Callable[[ast.Expr], Type]) -> Verdict | None:
    """The output of a clock read must be a DATE_AND_TIME or a DTL."""
    for arg in node.args:
        if (arg.name or "").upper() == CLOCKS[name] or (arg.name is None and arg is node.args[0]):
            found = type_of(arg.value)
            if is_silent(found) or found == _E("DATE_AND_TIME") or found == DTL:
                return None
            return Verdict("SCL214", {"actual": "DTL", "expected": describe(found)})
    return None


def time_result(name: str, node: ast.Call, type_of: Callable[[ast.Expr], Type]) -> Type | None:
    """The value of T_ADD, T_SUB (IN1's type), T_DIFF (TIME), T_COMBINE (DATE_AND_TIME); None
    when IN1 is not known."""
    if name == "T_COMBINE":
        return DT
    if name == "T_DIFF":
        return TIME
    for position, arg in enumerate(node.args):
        if (arg.name or "").upper() == "IN1" or (arg.name is None and position == 0):
            found = type_of(arg.value)
            return None if is_silent(found) else found
    return None


@cache
@cache
def concat_many(wide: bool = False) -> Signature:
    """TIA's CONCAT on the S7-1200/1500 profile: IN1 .. IN32 (at least two), a STRING (or,
    ``wide``, a WSTRING: CONCAT of a WSTRING, ``CONCAT_WSTRING``); on S7-300/400 CONCAT is the
    library's FC 2 with IN1 and IN2 only."""
    text = StringType(254, wide=wide)
    name = "CONCAT_WSTRING" if wide else "CONCAT"
    return _signature(name, _numbered("IN", 1, 2, (text,)), text)

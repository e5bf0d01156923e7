"""Rule: operand types (``SCL211`` for a binary, ``SCL212`` for a unary operator), with S7-SCL's
implicit conversions (seeds-003b §2.8, §2.15):
- ``AND & OR XOR NOT``: bit strings (BOOL, BYTE, WORD, DWORD), the result the wider one;
- ``+ - * /``: INT, DINT, REAL, the result the wider one (INT with REAL gives REAL); ``**``
  gives REAL; ``DIV MOD`` integers only; and the time arithmetic of the §2.8 table;
- comparisons: two numbers, two bit strings, CHAR/STRING, or two values of the same time
  type; the result is BOOL.
Mixing families (WORD with INT, ``'A' + 'B'``, BOOL + INT) needs an explicit conversion; under
the S7-1500 profile TIA's readings apply first (``typecheck.implicit``: ``DINT + WORD`` as
``DINT + UINT``, ``INT XOR INT`` as WORDs).
An operand whose type is already an error makes the result an error, silently."""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING

from nasaq.lang import s7_1500_types as s7_1500
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import implicit, time_dint, variant
from nasaq.lang.scl.typecheck.types import (
    ANYTHING,
    BIT_LIMITS,
    BITS,
    ERROR,
    INTEGERS,
    NUMBERS,
    RANGES,
    TEXT,
    BitsConst,
    CharsConst,
    IntConst,
    Type,
    describe,
    integer_of,
    is_silent,
    scalar,
    wider,
)
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

LOGIC = frozenset({"AND", "&", "OR", "XOR"})
# The S7-1200/1500 types (the checker never sees them under a classic profile).
_NEW = frozenset({*s7_1500.NEW_INTEGERS, "LREAL", "LWORD", "LTIME"})
_SIGNED_1500 = frozenset({"SINT", "LINT", "LREAL", "LTIME"})
COMPARE = frozenset({"=", "<>", "<", ">", "<=", ">="})
ARITHMETIC = frozenset({"+", "-", "*", "/"})
INTEGER_ONLY = frozenset({"DIV", "MOD"})
BOOL = Elementary("BOOL")
INT_LOW, INT_HIGH = RANGES["INT"]
TIMES = ("TIME", "S5TIME", "DATE", "TIME_OF_DAY", "DATE_AND_TIME")
# (op, left, right) → result, for the time types (seeds-003b §2.8)
TIME_ARITHMETIC = {
    ("+", "TIME", "TIME"): "TIME",
    ("-", "TIME", "TIME"): "TIME",
    ("+", "TIME_OF_DAY", "TIME"): "TIME_OF_DAY",
    ("-", "TIME_OF_DAY", "TIME"): "TIME_OF_DAY",
    ("+", "DATE_AND_TIME", "TIME"): "DATE_AND_TIME",
    ("-", "DATE_AND_TIME", "TIME"): "DATE_AND_TIME",
    ("-", "DATE", "DATE"): "TIME",
    ("-", "TIME_OF_DAY", "TIME_OF_DAY"): "TIME",
    ("-", "DATE_AND_TIME", "DATE_AND_TIME"): "TIME",
}


def paren(ctx: Context, node: ast.Paren) -> Type:
    return ctx.type_of(node.inner)


def unary(ctx: Context, node: ast.Unary) -> Type:
    value = ctx.type_of(node.operand)
    if is_silent(value):
        return value
    name = scalar(value)
    if node.op == "NOT":
        if name in BITS or name == "LWORD":
            return Elementary(name)
    elif isinstance(value, IntConst):
        return IntConst(-value.value if node.op == "-" else value.value)
    elif name in NUMBERS or name == "TIME" or name in _SIGNED_1500:
        return value
    return ctx.report("SCL212", node.loc, op=node.op, operand=describe(value))


def binary(ctx: Context, node: ast.Binary) -> Type:
    if variant.type_test(node) is not None:  # TypeOf(#v) = INT (S7-1200/1500)
        return variant.check_type_test(ctx, node)
    left = ctx.type_of(node.left)
    right = ctx.type_of(node.right)
    if (type(left) is IntConst) is not (type(right) is IntConst) and (
        node.op in COMPARE or node.op in LOGIC
    ):
        left, right = _bit_constant(node.op, left, right)
    found: Type | None
    wide = _wide_text(ctx, node, left, right)
    if wide is not None:
        return wide
    a, b = _plain(left), _plain(right)
    if a in _NEW and type(right) is IntConst:  # `u + 2`: the constant takes u's type (TIA)
        b = _constant_as(right.value, a) or b
    elif b in _NEW and type(left) is IntConst:
        a = _constant_as(left.value, b) or a
    elif a in _NEW and type(right) is BitsConst:  # `ud AND 16#7FFF_FFFF` likewise
        b = _constant_as(right.value, a)
    elif b in _NEW and type(left) is BitsConst:
        a = _constant_as(left.value, b)
    if a is not None and b is not None and not (type(left) is type(right) is IntConst):
        found = _combined(node.op, a, b)  # the common case, in short
    elif left is ERROR or right is ERROR:
        return ERROR
    elif is_silent(left) or is_silent(right):
        return BOOL if node.op in COMPARE else ANYTHING
    else:
        found = _result(node.op, left, right)
    if found is None:
        found = time_dint.combined(ctx, node.op, left, right)  # S7-1500: TIME with DINT
    if found is None and a is not None and b is not None and is_s7_1500(ctx.index.profile):
        found = _tia_operands(ctx, node, a, b)  # S7-1500: WORD as UINT, INT as WORD ...
    if found is None:
        return ctx.report(
            "SCL211", node.loc, op=node.op, left=describe(left), right=describe(right)
        )
    return found


def _tia_operands(ctx: Context, node: ast.Binary, a: str, b: str) -> Elementary | None:
    """``DINT + WORD``, ``INT XOR INT`` ...: computed as TIA computes them without the IEC
    check (``implicit.operand_types``), the operands converted in the tree."""
    types = implicit.operand_types(node.op, a, b)
    found = _combined(node.op, *types) if types is not None else None
    if types is not None and found is not None:
        implicit.convert_operands(ctx, node, types)
    return found


_WIDE = ("WSTRING", "WCHAR")


def _wide_text(ctx: Context, node: ast.Binary, left: Type, right: Type) -> Type | None:
    """A comparison with a WSTRING or WCHAR (``nasaq.lang.wide_text``): with a WSTRING, a WCHAR
    or a text constant (one character for two WCHARs) it is a BOOL. None otherwise: the other
    operations and mixtures with STRING/CHAR are SCL211 as usual."""
    names = (scalar(left), scalar(right))
    if names[0] not in _WIDE and names[1] not in _WIDE:
        return None
    if node.op not in COMPARE:
        return None
    if not all(
        name in _WIDE or isinstance(v, CharsConst)
        for name, v in zip(names, (left, right), strict=True)
    ):
        return None
    if "WSTRING" in names:
        return BOOL
    if all(not isinstance(v, CharsConst) or v.length == 1 for v in (left, right)):
        return BOOL  # two characters: their codes
    return None


def _bit_constant(op: str, left: Type, right: Type) -> tuple[Type, Type]:
    """An untyped constant compared with, or combined with, a bit string is that bit string when
    it fits (``w <> 0``, ``d AND 255``, ``x = 1`` for a BOOL), as STEP 7 compiles it."""
    constant, other = (left, right) if type(left) is IntConst else (right, left)
    assert isinstance(constant, IntConst)
    name = _plain(other)
    fits = name in BIT_LIMITS and 0 <= constant.value <= BIT_LIMITS[name]
    if not fits or (name == "BOOL" and op not in COMPARE):
        return left, right
    as_bits = Elementary(name or "")
    return (as_bits, right) if constant is left else (left, as_bits)


def _plain(value: Type) -> str | None:
    """The type name of a value of a known elementary type or of an integer constant (what
    ``scalar`` says of them); None for any other value."""
    if type(value) is Elementary:
        return value.name if value.name != "UNKNOWN" else None
    if type(value) is IntConst:
        return "INT" if INT_LOW <= value.value <= INT_HIGH else "DINT"
    return None


def _result(op: str, left: Type, right: Type) -> Type | None:
    a, b = scalar(left), scalar(right)
    if a is None or b is None:
        return None
    # A based constant (16#10) is an integer (S7-SCL §9.1.3) unless it meets a bit string or
    # a logic operator: 16#10 + 2#1010 is an INT sum, w AND 16#FF a WORD operation.
    if op not in LOGIC:
        left_bits = a in BITS and not isinstance(left, BitsConst)
        if isinstance(left, BitsConst) and not (b in BITS and not isinstance(right, BitsConst)):
            a = integer_of(left) or a
        if isinstance(right, BitsConst) and not left_bits:
            b = integer_of(right) or b
    if isinstance(left, IntConst) and isinstance(right, IntConst):
        folded = _fold(op, left.value, right.value)
        if folded is not None:
            return folded
    return _combined(op, a, b)


@cache  # the result depends on the operator and the two type names only: computed once each
def _combined(op: str, a: str, b: str) -> Elementary | None:
    common = wider(a, b)
    if common in _NEW or a in _NEW or b in _NEW:
        return _combined_1500(op, a, b, common)
    if op in LOGIC:
        return Elementary(common) if common in BITS else None
    if op in COMPARE:
        comparable = common is not None and (
            common in NUMBERS or common in BITS or common in TEXT or common in TIMES
        )
        if not comparable and {a, b} == {"TIME", "S5TIME"}:
            comparable = True
        return BOOL if comparable else None
    if op == "**":
        return Elementary("REAL") if a in NUMBERS and b in NUMBERS else None
    if op in INTEGER_ONLY:
        if a == "TIME" and b in INTEGERS and op == "DIV":
            return Elementary("TIME")
        return Elementary(common) if common in INTEGERS else None
    if op in ARITHMETIC:
        if common in NUMBERS:
            return Elementary(common)
        if op in ("*", "/") and a == "TIME" and b in INTEGERS:
            return Elementary("TIME")
        timed = TIME_ARITHMETIC.get((op, a, b))
        return Elementary(timed) if timed is not None else None
    return None


def _constant_as(value: int, kind: str) -> str | None:
    """``kind`` when the integer constant ``value`` is a valid ``kind`` (an S7-1500 type)."""
    if kind in s7_1500.FLOATS:
        return kind
    limits = s7_1500.INTEGER_RANGES.get(kind)
    return kind if limits is not None and limits[0] <= value <= limits[1] else None


def _combined_1500(op: str, a: str, b: str, common: str | None) -> Elementary | None:
    """An operation with an S7-1200/1500 type (``typecheck.s7_1500``): the result is the common
    type (``SINT + SINT`` a SINT, ``INT + UINT`` a DINT); ``**`` is an LREAL when an operand is
    an LREAL, LINT or ULINT,
    ``DIV``/``MOD`` integers only; LTIME works as TIME does, in nanoseconds."""
    if op in LOGIC:
        return Elementary(common) if common in s7_1500.BIT_STRINGS else None
    if op in COMPARE:
        comparable = common in s7_1500.ALL_NUMBERS or common in s7_1500.BIT_STRINGS
        return BOOL if comparable or common == "LTIME" else None
    if op == "**":  # of a 64-bit integer too an LREAL (computed by EXPT_LREAL: REAL would
        if a in s7_1500.ALL_NUMBERS and b in s7_1500.ALL_NUMBERS:  # lose its digits)
            return Elementary("LREAL" if {"LREAL", "LINT", "ULINT"} & {a, b} else "REAL")
        return None
    if common == "LTIME" and op in ("+", "-"):
        return Elementary("LTIME")
    if a == "LTIME" and b in s7_1500.ALL_INTEGERS and op in ("*", "/", "DIV"):
        return Elementary("LTIME")
    if op in INTEGER_ONLY:
        return Elementary(common) if common in s7_1500.ALL_INTEGERS else None
    if op in ARITHMETIC:
        return Elementary(common) if common in s7_1500.ALL_NUMBERS else None
    return None


def _fold(op: str, left: int, right: int) -> IntConst | None:
    """Two integer constants: their value, so that ``-1 * 40000`` is a DINT constant."""
    if op == "+":
        return IntConst(left + right)
    if op == "-":
        return IntConst(left - right)
    if op == "*":
        return IntConst(left * right)
    return None

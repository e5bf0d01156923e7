"""Rule: operand types (``SCL211`` for a binary, ``SCL212`` for a unary operator), with S7-SCL's
implicit conversions (seeds-003b §2.8, §2.15):
- ``AND & OR XOR NOT``: bit strings (BOOL, BYTE, WORD, DWORD), the result the wider one;
- ``+ - * /``: INT, DINT, REAL, the result the wider one (INT with REAL gives REAL); ``**``
  gives REAL; ``DIV MOD`` integers only; and the time arithmetic of the §2.8 table;
- comparisons: two numbers, two bit strings, CHAR/STRING, or two values of the same time
  type; the result is BOOL.
Mixing families (WORD with INT, ``'A' + 'B'``, BOOL + INT) needs an explicit conversion.
An operand whose type is already an error makes the result an error, silently."""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import (
    ANYTHING,
    BITS,
    ERROR,
    INTEGERS,
    NUMBERS,
    RANGES,
    TEXT,
    IntConst,
    Type,
    describe,
    is_silent,
    scalar,
    wider,
)
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

LOGIC = frozenset({"AND", "&", "OR", "XOR"})
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
        if name in BITS:
            return Elementary(name)
    elif isinstance(value, IntConst):
        return IntConst(-value.value if node.op == "-" else value.value)
    elif name in NUMBERS or name == "TIME":
        return value
    return ctx.report("SCL212", node.loc, op=node.op, operand=describe(value))


def binary(ctx: Context, node: ast.Binary) -> Type:
    left = ctx.type_of(node.left)
    right = ctx.type_of(node.right)
    found: Type | None
    a, b = _plain(left), _plain(right)
    if a is not None and b is not None and not (type(left) is type(right) is IntConst):
        found = _combined(node.op, a, b)  # the common case, in short
    elif left is ERROR or right is ERROR:
        return ERROR
    elif is_silent(left) or is_silent(right):
        return BOOL if node.op in COMPARE else ANYTHING
    else:
        found = _result(node.op, left, right)
    if found is None:
        return ctx.report(
            "SCL211", node.loc, op=node.op, left=describe(left), right=describe(right)
        )
    return found


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
    if isinstance(left, IntConst) and isinstance(right, IntConst):
        folded = _fold(op, left.value, right.value)
        if folded is not None:
            return folded
    return _combined(op, a, b)


@cache  # the result depends on the operator and the two type names only: computed once each
def _combined(op: str, a: str, b: str) -> Elementary | None:
    common = wider(a, b)
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


def _fold(op: str, left: int, right: int) -> IntConst | None:
    """Two integer constants: their value, so that ``-1 * 40000`` is a DINT constant."""
    if op == "+":
        return IntConst(left + right)
    if op == "-":
        return IntConst(left - right)
    if op == "*":
        return IntConst(left * right)
    return None

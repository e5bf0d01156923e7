"""Calls as expressions: the result type of standard functions (``*_TO_*``, numeric, shift,
string functions, S5 timers/counters) and of user FCs. The arguments are typed (so their own
problems are reported); the parameters are checked by ``call_parameters``, which runs this."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import library
from nasaq.lang.scl.typecheck.operands import function_value
from nasaq.lang.scl.typecheck.signatures import S5_FUNCTIONS
from nasaq.lang.scl.typecheck.types import (
    ANYTHING,
    CONVERSIONS,
    ERROR,
    LONG,
    BlockRef,
    DbRef,
    Type,
    scalar,
)
from nasaq.lang.types import Elementary, StringType

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

REAL_FUNCTIONS = frozenset(
    ["SQR", "SQRT", "EXP", "EXPD", "LN", "LOG", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN"]
)
FIXED_RESULTS = {
    "ROUND": "DINT",
    "TRUNC": "DINT",
    "LEN": "INT",
    "FIND": "INT",
    "WORD_BCD_TO_INT": "INT",
    "INT_TO_BCD_WORD": "WORD",
    "DWORD_BCD_TO_DINT": "DINT",
    "DINT_TO_BCD_DWORD": "DWORD",
    "BYTE_BCD_TO_INT": "INT",
    "INT_TO_BCD_BYTE": "BYTE",
}
STRING_RESULTS = frozenset(
    ["CONCAT", "LEFT", "RIGHT", "MID", "INSERT", "DELETE", "REPLACE", "I_STRNG"]
)
SAME_AS_INPUT = frozenset(["ABS", "SHL", "SHR", "ROL", "ROR"])
UNTYPED = frozenset(["MAX", "MIN", "LIMIT", "SEL", "MUX"])
STANDARD = (
    REAL_FUNCTIONS
    | FIXED_RESULTS.keys()
    | S5_FUNCTIONS.keys()
    | STRING_RESULTS
    | SAME_AS_INPUT
    | UNTYPED
    | CONVERSIONS
    | library.NAMES
)


def call(ctx: Context, node: ast.Call) -> Type:
    values = [ctx.type_of(arg.value) for arg in node.args]
    callee = node.callee
    if isinstance(callee, ast.Name) and ctx.variable(callee.name) is None:
        upper = callee.name.upper()
        if upper in STANDARD and ctx.index.named(callee.name) is None:
            return _standard(upper, node, values)
    if isinstance(callee, ast.Member):
        base = ctx.type_of(callee.base)  # FB1.DB1(...): an FB called with its instance DB
        if isinstance(base, BlockRef):  # (an FC with a DB is the call rule's to report)
            return ANYTHING
    target = ctx.type_of(callee)
    if target is ERROR:
        return ERROR
    if isinstance(target, BlockRef) and target.kind is BlockKind.FC:
        block = ctx.index.get(BlockKind.FC, target.number)
        return function_value(block) if block is not None else ANYTHING
    return ANYTHING


def _standard(name: str, node: ast.Call, values: list[Type]) -> Type:
    if name in CONVERSIONS:
        result = name.split("_TO_", 1)[1]
        if result == "BLOCK_DB":
            return DbRef(None)
        if result == "STRING":
            return StringType(254)
        return Elementary(LONG.get(result, result))
    if name in REAL_FUNCTIONS:
        return Elementary("REAL")
    if name in FIXED_RESULTS:
        return Elementary(FIXED_RESULTS[name])
    if name in S5_FUNCTIONS:
        return S5_FUNCTIONS[name].result or ANYTHING
    if name in library.NAMES:
        found = library.signature(name)
        return found.result if found is not None and found.result is not None else ANYTHING
    if name in STRING_RESULTS:
        return StringType(254)
    if name in SAME_AS_INPUT and values:
        named = [
            v for arg, v in zip(node.args, values, strict=True) if (arg.name or "").upper() == "IN"
        ]
        first = named[0] if named else values[0]
        kind = scalar(first)
        return Elementary(kind) if kind is not None and kind != "STRING" else first
    return ANYTHING

"""Calls as expressions: the result type of standard functions (``*_TO_*``, numeric, shift,
string functions, S5 timers/counters) and of user FCs. The arguments are typed (so their own
problems are reported); the parameters are checked by ``call_parameters``, which runs this."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang import number_text, text_instructions, tia_comm, tia_timing
from nasaq.lang.iec_library import WIDE_FUNCTIONS
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import character_arrays, instructions, library, variant
from nasaq.lang.scl.typecheck.operands import function_value
from nasaq.lang.scl.typecheck.rules import start_info
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
from nasaq.lang.types import BlockType, Elementary, StringType
from nasaq.lang.wide_text import unsimulated_conversion, wide_conversion

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

REAL_FUNCTIONS = frozenset(
    ["SQR", "SQRT", "EXP", "EXPD", "LN", "LOG", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN"]
)
FIXED_RESULTS = {
    "ROUND": "DINT",
    "TRUNC": "DINT",
    "CEIL": "DINT",  # TIA: the next integer up / down (RND+ / RND-)
    "FLOOR": "DINT",
    "LEN": "INT",
    "FIND": "INT",
    "WORD_BCD_TO_INT": "INT",
    "INT_TO_BCD_WORD": "WORD",
    "DWORD_BCD_TO_DINT": "DINT",
    "DINT_TO_BCD_DWORD": "DWORD",
    "BYTE_BCD_TO_INT": "INT",
    "INT_TO_BCD_BYTE": "BYTE",
    "BCD_TO_INT": "INT",  # S7-SCL Classic's short names, and TIA's
    "INT_TO_BCD": "WORD",
    "BCD16_TO_INT": "INT",
    "INT_TO_BCD16": "WORD",
    "BCD32_TO_DINT": "DINT",
    "DINT_TO_BCD32": "DWORD",
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
    | instructions.NAMES
    | variant.NAMES
)


def called_by_name(ctx: Context, name: str) -> bool:
    """Whether ``name(...)`` calls a function of that name: no variable of the block has the
    name, or one that is no instance (TIA writes locals with ``#``: ``LEN(IN := #s)`` next to
    ``#len : INT`` is the instruction)."""
    variable = ctx.variable(name)
    return variable is None or not isinstance(variable.type, BlockType)


def call(ctx: Context, node: ast.Call) -> Type:
    values = [ctx.type_of(arg.value) for arg in node.args]
    callee = node.callee
    if isinstance(callee, ast.Name) and called_by_name(ctx, callee.name):
        upper = callee.name.upper()
        if upper not in STANDARD:  # SCALE_X_REAL: SCALE_X
            upper = instructions.typed_form(upper)
        wide = upper in WIDE_FUNCTIONS or wide_conversion(upper)
        if wide and ctx.index.named(callee.name) is None:  # ``nasaq.lang.wide_text``
            if not is_s7_1500(ctx.index.profile):
                return ctx.report("SCL500", node.loc, what=upper, profile=ctx.index.profile)
            if unsimulated_conversion(upper):
                return ctx.report("SCL800", node.loc, what=upper)
        classic = not is_s7_1500(ctx.index.profile)
        s7_1500_only = upper in number_text.S7_1500_ONLY or upper in text_instructions.S7_1500_ONLY
        if s7_1500_only and classic and ctx.index.named(callee.name) is None:
            return ctx.report("SCL500", node.loc, what=upper, profile=ctx.index.profile)
        if upper in variant.NAMES and ctx.index.named(callee.name) is None:
            return variant.call(ctx, upper, node)
        if upper in STANDARD and ctx.index.named(callee.name) is None:
            if upper in instructions.NAMES:
                return _instruction(ctx, upper, node)
            if upper in character_arrays.NAMES:  # ATH, Strg_TO_Chars ...: what they reach
                character_arrays.check(ctx, upper, node)
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


def _instruction(ctx: Context, name: str, node: ast.Call) -> Type:
    """MAX, MIN, LIMIT, SEL, MUX, SCALE_X, NORM_X: the common type of the values they choose
    from (``instructions``); MOVE_BLK and the like have no value."""
    if name == "TIME_TCK":
        return Elementary("TIME")
    if name == "RE_TRIGR":  # SFC 43: no parameters, no value
        for arg in node.args:
            ctx.report("SCL223", arg.loc, block="RE_TRIGR", name=arg.name or ctx.text(arg.value))
        return ANYTHING
    if name in instructions.DTL_CONVERSIONS:
        return Elementary(instructions.DTL_CONVERSIONS[name])
    if name in tia_timing.PARAMETERS:  # RUNTIME: LREAL; RESET_TIMER, PRESET_TIMER: no value
        return tia_timing.PARAMETERS[name][1] or ANYTHING
    if name in tia_comm.SYSTEM_FUNCTIONS or name == tia_comm.GET_BLOCK_NAME:
        if name in tia_comm.S7_1500_ONLY and not is_s7_1500(ctx.index.profile):
            what = tia_comm.SPELLING.get(name, name)
            return ctx.report("SCL500", node.loc, what=what, profile=ctx.index.profile)
        if name in tia_comm.SYSTEM_FUNCTIONS:
            start_info.check_places(ctx, name, node)
        if name == "RD_SINFO":
            start_info.check(ctx, node)
        signature = instructions.signature(name)
        if signature is None or signature.result is None:
            return ANYTHING
        return signature.result
    if name in instructions.TIME_FUNCTIONS:
        mismatch = instructions.ltime_operands(name, node, ctx.type_of)
        if mismatch is not None:
            where, verdict = mismatch
            assert verdict.code is not None
            ctx.report(verdict.code, where.loc, **verdict.params)
        value = instructions.time_result(name, node, ctx.type_of)
        return ANYTHING if value is None else value
    if name in instructions.CLOCKS:
        problem = instructions.clock_output(name, node, ctx.type_of)
        if problem is not None:
            assert problem.code is not None
            ctx.report(problem.code, node.loc, **problem.params)
        return Elementary("INT")  # RET_VAL
    if name in instructions.BLOCK_MOVES:
        wrong = instructions.block_move(name, node, ctx.type_of)
        if wrong is not None:
            where, problem = wrong
            assert problem.code is not None
            ctx.report(problem.code, where.loc, **problem.params)
        return ANYTHING
    args = instructions.arguments(node, name)
    found = instructions.result(name, [ctx.type_of(arg.value) for arg in args])
    if isinstance(found, tuple):
        position, verdict = found
        assert verdict.code is not None
        return ctx.report(verdict.code, args[position].value.loc, **verdict.params)
    return ANYTHING if found is None else found


def _standard(name: str, node: ast.Call, values: list[Type]) -> Type:
    if name in CONVERSIONS:
        result = name.split("_TO_", 1)[1]
        if result == "BLOCK_DB":
            return DbRef(None)
        if result == "STRING":
            return StringType(254)
        return Elementary(LONG.get(result, result))
    if name in REAL_FUNCTIONS:  # of an LREAL an LREAL (S7-1200/1500)
        return Elementary("LREAL" if any(scalar(v) == "LREAL" for v in values) else "REAL")
    if name in FIXED_RESULTS:
        return Elementary(FIXED_RESULTS[name])
    if name in S5_FUNCTIONS:
        return S5_FUNCTIONS[name].result or ANYTHING
    if name in library.NAMES:
        found = library.signature(library.chosen(name, node.args, values))
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

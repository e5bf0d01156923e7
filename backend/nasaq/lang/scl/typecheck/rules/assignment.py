"""Rule: assignment compatibility. The value must convert implicitly to the target's type
(``types.assignable``): otherwise ``SCL213`` names the explicit ``*_TO_*`` function to write,
``SCL214`` says there is none, ``SCL218`` that a constant does not fit. STRUCT, UDT and ARRAY
values need the same type; STRING[n] takes any STRING or CHAR. Under the S7-1500 profile TIA's
further implicit conversions apply (``typecheck.implicit``): the value is then replaced by its
conversion."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import implicit, time_dint
from nasaq.lang.scl.typecheck.types import assignable, is_silent
from nasaq.lang.types import ArrayType, BlockType, Elementary, StringType, StructType

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

TARGET_TYPES = (Elementary, StringType, ArrayType, StructType, BlockType)


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if isinstance(stmt, ast.Assign):
        stmt.value = store(ctx, stmt.target, stmt.value)


def store(ctx: Context, target: ast.Expr, value: ast.Expr) -> ast.Expr:
    """Reports when the value of ``value`` cannot be stored in ``target``; returns the value
    as it is stored (TIA's implicit conversion made explicit, ``implicit.accepts``)."""
    goal = ctx.type_of(target)
    found = ctx.type_of(value)
    if is_silent(goal) or is_silent(found) or not isinstance(goal, TARGET_TYPES):
        return value
    verdict = assignable(found, goal)
    if verdict.code is None or time_dint.implicit(ctx, found, goal):
        return value
    converted = implicit.accepts(ctx, found, goal, value)
    if converted is None:
        ctx.report(verdict.code, value.loc, **verdict.params)
        return value
    return converted

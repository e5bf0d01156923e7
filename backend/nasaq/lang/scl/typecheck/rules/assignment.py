"""Rule: assignment compatibility. The value must convert implicitly to the target's type
(``types.assignable``): otherwise ``SCL213`` names the explicit ``*_TO_*`` function to write,
``SCL214`` says there is none, ``SCL218`` that a constant does not fit. STRUCT, UDT and ARRAY
values need the same type; STRING[n] takes any STRING or CHAR."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import time_dint
from nasaq.lang.scl.typecheck.types import assignable, is_silent
from nasaq.lang.types import ArrayType, BlockType, Elementary, StringType, StructType

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

TARGET_TYPES = (Elementary, StringType, ArrayType, StructType, BlockType)


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if isinstance(stmt, ast.Assign):
        store(ctx, stmt.target, stmt.value)


def store(ctx: Context, target: ast.Expr, value: ast.Expr) -> None:
    """Reports when the value of ``value`` cannot be stored in ``target``."""
    goal = ctx.type_of(target)
    found = ctx.type_of(value)
    if is_silent(goal) or is_silent(found) or not isinstance(goal, TARGET_TYPES):
        return
    verdict = assignable(found, goal)
    if verdict.code is not None and not time_dint.implicit(ctx, found, goal):
        ctx.report(verdict.code, value.loc, **verdict.params)

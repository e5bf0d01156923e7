"""Rule: the condition of IF, ELSIF, WHILE and REPEAT ... UNTIL must be BOOL (``SCL220``):
``IF MW10 THEN`` or ``WHILE i DO`` need a comparison."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import describe, is_silent, scalar

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if isinstance(stmt, ast.If):
        for number, branch in enumerate(stmt.branches):
            _condition(ctx, branch.condition, "ELSIF" if number else "IF")
    elif isinstance(stmt, ast.While):
        _condition(ctx, stmt.condition, "WHILE")
    elif isinstance(stmt, ast.Repeat):
        _condition(ctx, stmt.condition, "REPEAT")


def _condition(ctx: Context, condition: ast.Expr, statement: str) -> None:
    found = ctx.type_of(condition)
    if is_silent(found) or scalar(found) == "BOOL":
        return
    ctx.report("SCL220", condition.loc, statement=statement, actual=describe(found))

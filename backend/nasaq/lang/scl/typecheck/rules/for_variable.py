"""Rule: the control variable of FOR is an INT or DINT variable, or an S7-1500 SINT, USINT,
UINT, UDINT, LINT or ULINT (``SCL221``); the start, end and step values must be assignable to
it (reported as assignments are)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.rules.assignment import store
from nasaq.lang.scl.typecheck.types import INTEGERS, describe, is_silent, scalar
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

# INT and DINT; the S7-1200/1500's SINT, USINT and UINT too (computed as DINTs, ``lower.longs``),
# and UDINT, LINT, ULINT (``lower.wide_control``)
_COUNTERS = frozenset({*INTEGERS, "SINT", "USINT", "UINT", "UDINT", "LINT", "ULINT"})


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if not isinstance(stmt, ast.For):
        return
    found = ctx.type_of(stmt.variable)
    if is_silent(found):
        return
    if not isinstance(found, Elementary) or scalar(found) not in _COUNTERS:
        ctx.report(
            "SCL221", stmt.variable.loc, name=ctx.text(stmt.variable), actual=describe(found)
        )
        return
    stmt.start = store(ctx, stmt.variable, stmt.start)
    stmt.end = store(ctx, stmt.variable, stmt.end)
    if stmt.step is not None:
        stmt.step = store(ctx, stmt.variable, stmt.step)

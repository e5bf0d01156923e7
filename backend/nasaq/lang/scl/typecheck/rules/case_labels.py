"""Rule: CASE (seeds-003b §2.10). The selector must be an INT (``SCL235``): S7-SCL Classic
compares it with INT constants, so a WORD such as ``PIW252`` needs ``WORD_TO_INT``, and a
DINT ``DINT_TO_INT``. Each label is an integer constant that fits INT (``SCL218``, ``SCL214``
as an assignment to INT), and each value may occur only once in the whole CASE, also inside
ranges (``SCL236``, at the later label). A range ``low..high`` needs ``low <= high``: ``5..1``
selects nothing (``SCL248``); it takes part in no overlap test."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import (
    BitsConst,
    IntConst,
    assignable,
    describe,
    is_silent,
    scalar,
)
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

INT = Elementary("INT")


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if not isinstance(stmt, ast.Case):
        return
    selector = ctx.type_of(stmt.selector)
    if not is_silent(selector) and scalar(selector) != "INT":
        ctx.report("SCL235", stmt.selector.loc, actual=describe(selector))
    seen: list[tuple[int, int, int]] = []  # low, high, line
    for branch in stmt.branches:
        for label in branch.values:
            low = _value(ctx, label.low)
            high = low if label.high is None else _value(ctx, label.high)
            if low is None or high is None:
                continue
            if label.high is not None and high < low:
                ctx.report("SCL248", label.loc, low=ctx.text(label.low), high=ctx.text(label.high))
                continue
            for first_low, first_high, line in seen:
                if low <= first_high and first_low <= high:
                    value = max(low, first_low)
                    ctx.report("SCL236", label.loc, value=value, line=line)
                    break
            else:
                seen.append((low, high, label.loc.line))


def _value(ctx: Context, literal: ast.Literal) -> int | None:
    """The label's value; None when it is no INT constant (reported)."""
    found = ctx.type_of(literal)
    if is_silent(found):
        return None
    verdict = assignable(found, INT)
    if verdict.code is not None:
        ctx.report(verdict.code, literal.loc, **verdict.params)
        return None
    if isinstance(found, IntConst | BitsConst):
        return found.value
    value = ctx.index.const_value(ctx.block, literal)  # INT#5
    return value if isinstance(value, int) else None

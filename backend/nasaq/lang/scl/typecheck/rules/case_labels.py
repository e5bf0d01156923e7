"""Rule: CASE (seeds-003b §2.10). The selector must be an INT (``SCL235``): S7-SCL Classic
compares it with INT constants, so a WORD such as ``PIW252`` needs ``WORD_TO_INT``, and a
DINT ``DINT_TO_INT``. Each label is an integer constant that fits INT (``SCL218``, ``SCL214``
as an assignment to INT), and each value may occur only once in the whole CASE, also inside
ranges (``SCL236``, at the later label). A range ``low..high`` needs ``low <= high``: ``5..1``
selects nothing (``SCL248``); it takes part in no overlap test. A label may be a named constant
of the block (``CONST``, TIA's ``VAR CONSTANT``; ``K1``, ``#K1``), as in TIA Portal; any other
name there is ``SCL700``. Under the S7-1500 profile the selector may also be a DINT, UDINT,
BYTE, WORD or DWORD (a bit string compared as its unsigned integer)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import implicit
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
# INT, and the S7-1200/1500's SINT, USINT and UINT (compared as DINTs, ``lower.longs``)
_SELECTORS = frozenset({"INT", "SINT", "USINT", "UINT"})
# TIA Portal on S7-1200/1500 takes the 32- and 64-bit integers too (``lower.wide_control``),
# and the bit strings (its help, "CASE: Create multiway branch": "an integer or a bit
# string"), whose labels are then numbers the unsigned integer of their width holds
_SELECTORS_1500 = _SELECTORS | {"DINT", "UDINT", "LINT", "ULINT"}
_BIT_SELECTORS = frozenset({"BYTE", "WORD", "DWORD"})


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if not isinstance(stmt, ast.Case):
        return
    selector = ctx.type_of(stmt.selector)
    kind = scalar(selector)
    selectors = _SELECTORS_1500 if is_s7_1500(ctx.index.profile) else _SELECTORS
    if kind in _BIT_SELECTORS and is_s7_1500(ctx.index.profile):  # compared as unsigned
        kind = implicit.AS_UNSIGNED[kind]
        stmt.selector = implicit.wrap(ctx, stmt.selector, (f"{scalar(selector)}_TO_{kind}",))
    if not is_silent(selector) and kind not in selectors:
        ctx.report("SCL235", stmt.selector.loc, actual=describe(selector))
    goal = Elementary(kind) if kind in selectors else INT
    seen: list[tuple[int, int, int]] = []  # low, high, line
    for branch in stmt.branches:
        for label in branch.values:
            low = _value(ctx, label.low, goal)
            high = low if label.high is None else _value(ctx, label.high, goal)
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


def _value(
    ctx: Context, literal: ast.Literal | ast.Name | ast.Local | ast.Symbol, goal: Elementary
) -> int | None:
    """The label's value; None when it is no INT constant (reported)."""
    if not isinstance(literal, ast.Literal) and (
        isinstance(literal, ast.Symbol) or ctx.constant(literal.name) is None
    ):
        if not is_silent(ctx.type_of(literal)):  # an undeclared name is SCL201 (a global
            ctx.report("SCL700", literal.loc, name=ctx.text(literal))  # constant of the
        return None  # PLC tag table, which Nasaq's symbol table has no place for)
    found = ctx.type_of(literal)
    if is_silent(found):
        return None
    verdict = assignable(found, goal)
    if verdict.code is not None:
        ctx.report(verdict.code, literal.loc, **verdict.params)
        return None
    if isinstance(found, IntConst | BitsConst):
        return found.value
    value = ctx.index.const_value(ctx.block, literal)  # INT#5
    return value if isinstance(value, int) else None

"""Rule (a warning, ``SCL246``): a sign right after a binary operator, ``A * -B``. TIA accepts
it; the S7-SCL book calls it wrong ("a combination of operations must be separated by
parentheses", seeds-003b §2.8) and asks for ``A * (-B)``. A signed number (``A * -5``) is a
constant of its own in S7-SCL and is not reported."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

NUMBERS = ("INTEGER", "REAL")


def check(ctx: Context, stmt: ast.Stmt) -> None:
    for node, sign in ctx.outline.signs.get(id(stmt), ()):
        operand = sign.operand
        if isinstance(operand, ast.Literal) and operand.kind in NUMBERS:
            continue
        ctx.report("SCL246", sign.loc, op=node.op, operand=ctx.text(sign))

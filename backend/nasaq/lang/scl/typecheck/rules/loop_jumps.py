"""Rule: EXIT and CONTINUE belong to a loop (``SCL237``): they leave or restart the innermost
FOR, WHILE or REPEAT (seeds-003b §2.10); an IF, CASE or REGION around them is no loop.
RETURN is allowed anywhere."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.walk import LOOPS, bodies

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context) -> None:
    _body(ctx, ctx.block.node.code, in_loop=False)


def _body(ctx: Context, body: list[ast.Stmt], in_loop: bool) -> None:
    for stmt in body:
        if isinstance(stmt, ast.Exit | ast.Continue) and not in_loop:
            ctx.report("SCL237", stmt.loc, statement=type(stmt).__name__.upper())
        for nested in bodies(stmt):
            _body(ctx, nested, in_loop or isinstance(stmt, LOOPS))

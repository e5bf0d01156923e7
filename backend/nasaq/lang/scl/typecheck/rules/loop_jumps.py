"""Rule: EXIT and CONTINUE belong to a loop (``SCL237``): they leave or restart the innermost
FOR, WHILE or REPEAT (seeds-003b §2.10); an IF, CASE or REGION around them is no loop.
RETURN is allowed anywhere."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context) -> None:
    for stmt, loops in ctx.outline.jumps:
        if isinstance(stmt, ast.Exit | ast.Continue) and not loops:
            ctx.report("SCL237", stmt.loc, statement=type(stmt).__name__.upper())

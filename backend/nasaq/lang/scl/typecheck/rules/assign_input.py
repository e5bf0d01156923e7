"""Rule: a write to an input parameter (VAR_INPUT) is a **warning** (``SCL215``), also when a
member or element of it is the target (``in.x := 1``, ``in[2] := 0``). STEP 7 (Classic and
TIA) compiles it with a warning and the code runs: in an FC the write goes through the
parameter's pointer to the caller's actual (a constant actual is the caller's temporary copy),
in an FB it changes the instance until the next call passes the input again."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context, stmt: ast.Stmt) -> None:
    if not isinstance(stmt, ast.Assign):
        return
    root = stmt.target
    while isinstance(root, ast.Member | ast.Index):
        root = root.base
    if not isinstance(root, ast.Name | ast.Local | ast.Symbol):
        return
    variable = ctx.variable(root.name)
    if variable is not None and variable.section == "IN":
        ctx.report("SCL215", root.loc, name=variable.name, block=ctx.block.label)

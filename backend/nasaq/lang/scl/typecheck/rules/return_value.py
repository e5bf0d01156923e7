"""Rule: an FC with a return type must assign its function value (``SCL242``, at END_FUNCTION).
S7-SCL rejects such a block: "Return value of function is not set" is an error (E:) in the
compiler listing of seeds-003b §2.1. Any assignment counts (``Calc := ...``, ``FC1 := ...``,
``Calc.x := ...`` for a STRUCT, TIA's ``#Calc := ...``, a target of ``a := Calc := b``, or an
output ``q => Calc``), wherever it stands; whether every path assigns it is not followed. A
VOID FC has no function value."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import UNKNOWN, VOID
from nasaq.lang.scl.typecheck.walk import statements

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context) -> None:
    block = ctx.block
    if block.kind is not BlockKind.FC or block.return_type in (None, VOID, UNKNOWN):
        return
    code = block.node.code
    targets = [
        target
        for stmt in statements(code)
        if isinstance(stmt, ast.Assign)
        for target in (stmt.target, *stmt.chain)
    ]
    targets += [arg.value for call in ctx.outline.calls for arg in call.args if arg.name]
    if not any(_is_function_value(ctx, target) for target in targets):
        ctx.report("SCL242", block.node.end, block=block.label, name=block.node.name.text)


def _is_function_value(ctx: Context, target: ast.Expr) -> bool:
    while isinstance(target, ast.Member | ast.Index):
        target = target.base
    if isinstance(target, ast.Name | ast.Symbol | ast.Local):
        if ctx.variable(target.name) is not None:
            return False
        return ctx.index.named(target.name) is ctx.block
    return isinstance(target, ast.Address) and ctx.index.named(target.text) is ctx.block

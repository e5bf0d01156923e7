"""Rule: the assignment section of a DATA_BLOCK (after BEGIN, seeds-003b §2.3): each target is
a member of the DB (``SCL201``, ``SCL222``, ``SCL216`` ... as in code), each value a constant
(``SCL243``) that can be stored in it (``SCL213``, ``SCL214``, ``SCL218``, as initial values)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.rules.assignment import TARGET_TYPES
from nasaq.lang.scl.typecheck.rules.initial_values import is_constant, store_constant
from nasaq.lang.scl.typecheck.types import is_silent

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context) -> None:
    if ctx.block.kind is not BlockKind.DB:
        return
    for stmt in ctx.block.node.code:
        if not isinstance(stmt, ast.Assign):
            continue
        target = ctx.type_of(stmt.target)
        name = ctx.text(stmt.target)
        if isinstance(target, TARGET_TYPES) and not is_silent(target):
            store_constant(ctx, name, stmt.value, target)
        elif not is_constant(ctx, stmt.value):
            ctx.report("SCL243", stmt.value.loc, name=name)

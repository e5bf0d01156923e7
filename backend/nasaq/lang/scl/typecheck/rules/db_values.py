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
    if ctx.block.db_type is None and ctx.block.node.sources:
        return  # made of an unknown FB/UDT or a system block: reported once, where it is named
    for stmt in ctx.block.node.code:
        if not isinstance(stmt, ast.Assign):
            continue
        _member_named_like_an_address(ctx, stmt)
        target = ctx.type_of(stmt.target)
        name = ctx.text(stmt.target)
        if isinstance(target, TARGET_TYPES) and not is_silent(target):
            store_constant(ctx, name, stmt.value, target)
        elif not is_constant(ctx, stmt.value):
            ctx.report("SCL243", stmt.value.loc, name=name)


def _member_named_like_an_address(ctx: Context, stmt: ast.Assign) -> None:
    """``T1 := 4;`` in a DB whose member is called T1 (TIA writes the members bare there): the
    lexer read an address, but only the DB's members can be assigned here, so it is the member
    (for the lowering too, which reads the same node)."""
    parent: ast.Member | ast.Index | None = None
    head = stmt.target
    while isinstance(head, ast.Member | ast.Index):
        parent, head = head, head.base
    if not isinstance(head, ast.Address) or not head.text.isidentifier():
        return
    if ctx.variable(head.text) is None:
        return
    name = ast.Name(head.text, head.loc)
    if parent is None:
        stmt.target = name
    else:
        parent.base = name

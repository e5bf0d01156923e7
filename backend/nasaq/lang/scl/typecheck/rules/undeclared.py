"""Rule: every name must be declared (``SCL201``): a variable, parameter or constant of the
block, the FC's own name (its return value), a block, or a symbol of the symbol table. ``OK``
and ``ENO`` are predefined BOOL variables of every code block (seeds-003b §2.11): the OK flag,
and the block's own ENO. A system instruction Nasaq does not simulate (``RUNTIME``, ``VAL_STRG``
..., ``nasaq.lang.tia_system``) is ``SCL920`` instead, which says so."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.operands import block_value, function_value, symbol_type
from nasaq.lang.scl.typecheck.types import ERROR, Type
from nasaq.lang.tia_system import tia_system
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

PREDEFINED = {"OK": Elementary("BOOL"), "ENO": Elementary("BOOL")}


def name(ctx: Context, node: ast.Name) -> Type:
    found = _local(ctx, node.name)
    if found is None:
        found = _global(ctx, node.name)
    return found if found is not None else _undeclared(ctx, node, node.name)


def local(ctx: Context, node: ast.Local) -> Type:
    found = _local(ctx, node.name)
    return found if found is not None else _undeclared(ctx, node, f"#{node.name}")


def symbol(ctx: Context, node: ast.Symbol) -> Type:
    found = _global(ctx, node.name)
    if found is None:  # TIA writes "quoted" locals too
        found = _local(ctx, node.name)
    return found if found is not None else _undeclared(ctx, node, f'"{node.name}"')


def _undeclared(ctx: Context, node: ast.Name | ast.Local | ast.Symbol, shown: str) -> Type:
    """Reported at the first use only: the other uses are the same mistake."""
    key = f"undeclared:{node.name.casefold()}"
    if key in ctx.reported:
        return ERROR
    ctx.reported.add(key)
    system = tia_system(node.name) if isinstance(node, ast.Name) else None
    if system is not None:  # RUNTIME, VAL_STRG ... (``nasaq.lang.tia_system``)
        return ctx.report("SCL920", node.loc, name=system)
    return ctx.report("SCL201", node.loc, name=shown, block=ctx.block.label)


def _local(ctx: Context, text: str) -> Type | None:
    found = ctx.variable_type(text)
    if found is not None:
        return found
    constant = ctx.constant(text)
    if constant is not None:
        return ctx.type_of(constant.node)
    block = ctx.block
    if block.kind is BlockKind.FC and text.casefold() == block.name.casefold():
        return function_value(block)
    if text.upper() in PREDEFINED and block.kind in (BlockKind.OB, BlockKind.FB, BlockKind.FC):
        return PREDEFINED[text.upper()]
    return None


def _global(ctx: Context, text: str) -> Type | None:
    block = ctx.index.named(text)
    if block is not None:
        return block_value(ctx, block)
    found = ctx.index.symbol(text)
    return None if found is None else symbol_type(found)

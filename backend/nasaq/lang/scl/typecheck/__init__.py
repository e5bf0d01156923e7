"""The S7-SCL type checker: ``check_index`` runs every rule of ``typecheck.rules`` over the code
of every OB, FB and FC of a bound index (``nasaq.lang.scl.bind``), and the block rules over every
block (declarations of UDTs and DBs too, a DB's assignment section).

Each statement is given to every statement rule; then the expressions it contains directly are
typed (so a name used only as an actual parameter is still checked); then its nested statements
follow. An expression is typed once (``Context.type_of`` caches), and an expression whose type is
already an error (``types.ERROR``) makes nothing built on it reported again: one mistake gives one
diagnostic. Before any block, the instance DBs that calls create are entered in the index
(``instances``), so that their members are typed wherever they are used.
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.scl.typecheck.instances import note_implicit_instances
from nasaq.lang.scl.typecheck.rules import BLOCKS, EXPRESSIONS, STATEMENTS
from nasaq.lang.scl.typecheck.walk import bodies, expressions

CODE_BLOCKS = (BlockKind.OB, BlockKind.FB, BlockKind.FC)


def check_block(index: SclIndex, block: SclBlock) -> list[Diagnostic]:
    """The problems of one block: its code (OB, FB, FC), its declarations, a DB's values."""
    return checked_block(index, block).diagnostics


def checked_block(index: SclIndex, block: SclBlock) -> Context:
    """The context a block was checked in: its ``diagnostics``, and the types of its
    expressions, which the code generator reads instead of typing everything again."""
    ctx = Context(index, block, EXPRESSIONS)
    if block.kind in CODE_BLOCKS:
        _statements(ctx, block.node.code)
    for rule in BLOCKS:
        rule(ctx)
    return ctx


def check_index(
    index: SclIndex, contexts: dict[tuple[BlockKind, int], Context] | None = None
) -> list[Diagnostic]:
    """The problems of every block of the index, in block order; ``contexts`` (if given)
    receives each block's checking context."""
    note_implicit_instances(index)
    found: list[Diagnostic] = []
    for block in index:
        if block.external:  # an STL block in the index: the STL compiler checks it
            continue
        ctx = checked_block(index, block)
        found.extend(ctx.diagnostics)
        if contexts is not None:
            contexts[(block.kind, block.number)] = ctx
    return found


def _statements(ctx: Context, body: list[ast.Stmt]) -> None:
    for stmt in body:
        for rule in STATEMENTS:
            rule(ctx, stmt)
        for expression in expressions(stmt):
            ctx.type_of(expression)
        for nested in bodies(stmt):
            _statements(ctx, nested)


__all__ = ["check_block", "check_index", "checked_block"]

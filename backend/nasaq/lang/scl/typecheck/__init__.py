"""The S7-SCL type checker: ``check_index`` runs every rule of ``typecheck.rules`` over the code
of every OB, FB and FC of a bound index (``nasaq.lang.scl.bind``), and the block rules over every
block (declarations of UDTs and DBs too, a DB's assignment section).

Each statement is given to the statement rules of its class; then the expressions it contains
directly are typed (so a name used only as an actual parameter is still checked); then its nested
statements follow. An expression is typed once (``Context.type_of`` caches), and an expression
whose type is already an error (``types.ERROR``) makes nothing built on it reported again: one
mistake gives one diagnostic. Before any block, one walk over each block's code finds what the
rules look for in it (``walk.outline``: its calls, its operations), and the instance DBs that
calls create are entered in the index (``instances``), so that their members are typed wherever
they are used.
"""

from __future__ import annotations

from typing import get_args

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.scl.typecheck.instances import note_implicit_instances
from nasaq.lang.scl.typecheck.rules import BLOCKS, EXPRESSIONS, STATEMENTS, StatementRule
from nasaq.lang.scl.typecheck.types import assignable
from nasaq.lang.scl.typecheck.walk import Outline, bodies, expressions, outline
from nasaq.lang.types import ArrayType, BlockType, Elementary, StringType, StructType

CODE_BLOCKS = (BlockKind.OB, BlockKind.FB, BlockKind.FC)
DATA_TYPES = (Elementary, StringType, ArrayType, StructType, BlockType)


def check_block(index: SclIndex, block: SclBlock) -> list[Diagnostic]:
    """The problems of one block: its code (OB, FB, FC), its declarations, a DB's values."""
    return checked_block(index, block).diagnostics


def checked_block(index: SclIndex, block: SclBlock, found: Outline | None = None) -> Context:
    """The context a block was checked in: its ``diagnostics``, and the types of its
    expressions, which the code generator reads instead of typing everything again.
    ``found`` is the block's outline when the caller has it already."""
    ctx = Context(index, block, EXPRESSIONS, found)
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
    outlines = [(block, outline(block.node.code)) for block in index]
    note_implicit_instances(index, outlines)
    found: list[Diagnostic] = []
    for block, block_outline in outlines:
        if block.external:  # an STL block in the index: the STL compiler checks it
            continue
        ctx = checked_block(index, block, block_outline)
        found.extend(ctx.diagnostics)
        if contexts is not None:
            contexts[(block.kind, block.number)] = ctx
    return found


# The statement rules of each statement class, in the order of ``STATEMENTS``.
_RULES: dict[type, list[StatementRule]] = {
    kind: [rule for rule, kinds in STATEMENTS if issubclass(kind, kinds)]
    for kind in get_args(ast.Stmt)
}


def _statements(ctx: Context, body: list[ast.Stmt]) -> None:
    for stmt in body:
        if type(stmt) is ast.Assign and (stmt.chain or stmt.op):  # a := b := c, a += b
            _multiple_assignment(ctx, stmt)
            continue
        for rule in _RULES.get(type(stmt), ()):
            rule(ctx, stmt)
        for expression in expressions(stmt):
            ctx.type_of(expression)
        for nested in bodies(stmt):
            _statements(ctx, nested)


def _multiple_assignment(ctx: Context, stmt: ast.Assign) -> None:
    """TIA's ``a := b := c`` and ``a += b`` (S7-1200/1500 only): checked as the assignments
    they stand for."""
    profile = ctx.index.profile
    if not is_s7_1500(profile):
        what = f"{stmt.op}=" if stmt.op else "a multiple assignment"
        ctx.report("SCL500", stmt.loc, what=what, profile=profile)
    plain = [ast.Assign(stmt.target, stmt.value, loc=stmt.loc)] if stmt.op else stmt.steps()
    originals = [step.value for step in plain]
    _statements(ctx, list[ast.Stmt](plain))
    stmt.value = plain[0].value  # the value as stored (TIA's implicit conversion, S7-1500)
    for step, original in zip(plain[1:], originals[1:], strict=True):
        goal = ctx.type_of(step.target)
        if step.value is not original and isinstance(goal, DATA_TYPES):
            verdict = assignable(ctx.type_of(original), goal)  # no conversion between targets
            if verdict.code is not None:
                ctx.report(verdict.code, original.loc, **verdict.params)


__all__ = ["check_block", "check_index", "checked_block"]

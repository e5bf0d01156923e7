"""The S7-SCL type checker: ``check_index`` runs every rule of ``typecheck.rules`` over the code
of every OB, FB and FC of a bound index (``nasaq.lang.scl.bind``).

Each statement is given to every statement rule; then the expressions it contains directly are
typed (so a name used only as an actual parameter is still checked); then its nested statements
follow. An expression is typed once (``Context.type_of`` caches), and an expression whose type is
already an error (``types.ERROR``) makes nothing built on it reported again: one mistake gives one
diagnostic.
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.scl.typecheck.rules import EXPRESSIONS, STATEMENTS

CODE_BLOCKS = (BlockKind.OB, BlockKind.FB, BlockKind.FC)


def check_block(index: SclIndex, block: SclBlock) -> list[Diagnostic]:
    """The problems of one block's code."""
    ctx = Context(index, block, EXPRESSIONS)
    _statements(ctx, block.node.code)
    return ctx.diagnostics


def check_index(index: SclIndex) -> list[Diagnostic]:
    """The problems of the code of every OB, FB and FC of the index, in block order."""
    found: list[Diagnostic] = []
    for block in index:
        if block.kind in CODE_BLOCKS:
            found.extend(check_block(index, block))
    return found


def _statements(ctx: Context, body: list[ast.Stmt]) -> None:
    for stmt in body:
        for rule in STATEMENTS:
            rule(ctx, stmt)
        for expression in _expressions(stmt):
            ctx.type_of(expression)
        for nested in _bodies(stmt):
            _statements(ctx, nested)


def _expressions(stmt: ast.Stmt) -> list[ast.Expr]:
    if isinstance(stmt, ast.Assign):
        return [stmt.target, stmt.value]
    if isinstance(stmt, ast.CallStmt):
        return [stmt.call]
    if isinstance(stmt, ast.If):
        return [branch.condition for branch in stmt.branches]
    if isinstance(stmt, ast.Case):
        return [stmt.selector]
    if isinstance(stmt, ast.For):
        found = [stmt.variable, stmt.start, stmt.end]
        return found + ([stmt.step] if stmt.step is not None else [])
    if isinstance(stmt, ast.While | ast.Repeat):
        return [stmt.condition]
    return []


def _bodies(stmt: ast.Stmt) -> list[list[ast.Stmt]]:
    if isinstance(stmt, ast.If):
        bodies = [branch.body for branch in stmt.branches]
        return bodies + ([stmt.orelse] if stmt.orelse is not None else [])
    if isinstance(stmt, ast.Case):
        bodies = [branch.body for branch in stmt.branches]
        return bodies + ([stmt.orelse] if stmt.orelse is not None else [])
    if isinstance(stmt, ast.For | ast.While | ast.Repeat | ast.Region):
        return [stmt.body]
    return []


__all__ = ["check_block", "check_index"]

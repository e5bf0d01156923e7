"""Walking the statements and expressions of a block: shared by the checker's walker and the
rules that look at a whole body (loops, labels, the return value) or at nested expressions."""

from __future__ import annotations

from collections.abc import Iterator

from nasaq.lang.scl import ast

LOOPS = (ast.For, ast.While, ast.Repeat)


def expressions(stmt: ast.Stmt) -> list[ast.Expr]:
    """The expressions a statement holds directly (not those of its nested statements)."""
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


def bodies(stmt: ast.Stmt) -> list[list[ast.Stmt]]:
    """The statement lists nested in a statement (branches, loop bodies, a REGION)."""
    if isinstance(stmt, ast.If):
        found = [branch.body for branch in stmt.branches]
        return found + ([stmt.orelse] if stmt.orelse is not None else [])
    if isinstance(stmt, ast.Case):
        found = [branch.body for branch in stmt.branches]
        return found + ([stmt.orelse] if stmt.orelse is not None else [])
    if isinstance(stmt, ast.For | ast.While | ast.Repeat | ast.Region):
        return [stmt.body]
    return []


def statements(body: list[ast.Stmt]) -> Iterator[ast.Stmt]:
    """Every statement of a body, nested ones included, in source order."""
    for stmt in body:
        yield stmt
        for nested in bodies(stmt):
            yield from statements(nested)


def children(node: ast.Expr) -> list[ast.Expr]:
    """The expressions an expression is built of."""
    if isinstance(node, ast.Unary):
        return [node.operand]
    if isinstance(node, ast.Binary):
        return [node.left, node.right]
    if isinstance(node, ast.Paren):
        return [node.inner]
    if isinstance(node, ast.Member):
        return [node.base, node.name]
    if isinstance(node, ast.Index):
        return [node.base, *node.indices]
    if isinstance(node, ast.IndexedAddress):
        return list(node.indices)
    if isinstance(node, ast.Call):
        return [node.callee, *(arg.value for arg in node.args)]
    return []


def nested(node: ast.Expr) -> Iterator[ast.Expr]:
    """An expression and every expression inside it."""
    yield node
    for child in children(node):
        yield from nested(child)


def calls(body: list[ast.Stmt]) -> Iterator[ast.Call]:
    """Every call in a body, in statements and inside expressions."""
    for stmt in statements(body):
        for expression in expressions(stmt):
            for node in nested(expression):
                if isinstance(node, ast.Call):
                    yield node

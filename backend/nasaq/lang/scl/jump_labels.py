"""TIA Portal's jump labels inside CASE branches. ``Name:`` at the start of a statement in a
CASE branch parses as the label of a new branch, a named constant (``nasaq.lang.scl.build``
splits the branch there: LALR(1) cannot tell the two apart). TIA reads it as a jump label when
a GOTO of the block names it: a named constant is never a jump target. Run by the binder, after
the nesting limits (the walk is recursive)."""

from __future__ import annotations

from nasaq.lang.scl import ast


def rejoin(code: list[ast.Stmt]) -> None:
    """Turns the CASE branches labelled by a GOTO's target back into that jump label, at the
    end of the branch before them."""
    found = _statements(code)
    targets = {stmt.label.casefold() for stmt in found if type(stmt) is ast.Goto}
    if not targets:
        return
    for stmt in found:
        if type(stmt) is ast.Case and len(stmt.branches) > 1:
            stmt.branches[:] = _merged(stmt.branches, targets)


def _merged(branches: list[ast.CaseBranch], targets: set[str]) -> list[ast.CaseBranch]:
    kept = [branches[0]]
    for branch in branches[1:]:
        value = branch.values[0]
        low = value.low
        is_label = len(branch.values) == 1 and value.high is None and type(low) is ast.Name
        if is_label and isinstance(low, ast.Name) and low.name.casefold() in targets:
            kept[-1].body.append(ast.Label(low.name, value.loc))
            kept[-1].body.extend(branch.body)
        else:
            kept.append(branch)
    return kept


def _statements(body: list[ast.Stmt]) -> list[ast.Stmt]:
    """Every statement, nested ones included (``typecheck.walk.statements``, which imports the
    binder)."""
    found: list[ast.Stmt] = []
    for stmt in body:
        found.append(stmt)
        for inner in _bodies(stmt):
            found += _statements(inner)
    return found


def _bodies(stmt: ast.Stmt) -> list[list[ast.Stmt]]:
    if isinstance(stmt, ast.If | ast.Case):
        parts = [branch.body for branch in stmt.branches]
        return parts if stmt.orelse is None else [*parts, stmt.orelse]
    if isinstance(stmt, ast.For | ast.While | ast.Repeat | ast.Region):
        return [stmt.body]
    return []

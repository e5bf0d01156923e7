"""Walking the statements and expressions of a block: shared by the checker's walker and the
rules that look at a whole body (loops, labels, the return value) or at nested expressions.

Each node class has its own small function in a table keyed by the class (the node classes
have no subclasses): one dictionary look-up per node instead of a chain of ``isinstance``
tests, which made walking the largest part of checking a big source."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from nasaq.lang.scl import ast

LOOPS = (ast.For, ast.While, ast.Repeat)

_Parts = Callable[[Any], list[Any]]


def _for_expressions(stmt: ast.For) -> list[ast.Expr]:
    found = [stmt.variable, stmt.start, stmt.end]
    return found + ([stmt.step] if stmt.step is not None else [])


def _branch_bodies(stmt: ast.If | ast.Case) -> list[list[ast.Stmt]]:
    found = [branch.body for branch in stmt.branches]
    return found + ([stmt.orelse] if stmt.orelse is not None else [])


_EXPRESSIONS: dict[type, _Parts] = {
    ast.Assign: lambda stmt: [stmt.target, *stmt.chain, stmt.value],
    ast.CallStmt: lambda stmt: [stmt.call],
    ast.If: lambda stmt: [branch.condition for branch in stmt.branches],
    ast.Case: lambda stmt: [stmt.selector],
    ast.For: _for_expressions,
    ast.While: lambda stmt: [stmt.condition],
    ast.Repeat: lambda stmt: [stmt.condition],
}

_BODIES: dict[type, _Parts] = {
    ast.If: _branch_bodies,
    ast.Case: _branch_bodies,
    ast.For: lambda stmt: [stmt.body],
    ast.While: lambda stmt: [stmt.body],
    ast.Repeat: lambda stmt: [stmt.body],
    ast.Region: lambda stmt: [stmt.body],
}


def expressions(stmt: ast.Stmt) -> list[ast.Expr]:
    """The expressions a statement holds directly (not those of its nested statements)."""
    parts = _EXPRESSIONS.get(type(stmt))
    return parts(stmt) if parts is not None else []


def bodies(stmt: ast.Stmt) -> list[list[ast.Stmt]]:
    """The statement lists nested in a statement (branches, loop bodies, a REGION)."""
    parts = _BODIES.get(type(stmt))
    return parts(stmt) if parts is not None else []


def statements(body: list[ast.Stmt]) -> list[ast.Stmt]:
    """Every statement of a body, nested ones included, in source order."""
    found: list[ast.Stmt] = []
    for stmt in body:
        found.append(stmt)
        parts = _BODIES.get(type(stmt))
        if parts is not None:
            for inner in parts(stmt):
                found += statements(inner)
    return found


def nested(node: ast.Expr) -> list[ast.Expr]:
    """An expression and every expression inside it, each before its parts (left to right)."""
    found: list[ast.Expr] = []
    _add(node, found)
    return found


def _add(node: ast.Expr, found: list[ast.Expr]) -> None:
    add = _ADD.get(type(node))
    if add is None:  # a name, constant or address: no parts
        found.append(node)
    else:
        add(node, found)


def _unary(node: ast.Unary, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.operand, found)


def _binary(node: ast.Binary, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.left, found)
    _add(node.right, found)


def _paren(node: ast.Paren, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.inner, found)


def _member(node: ast.Member, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.base, found)
    _add(node.name, found)


def _slice(node: ast.Slice, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.base, found)


def _index(node: ast.Index, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.base, found)
    for index in node.indices:
        _add(index, found)


def _indexed_address(node: ast.IndexedAddress, found: list[ast.Expr]) -> None:
    found.append(node)
    for index in node.indices:
        _add(index, found)


def _call(node: ast.Call, found: list[ast.Expr]) -> None:
    found.append(node)
    _add(node.callee, found)
    for arg in node.args:
        _add(arg.value, found)


_ADD: dict[type, Callable[[Any, list[ast.Expr]], None]] = {
    ast.Unary: _unary,
    ast.Binary: _binary,
    ast.Paren: _paren,
    ast.Member: _member,
    ast.Slice: _slice,
    ast.Index: _index,
    ast.IndexedAddress: _indexed_address,
    ast.Call: _call,
}


def calls(body: list[ast.Stmt]) -> list[ast.Call]:
    """Every call in a body, in statements and inside expressions."""
    return outline(body).calls


Loops = tuple[int, ...]  # the loops around a statement, outermost first (their ids)
Signed = tuple[ast.Binary, ast.Unary]  # A * -B: the operation, the sign
Counters = tuple[tuple[str, ast.For], ...]  # the FOR loops around, innermost first, by variable


@dataclass(slots=True)
class Outline:
    """What the rules look for in the code of a block, found in one walk: its calls (in source
    order) and, by id, those that are statements of their own; by statement (id), the binary
    operations whose right operand begins with a sign (``A * -B``, ``A + -B * C``) inside the
    expressions it holds directly, with that sign; the labels, GOTO, EXIT and CONTINUE
    statements with the loops around each; and what may write the control variable of a FOR
    loop around it (``counter_writes``: an assignment target, the variable of an inner FOR, or
    an actual parameter, which writes only if it is an output or in/out), with that loop."""

    calls: list[ast.Call] = field(default_factory=list)
    statement_calls: set[int] = field(default_factory=set)
    signs: dict[int, list[Signed]] = field(default_factory=dict)
    jumps: list[tuple[ast.Label | ast.Goto | ast.Exit | ast.Continue, Loops]] = field(
        default_factory=list
    )
    counter_writes: list[tuple[ast.Expr | ast.Arg, ast.For]] = field(default_factory=list)


JUMPS = (ast.Label, ast.Goto, ast.Exit, ast.Continue)


def outline(body: list[ast.Stmt]) -> Outline:
    found = Outline()
    _outline(body, (), (), found)
    return found


def variable_key(node: ast.Expr) -> str | None:
    """How a FOR control variable is matched with what is written: ``k`` and ``#k`` alike, a
    ``"symbol"`` apart (it may be global); None for anything else (not followed)."""
    if isinstance(node, ast.Name | ast.Local):
        return node.name.casefold()
    if isinstance(node, ast.Symbol):
        return '"' + node.name.casefold()
    return None


def _outline(body: list[ast.Stmt], loops: Loops, counters: Counters, found: Outline) -> None:
    for stmt in body:
        parts = _EXPRESSIONS.get(type(stmt))
        if parts is not None:
            signs: list[Signed] = []
            first_call = len(found.calls)
            for expression in parts(stmt):
                _operations(expression, found.calls, signs)
            if signs:
                found.signs[id(stmt)] = signs
            if isinstance(stmt, ast.CallStmt):
                found.statement_calls.add(id(stmt.call))
            if counters:
                _counter_writes(stmt, found.calls[first_call:], counters, found)
        elif isinstance(stmt, JUMPS):
            found.jumps.append((stmt, loops))
        inner = _BODIES.get(type(stmt))
        if inner is not None:
            around, within = loops, counters
            if isinstance(stmt, LOOPS):
                around = (*loops, id(stmt))
            if isinstance(stmt, ast.For):
                key = variable_key(stmt.variable)
                if key is not None:
                    within = ((key, stmt), *counters)
            for nested_body in inner(stmt):
                _outline(nested_body, around, within, found)


def _counter_writes(
    stmt: ast.Stmt, calls: list[ast.Call], counters: Counters, found: Outline
) -> None:
    """Notes what in ``stmt`` may write the variable of a FOR loop around it (the innermost
    loop of that variable)."""
    written: list[ast.Expr | ast.Arg] = [arg for call in calls for arg in call.args]
    if isinstance(stmt, ast.Assign):
        written.append(stmt.target)
    elif isinstance(stmt, ast.For):
        written.append(stmt.variable)
    for item in written:
        key = variable_key(item.value if isinstance(item, ast.Arg) else item)
        if key is None:
            continue
        for counter, loop in counters:
            if counter == key:
                found.counter_writes.append((item, loop))
                break


def _operations(node: ast.Expr, calls: list[ast.Call], signs: list[Signed]) -> None:
    """Adds the calls and the signed binary operations (``Outline``) of an expression, itself
    included, in the order of ``nested``; names and constants (most nodes) cost a look-up."""
    add = _OPERATIONS.get(type(node))
    if add is not None:
        add(node, calls, signs)


def _in_unary(node: ast.Unary, calls: list[ast.Call], signs: list[Signed]) -> None:
    _operations(node.operand, calls, signs)


def _in_binary(node: ast.Binary, calls: list[ast.Call], signs: list[Signed]) -> None:
    first = node.right
    while type(first) is ast.Binary:  # A + -B * C: the sign still follows the +
        first = first.left
    if type(first) is ast.Unary and first.op in ("-", "+"):
        signs.append((node, first))
    _operations(node.left, calls, signs)
    _operations(node.right, calls, signs)


def _in_paren(node: ast.Paren, calls: list[ast.Call], signs: list[Signed]) -> None:
    _operations(node.inner, calls, signs)


def _in_member(node: ast.Member, calls: list[ast.Call], signs: list[Signed]) -> None:
    _operations(node.base, calls, signs)
    _operations(node.name, calls, signs)


def _in_index(node: ast.Index, calls: list[ast.Call], signs: list[Signed]) -> None:
    _operations(node.base, calls, signs)
    for index in node.indices:
        _operations(index, calls, signs)


def _in_indexed_address(
    node: ast.IndexedAddress, calls: list[ast.Call], signs: list[Signed]
) -> None:
    for index in node.indices:
        _operations(index, calls, signs)


def _in_call(node: ast.Call, calls: list[ast.Call], signs: list[Signed]) -> None:
    calls.append(node)
    _operations(node.callee, calls, signs)
    for arg in node.args:
        _operations(arg.value, calls, signs)


_OPERATIONS: dict[type, Callable[[Any, list[ast.Call], list[Signed]], None]] = {
    ast.Unary: _in_unary,
    ast.Binary: _in_binary,
    ast.Paren: _in_paren,
    ast.Member: _in_member,
    ast.Index: _in_index,
    ast.IndexedAddress: _in_indexed_address,
    ast.Call: _in_call,
}

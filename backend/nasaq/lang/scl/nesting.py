"""Refuses SCL the compiler's recursive passes cannot take: nesting and numbers past
``nasaq.lang.limits``.

The LALR parser itself nests without recursion, so any depth parses; binding, type checking,
lowering and formatting then walk the tree recursively. After the parse, ``limit_nesting``
walks each block without recursion and, where a control statement is nested deeper than
``MAX_STATEMENT_NESTING`` (SCL150), a statement's expression deeper than
``MAX_EXPRESSION_DEPTH`` (SCL151), a declaration's type deeper than ``MAX_STRUCT_NESTING``
(SCL152) or a number literal longer than ``MAX_NUMBER_DIGITS`` digits (SCL153), reports it once
and puts an ``ast.Bad`` (what the parser leaves for skipped input) in its place, so the later
passes see an already reported gap instead of the deep tree.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from operator import attrgetter
from typing import Any

from nasaq.diagnostics import Diagnostic, render
from nasaq.lang.limits import (
    MAX_EXPRESSION_DEPTH,
    MAX_NUMBER_DIGITS,
    MAX_STATEMENT_NESTING,
    MAX_STRUCT_NESTING,
)
from nasaq.lang.scl import ast
from nasaq.lang.stl.diag import span

_BODIES = frozenset({"body", "orelse"})  # statements; a branch's condition or labels are not
_NOTHING: frozenset[str] = frozenset()
# A STRUCT in a STRUCT is two tree levels (the member's declaration, its type), plus the
# declaration's own name and type nodes.
_TYPE_LEVELS = 2 * MAX_STRUCT_NESTING + 2


def _getter(kind: Any, skip: frozenset[str]) -> Callable[[Any], tuple[Any, ...]] | None:
    """What of a node of ``kind`` may nest (its fields but ``loc`` and ``skip``), as one call
    that gives them as a tuple; None for no dataclass or no such field."""
    if not dataclasses.is_dataclass(kind):
        return None
    names = [f.name for f in dataclasses.fields(kind) if f.name != "loc" and f.name not in skip]
    if not names:
        return None
    if len(names) == 1:
        name = names[0]
        return lambda node: (getattr(node, name),)
    found: Callable[[Any], tuple[Any, ...]] = attrgetter(*names)
    return found


# A statement on one line shorter than this holds no expression deeper than the limit (a tree
# level takes at least two thirds of a character: ``f(x)`` is a call, an argument and a name)
# and no number that long: its expressions need not be walked.
_SHORT = min(MAX_EXPRESSION_DEPTH * 2 // 3, MAX_NUMBER_DIGITS)
# The same holds for any node the walk meets: one on one line narrower than ``_ROOM[limit -
# depth]`` characters cannot reach the limit below it (nor hold a number of MAX_NUMBER_DIGITS),
# so the walk leaves it; a node without a place of its own (width 0, made by the compiler)
# is walked. This keeps the walk to a few nodes per long statement.
_ROOM = [max(0, min((left - 1) * 2 // 3, MAX_NUMBER_DIGITS)) for left in range(200)]
# per node type and whether statement bodies count: ``_getter``
_CHILDREN: dict[tuple[type, frozenset[str]], Callable[[Any], tuple[Any, ...]] | None] = {}
_LEAVES = frozenset({str, int, bool, float, type(None), ast.Loc})


def _digits(text: str) -> int:
    return sum(ch.isdigit() or ch in "abcdefABCDEF" for ch in text)


class _Limiter:
    def __init__(self, file: str) -> None:
        self.file = file
        self.diagnostics: list[Diagnostic] = []

    def report(self, code: str, loc: ast.Loc, **params: Any) -> None:
        self.diagnostics.append(render(code, span(self.file, loc), **params))

    def too_deep(self, root: Any, limit: int, statements: bool) -> tuple[str, Any] | None:
        """(code, node) of the first problem under ``root``, or None: a tree level deeper than
        ``limit`` (SCL152 for types, else SCL151) or a long number (SCL153). Without
        ``statements`` the bodies of control statements are left out (``body`` walks them).
        It runs on every statement of every compile, so it is written for speed."""
        skip = _BODIES if not statements else _NOTHING
        level: list[Any] = root if type(root) is list else [root]
        depth = 0
        while level:
            room = _ROOM[limit - depth] if 0 <= limit - depth < len(_ROOM) else 0
            below: list[Any] = []
            add = below.append
            for node in level:
                kind = type(node)
                if kind is list:
                    below.extend(node)  # a list is no level of its own
                    continue
                if kind is ast.Literal:
                    text = node.text
                    if len(text) > MAX_NUMBER_DIGITS and _digits(text) > MAX_NUMBER_DIGITS:
                        return "SCL153", node
                    continue
                key = (kind, skip)
                children = _CHILDREN.get(key)
                if children is None:
                    if key in _CHILDREN:
                        continue
                    children = _CHILDREN[key] = _getter(kind, skip)
                    if children is None:
                        continue
                if depth > limit:
                    return ("SCL152" if statements else "SCL151"), node
                loc = node.loc  # every node of a block has one (``ast.SourceFile`` is none)
                if loc[0] == loc[2] and 0 < loc[3] - loc[1] < room:
                    continue
                for value in children(node):
                    if type(value) is list:
                        below.extend(value)  # a list's items are its owner's children
                    elif type(value) not in _LEAVES:
                        add(value)
            level = below
            depth += 1
        return None

    def statement_problem(self, stmt: Any) -> bool:
        """Reports what is wrong with ``stmt``'s own expressions; True when it must go."""
        found = self.too_deep(stmt, MAX_EXPRESSION_DEPTH, statements=False)
        if found is None:
            return False
        code, node = found
        where = getattr(node, "loc", None) or stmt.loc
        if code == "SCL153":
            self.report(code, where, digits=_digits(node.text), limit=MAX_NUMBER_DIGITS)
        else:
            self.report(code, where, limit=MAX_EXPRESSION_DEPTH)
        return True

    def body(self, code: list[Any]) -> None:
        stack: list[tuple[list[Any], int]] = [(code, 1)]
        while stack:
            statements, depth = stack.pop()
            for k, stmt in enumerate(statements):
                kind = type(stmt)
                if kind is ast.Bad:
                    continue
                loc = stmt.loc
                short = loc[0] == loc[2] and loc[3] - loc[1] < _SHORT
                if not short and self.statement_problem(stmt):
                    statements[k] = ast.Bad(stmt.loc)
                    continue
                if kind not in _CONTROL:
                    continue
                inner = _bodies(stmt)
                if depth > MAX_STATEMENT_NESTING:
                    self.report("SCL150", stmt.loc, limit=MAX_STATEMENT_NESTING)
                    statements[k] = ast.Bad(stmt.loc)
                    continue
                stack.extend((body, depth + 1) for body in inner)

    def decls(self, decls: list[Any]) -> None:
        for k, decl in enumerate(decls):
            if not isinstance(decl, ast.VarDecl):
                continue
            found = self.too_deep(decl.type, _TYPE_LEVELS, statements=True)
            if found is None and decl.init:
                found = self.too_deep(decl.init, MAX_EXPRESSION_DEPTH, statements=False)
            if found is None:
                continue
            code, node = found
            where = getattr(node, "loc", None) or decl.loc
            if code == "SCL153":
                self.report(code, where, digits=_digits(node.text), limit=MAX_NUMBER_DIGITS)
            elif code == "SCL152":
                self.report(code, decl.loc, limit=MAX_STRUCT_NESTING)
            else:
                self.report(code, where, limit=MAX_EXPRESSION_DEPTH)
            decls[k] = ast.Bad(decl.loc)

    def block(self, block: ast.Block) -> None:
        for section in block.sections:
            if isinstance(section, ast.VarSection):
                self.decls(section.decls)
            elif isinstance(section, ast.ConstSection):
                for k, const in enumerate(section.decls):
                    if isinstance(const, ast.ConstDecl) and self.statement_problem(const):
                        section.decls[k] = ast.Bad(const.loc)
        for source in block.sources:
            if isinstance(source, ast.StructType):
                self.decls(source.members)
        returned = block.return_type
        if returned is not None and self.too_deep(returned, _TYPE_LEVELS, statements=True):
            self.report("SCL152", block.loc, limit=MAX_STRUCT_NESTING)
            block.return_type = ast.NamedType("VOID", loc=block.loc)
        self.body(block.code)


_CONTROL = frozenset({ast.If, ast.Case, ast.For, ast.While, ast.Repeat, ast.Region})


def _bodies(stmt: Any) -> list[list[Any]]:
    if isinstance(stmt, ast.If):
        found = [branch.body for branch in stmt.branches]
        return found + ([stmt.orelse] if stmt.orelse is not None else [])
    if isinstance(stmt, ast.Case):
        found = [branch.body for branch in stmt.branches]
        return found + ([stmt.orelse] if stmt.orelse is not None else [])
    if isinstance(stmt, (ast.For, ast.While, ast.Repeat, ast.Region)):
        return [stmt.body]
    return []


def limit_nesting(file: str, blocks: list[ast.Block]) -> list[Diagnostic]:
    """The limit diagnostics of ``blocks``, whose too-deep parts are replaced by ``ast.Bad``."""
    limiter = _Limiter(file)
    for block in blocks:
        limiter.block(block)
    return limiter.diagnostics

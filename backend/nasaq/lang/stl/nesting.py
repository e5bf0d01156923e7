"""Refuses STL declarations nested deeper than ``nasaq.lang.limits.MAX_STRUCT_NESTING``
(STL150) or with array bounds outside DINT (STL153).

STEP 7's own rules (7 levels of ``A(``, STL2xx) are checked where the code is lowered; this is
the compiler protecting itself: binding, layout and the comment pass walk a declaration's
STRUCTs and ARRAYs recursively, so a STRUCT nested thousands of times would end in a
RecursionError. ``limit_nesting`` measures every declaration without recursion and drops the
ones over the limit with one STL150 each (the declaration is not compiled further).
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.limits import MAX_ARRAY_BOUND, MAX_STRUCT_NESTING, MIN_ARRAY_BOUND
from nasaq.lang.stl import ast
from nasaq.lang.stl.diag import problem


def _depth_over(node: ast.TypeNode | None, limit: int) -> bool:
    stack: list[tuple[object, int]] = [(node, 0)]
    while stack:
        current, depth = stack.pop()
        if depth > limit:
            return True
        if isinstance(current, ast.StructTypeNode):
            stack.extend((member.type, depth + 1) for member in current.members)
        elif isinstance(current, ast.ArrayTypeNode):
            stack.append((current.element, depth + 1))
    return False


def _bound_out_of_range(node: ast.TypeNode | None) -> int | None:
    """The first array bound of ``node`` outside DINT (no S7 CPU indexes further), or None."""
    stack: list[object] = [node]
    while stack:
        current = stack.pop()
        if isinstance(current, ast.StructTypeNode):
            stack.extend(member.type for member in current.members)
        elif isinstance(current, ast.ArrayTypeNode):
            for low, high in current.dims:
                for bound in (low, high):
                    if not MIN_ARRAY_BOUND <= bound <= MAX_ARRAY_BOUND:
                        return bound
            stack.append(current.element)
    return None


def _limit(file: str, decls: list[ast.VarDeclNode], found: list[Diagnostic]) -> None:
    kept = []
    for decl in decls:
        if _depth_over(decl.type, MAX_STRUCT_NESTING):
            limit = MAX_STRUCT_NESTING
            found.append(problem("STL150", file, decl.loc, name=decl.name, limit=limit))
        elif (bound := _bound_out_of_range(decl.type)) is not None:
            shown = str(bound) if abs(bound) < 10**12 else ("-" if bound < 0 else "") + "10^12…"
            params = {"name": decl.name, "bound": shown}
            found.append(problem("STL153", file, decl.loc, low=MIN_ARRAY_BOUND, **params))
        else:
            kept.append(decl)
    if len(kept) != len(decls):
        decls[:] = kept


def limit_nesting(file: str, blocks: list[ast.BlockNode]) -> list[Diagnostic]:
    """STL150 for each declaration of ``blocks`` nested too deep; those are removed."""
    found: list[Diagnostic] = []
    for block in blocks:
        for item in block.head:
            if isinstance(item, ast.VarSectionNode):
                _limit(file, item.decls, found)
        if isinstance(block.db_body, ast.StructTypeNode):
            _limit(file, block.db_body.members, found)
        if block.return_type is not None and _depth_over(block.return_type, MAX_STRUCT_NESTING):
            found.append(
                problem("STL150", file, block.loc, name=block.ident, limit=MAX_STRUCT_NESTING)
            )
            block.return_type = None
    return found

"""Rule: a member must exist (``SCL222``): ``s.x`` in a STRUCT, UDT or FB instance, ``DB10.x``
and ``"Data".x`` in a DB's declaration; after a DB also absolute parts (``DB10.DW2``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.operands import db_part
from nasaq.lang.scl.typecheck.types import ANYTHING, DbRef, Type, describe, is_silent

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def member(ctx: Context, node: ast.Member) -> Type:
    base = ctx.type_of(node.base)
    if is_silent(base):
        for index in node.name.indices if isinstance(node.name, ast.IndexedAddress) else []:
            ctx.type_of(index)
        return base
    part = node.name
    if isinstance(part, ast.Address | ast.IndexedAddress):
        if not isinstance(base, DbRef):
            return ctx.report("SCL222", part.loc, type=describe(base), name=ctx.text(part))
        if isinstance(part, ast.IndexedAddress):
            return ctx.type_of(part)
        found = db_part(part.text)
        return found if found is not None else ANYTHING
    if isinstance(base, DbRef) and base.number is None:
        return ANYTHING
    members = ctx.members(base)
    if members is None and isinstance(base, DbRef):
        return ANYTHING  # a DB the sources do not declare (its structure is unknown)
    found_type = None if members is None else members.get(part.name.casefold())
    if found_type is None:
        return ctx.report("SCL222", part.loc, type=describe(base), name=part.name)
    return ctx.declared(found_type)

"""Rule: a member must exist (``SCL222``): ``s.x`` in a STRUCT, UDT or FB instance, ``DB10.x``
and ``"Data".x`` in a DB's declaration; after a DB also absolute parts (``DB10.DW2``), except
in an optimized DB (``SCL600``, ``nasaq.lang.scl.optimized``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.optimized import db_label, optimized_db
from nasaq.lang.scl.typecheck import iec_calls
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
        if base.number is not None and optimized_db(ctx.index, base.number):
            block = db_label(ctx.index, base.number)
            return ctx.report("SCL600", part.loc, operand=ctx.text(node), block=block)
        if isinstance(part, ast.IndexedAddress):
            return ctx.type_of(part)
        found = db_part(part.text)
        return found if found is not None else ANYTHING
    if isinstance(base, DbRef) and base.number is None:
        return ANYTHING
    if iec_calls.instruction(node) is not None and iec_calls.instance_of(ctx.index, base):
        return ANYTHING  # "IEC_Timer_0_DB".TON: the callee of a call (``iec_calls``)
    members = ctx.members(base)
    if members is None and isinstance(base, DbRef) and base.number is not None:
        # A DB only the symbol table knows: STEP 7 and TIA refuse it as well (the block must
        # exist); the error names the DB, so the file's fault is a block from elsewhere.
        label = unknown_db(ctx, node.base, base.number)
        return ctx.report("SCL923", part.loc, block=label, name=part.name)
    found_type = None if members is None else members.get(part.name.casefold())
    called = found_type is None and iec_calls.instruction(node) is not None
    if called and any(call.callee is node for call in ctx.outline.calls):
        return ANYTHING  # "Plain".TON(...): the call's SCL704
    if found_type is None:
        return ctx.report("SCL222", part.loc, type=describe(base), name=part.name)
    return ctx.declared(found_type)


def unknown_db(ctx: Context, base: ast.Expr, number: int) -> str:
    """``"Data" (DB 200)`` for a DB named by its symbol, ``DB 200`` for ``DB200``."""
    if isinstance(base, ast.Address):
        return f"DB {number}"
    return f'"{ctx.text(base).strip(chr(34))}" (DB {number})'

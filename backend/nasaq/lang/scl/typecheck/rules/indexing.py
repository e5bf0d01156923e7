"""Rule: indices. An array takes as many indices as it has dimensions, or fewer for a row of a
matrix (``m[2]`` of ``ARRAY[1..3, 1..4]``); more is ``SCL216``, indexing something that is no
array ``SCL217``. ``MW[i]`` takes one index (the byte), ``I[i, k]``/``DX[i, k]`` two (byte and
bit). Each index must be an integer."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import UNKNOWN
from nasaq.lang.scl.typecheck.operands import indexed_type
from nasaq.lang.scl.typecheck.types import ERROR, Type, assignable, describe, is_silent
from nasaq.lang.types import ArrayType, Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

_DINT = Elementary("DINT")


def _indices(ctx: Context, indices: list[ast.Expr]) -> bool:
    """Types the indices; False when one is wrong (reported)."""
    good = True
    for index in indices:
        value = ctx.type_of(index)
        if is_silent(value):
            good = good and value is not ERROR
            continue
        verdict = assignable(value, _DINT)
        if verdict.code is not None:
            ctx.report(verdict.code, index.loc, **verdict.params)
            good = False
    return good


def index(ctx: Context, node: ast.Index) -> Type:
    return _element(ctx, ctx.type_of(node.base), ctx.text(node.base), node.indices, node.loc)


def _element(ctx: Context, base: Type, name: str, indices: list[ast.Expr], where: ast.Loc) -> Type:
    good = _indices(ctx, indices)
    if is_silent(base):
        return base
    if not isinstance(base, ArrayType):
        return ctx.report("SCL217", where, name=name, type=describe(base))
    given, dims = len(indices), len(base.dims)
    if given > dims:
        return ctx.report("SCL216", where, name=name, expected=dims, actual=given)
    if not good:
        return ERROR
    if given < dims:  # a row of a matrix (seeds-003b §2.6)
        return ArrayType(base.dims[given:], base.element)
    return ctx.declared(base.element)


def indexed_address(ctx: Context, node: ast.IndexedAddress) -> Type:
    variable = ctx.variable(node.area)
    # `m[2]` for an array called m: the lexer read an address. `I[i, k]` next to a variable
    # `i : INT` is the input area (names are case-insensitive): only an array is indexed.
    if variable is not None and (isinstance(variable.type, ArrayType) or variable.type == UNKNOWN):
        return _element(ctx, ctx.declared(variable.type), node.area, node.indices, node.loc)
    good = _indices(ctx, node.indices)
    value, count = indexed_type(node.area)
    if len(node.indices) != count:
        return ctx.report(
            "SCL216", node.loc, name=node.area, expected=count, actual=len(node.indices)
        )
    return value if good else ERROR

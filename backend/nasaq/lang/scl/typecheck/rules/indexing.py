"""Rule: indices. An array takes as many indices as it has dimensions, or fewer for a row of a
matrix (``m[2]`` of ``ARRAY[1..3, 1..4]``); more is ``SCL216``, indexing something that is no
array ``SCL217``. ``MW[i]`` takes one index (the byte), ``I[i, k]``/``DX[i, k]`` two (byte and
bit). Each index must be an integer. An index that is a constant (a number, a CONST name, an
expression of them) must lie within the bounds of its dimension (``SCL249``): S7-SCL computes
its address when it compiles, so it reports ``a[11]`` of ``ARRAY[1..10]`` there."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import UNKNOWN
from nasaq.lang.scl.descriptor import OpenArray
from nasaq.lang.scl.typecheck import variant
from nasaq.lang.scl.typecheck.operands import indexed_type
from nasaq.lang.scl.typecheck.rules.initial_values import is_constant
from nasaq.lang.scl.typecheck.types import (
    ERROR,
    BitsConst,
    IntConst,
    Type,
    assignable,
    describe,
    is_silent,
)
from nasaq.lang.types import ArrayType, Elementary, StringType

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

_DINT = Elementary("DINT")


def _indices(ctx: Context, indices: list[ast.Expr]) -> list[Type] | None:
    """The types of the indices; None when one is wrong (reported)."""
    good = True
    found: list[Type] = []
    for index in indices:
        value = ctx.type_of(index)
        found.append(value)
        if is_silent(value):
            good = good and value is not ERROR
            continue
        verdict = assignable(value, _DINT)
        if verdict.code is not None:
            ctx.report(verdict.code, index.loc, **verdict.params)
            good = False
    return found if good else None


def index(ctx: Context, node: ast.Index) -> Type:
    return _element(ctx, ctx.type_of(node.base), ctx.text(node.base), node.indices, node.loc)


def _element(ctx: Context, base: Type, name: str, indices: list[ast.Expr], where: ast.Loc) -> Type:
    values = _indices(ctx, indices)
    if is_silent(base):
        return base
    if isinstance(base, OpenArray):  # ARRAY[*] (S7-1200/1500): the bounds come at run time
        return variant.element(ctx, base, name, indices, where)
    if isinstance(base, StringType) and len(indices) == 1:
        if values is None:
            return ERROR
        chars = ArrayType(((1, max(1, base.length)),), Elementary("CHAR"))
        if not _within(ctx, name, chars, indices, values):
            return ERROR
        return _character(ctx, base, name, where)
    if not isinstance(base, ArrayType):
        return ctx.report("SCL217", where, name=name, type=describe(base))
    given, dims = len(indices), len(base.dims)
    if given > dims:
        return ctx.report("SCL216", where, name=name, expected=dims, actual=given)
    if values is None or not _within(ctx, name, base, indices, values):
        return ERROR
    if given < dims:  # a row of a matrix (seeds-003b §2.6)
        return ArrayType(base.dims[given:], base.element)
    return ctx.declared(base.element)


def _character(ctx: Context, base: StringType, name: str, where: ast.Loc) -> Type:
    """``#s[i]``: the i-th character of a (W)STRING, 1 first (TIA Portal, S7-1200/1500)."""
    if not is_s7_1500(ctx.index.profile):
        what = f"{name}[...] (a character of a {base.name})"
        return ctx.report("SCL500", where, what=what, profile=ctx.index.profile)
    return Elementary("WCHAR" if base.wide else "CHAR")


def _within(
    ctx: Context, name: str, base: ArrayType, indices: list[ast.Expr], values: list[Type]
) -> bool:
    """Reports each constant index outside its dimension; True when there is none."""
    good = True
    for index, value, (low, high) in zip(indices, values, base.dims, strict=False):
        number = _constant(ctx, index, value)
        if number is not None and not low <= number <= high:
            ctx.report("SCL249", index.loc, value=number, name=name, low=low, high=high)
            good = False
    return good


def _constant(ctx: Context, index: ast.Expr, value: Type) -> int | None:
    """The value of a constant index, None for any other. Numbers, CONST names and ``+ - *``
    of them are typed as their value already (``IntConst``); ``INT#5`` or ``N DIV 2`` are
    folded by the binder's ``const_value`` (``is_constant`` first: a variable of the name
    hides a CONST)."""
    if type(value) is IntConst or type(value) is BitsConst:
        return value.value
    if not is_constant(ctx, index):
        return None
    found = ctx.index.const_value(ctx.block, index)
    return found if isinstance(found, int) else None


# The areas an indexed address may have: the peripheral ones only in bytes, words and dwords.
_AREAS = frozenset(
    {
        *("PIB", "PIW", "PID", "PQB", "PQW", "PQD", "IB", "IW", "ID", "IX", "QB", "QW", "QD"),
        *("QX", "MB", "MW", "MD", "MX", "I", "Q", "M", "DBX", "DBB", "DBW", "DBD", "DX", "DB"),
        *("DW", "DD"),
    }
)


def indexed_address(ctx: Context, node: ast.IndexedAddress) -> Type:
    variable = ctx.variable(node.area)
    # `m[2]` for an array called m: the lexer read an address. `I[i, k]` next to a variable
    # `i : INT` is the input area (names are case-insensitive): only an array is indexed.
    if variable is not None and (isinstance(variable.type, ArrayType) or variable.type == UNKNOWN):
        return _element(ctx, ctx.declared(variable.type), node.area, node.indices, node.loc)
    if node.area.upper().lstrip("%") not in _AREAS:  # TIA's %MB(#i):P (``build.area_paren``)
        _indices(ctx, node.indices)
        return ctx.report("SCL924", node.loc, area=node.area[1:])
    good = _indices(ctx, node.indices) is not None
    value, count = indexed_type(node.area)
    if len(node.indices) != count:
        return ctx.report(
            "SCL216", node.loc, name=node.area, expected=count, actual=len(node.indices)
        )
    return value if good else ERROR

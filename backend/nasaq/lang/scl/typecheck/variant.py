"""Checks of VARIANT and ``ARRAY[*]`` parameters (S7-1200/1500; ``nasaq.lang.scl.descriptor``).

- an actual for a VARIANT formal is a variable of any type (elementary, STRING, STRUCT, UDT,
  ARRAY) or another VARIANT/``ARRAY[*]`` parameter (passed on), never a constant or an
  expression (``SCL554``); for an ``ARRAY[*] OF T`` formal an array of T with as many
  dimensions, or such a parameter (``SCL553``);
- ``#arr[i, j]`` of an ``ARRAY[*]`` parameter is its element type (the bounds are the actual's,
  known at run time);
- the instructions, as TIA Portal declares them: ``LOWER_BOUND``/``UPPER_BOUND(ARR, DIM)``
  (DINT; DIM a constant within the dimensions, ``SCL556``), ``CountOfElements(v)`` (UDINT),
  ``IS_ARRAY(v)`` (BOOL), ``TypeOf(v)``/``TypeOfElements(v)`` only in ``=``/``<>`` with a
  data type name (``SCL557``);
- a descriptor used as a value anywhere else is the usual type error, naming it VARIANT or
  ``ARRAY[*] OF T`` (``types.type_text``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang import dtl
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.descriptor import DB_ANY, DbAnyType, OpenArray, VariantParam, describe
from nasaq.lang.scl.descriptor import VARIANT as VARIANT_FORMAL
from nasaq.lang.scl.typecheck.types import (
    ANYTHING,
    ERROR,
    BitsConst,
    DbRef,
    IntConst,
    Type,
    is_silent,
    scalar,
)
from nasaq.lang.types import ArrayType, BlockType, DataType, Elementary, elementary, type_text

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

BOUNDS = frozenset(["LOWER_BOUND", "UPPER_BOUND"])
TYPE_TESTS = frozenset(["TYPEOF", "TYPEOFELEMENTS"])
# The copying instructions: (source, target, parameters in TIA's order).
COPIES = {
    "SERIALIZE": ("SRC_VARIABLE", "DEST_ARRAY", ("SRC_VARIABLE", "DEST_ARRAY", "POS")),
    "DESERIALIZE": ("SRC_ARRAY", "DEST_VARIABLE", ("SRC_ARRAY", "DEST_VARIABLE", "POS")),
    "VARIANTGET": ("SRC", "DST", ("SRC", "DST")),
    "VARIANTPUT": ("SRC", "DST", ("SRC", "DST")),
    "MOVE_BLK_VARIANT": ("SRC", "DEST", ("SRC", "COUNT", "SRC_INDEX", "DEST_INDEX", "DEST")),
}
_INTEGERS = frozenset(["POS", "COUNT", "SRC_INDEX", "DEST_INDEX"])
_INTEGER_TYPES = frozenset(["SINT", "INT", "DINT", "USINT", "UINT", "UDINT"])
# Every name (the editor's word list reads this literal: tests/frontend/editorLanguages.test.ts).
NAMES = frozenset(
    [
        "LOWER_BOUND",
        "UPPER_BOUND",
        "TYPEOF",
        "TYPEOFELEMENTS",
        "COUNTOFELEMENTS",
        "IS_ARRAY",
        "SERIALIZE",
        "DESERIALIZE",
        "VARIANTGET",
        "VARIANTPUT",
        "MOVE_BLK_VARIANT",
        "DB_ANY_TO_UINT",
        "UINT_TO_DB_ANY",
        "PEEK",
        "PEEK_BOOL",
        "PEEK_WORD",
        "PEEK_DWORD",
        "POKE",
        "POKE_BOOL",
    ]
)
# PEEK/POKE (TIA, S7-1200/1500): their value's type, and their parameters in TIA's order.
PEEKS = {"PEEK": "BYTE", "PEEK_BOOL": "BOOL", "PEEK_WORD": "WORD", "PEEK_DWORD": "DWORD"}
POKES = frozenset(["POKE", "POKE_BOOL"])
MEMORY_PARAMS = {
    "PEEK": ("AREA", "DBNUMBER", "BYTEOFFSET"),
    "PEEK_BOOL": ("AREA", "DBNUMBER", "BYTEOFFSET", "BITOFFSET"),
    "POKE": ("AREA", "DBNUMBER", "BYTEOFFSET", "VALUE"),
    "POKE_BOOL": ("AREA", "DBNUMBER", "BYTEOFFSET", "BITOFFSET", "VALUE"),
}
MEMORY_PARAMS["PEEK_WORD"] = MEMORY_PARAMS["PEEK_DWORD"] = MEMORY_PARAMS["PEEK"]
# The areas PEEK/POKE reach: 16#81 inputs, 16#82 outputs, 16#83 memory, 16#84 a DB.
AREAS = {0x81: "I", 0x82: "Q", 0x83: "M", 0x84: "DB"}
assert BOUNDS | TYPE_TESTS | COPIES.keys() | PEEKS.keys() | POKES <= NAMES
BOOL, DINT, UDINT = Elementary("BOOL"), Elementary("DINT"), Elementary("UDINT")
_POSITION = ("first", "second")


def name_of(node: ast.Call) -> str | None:
    callee = node.callee
    if isinstance(callee, ast.Name) and callee.name.upper() in NAMES:
        return callee.name.upper()
    return None


def accepts(formal: DataType, value: Type) -> bool:
    """Whether a descriptor formal takes a variable of type ``value``."""
    if is_silent(value):
        return True
    if isinstance(formal, VariantParam):
        if isinstance(value, Elementary):
            return value.name not in ("UNKNOWN", "VOID")
        return isinstance(value, DataType)
    if isinstance(formal, OpenArray):
        if isinstance(value, OpenArray):
            return value.dims == formal.dims and value.element == formal.element
        return (
            isinstance(value, ArrayType)
            and len(value.dims) == formal.dims
            and value.element == formal.element
        )
    return False


def check_db_any(ctx: Context, name: str, actual: ast.Expr, value: Type) -> None:
    """A DB_ANY formal takes a DB (``"Data"``, ``DB5``) or a DB_ANY (``SCL558``)."""
    if is_silent(value) or _db_number(value, (DbAnyType,)):
        return
    ctx.report("SCL558", actual.loc, actual=ctx.text(actual), name=name)


def check_actual(ctx: Context, formal: DataType, actual: ast.Expr, value: Type) -> None:
    """Reports an actual a descriptor formal does not take."""
    if is_silent(value) or (accepts(formal, value) and _is_variable(actual)):
        return
    if isinstance(formal, VariantParam) or not _is_variable(actual):
        ctx.report("SCL554", actual.loc, actual=ctx.text(actual))
        return
    assert isinstance(formal, OpenArray)
    ctx.report(
        "SCL553",
        actual.loc,
        actual=ctx.text(actual),
        what=describe(formal),
        dims=formal.dims,
        element=type_text(formal.element),
    )


def _is_variable(node: ast.Expr) -> bool:
    while isinstance(node, ast.Paren):
        node = node.inner
    return isinstance(node, ast.Name | ast.Local | ast.Symbol | ast.Member | ast.Index)


def element(
    ctx: Context, base: OpenArray, name: str, indices: list[ast.Expr], where: ast.Loc
) -> Type:
    """``#arr[i]`` of an ``ARRAY[*]`` parameter: all dimensions are indexed (no rows)."""
    for index in indices:
        ctx.type_of(index)
    if len(indices) != base.dims:
        return ctx.report("SCL216", where, name=name, expected=base.dims, actual=len(indices))
    return ctx.declared(base.element)


def call(ctx: Context, name: str, node: ast.Call) -> Type:
    """The value of a VARIANT/array instruction; its arguments checked."""
    args = [arg for arg in node.args if (arg.name or "").upper() not in ("EN", "ENO")]
    values = [ctx.type_of(arg.value) for arg in args]
    if not is_s7_1500(ctx.index.profile):
        what = name_spelling(name)
        return ctx.report("SCL500", node.loc, what=what, profile=ctx.index.profile)
    if name in TYPE_TESTS:
        return (
            ctx.report("SCL557", node.loc, name=ctx.text(node), function=name_spelling(name))
            if not values
            else _descriptor_arg(ctx, name, args, values, (OpenArray, VariantParam))
        )
    if name in BOUNDS:
        return _bound(ctx, name, node, args, values)
    if name in COPIES:
        return _copy(ctx, name, node, args, values)
    if name in MEMORY_PARAMS:
        return _memory(ctx, name, node, args, values)
    if name == "DB_ANY_TO_UINT" or name == "UINT_TO_DB_ANY":
        wanted: tuple[type, ...] = (DbAnyType,) if name == "DB_ANY_TO_UINT" else (Elementary,)
        if len(args) != 1 or not (is_silent(values[0]) or _db_number(values[0], wanted)):
            return ctx.report(
                "SCL555",
                args[0].value.loc if args else node.loc,
                function=name,
                expected="DB_ANY" if name == "DB_ANY_TO_UINT" else "UINT",
                param="IN",
                actual=ctx.text(args[0].value) if args else "()",
            )
        return Elementary("UINT") if name == "DB_ANY_TO_UINT" else DB_ANY
    found = _descriptor_arg(ctx, name, args, values, (OpenArray, VariantParam))
    if found is ERROR:
        return ERROR
    return BOOL if name == "IS_ARRAY" else UDINT


def _given(
    ctx: Context,
    spelling: str,
    node: ast.Call,
    args: list[ast.Arg],
    values: list[Type],
    order: tuple[str, ...],
) -> dict[str, tuple[ast.Expr, Type]] | Type:
    """The actuals by parameter name (named, or in TIA's ``order``), every one given once;
    else the reported error (SCL555 an unknown or repeated one, SCL227 one missing)."""
    given: dict[str, tuple[ast.Expr, Type]] = {}
    for position, (arg, value) in enumerate(zip(args, values, strict=True)):
        key = (arg.name or (order[position] if position < len(order) else "")).upper()
        if key not in order or key in given:
            return ctx.report(
                "SCL555",
                arg.value.loc,
                function=spelling,
                expected=", ".join(order),
                param=arg.name or _ordinal(position),
                actual=ctx.text(arg.value),
            )
        given[key] = (arg.value, value)
    missing = [key for key in order if key not in given]
    if missing:
        return ctx.report("SCL227", node.loc, block=spelling, names=", ".join(missing))
    return given


def _copy(ctx: Context, name: str, node: ast.Call, args: list[ast.Arg], values: list[Type]) -> Type:
    """Serialize, Deserialize, VariantGet, VariantPut, MOVE_BLK_VARIANT: every parameter given
    (by name, or in TIA's order), places that are variables, the numbers integers."""
    _source, _target, order = COPIES[name]
    given = _given(ctx, name_spelling(name), node, args, values, order)
    if not isinstance(given, dict):
        return given
    for key in order:
        expr, value = given[key]
        if is_silent(value):
            continue
        good = (
            type(value) is IntConst or scalar(value) in _INTEGER_TYPES
            if key in _INTEGERS
            else accepts(VARIANT_FORMAL, value)
        )
        if key in ("POS",) or key not in _INTEGERS:
            good = good and _is_variable(expr)
        if not good:
            return ctx.report(
                "SCL555",
                expr.loc,
                function=name_spelling(name),
                expected="DINT" if key in _INTEGERS else "VARIANT",
                param=key,
                actual=ctx.text(expr),
            )
        if key not in _INTEGERS or key == "POS":
            ctx.written_actuals.add(id(expr))
    if name in ("VARIANTGET", "VARIANTPUT"):
        return ANYTHING
    return Elementary("INT")


def _db_number(value: Type, kinds: tuple[type, ...]) -> bool:
    if isinstance(value, DbAnyType) or (isinstance(value, DbRef) and value.number is not None):
        return True
    return DbAnyType not in kinds and (
        type(value) is IntConst or scalar(value) in ("UINT", "INT", "WORD")
    )


def _memory(
    ctx: Context, name: str, node: ast.Call, args: list[ast.Arg], values: list[Type]
) -> Type:
    """PEEK/POKE: every parameter (by name or in order), the area a constant TIA knows, the
    DB a DB_ANY, a DB or a number."""
    given = _given(ctx, name, node, args, values, MEMORY_PARAMS[name])
    if not isinstance(given, dict):
        return given
    area_node, _area = given["AREA"]
    area = memory_area(ctx, area_node)
    if area is None:
        return ctx.report(
            "SCL555",
            area_node.loc,
            function=name,
            expected="16#81, 16#82, 16#83, 16#84",
            param="area",
            actual=ctx.text(area_node),
        )
    db_node, db_value = given["DBNUMBER"]
    if not (is_silent(db_value) or _db_number(db_value, (Elementary,))):
        return ctx.report(
            "SCL555",
            db_node.loc,
            function=name,
            expected="DB_ANY",
            param="dbNumber",
            actual=ctx.text(db_node),
        )
    for key in ("BYTEOFFSET", "BITOFFSET"):
        if key in given:
            offset_node, offset = given[key]
            if not (
                is_silent(offset) or type(offset) is IntConst or scalar(offset) in _INTEGER_TYPES
            ):
                return ctx.report(
                    "SCL555",
                    offset_node.loc,
                    function=name,
                    expected="DINT",
                    param=key,
                    actual=ctx.text(offset_node),
                )
    if name in POKES:
        value_node, value = given["VALUE"]
        kind = scalar(value)
        wanted = ("BOOL",) if name == "POKE_BOOL" else ("BYTE", "WORD", "DWORD")
        if not is_silent(value) and kind not in wanted and type(value) is not IntConst:
            return ctx.report(
                "SCL555",
                value_node.loc,
                function=name,
                expected=" / ".join(wanted),
                param="value",
                actual=ctx.text(value_node),
            )
        return ANYTHING
    return Elementary(PEEKS[name])


def memory_area(ctx: Context, node: ast.Expr) -> str | None:
    """The area letter(s) of a PEEK/POKE area constant (``16#84``: DB), None for others."""
    value = ctx.type_of(node)
    number = value.value if type(value) is IntConst or type(value) is BitsConst else None
    if number is None:
        found = ctx.index.const_value(ctx.block, node)
        number = found if isinstance(found, int) else None
    if number is None and isinstance(node, ast.Literal):
        body = node.text.replace("_", "").rpartition("#")
        if body[0].upper().endswith("16") and body[2]:
            number = int(body[2], 16)
    return AREAS.get(number) if number is not None else None


def _ordinal(position: int) -> str:
    return str(position + 1)  # a parameter without a name: its place


def _descriptor_arg(
    ctx: Context,
    name: str,
    args: list[ast.Arg],
    values: list[Type],
    kinds: tuple[type, ...],
) -> Type:
    if len(args) != 1 or not (is_silent(values[0]) or isinstance(values[0], kinds)):
        where = args[0].value.loc if args else ctx.block.node.loc
        shown = ctx.text(args[0].value) if args else "nothing"
        return ctx.report(
            "SCL555",
            where,
            function=name_spelling(name),
            expected="VARIANT",
            param="1",
            actual=shown,
        )
    return ANYTHING


def _bound(
    ctx: Context, name: str, node: ast.Call, args: list[ast.Arg], values: list[Type]
) -> Type:
    """``LOWER_BOUND(ARR := #a, DIM := 1)``, also without names, in that order."""
    by_name = {(arg.name or "").upper(): i for i, arg in enumerate(args)}
    arr = by_name.get("ARR", 0 if args and args[0].name is None else None)
    dim = by_name.get("DIM", 1 if len(args) > 1 and args[1].name is None else None)
    if arr is None or dim is None or len(args) != 2:
        return ctx.report(
            "SCL555",
            node.loc,
            function=name,
            expected="ARR := ARRAY[*], DIM := n",
            param="ARR, DIM",
            actual=ctx.text(node),
        )
    base = values[arr]
    if is_silent(base):
        return DINT
    if not isinstance(base, OpenArray):
        return ctx.report(
            "SCL555",
            args[arr].value.loc,
            function=name,
            expected="ARRAY[*]",
            param="ARR",
            actual=ctx.text(args[arr].value),
        )
    number = constant_dimension(ctx, args[dim].value)
    if number is None or not 1 <= number <= base.dims:
        return ctx.report(
            "SCL556",
            args[dim].value.loc,
            function=name,
            dim=ctx.text(args[dim].value),
            name=ctx.text(args[arr].value),
            dims=base.dims,
        )
    return DINT


def constant_dimension(ctx: Context, node: ast.Expr) -> int | None:
    """A DIM argument's number: a constant, also typed (TIA writes ``UDINT#1``)."""
    value = ctx.type_of(node)
    if type(value) is IntConst:
        return value.value
    found = ctx.index.const_value(ctx.block, node)
    if isinstance(found, int):
        return found
    if isinstance(node, ast.Literal):  # UDINT#1, USINT#2: TIA's typed dimension numbers
        _prefix, _, body = node.text.replace("_", "").rpartition("#")
        if body.isdigit():
            return int(body)
    return None


_SPELLING = {
    "TYPEOF": "TypeOf",
    "TYPEOFELEMENTS": "TypeOfElements",
    "COUNTOFELEMENTS": "CountOfElements",
    "SERIALIZE": "Serialize",
    "DESERIALIZE": "Deserialize",
    "VARIANTGET": "VariantGet",
    "VARIANTPUT": "VariantPut",
}


def name_spelling(upper: str) -> str:
    """How TIA Portal writes an instruction's name."""
    return _SPELLING.get(upper, upper)


# ---- TypeOf(v) = INT ------------------------------------------------------------------------


def type_test(node: ast.Binary) -> tuple[ast.Call, ast.Expr] | None:
    """``TypeOf(#v) = INT`` (either side): the call and the type name, else None."""
    if node.op not in ("=", "<>"):
        return None
    for call_side, other in ((node.left, node.right), (node.right, node.left)):
        while isinstance(call_side, ast.Paren):
            call_side = call_side.inner
        if isinstance(call_side, ast.Call) and name_of(call_side) in TYPE_TESTS:
            return call_side, other
    return None


def named_type(ctx: Context, node: ast.Expr) -> DataType | None:
    """The data type a comparison names: an elementary type, STRING/WSTRING, DTL, a UDT."""
    if isinstance(node, ast.Name | ast.Symbol):
        if isinstance(node, ast.Name):
            found = elementary(node.name)
            if found is not None:
                return found
            if node.name.upper() == dtl.NAME:
                return dtl.DTL
        block = ctx.index.named(node.name)
        if block is not None and block.kind.value == "UDT":
            return BlockType("UDT", block.number)
    return None


def check_type_test(ctx: Context, node: ast.Binary) -> Type:
    found = type_test(node)
    assert found is not None
    call_node, other = found
    upper = name_of(call_node) or ""
    args = [arg for arg in call_node.args if (arg.name or "").upper() not in ("EN", "ENO")]
    values = [ctx.type_of(arg.value) for arg in args]
    kinds: tuple[type, ...] = (OpenArray, VariantParam)
    if not is_s7_1500(ctx.index.profile):
        what = name_spelling(upper)
        return ctx.report("SCL500", node.loc, what=what, profile=ctx.index.profile)
    if _descriptor_arg(ctx, upper, args, values, kinds) is ERROR:
        return ERROR
    if named_type(ctx, other) is None:
        return ctx.report("SCL557", other.loc, name=ctx.text(other), function=name_spelling(upper))
    return BOOL

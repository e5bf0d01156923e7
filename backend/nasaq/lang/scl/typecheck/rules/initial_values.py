"""Rule: initial values in declarations (seeds-003b §2.5), in FBs, FCs, OBs, DBs and UDTs.

- Only FB parameters and static variables, DB and UDT members take one: a VAR_TEMP (and the
  VAR of an FC or OB) or a structured in/out has no memory to hold it (``SCL245``). An FB's
  elementary in/out is kept in its instance, so TIA exports give it a start value (accepted).
  STEP 7 accepts one on an FC input or output too, where it does nothing (every call supplies
  the parameter): a warning (``SCL921``); an FC in/out stays ``SCL245``.
- The value must be a constant: literals and CONST names, with operators (``SCL243``).
- It must be assignable to the declared type, as an assignment (``SCL213``, ``SCL214``,
  ``SCL218``); a text must fit the STRING's length (``SCL218``).
- An ARRAY takes a list with repetitions, ``0.0, 10(100.0), 1.0``, of at most as many values as
  it has elements (``SCL244``); fewer leave the rest at 0. Anything else takes one value.
Members of a STRUCT are checked where the STRUCT is declared (a UDT in its TYPE)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import CharsConst, assignable, is_silent
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
    type_text,
)

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

NO_INITIAL = ("TEMP", "IN_OUT")


def check(ctx: Context) -> None:
    block = ctx.block
    seen: set[int] = set()  # `a, b : INT := 1;` shares one initialiser: checked once
    for section, fields in block.sections:
        for declared in fields:
            items = _items(declared)
            if items and block.kind is BlockKind.FC and section in ("IN", "OUT"):
                # STEP 7 accepts it, but every call supplies an FC's parameters.
                if id(declared.initial) not in seen:
                    ctx.report("SCL921", items[0].loc, name=declared.name, section=section)
                _field(ctx, declared, seen)
            elif items and (section in NO_INITIAL or block.kind is BlockKind.FC):
                if section == "IN_OUT" and block.kind is BlockKind.FB and _by_value(declared):
                    _field(ctx, declared, seen)  # kept in the instance, as TIA's start value
                    continue
                if id(declared.initial) not in seen:
                    seen.add(id(declared.initial))
                    where = items[0].loc
                    ctx.report("SCL245", where, name=declared.name, section=section)
            else:
                _field(ctx, declared, seen)
    struct = block.db_type if block.kind in (BlockKind.DB, BlockKind.UDT) else None
    if isinstance(struct, StructType) and not block.sections:  # a STRUCT, not TIA's VARs
        for declared in struct.fields:
            _field(ctx, declared, seen)


def _by_value(declared: Field) -> bool:
    """An FB in/out its instance holds by value (an elementary type; not a STRING, a
    DATE_AND_TIME or a structure, which are passed as a pointer)."""
    data_type = declared.type
    return type(data_type) is Elementary and data_type.name != "DATE_AND_TIME"


def is_constant(ctx: Context, node: ast.Expr) -> bool:
    """Literals and CONST names, combined with operators."""
    if isinstance(node, ast.Literal):
        return True
    if isinstance(node, ast.Name | ast.Local):
        return ctx.variable(node.name) is None and ctx.constant(node.name) is not None
    if isinstance(node, ast.Unary):
        return is_constant(ctx, node.operand)
    if isinstance(node, ast.Binary):
        return is_constant(ctx, node.left) and is_constant(ctx, node.right)
    if isinstance(node, ast.Paren):
        return is_constant(ctx, node.inner)
    return False


def store_constant(ctx: Context, name: str, value: ast.Expr, target: DataType) -> None:
    """Reports a value that is no constant or cannot be stored in a ``target``."""
    if not is_constant(ctx, value):
        ctx.report("SCL243", value.loc, name=name)
        return
    found = ctx.type_of(value)
    if is_silent(found):
        return
    verdict = assignable(found, target)
    if verdict.code is not None:
        ctx.report(verdict.code, value.loc, **verdict.params)
    elif _too_long(found, target):
        text = ctx.text(value)
        ctx.report("SCL218", value.loc, text=text, type=type_text(target), hint="")


def _too_long(found: object, target: DataType) -> bool:
    """A text constant longer than the STRING[n] it is stored in."""
    return (
        isinstance(found, CharsConst)
        and isinstance(target, StringType)
        and found.length > target.length
    )


def _items(declared: Field) -> list[ast.InitItem]:
    initial = declared.initial
    return list(initial) if isinstance(initial, list) else []


def _field(ctx: Context, declared: Field, seen: set[int]) -> None:
    items = _items(declared)
    target = declared.type
    if items and id(declared.initial) not in seen:
        seen.add(id(declared.initial))
        values = _flatten(items)
        count = sum(times for _value, times in values)
        capacity = target.count if isinstance(target, ArrayType) else 1
        if count > capacity:
            ctx.report("SCL244", items[0].loc, name=declared.name, count=capacity, given=count)
        else:
            element = target.element if isinstance(target, ArrayType) else target
            for value, _times in values:
                if isinstance(value, ast.InitStruct):
                    _members(ctx, declared.name, value, element)
                else:
                    store_constant(ctx, declared.name, value, element)
    inner = target.element if isinstance(target, ArrayType) else target
    if isinstance(inner, StructType):
        for member in inner.fields:
            _field(ctx, member, seen)


def _members(ctx: Context, name: str, value: ast.InitStruct, target: DataType) -> None:
    """TIA's ``(v1, (), v3)`` for a STRUCT or UDT: at most one item per member, each checked
    as that member's initial value (``()`` keeps the member's own)."""
    if is_silent(target):
        return  # an unknown type: reported where it is named
    fields = _struct_fields(ctx, target)
    if fields is None:
        ctx.report("SCL922", value.loc, name=name, type=type_text(target))
        return
    if len(value.values) > len(fields):
        ctx.report("SCL244", value.loc, name=name, count=len(fields), given=len(value.values))
        return
    for member, item in zip(fields, value.values, strict=False):
        if isinstance(item, ast.InitStruct) and not item.values:
            continue
        _field(ctx, Field(f"{name}.{member.name}", member.type, [item]), set())


def _struct_fields(ctx: Context, target: DataType) -> tuple[Field, ...] | None:
    if isinstance(target, StructType):
        return target.fields
    if isinstance(target, BlockType) and target.kind == "UDT":
        udt = ctx.index.get(BlockKind.UDT, target.number)
        if udt is not None and isinstance(udt.db_type, StructType):
            return udt.db_type.fields
    return None


def _flatten(
    items: list[ast.InitItem], times: int = 1
) -> list[tuple[ast.Expr | ast.InitStruct, int]]:
    """The values of an initialiser with how often each stands (``3(1, 2)``: 1 and 2, 3 times);
    a structure's ``(...)`` is one value."""
    found: list[tuple[ast.Expr | ast.InitStruct, int]] = []
    for item in items:
        if isinstance(item, ast.InitRepeat):
            found += _flatten(item.values, times * int(item.count.replace("_", "")))
        elif isinstance(item, ast.InitList):
            found += _flatten(item.values, times)
        else:
            found.append((item, times))
    return found

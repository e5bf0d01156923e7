"""Types of absolute operands (not a rule: the parser has checked their shape already):
``M0.0`` BOOL, ``MB1`` BYTE, ``MW2`` WORD, ``MD4`` DWORD, ``T1`` TIMER, ``C1`` COUNTER,
``DB10`` the data block, ``FC1`` the function (inside FC1: its return value); after a DB,
``DW2``/``DBW2`` WORD, ``DX1.0``/``D1.1``/``DBX1.0`` BOOL, ``DB1``/``DBB1`` BYTE, ``DD4`` DWORD."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock
from nasaq.lang.scl.typecheck.types import ANYTHING, BlockRef, DbRef, Type
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.symbols import Symbol
from nasaq.lang.types import Elementary, elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

WIDTH_TYPES = {1: "BOOL", 8: "BYTE", 16: "WORD", 32: "DWORD"}
_WIDTH_ELEMENTARY = {bits: Elementary(name) for bits, name in WIDTH_TYPES.items()}
_DB_PART = re.compile(r"^DB?(?P<size>[XBWD])?(?P<byte>\d+)(?:\.(?P<bit>\d+))?$")


def address(ctx: Context, node: ast.Address) -> Type:
    text = node.text.lstrip("%")
    try:
        parsed = parse_address(text)
    except AddressError:
        return ANYTHING
    if parsed.kind == "timer":
        return Elementary("TIMER")
    if parsed.kind == "counter":
        return Elementary("COUNTER")
    if parsed.kind == "block" and parsed.block is not None:
        block = ctx.index.get(parsed.block, parsed.number)
        if block is not None:
            return block_value(ctx, block)
        if parsed.block is BlockKind.DB:
            return DbRef(parsed.number)
        return BlockRef(parsed.block, parsed.number)
    if parsed.width is not None:
        return _WIDTH_ELEMENTARY[int(parsed.width)]
    return ANYTHING


def db_part(text: str) -> Type | None:
    """The type of a DB-relative address after a ``.``; None if it is not one."""
    match = _DB_PART.match(text.upper().replace(" ", ""))
    if match is None:
        return None
    size = match["size"]
    if size == "X" or match["bit"] is not None:
        return Elementary("BOOL")
    return Elementary({"B": "BYTE", "W": "WORD", "D": "DWORD"}.get(size or "B", "BYTE"))


def indexed_type(area: str) -> tuple[Type, int]:
    """``MW`` → (WORD, 1 index), ``I``/``DX`` → (BOOL, 2 indices: byte and bit)."""
    upper = area.upper().lstrip("%")
    last = upper[-1]
    if (last in "WD" and len(upper) > 1) or upper in ("DW", "DD"):
        return Elementary("WORD" if last == "W" else "DWORD"), 1
    if last == "B" and len(upper) > 1:  # MB[i], DB10.DBB[i], DB10.DB[i] (a byte)
        return Elementary("BYTE"), 1
    return Elementary("BOOL"), 2


def function_value(block: SclBlock) -> Type:
    """The type of an FC's own name: its return value."""
    if block.return_type is None or block.return_type == Elementary("VOID"):
        return ANYTHING
    return block.return_type


def block_value(ctx: Context, block: SclBlock) -> Type:
    if block.kind is BlockKind.DB:
        return DbRef(block.number)
    if block is ctx.block and block.kind is BlockKind.FC:
        return function_value(block)
    return BlockRef(block.kind, block.number)


def symbol_type(found: Symbol) -> Type:
    """A symbol's declared type, or the one its address implies (``MW 10`` → WORD)."""
    parsed = found.parsed
    if parsed.kind == "block" and parsed.block is not None:
        if parsed.block is BlockKind.DB:
            return DbRef(parsed.number)
        return BlockRef(parsed.block, parsed.number)
    declared = elementary(found.type) if found.type else None
    if declared is not None:
        return declared
    if parsed.kind == "timer":
        return Elementary("TIMER")
    if parsed.kind == "counter":
        return Elementary("COUNTER")
    if parsed.width is not None:
        return Elementary(WIDTH_TYPES.get(int(parsed.width), "DWORD"))
    return ANYTHING

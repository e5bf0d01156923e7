"""Instance data blocks that no ``DATA_BLOCK`` declares.

S7-SCL creates the instance DB of ``FB1.DB5(...)`` when it compiles the call (seeds-003b §2.11),
and a symbol table may give a DB the type of an FB (``ACQUIRE_DATA,DB 10,FB 10``). Before the
code is checked, these DBs are entered in ``SclIndex.implicit_dbs`` with their FB, so that
``DB5.out`` has the FB's interface types; so is TIA's ``DB99.TON(...)`` of a DB no source
declares (an instance of the SFB named after the dot). The first call names the FB of a DB; a
later call with another FB is the call rule's error (``SCL233``)."""

from __future__ import annotations

import re

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import IEC_INSTANCES, SclBlock, SclIndex
from nasaq.lang.scl.typecheck.walk import Outline
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.system_blocks import SFB_INTERFACES
from nasaq.lang.types import BlockType

INSTANCE_KINDS = (BlockKind.FB, BlockKind.SFB)
_FB_TYPE = re.compile(r"^\s*(S?FB)\s*(\d+)\s*$", re.IGNORECASE)


def block_id(index: SclIndex, block: SclBlock, node: ast.Expr) -> tuple[BlockKind, int] | None:
    """The block an expression names (``FB10``, ``Motor``, ``"Motor"``), None if it names
    none; a variable of ``block`` hides a block of the same name."""
    if isinstance(node, ast.Address):
        try:
            parsed = parse_address(node.text.lstrip("%"))
        except AddressError:
            return None
        return (parsed.block, parsed.number) if parsed.block is not None else None
    if not isinstance(node, ast.Name | ast.Symbol):
        return None
    if isinstance(node, ast.Name) and node.name.casefold() in block.variables:
        return None
    found = index.named(node.name)
    if found is not None:
        return found.kind, found.number
    symbol = index.symbol(node.name)
    if symbol is not None and symbol.parsed.kind == "block" and symbol.parsed.block is not None:
        return symbol.parsed.block, symbol.parsed.number
    return None


def exists(index: SclIndex, kind: BlockKind, number: int) -> bool:
    """Whether an FB/SFB can be instantiated: declared in the sources, or a known SFB."""
    if kind is BlockKind.SFB:
        return number in SFB_INTERFACES
    return index.get(kind, number) is not None


def note_implicit_instances(index: SclIndex, outlines: list[tuple[SclBlock, Outline]]) -> None:
    """Fills ``index.implicit_dbs`` from the symbol table and from every ``FB.DB(...)`` call
    (``outlines``: every block of the index with the outline of its code)."""
    for symbol in index.symbols.symbols.values():
        parsed = symbol.parsed
        typed = _FB_TYPE.match(symbol.type)
        if parsed.block is not BlockKind.DB or typed is None:
            continue
        kind, number = BlockKind(typed[1].upper()), int(typed[2])
        if index.get(BlockKind.DB, parsed.number) is None and exists(index, kind, number):
            index.implicit_dbs.setdefault(parsed.number, BlockType(kind.value, number))
    for block, found in outlines:
        for call in found.calls:
            callee = call.callee
            if not isinstance(callee, ast.Member):
                continue
            fb = block_id(index, block, callee.base)
            db = block_id(index, block, callee.name)
            part = callee.name
            run = IEC_INSTANCES.get(part.name.upper()) if isinstance(part, ast.Name) else None
            if run is not None and fb is not None and fb[0] is BlockKind.DB:
                fb, db = (BlockKind.SFB, run), fb  # TIA's DB99.TON(...): an instance of TON
            if fb is None or db is None or fb[0] not in INSTANCE_KINDS or db[0] != BlockKind.DB:
                continue
            if index.get(BlockKind.DB, db[1]) is None and exists(index, *fb):
                index.implicit_dbs.setdefault(db[1], BlockType(fb[0].value, fb[1]))

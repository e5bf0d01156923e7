"""Numbers for blocks a source names only by symbol, as TIA Portal numbers them.

TIA Portal's STL export writes ``FUNCTION_BLOCK "Motor"``, ``DATA_BLOCK "Data"``,
``ORGANIZATION_BLOCK "Main"``: the numbers stay in the project. A quoted name the symbol table
gives a number keeps it (STEP 7 Classic's way); every other one is numbered here, before the
blocks are registered, and becomes a symbol of the program (``"Motor"`` = ``FB 1``) so that a
CALL, a type, an instance DB or a ``"Data".member`` operand finds it like any symbol:

- numbers already used are collected first: absolute ids (``FB 10``) of the STL and SCL sources
  and every block number the symbol table gives (a block of another source may own it);
- then, in source order, an FB, FC, DB or UDT takes the lowest free number of its kind from 1
  (TIA's automatic numbering, the same rule as ``nasaq.lang.scl.bind``);
- an instance DB that a ``CALL "Fb", "Fb_DB"`` names and no source or table defines is
  numbered last (lowest free DB number); the call then creates it (``STL229``), as STEP 7 does
  for ``CALL FB 1, DB 5`` and TIA Portal when it adds a call with its instance DB;
- an OB takes the number its event name gives (``nasaq.lang.tia_names``: "Main" is OB 1,
  "Startup" OB 100, "Cyclic interrupt" OB 35 on S7-300/400); an OB whose name is no event has
  no number on S7-300/400 (``STL600``) and takes the first free from 123 on S7-1200/1500; an
  event of the S7-1200/1500 family only ("MC-Servo") is ``STL500`` on S7-300/400; an event
  whose numbers are all used takes its first one, so that the duplicate is reported.
"""

from __future__ import annotations

from collections.abc import Iterable

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.stl import ast
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.library import CALL_SPELLINGS
from nasaq.lang.stl.symbols import Symbol, SymbolTable
from nasaq.lang.tia_names import ob_event, ob_number

_KIND_OF_KEYWORD = {
    "ORGANIZATION_BLOCK": BlockKind.OB,
    "FUNCTION_BLOCK": BlockKind.FB,
    "FUNCTION": BlockKind.FC,
    "DATA_BLOCK": BlockKind.DB,
    "TYPE": BlockKind.UDT,
}


def number_blocks(
    blocks: Iterable[tuple[str, ast.BlockNode]],
    symbols: SymbolTable,
    used: Iterable[tuple[BlockKind, int]],
    profile: str,
    unnumbered: set[int],
) -> list[Diagnostic]:
    """Gives every ``(file, block)`` named by an unknown quoted symbol its TIA number, as a new
    symbol in ``symbols``; ``used`` are numbers taken elsewhere (SCL sources). The ``id`` of
    each block that gets no number (reported) goes to ``unnumbered``."""
    taken: dict[BlockKind, set[int]] = {kind: set() for kind in _KIND_OF_KEYWORD.values()}
    for kind, number in used:
        taken.setdefault(kind, set()).add(number)
    for symbol in symbols.symbols.values():
        if symbol.parsed.kind == "block" and symbol.parsed.block is not None:
            taken.setdefault(symbol.parsed.block, set()).add(symbol.parsed.number)
    pending: list[tuple[str, ast.BlockNode, BlockKind]] = []
    blocks = list(blocks)
    calls = instance_calls(blocks)
    for file, node in blocks:
        kind = _KIND_OF_KEYWORD[node.keyword]
        if node.ident_quoted:
            if symbols.get(node.ident) is None:
                pending.append((file, node, kind))
            continue
        try:
            parsed = parse_address(node.ident)
        except AddressError:
            continue  # reported when the block is registered
        if parsed.block is not None:
            taken.setdefault(parsed.block, set()).add(parsed.number)
    diagnostics: list[Diagnostic] = []
    for file, node, kind in pending:
        if symbols.get(node.ident) is not None:
            continue  # the same name twice: registering reports the duplicate
        numbers = taken[kind]
        if kind is BlockKind.OB:
            found = _ob_number(file, node, numbers, profile, diagnostics)
            if found is None:
                unnumbered.add(id(node))
                continue
        else:
            found = _lowest_free(numbers)
        numbers.add(found)
        _define(symbols, node.ident, kind, found, file, node.loc)
    for file, call in calls:
        name = call.operands[1]
        if not isinstance(name, ast.SymbolNode) or name.local or name.path:
            continue
        if symbols.lookup(name.name) is None:
            number = _lowest_free(taken[BlockKind.DB])
            taken[BlockKind.DB].add(number)
            _define(symbols, name.name, BlockKind.DB, number, file, name.loc)
    return diagnostics


def _lowest_free(numbers: set[int]) -> int:
    number = 1
    while number in numbers:
        number += 1
    return number


def _ob_number(
    file: str, node: ast.BlockNode, taken: set[int], profile: str, found: list[Diagnostic]
) -> int | None:
    """The OB's number by its name, or None (reported in ``found``)."""
    number = ob_number(node.ident, taken, profile)
    if number is not None:
        return number
    event = ob_event(node.ident)
    modern = is_s7_1500(profile)
    if event is not None and not event.classic and not modern:
        what = f'the OB "{node.ident}"'  # an event of the S7-1200/1500 family only
        found.append(problem("STL500", file, node.loc, what=what, profile=profile))
        return None
    if event is not None:  # every OB of its event is there: registering reports the duplicate
        return (event.s7_1500 if modern else event.classic)[0]
    found.append(problem("STL600", file, node.loc, name=f'"{node.ident}"', profile=profile))
    return None


def instance_calls(
    blocks: Iterable[tuple[str, ast.BlockNode]],
) -> list[tuple[str, ast.InstrNode]]:
    """The ``CALL fb, db`` statements of the blocks."""
    found: list[tuple[str, ast.InstrNode]] = []
    for file, node in blocks:
        for item in node.code:
            if (
                type(item) is ast.InstrNode
                and item.mnemonic in CALL_SPELLINGS
                and len(item.operands) == 2
            ):
                found.append((file, item))
    return found


def _define(
    symbols: SymbolTable, name: str, kind: BlockKind, number: int, file: str, where: ast.Loc
) -> None:
    address = f"{kind.value} {number}"
    symbols.symbols[name.casefold()] = Symbol(
        name, address, parse_address(address), "", "", file, where.line
    )

"""The IEC library FCs a program calls (``nasaq.lang.iec_library``), added to the program as STEP 7
adds them when they are copied from the Standard Library into the block folder.

After every block of every source is registered, the CALLs are looked at:
- ``CALL "CONCAT"``: a name of the library that no symbol has; the block gets the library's
  number (FC 2) and the symbol ``CONCAT``;
- ``CALL "CONCAT"`` where the symbol table names an FC that no source defines: the library block
  takes that number.
``CALL FC 2`` without an FC 2 in the sources stays a missing block (``STL213``), as in STEP 7,
where a library block is called by number only once it has been copied into the program: a
mistyped number must not call CONCAT silently. Once ``CALL "CONCAT"`` has added FC 2, ``CALL
FC 2`` calls it too. When the library's number is taken (a block of the program or a symbol of
another name has it), the block takes the lowest number from ``RELOCATED_BASE`` (FC 1000) up
that is free.

A library block is an STL FC with ``FAMILY : IEC``, ``NAME :`` its IEC name, the library's
interface and no code; the CPU gives it its body (``nasaq.cpu.iec_library``).
"""

from __future__ import annotations

from collections.abc import Iterable
from itertools import product

from nasaq.ir import BlockKind
from nasaq.lang.iec_library import FAMILY, FUNCTIONS, RELOCATED_BASE, LibraryFunction
from nasaq.lang.stl import ast
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.bind import BlockInfo, ProgramIndex
from nasaq.lang.stl.symbols import Symbol, SymbolTable
from nasaq.lang.types import DataType, StringType, type_text

LIBRARY_FILE = "<IEC library>"
_WHERE = ast.Loc(1, 1, 1, 1)
CALL_SPELLINGS = frozenset(map("".join, product(*zip("call", "CALL", strict=True))))


def add_library_blocks(
    index: ProgramIndex, symbols: SymbolTable, nodes: Iterable[ast.BlockNode]
) -> list[BlockInfo]:
    """Registers and declares the library FCs that ``nodes`` call and the program lacks."""
    wanted = _called(index, symbols, nodes)
    added: list[BlockInfo] = []
    for function in sorted(wanted, key=lambda f: f.number):
        given = wanted[function]
        number = given if given is not None else _number(index, symbols, function)
        if symbols.get(function.name) is None and symbols.block_symbol("FC", number) is None:
            address = f"FC {number}"
            symbols.symbols[function.name.casefold()] = Symbol(
                function.name, address, parse_address(address), "", function.title, LIBRARY_FILE, 0
            )
        info = index.register(block_node(function, number), LIBRARY_FILE, "en")
        if info is not None:
            index.declare(info)
            added.append(info)
    return added


def _called(
    index: ProgramIndex, symbols: SymbolTable, nodes: Iterable[ast.BlockNode]
) -> dict[LibraryFunction, int | None]:
    """The library FCs called and missing, each with the number it must have (None: free)."""
    wanted: dict[LibraryFunction, int | None] = {}
    for node in nodes:
        for item in node.code:
            # every instruction of the program passes here: one set lookup for most of them
            if type(item) is not ast.InstrNode or item.mnemonic not in CALL_SPELLINGS:
                continue
            if not item.operands:
                continue
            target = item.operands[0]
            if not isinstance(target, ast.SymbolNode) or target.local or target.path:
                continue
            function = FUNCTIONS.get(target.name.upper())
            if function is None:
                continue
            symbol = symbols.get(target.name)
            if symbol is None:
                wanted.setdefault(function, None)
                continue
            number = _missing_fc(index, symbol.address)
            if number is not None:
                wanted[function] = number
    return wanted


def _missing_fc(index: ProgramIndex, text: str) -> int | None:
    """The number of ``FC n`` when no source defines that FC."""
    try:
        parsed = parse_address(text)
    except AddressError:
        return None
    if parsed.kind != "block" or parsed.block is not BlockKind.FC:
        return None
    return None if (BlockKind.FC, parsed.number) in index.blocks else parsed.number


def _number(index: ProgramIndex, symbols: SymbolTable, function: LibraryFunction) -> int:
    def free(number: int) -> bool:
        symbol = symbols.block_symbol("FC", number)
        named_else = symbol is not None and symbol.name.upper() != function.name
        return (BlockKind.FC, number) not in index.blocks and not named_else

    if free(function.number):
        return function.number
    number = RELOCATED_BASE
    while not free(number):
        number += 1
    return number


def _type(data_type: DataType) -> ast.NamedTypeNode:
    if isinstance(data_type, StringType):
        return ast.NamedTypeNode(data_type.name, data_type.length, _WHERE)
    return ast.NamedTypeNode(type_text(data_type), None, _WHERE)


def block_node(function: LibraryFunction, number: int) -> ast.BlockNode:
    """``FUNCTION FC n : type`` with the library's header and inputs, without code."""
    node = ast.BlockNode("FUNCTION", f"FC {number}", False, _WHERE, _WHERE)
    node.return_type = _type(function.result)
    inputs = [
        ast.VarDeclNode(name, _type(data_type), None, {}, _WHERE)
        for name, data_type in function.inputs
    ]
    node.head = [
        ast.TitleNode(function.title, _WHERE),
        ast.HeaderPropNode("FAMILY", FAMILY, _WHERE),
        ast.HeaderPropNode("NAME", function.name, _WHERE),
        ast.VarSectionNode("VAR_INPUT", inputs, _WHERE),
    ]
    for section, heading in (("OUT", "VAR_OUTPUT"), ("IN_OUT", "VAR_IN_OUT")):
        others = [
            ast.VarDeclNode(name, _type(data_type), None, {}, _WHERE)
            for kind, name, data_type in function.others
            if kind == section
        ]
        if others:
            node.head.append(ast.VarSectionNode(heading, others, _WHERE))
    return node

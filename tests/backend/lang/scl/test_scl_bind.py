"""The SCL binder: TIA Portal automatic numbering, declared types and the standard S7-300/400
layout of FB instances, DBs and the L stack (``nasaq.lang.scl.bind``)."""

from __future__ import annotations

from nasaq.ir import BlockKind
from nasaq.lang.layout import Slot
from nasaq.lang.scl import ast, check_sources, parse_source
from nasaq.lang.scl.bind import SclIndex, bind
from nasaq.lang.stl.symbols import SymbolTable, read_symbol_table
from nasaq.lang.types import ArrayType, BlockType, Elementary, StringType


def _parse(file: str, text: str) -> ast.SourceFile:
    result = parse_source(file, text)
    assert result.diagnostics == []
    return result.source


def _index(*texts: str, symbols: SymbolTable | None = None) -> SclIndex:
    sources = [_parse(f"s{number}.scl", text) for number, text in enumerate(texts)]
    return bind(sources, symbols)


def _problems(index: SclIndex) -> list[tuple[str, int, int]]:
    return [
        (item.code, item.span.line or 0, item.span.column or 0)
        for item in index.diagnostics
        if item.span
    ]


FIRST = """FUNCTION_BLOCK "Alpha"
BEGIN
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB1
BEGIN
END_FUNCTION_BLOCK
FUNCTION_BLOCK Beta
BEGIN
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB10
BEGIN
END_FUNCTION_BLOCK
FUNCTION "Calc" : INT
BEGIN
  Calc := 1;
END_FUNCTION
DATA_BLOCK "Data"
STRUCT x : INT; END_STRUCT
BEGIN
END_DATA_BLOCK
"""
SECOND = """DATA_BLOCK DB1
STRUCT y : INT; END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK "Main"
BEGIN
END_ORGANIZATION_BLOCK
FUNCTION_BLOCK "Gamma"
BEGIN
END_FUNCTION_BLOCK
PROGRAM "Delta"
END_PROGRAM
"""


def test_tia_automatic_numbering_takes_the_lowest_free_number_in_source_order() -> None:
    index = _index(FIRST, SECOND)
    assert _problems(index) == []
    numbered = {(block.kind.value, block.number): block.name for block in index}
    assert numbered == {
        ("FB", 1): "FB1",
        ("FB", 2): "Alpha",
        ("FB", 3): "Beta",
        ("FB", 4): "Gamma",
        ("FB", 5): "Delta",  # PROGRAM is FUNCTION_BLOCK's alias
        ("FB", 10): "FB10",
        ("FC", 1): "Calc",
        ("DB", 1): "DB1",
        ("DB", 2): "Data",
        ("OB", 1): "Main",
    }
    assert index.named("alpha") is index.get(BlockKind.FB, 2)
    assert index.named("FB10") is index.get(BlockKind.FB, 10)


def test_a_symbol_table_gives_blocks_their_numbers() -> None:
    symbols = SymbolTable()
    read_symbol_table("s.csv", "Motor,FB 7,FB 7,\nCycle,OB 35,OB 35,\n", symbols)
    index = _index(
        'FUNCTION_BLOCK "Motor"\nBEGIN\nEND_FUNCTION_BLOCK\n'
        "ORGANIZATION_BLOCK Cycle\nBEGIN\nEND_ORGANIZATION_BLOCK\n"
        "FUNCTION_BLOCK Other\nBEGIN\nEND_FUNCTION_BLOCK\n",
        symbols=symbols,
    )
    assert _problems(index) == []
    assert [(block.label, block.name) for block in index] == [
        ("FB 1", "Other"),
        ("FB 7", "Motor"),
        ("OB 35", "Cycle"),
    ]


def test_numbering_problems() -> None:
    index = _index(
        "ORGANIZATION_BLOCK Cycle\nBEGIN\nEND_ORGANIZATION_BLOCK\n"
        "FUNCTION_BLOCK FB2\nBEGIN\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK FB2\nBEGIN\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK FC3\nBEGIN\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Twice\nBEGIN\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK twice\nBEGIN\nEND_FUNCTION_BLOCK\n"
    )
    assert sorted(_problems(index)) == [
        ("SCL203", 7, 16),  # FB2 again
        ("SCL203", 16, 16),  # Twice again (names are case-insensitive)
        ("SCL204", 10, 16),  # FC3 cannot name a FUNCTION_BLOCK
        ("SCL205", 1, 20),  # an OB other than "Main" needs a number
    ]


FB = """TYPE "Rec"
STRUCT
  x : INT;
  y : BOOL;
END_STRUCT
END_TYPE
FUNCTION_BLOCK "Motor"
CONST
  N := 3;
END_CONST
VAR_INPUT
  start, stop : BOOL;
  speed : INT;
END_VAR
VAR_OUTPUT
  running : BOOL;
END_VAR
VAR_IN_OUT
  text : STRING[10];
END_VAR
VAR
  count : DINT;
  flags : ARRAY[1..N] OF BOOL;
  name : STRING[4];
  rec : "Rec";
  timer : TON;
END_VAR
VAR_TEMP
  t : INT;
  b : BYTE;
  c : BYTE;
  r : REAL;
END_VAR
BEGIN
END_FUNCTION_BLOCK
DATA_BLOCK "Motor_DB" "Motor"
BEGIN
END_DATA_BLOCK
DATA_BLOCK "Values"
STRUCT
  a : BOOL;
  b : BYTE;
  c : INT;
  d : ARRAY[1..2, 0..1] OF REAL;
  e : STRUCT f : BOOL; g : WORD; END_STRUCT;
  h : CHAR;
END_STRUCT
BEGIN
END_DATA_BLOCK
"""


def _offsets(slots: list[Slot]) -> list[tuple[str, str, int]]:
    """(name, section, offset as byte.bit in tenths: 2.1 → 21)."""
    return [
        (slot.name, slot.section, slot.offset_bits // 8 * 10 + slot.offset_bits % 8)
        for slot in slots
    ]


def test_fb_interface_types_and_instance_layout() -> None:
    index = _index(FB)
    assert _problems(index) == []
    motor = index.named("Motor")
    assert motor is not None
    assert (motor.kind, motor.number) == (BlockKind.FB, 1)
    assert motor.variables["flags"].type == ArrayType(((1, 3),), Elementary("BOOL"))
    assert motor.variables["rec"].type == BlockType("UDT", 1)
    assert motor.variables["text"].type == StringType(10)
    assert motor.variables["timer"].type == BlockType("SFB", 4)
    slots, size = index.instance_layout(motor)
    assert _offsets(slots) == [
        ("start", "IN", 0),
        ("stop", "IN", 1),
        ("speed", "IN", 20),
        ("running", "OUT", 40),
        ("text", "IN_OUT", 60),  # a STRING IN_OUT is a 6-byte pointer
        ("count", "STAT", 120),
        ("flags", "STAT", 160),
        ("name", "STAT", 180),  # STRING[4]: 6 bytes
        ("rec", "STAT", 240),  # UDT: INT + BOOL = 4 bytes
        ("timer", "STAT", 280),
    ]
    assert slots[0].by_reference is False
    assert slots[4].by_reference is True
    timer = slots[-1]
    assert [member.name for member in timer.members][:4] == ["IN", "PT", "Q", "ET"]
    assert size == (28 + timer.size_bits // 8) * 8
    temp, temp_size = index.temp_layout(motor)
    assert _offsets(temp) == [
        ("t", "TEMP", 0),
        ("b", "TEMP", 20),
        ("c", "TEMP", 30),
        ("r", "TEMP", 40),
    ]
    assert temp_size == 64


def test_db_layouts_shared_and_instance() -> None:
    index = _index(FB)
    values = index.named("values")
    assert values is not None
    assert values.number == 2
    slots, size = index.db_layout(values)
    assert _offsets(slots) == [
        ("a", "", 0),
        ("b", "", 10),
        ("c", "", 20),
        ("d", "", 40),  # 4 REALs: 16 bytes
        ("e", "", 200),
        ("h", "", 240),
    ]
    assert _offsets(slots[4].members) == [("f", "", 200), ("g", "", 220)]
    assert size == 26 * 8
    instance = index.named("Motor_DB")
    motor = index.named("Motor")
    assert instance is not None
    assert motor is not None
    assert instance.number == 1
    assert instance.db_type == BlockType("FB", 1)
    assert index.db_layout(instance) == index.instance_layout(motor)


def test_declaration_problems() -> None:
    index = _index(
        "FUNCTION_BLOCK FB1\n"
        "VAR\n"
        "  a : Missing;\n"
        "  b : INT;\n"
        "  b : INT;\n"
        "  c : ARRAY[5..1] OF INT;\n"
        "  d : ARRAY[1..n] OF INT;\n"
        "  e : STRING[300];\n"
        "END_VAR\n"
        "BEGIN\n"
        "END_FUNCTION_BLOCK\n"
        "TYPE UDT1 STRUCT u : UDT1; END_STRUCT END_TYPE\n"
        "DATA_BLOCK DB1 UDT1\nBEGIN\nEND_DATA_BLOCK\n"
    )
    assert _problems(index) == [
        ("SCL202", 3, 7),
        ("SCL206", 5, 3),
        ("SCL208", 6, 13),
        ("SCL209", 7, 16),
        ("SCL218", 8, 14),
    ]
    db = index.get(BlockKind.DB, 1)
    assert db is not None
    assert index.db_layout(db) == ([], 0)
    assert _problems(index)[-1] == ("SCL210", 13, 12)  # DB1 is made of UDT1, which contains itself


def test_check_sources_is_the_public_entry() -> None:
    source = _parse("a.scl", FB)
    index, diagnostics = check_sources([source])
    assert diagnostics == []
    assert index.named("Rec") is index.get(BlockKind.UDT, 1)

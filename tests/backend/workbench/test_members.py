"""The DB editor's rows: a block's variables flattened in declaration order with offsets,
initial and compiled actual values, as a watch table addresses them."""

from __future__ import annotations

import pytest

from nasaq.ir import BlockKind, Program
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.workbench.members import MAX_ELEMENTS, Member, block_members

STL = """TYPE UDT 5
  STRUCT
   a : INT := 3;
   b : BOOL;
  END_STRUCT ;
END_TYPE
DATA_BLOCK DB 3
  STRUCT
   x : INT := 7;   // a counter
   s : STRUCT
     y : REAL := 1.5;
     z : BOOL := TRUE;
   END_STRUCT ;
   arr : ARRAY [1..3] OF INT := 1, 2, 3;
   u : UDT 5;
   t : TIME := T#2S;
   w : WORD := W#16#FF;
   c : CHAR := 'A';
   st : STRING[4] := 'ab';
   d : DINT := L#-70000;
   big : ARRAY [0..999] OF BYTE;
   rep : ARRAY [1..4] OF INT := 2 (5), 2 (6);
  END_STRUCT ;
BEGIN
   x := 9;
   s.y := 2.5;
   arr[2] := 5;
END_DATA_BLOCK
"""
SCL = """FUNCTION_BLOCK FB 3
VAR_INPUT
  a : INT := 4;
END_VAR
VAR_IN_OUT
  io : STRING[8];
END_VAR
VAR
  m : ARRAY[0..1] OF BOOL;
  r : STRUCT
    q : INT;
  END_STRUCT;
END_VAR
VAR_TEMP
  tmp : INT;
END_VAR
BEGIN
END_FUNCTION_BLOCK
DATA_BLOCK DB 4 FB 3
BEGIN
END_DATA_BLOCK
"""
TEXTS = {"a.awl": STL, "b.scl": SCL}


@pytest.fixture(scope="module")
def program() -> Program:
    result = compile_sources(SourceFile(name, text) for name, text in TEXTS.items())
    assert not [item for item in result.diagnostics if item.severity == "error"]
    return result.program


def _rows(program: Program, number: int) -> dict[str, Member]:
    block = program.get(BlockKind.DB, number)
    assert block is not None
    return {row.path: row for row in block_members(block, program, TEXTS)}


def test_shared_db_rows_have_offsets_initial_and_actual_values(program: Program) -> None:
    rows = _rows(program, 3)
    x = rows["x"]
    assert (x.type, x.section, x.depth, x.offset) == ("INT", "DATA", 0, "0.0")
    assert (x.initial, x.actual, x.comment, x.elementary) == ("7", "9", "a counter", True)
    assert (x.file, x.line) == ("a.awl", 9)
    assert rows["s"].elementary is False
    assert rows["s"].actual is None
    assert (rows["s.y"].depth, rows["s.y"].initial, rows["s.y"].actual) == (1, "1.5", "2.5")
    assert (rows["s.z"].offset, rows["s.z"].actual) == ("6.0", "TRUE")
    assert rows["t"].actual == "T#2S"
    assert rows["w"].actual == "W#16#00FF"
    assert rows["c"].actual == "'A'"
    assert rows["d"].actual == "L#-70000"
    assert rows["st"].actual == "'ab'"
    assert rows["st"].elementary is True  # a watch table shows and modifies a STRING


def test_elementary_arrays_are_flattened_and_udts_expanded(program: Program) -> None:
    rows = _rows(program, 3)
    paths = list(rows)
    assert paths[paths.index("arr") + 1 : paths.index("arr") + 4] == ["arr[1]", "arr[2]", "arr[3]"]
    second = rows["arr[2]"]
    assert (second.offset, second.initial, second.actual, second.depth) == ("10.0", "2", "5", 1)
    assert second.line == rows["arr"].line == 14
    assert [rows[f"rep[{i}]"].initial for i in range(1, 5)] == ["5", "5", "6", "6"]
    assert rows["u"].type == "UDT 5"
    assert (rows["u.a"].initial, rows["u.a"].actual, rows["u.b"].offset) == ("3", "3", "16.0")
    assert MAX_ELEMENTS < 1000
    assert "big" in rows
    assert "big[0]" not in rows


def test_instance_db_uses_its_fb_interface_and_sections(program: Program) -> None:
    rows = _rows(program, 4)
    assert rows["a"].section == "IN"
    assert rows["a"].actual == "4"
    assert (rows["a"].file, rows["a"].line) == ("b.scl", 3)
    assert rows["io"].section == "IN_OUT"
    assert rows["io"].actual is None
    assert rows["m[1]"].offset.endswith(".1")
    assert rows["m[1]"].section == "STAT"
    assert rows["r.q"].section == "STAT"
    assert rows["r.q"].line == 11
    assert "tmp" not in rows or rows["tmp"].offset is None


def test_rows_without_texts_have_no_lines(program: Program) -> None:
    block = program.get(BlockKind.DB, 3)
    assert block is not None
    assert all(row.line is None for row in block_members(block, program))

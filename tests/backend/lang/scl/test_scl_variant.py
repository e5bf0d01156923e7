"""VARIANT and ``ARRAY[*]`` parameters and ANY actuals (issue 20, the variant part): parse,
check (the new codes SCL550-557), lower (the descriptor, ``nasaq.lang.scl.descriptor``) and run.
The self-checking programs of ``tests/selfcheck/variant`` run the larger cases."""

from __future__ import annotations

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.lang.scl.bind import SclIndex
from nasaq.lang.scl.descriptor import FIELDS, OFFSETS, SIZE, OpenArray, VariantParam
from nasaq.lang.scl.parse import parse_source
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block
from nasaq.lang.types import Elementary

HEADER = """FUNCTION "Sum" : DINT
VAR_IN_OUT
  arr : ARRAY[*] OF INT;
END_VAR
VAR_TEMP
  i : DINT;
END_VAR
BEGIN
  #Sum := 0;
  FOR i := LOWER_BOUND(arr, 1) TO UPPER_BOUND(ARR := arr, DIM := 1) DO
    #Sum := #Sum + arr[i];
  END_FOR;
END_FUNCTION
"""


def _errors(text: str, profile: str = "S7-1500", *more: SourceFile) -> list[tuple[str, int]]:
    result = compile_sources([SourceFile("t.scl", text), *more], profile=profile)
    return [
        (d.code, d.span.line)
        for d in result.diagnostics
        if d.span is not None and d.severity == "error"
    ]


def _run(text: str, *more: SourceFile) -> Cpu:
    result = compile_sources([SourceFile("prog.scl", text), *more], profile="S7-1500")
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def _db_int(cpu: Cpu, number: int, byte: int, size: int = 2) -> int:
    data = cpu.db_bytes(number)
    assert data is not None
    return int.from_bytes(data[byte : byte + size], "big", signed=True)


# ---- parse and bind --------------------------------------------------------------------------


def test_the_declarations_parse_and_bind_to_descriptors() -> None:
    text = HEADER.replace("ARRAY[*] OF INT", "ARRAY[*, *] OF INT").replace("arr[i]", "arr[i, 1]")
    parsed = parse_source("t.scl", text)
    assert not parsed.diagnostics
    index = SclIndex(profile="S7-1500")
    index.add_sources([parsed.source])
    assert not index.diagnostics
    block = next(iter(index))
    declared = block.variables["arr"].type
    assert isinstance(declared, OpenArray)
    assert (declared.dims, declared.element) == (2, Elementary("INT"))
    # the STL interface and every layout see the descriptor
    assert declared.fields == FIELDS
    assert SIZE == 70
    assert OFFSETS["PTR"] == 6
    assert OFFSETS["BOUNDS"] == 22


def test_under_a_classic_profile_they_stay_scl500() -> None:
    assert _errors(HEADER, "S7-300")[:1] == [("SCL500", 3)]
    variant = (
        'FUNCTION "F" : INT\nVAR_INPUT\n  v : VARIANT;\nEND_VAR\nBEGIN\n  #F := 1;\nEND_FUNCTION\n'
    )
    assert _errors(variant, "S7-300") == [("SCL500", 3)]
    assert _errors(variant, "S7-1500") == []
    assert isinstance(VariantParam(FIELDS), VariantParam)


# ---- checks ----------------------------------------------------------------------------------

MISUSE = """FUNCTION "Bad" : INT
VAR_INPUT
  v : VARIANT;
  a : ARRAY[*] OF INT;
  m : ARRAY[*, 1..3] OF INT;
END_VAR
VAR_TEMP
  t : ARRAY[*] OF INT;
  x : INT;
  r : ARRAY[0..3] OF REAL;
END_VAR
BEGIN
  x := v + 1;
  x := DINT_TO_INT(LOWER_BOUND(a, 2));
  x := DINT_TO_INT(UPPER_BOUND(v, 1));
  IF TypeOf(v) = Foo THEN x := 1; END_IF;
  x := UDINT_TO_INT(CountOfElements(x));
  x := a[1, 2];
  #Bad := "Two"(arr := r, w := 5);
END_FUNCTION
FUNCTION "Two" : INT
VAR_IN_OUT
  arr : ARRAY[*] OF INT;
END_VAR
VAR_INPUT
  w : VARIANT;
END_VAR
BEGIN
  #Two := 1;
END_FUNCTION
"""


def test_misuse_gets_a_code_at_its_place() -> None:
    assert _errors(MISUSE) == [
        ("SCL551", 5),  # bounds mixed with *
        ("SCL550", 8),  # ARRAY[*] as a temporary
        ("SCL211", 13),  # a VARIANT in arithmetic
        ("SCL556", 14),  # no second dimension
        ("SCL555", 15),  # UPPER_BOUND of a VARIANT
        ("SCL557", 16),  # TypeOf compared with no type
        ("SCL555", 17),  # CountOfElements of an INT
        ("SCL216", 18),  # two indices for one dimension
        ("SCL553", 19),  # an array of REAL for ARRAY[*] OF INT
        ("SCL554", 19),  # a constant for a VARIANT
    ]


def test_the_message_names_the_type_as_tia_does() -> None:
    result = compile_sources([SourceFile("t.scl", MISUSE)], profile="S7-1500")
    texts = {d.code: d.message for d in result.diagnostics}
    assert texts["SCL211"] == "The operator + cannot combine VARIANT and INT."
    assert "ARRAY[*] OF INT" in texts["SCL553"]


def test_an_fb_takes_array_star_only_as_in_out() -> None:
    text = (
        'FUNCTION_BLOCK "B"\nVAR_INPUT\n  a : ARRAY[*] OF INT;\n  v : VARIANT;\nEND_VAR\n'
        "VAR_OUTPUT\n  w : VARIANT;\nEND_VAR\nBEGIN\n  ;\nEND_FUNCTION_BLOCK\n"
    )
    assert _errors(text) == [("SCL550", 3), ("SCL550", 7)]


# ---- lowering --------------------------------------------------------------------------------


def test_an_element_is_reached_through_the_descriptor() -> None:
    result = compile_sources([SourceFile("t.scl", HEADER)], profile="S7-1500")
    assert not result.diagnostics
    text = format_block(result.generated[0][1])
    assert "arr : STRUCT" in text
    assert "BOUNDS : ARRAY  [1 .. 12 ] OF DINT" in text
    assert "L     P##arr;" in text  # the caller's DB pointer to its descriptor
    assert "L     D [AR1,P#22.0];" in text  # the first lower bound
    assert "L     D [AR1,P#26.0];" in text  # the first upper bound


# ---- running ---------------------------------------------------------------------------------


def test_array_star_sums_arrays_of_any_bounds() -> None:
    text = HEADER + (
        'DATA_BLOCK "D"\nSTRUCT\n  a : ARRAY[-2..1] OF INT;\n  b : ARRAY[5..6] OF INT;\n'
        "  s1 : DINT;\n  s2 : DINT;\nEND_STRUCT\nBEGIN\n  a[-2] := 1; a[-1] := 2; a[0] := 3;\n"
        "  a[1] := 4; b[5] := 100; b[6] := -1;\nEND_DATA_BLOCK\n"
        'ORGANIZATION_BLOCK OB1\nBEGIN\n  "D".s1 := "Sum"(arr := "D".a);\n'
        '  "D".s2 := "Sum"(arr := "D".b);\nEND_ORGANIZATION_BLOCK\n'
    )
    cpu = _run(text)
    assert _db_int(cpu, 1, 12, 4) == 10
    assert _db_int(cpu, 1, 16, 4) == 99


def test_a_variant_passed_on_keeps_its_type_and_count() -> None:
    text = """FUNCTION "Count" : UDINT
VAR_INPUT
  v : VARIANT;
END_VAR
BEGIN
  #Count := CountOfElements(v);
END_FUNCTION
FUNCTION "Outer" : UDINT
VAR_INPUT
  v : VARIANT;
END_VAR
BEGIN
  IF TypeOfElements(v) = REAL AND IS_ARRAY(v) THEN
    #Outer := "Count"(v) + 100;
  ELSE
    #Outer := "Count"(v);
  END_IF;
END_FUNCTION
DATA_BLOCK "D"
STRUCT
  r : ARRAY[1..7] OF REAL;
  n : UDINT;
  m : UDINT;
  k : UDINT;
END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
VAR_TEMP
  i : ARRAY[0..2] OF INT;
  x : INT;
END_VAR
BEGIN
  "D".n := "Outer"(v := "D".r);
  "D".m := "Outer"(v := i);
  "D".k := "Outer"(v := x);
END_ORGANIZATION_BLOCK
"""
    cpu = _run(text)
    assert [_db_int(cpu, 1, at, 4) for at in (28, 32, 36)] == [107, 3, 0]


def test_an_any_actual_of_scl_carries_type_count_and_place() -> None:
    """``VAR_INPUT src : ANY`` (STEP 7 Classic SCL): a structure, an array and an element of a
    temporary give the 10-byte ANY STEP 7 builds; an STL FC reads it."""
    reader = """FUNCTION "Peek" : VOID
VAR_INPUT
  src : ANY;
END_VAR
VAR_OUTPUT
  kind : INT;
  count : INT;
  db : INT;
  area : INT;
END_VAR
BEGIN
NETWORK
      L     P##src;
      LAR1  ;
      L     B [AR1,P#1.0];
      T     #kind;
      L     W [AR1,P#2.0];
      T     #count;
      L     W [AR1,P#4.0];
      T     #db;
      L     B [AR1,P#6.0];
      T     #area;
END_FUNCTION
"""
    text = """DATA_BLOCK "D"
STRUCT
  s : STRUCT a : INT; b : REAL; END_STRUCT;
  out : ARRAY[0..11] OF INT;
END_STRUCT
BEGIN
END_DATA_BLOCK
FUNCTION "Probe" : VOID
VAR_TEMP
  arr : ARRAY[1..5] OF DINT;
END_VAR
BEGIN
  "Peek"(src := "D".s, kind => "D".out[0], count => "D".out[1], db => "D".out[2],
         area => "D".out[3]);
  "Peek"(src := arr, kind => "D".out[4], count => "D".out[5], db => "D".out[6],
         area => "D".out[7]);
END_FUNCTION
ORGANIZATION_BLOCK OB1
BEGIN
  "Probe"();
END_ORGANIZATION_BLOCK
"""
    cpu = _run(text, SourceFile("peek.awl", reader))
    values = [_db_int(cpu, 1, 6 + 2 * k) for k in range(8)]
    assert values[:4] == [2, 6, 1, 0x84]  # BYTE 6 (a structure), in DB 1
    assert values[4:] == [7, 5, 0, 0x87]  # DINT 5, the caller's local data


@pytest.mark.parametrize("name", ["TypeOf", "IS_ARRAY", "CountOfElements", "Serialize"])
def test_the_instructions_need_the_s7_1500_profile(name: str) -> None:
    call = {
        "TypeOf": "TypeOf(x) = INT",
        "IS_ARRAY": "IS_ARRAY(x)",
        "CountOfElements": "CountOfElements(x) = 0",
        "Serialize": "Serialize(SRC_VARIABLE := x, DEST_ARRAY => x, POS := y) = 0",
    }[name]
    text = (
        'FUNCTION "F" : BOOL\nVAR_TEMP\n  x : INT;\n  y : DINT;\nEND_VAR\nBEGIN\n'
        f"  #F := {call};\nEND_FUNCTION\n"
    )
    assert ("SCL500", 7) in _errors(text, "S7-300")


DB_ANY_MISUSE = """DATA_BLOCK "D"
STRUCT
  x : INT;
END_STRUCT
BEGIN
END_DATA_BLOCK
FUNCTION "Take" : WORD
VAR_INPUT
  db : DB_ANY;
END_VAR
VAR_TEMP
  n : INT;
END_VAR
BEGIN
  #Take := PEEK_WORD(area := 16#85, dbNumber := db, byteOffset := 0);
  n := DB_ANY_TO_UINT(n);
  POKE(area := 16#84, dbNumber := db, byteOffset := 0, value := 1.5);
END_FUNCTION
ORGANIZATION_BLOCK OB1
VAR_TEMP
  w : WORD;
  i : INT;
END_VAR
BEGIN
  w := "Take"(db := "D");
  w := "Take"(db := i);
END_ORGANIZATION_BLOCK
"""


def test_db_any_and_peek_poke_misuse_gets_a_code() -> None:
    assert _errors(DB_ANY_MISUSE) == [
        ("SCL555", 15),  # 16#85 is no area PEEK reaches
        ("SCL555", 16),  # DB_ANY_TO_UINT of an INT
        ("SCL555", 17),  # a REAL poked
        ("SCL558", 26),  # an INT for a DB_ANY (a DB is fine, line 25)
    ]


def test_a_db_passed_to_db_any_becomes_its_number() -> None:
    text = """DATA_BLOCK "D"
STRUCT
  x : INT := 77;
END_STRUCT
BEGIN
END_DATA_BLOCK
FUNCTION "Take" : WORD
VAR_INPUT
  db : DB_ANY;
END_VAR
BEGIN
  #Take := PEEK_WORD(area := 16#84, dbNumber := db, byteOffset := 0);
END_FUNCTION
DATA_BLOCK "R"
STRUCT
  w : WORD;
END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "R".w := "Take"(db := "D");
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("t.scl", text)], profile="S7-1500")
    ob1 = next(block for _file, block in result.generated if "OB 1" in format_block(block))
    assert "L     1;" in format_block(ob1)  # DB 1 as its number
    cpu = _run(text)
    assert _db_int(cpu, 2, 0) == 77

"""WSTRING and WCHAR (TIA Portal's Unicode text, S7-1200/1500 only; ``nasaq.lang.wide_text``):
declared in every section, DBs, UDTs and FB instances with the header of a WSTRING written at
start-up, assigned, compared, passed to FCs and to the text functions, run on the CPU. Under a
classic profile they stay SCL500; what is not simulated yet is SCL800."""

from __future__ import annotations

import re

import pytest

from nasaq.cpu import Cpu
from nasaq.headless.addresses import parse_address, signed
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block


def run(source: str) -> Cpu:
    """The program compiled for S7-1500 without errors, started and scanned once."""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def codes(source: str, profile: str = "S7-1500") -> list[tuple[str, int]]:
    result = compile_sources([SourceFile("prog.scl", source)], profile=profile)
    return [(d.code, d.span.line) for d in result.diagnostics]


def read(cpu: Cpu, text: str) -> int:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return signed(cpu.read(address), address.width)


def wide(cpu: Cpu, db: int, byte: int) -> tuple[int, str]:
    """(maximum length, characters) of the WSTRING at ``byte`` of DB ``db``."""
    data = cpu.db_bytes(db)
    assert data is not None
    maximum = int.from_bytes(data[byte : byte + 2], "big")
    length = int.from_bytes(data[byte + 2 : byte + 4], "big")
    return maximum, data[byte + 4 : byte + 4 + 2 * length].decode("utf-16-be")


def wchar(cpu: Cpu, db: int, byte: int) -> str:
    data = cpu.db_bytes(db)
    assert data is not None
    return data[byte : byte + 2].decode("utf-16-be")


# ---- declarations and layout --------------------------------------------------------------------

TEXTS = """TYPE Rec
STRUCT
  name : WSTRING[6] := 'abc';
  ch : WCHAR := WCHAR#'k';
END_STRUCT
END_TYPE
DATA_BLOCK Texts
STRUCT
  w : WSTRING[4] := WSTRING#'ab';
  c : WCHAR := 'z';
  x : WSTRING[3];
  arr : ARRAY[1..2] OF WSTRING[2];
  r : Rec;
  d : WSTRING;
END_STRUCT
BEGIN
  x := WSTRING#'q';
END_DATA_BLOCK
"""
# Texts (DB1): w 0 (4 + 8), c 12, x 14 (4 + 6), arr 24 and 32 (4 + 4 each), r 40 (name 40,
# ch 56), d 58 (4 + 508)


def test_declarations_are_laid_out_as_tia_with_their_header_and_initial_values() -> None:
    cpu = run(TEXTS + "ORGANIZATION_BLOCK OB1\nBEGIN\nEND_ORGANIZATION_BLOCK\n")
    data = cpu.db_bytes(1)
    assert data is not None
    assert len(data) == 58 + 4 + 2 * 254
    assert data[0:8] == bytes([0, 4, 0, 2, 0, 0x61, 0, 0x62])  # WORD max, WORD length, UTF-16
    assert wchar(cpu, 1, 12) == "z"
    assert wide(cpu, 1, 14) == (3, "q")  # the DB's own assignment
    assert wide(cpu, 1, 24) == wide(cpu, 1, 32) == (2, "")
    assert wide(cpu, 1, 40) == (6, "abc")
    assert wchar(cpu, 1, 56) == "k"
    assert wide(cpu, 1, 58) == (254, "")  # WSTRING without a length: 254


def test_an_initial_value_too_long_for_its_wstring_is_an_error() -> None:
    source = "DATA_BLOCK D\nSTRUCT w : WSTRING[2] := 'abc'; END_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
    assert codes(source) == [("SCL218", 2)]


def test_a_wstring_length_is_checked_as_tia_does() -> None:
    ok = "FUNCTION F : VOID\nVAR_TEMP w : WSTRING[16382]; END_VAR\nBEGIN\nEND_FUNCTION\n"
    assert codes(ok) == []
    bad = ok.replace("16382", "16383")
    assert codes(bad) == [("SCL218", 2)]


# ---- assignments --------------------------------------------------------------------------------

ASSIGNMENTS = """FUNCTION_BLOCK Fb
VAR_INPUT
  i : INT;
END_VAR
VAR
  s : WSTRING[2];
  arr : ARRAY[1..2] OF WSTRING[3];
  long : WSTRING[10];
  other : WCHAR;
END_VAR
VAR_TEMP
  t : WSTRING[8];
  c : WCHAR;
END_VAR
BEGIN
  t := WSTRING#'héllo';
  long := t;
  s := t;
  c := WCHAR#'Z';
  other := c;
  arr[i] := other;
  arr[1] := '';
END_FUNCTION_BLOCK
DATA_BLOCK Inst Fb
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  Inst(i := 2);
END_ORGANIZATION_BLOCK
"""
# Inst (DB1): i 0, s 2 (4 + 4), arr 10 and 20 (4 + 6 each), long 30 (4 + 20), other 54


def test_assignments_copy_constants_wstrings_and_wchars_into_an_instance() -> None:
    cpu = run(ASSIGNMENTS)
    assert wide(cpu, 1, 30) == (10, "héllo")  # a copy: min(current length, maximum)
    assert wide(cpu, 1, 2) == (2, "hé")  # cut to the target's maximum length
    assert wide(cpu, 1, 20) == (3, "Z")  # a WCHAR: one character, element by a variable index
    assert wide(cpu, 1, 10) == (3, "")
    assert wchar(cpu, 1, 54) == "Z"  # WCHAR := WCHAR


def test_temporaries_get_their_wstring_header_at_the_start_of_the_block() -> None:
    source = """FUNCTION Put : VOID
VAR_IN_OUT io : WSTRING; END_VAR
BEGIN
  io := 'set';
END_FUNCTION
DATA_BLOCK D
STRUCT r : WSTRING[4]; p : WSTRING[2]; END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
VAR_TEMP u : WSTRING[3]; END_VAR
BEGIN
  u := 'abcdef';
  D.r := u;
  Put(io := D.p);
END_ORGANIZATION_BLOCK
"""
    cpu = run(source)
    assert wide(cpu, 1, 0) == (4, "abc")  # u's maximum (3) came from its header
    assert wide(cpu, 1, 12) == (2, "se")  # an IN_OUT knows its room at run time only


# ---- comparisons and the text functions -------------------------------------------------------

FUNCTIONS = """FUNCTION Echo : WSTRING
VAR_INPUT a : WSTRING; END_VAR
BEGIN
  Echo := a;
END_FUNCTION
ORGANIZATION_BLOCK OB1
VAR_TEMP
  t : WSTRING[8];
  u : WSTRING[8];
  r : WSTRING[20];
  c : WCHAR;
END_VAR
BEGIN
  t := 'abc';
  u := WSTRING#'abc';
  c := 'b';
  M0.0 := t = u;
  M0.1 := t <> 'abd';
  M0.2 := t < 'abd';
  M0.3 := c = u;
  MW2 := INT_TO_WORD(LEN(t));
  r := CONCAT(IN1 := t, IN2 := WSTRING#'-xy');
  MW4 := INT_TO_WORD(LEN(r));
  MW6 := INT_TO_WORD(FIND(IN1 := r, IN2 := 'xy'));
  r := MID(IN := r, L := 2, P := 2);
  MW8 := INT_TO_WORD(LEN(r));
  M0.4 := r = 'bc';
  M0.5 := LEFT(IN := t, L := 1) = 'a';
  M0.6 := RIGHT(IN := t, L := 2) = WSTRING#'bc';
  M0.7 := Echo(a := 'const') = 'const';
  M1.0 := WSTRING_TO_STRING(t) = 'abc';
  r := STRING_TO_WSTRING('xyz');
  MW10 := INT_TO_WORD(LEN(r));
END_ORGANIZATION_BLOCK
"""


def test_comparisons_functions_and_conversions_of_wstrings_run() -> None:
    cpu = run(FUNCTIONS)
    assert [read(cpu, f"M0.{bit}") for bit in range(8)] == [1, 1, 1, 0, 1, 1, 1, 1]
    assert read(cpu, "M1.0") == 1
    assert [read(cpu, f"MW{byte}") for byte in (2, 4, 6, 8, 10)] == [3, 6, 5, 2, 3]


def test_the_generated_stl_calls_the_wstring_library_and_compiles_back() -> None:
    """``nasaq compile --emit stl``: WSTRING declarations and the hidden FCs (``LEN_WSTRING``
    ...) in STL compile again (S7-1500) and compute the same."""
    result = compile_sources([SourceFile("prog.scl", FUNCTIONS)], profile="S7-1500")
    printed = "\n".join(format_block(block) for _file, block in result.generated)
    for name in ("EQ_WSTRING", "LEN_WSTRING", "CONCAT_WSTRING", "STRING_TO_WSTRING"):
        assert f'CALL "{name}"' in printed
    assert re.search(r"t : WSTRING\s*\[8\s*\]", printed)
    again = compile_sources([SourceFile("prog.awl", printed)], profile="S7-1500")
    assert not [d for d in again.diagnostics if d.severity == "error"]
    found = []
    for program in (result.program, again.program):
        cpu = Cpu(program, cycle_ms=10)
        cpu.start()
        cpu.run(1)
        found.append([read(cpu, f"MB{byte}") & 0xFF for byte in (0, 1)])
        found[-1] += [read(cpu, f"MW{byte}") for byte in (2, 4, 6, 8, 10)]
    assert found[0] == found[1] == [0b1111_0111, 1, 3, 6, 5, 2, 3]


def test_wchars_compare_by_their_code_beyond_latin_1_too() -> None:
    source = """DATA_BLOCK D
STRUCT a : WCHAR := 'a'; b : WCHAR := 'Ω'; c : WCHAR; END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  D.c := 'Ω';
  M0.0 := D.a = 'a';
  M0.1 := D.b = D.c;
  M0.2 := D.a < D.b;
  M0.3 := D.b <> WCHAR#'Ω';
  M0.4 := D.a = D.b;
  M0.5 := D.b > 'a';
END_ORGANIZATION_BLOCK
"""
    cpu = run(source)
    assert wchar(cpu, 1, 4) == "Ω"
    assert [read(cpu, f"M0.{bit}") for bit in range(6)] == [1, 1, 1, 0, 0, 1]


def test_wchar_conversions_work_on_its_code_unit() -> None:
    source = """DATA_BLOCK D
STRUCT
  a : WCHAR := 'Ω'; k : CHAR := 'b'; i : INT; d : DINT; c2 : WCHAR; c3 : WCHAR; ch : CHAR;
  low : CHAR;
END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  D.i := WCHAR_TO_INT(D.a);
  D.d := WCHAR_TO_DINT(D.a);
  D.c2 := CHAR_TO_WCHAR(D.k);
  D.c3 := INT_TO_WCHAR(66);
  D.ch := WCHAR_TO_CHAR(D.c3);
  D.low := WCHAR_TO_CHAR(D.a);
END_ORGANIZATION_BLOCK
"""
    cpu = run(source)
    assert read(cpu, "DB1.DBW4") == 0x3A9
    assert read(cpu, "DB1.DBD6") == 0x3A9
    assert wchar(cpu, 1, 10) == "b"
    assert wchar(cpu, 1, 12) == "B"
    assert read(cpu, "DB1.DBB14") == 0x42
    assert read(cpu, "DB1.DBB15") & 0xFF == 0xA9  # beyond Latin-1: the low byte (*Nasaq*)


def test_a_wchar_into_a_char_needs_the_conversion() -> None:
    source = """FUNCTION F : VOID
VAR_TEMP c : WCHAR; k : CHAR; END_VAR
BEGIN
  k := c;
END_FUNCTION
"""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    assert [d.code for d in result.diagnostics] == ["SCL213"]
    assert "WCHAR_TO_CHAR" in result.diagnostics[0].message


# ---- refusals -----------------------------------------------------------------------------------


def test_mixing_string_and_wstring_is_a_type_error() -> None:
    source = """FUNCTION F : VOID
VAR_TEMP w : WSTRING[4]; s : STRING[4]; k : CHAR; c : WCHAR; END_VAR
BEGIN
  s := w;
  w := s;
  c := k;
  M0.0 := s = w;
END_FUNCTION
"""
    assert codes(source) == [("SCL214", 4), ("SCL214", 5), ("SCL213", 6), ("SCL211", 7)]


def test_what_is_not_simulated_yet_is_scl800_naming_the_operation() -> None:
    source = """FUNCTION F : VOID
VAR_TEMP r : LREAL; t : TIME; w : WSTRING; END_VAR
BEGIN
  w := LREAL_TO_WSTRING(r);
  w := TIME_TO_WSTRING(t);
  w := CONCAT(IN1 := w, IN2 := w, IN3 := w);
END_FUNCTION
"""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    found = [(d.code, d.span.line) for d in result.diagnostics]
    assert found == [("SCL800", 4), ("SCL800", 5)]  # CONCAT of WSTRINGs takes IN1 .. INn
    assert "LREAL_TO_WSTRING" in result.diagnostics[0].message
    assert "TIME_TO_WSTRING" in result.diagnostics[1].message


@pytest.mark.parametrize("profile", ["S7-300", "S7-400"])
def test_a_classic_profile_refuses_every_wide_construct_with_scl500(profile: str) -> None:
    source = """FUNCTION F : VOID
VAR_TEMP w : WSTRING[4]; c : WCHAR; s : STRING; END_VAR
BEGIN
  s := WSTRING_TO_STRING(w);
  c := CHAR_TO_WCHAR('a');
END_FUNCTION
"""
    found = codes(source, profile)
    assert found == [("SCL500", 2), ("SCL500", 2), ("SCL500", 4), ("SCL500", 5)]


def test_an_stl_source_declares_wstring_only_for_s7_1500() -> None:
    source = "DATA_BLOCK DB1\nSTRUCT\n  w : WSTRING[3];\nEND_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
    classic = compile_sources([SourceFile("prog.awl", source)], profile="S7-300")
    assert [d.code for d in classic.diagnostics] == ["STL500"]
    result = compile_sources([SourceFile("prog.awl", source)], profile="S7-1500")
    assert result.diagnostics == []


def test_the_db_view_shows_wstring_and_wchar_values() -> None:
    """The workbench's member rows (``workbench.members``) read a WSTRING as its text."""
    from nasaq.ir import BlockKind
    from nasaq.workbench.members import block_members

    result = compile_sources([SourceFile("prog.scl", TEXTS)], profile="S7-1500")
    block = result.program.get(BlockKind.DB, 1)
    assert block is not None
    rows = {row.path: row for row in block_members(block, result.program)}
    assert rows["w"].actual == "'ab'"
    assert rows["c"].actual == "WCHAR#'z'"
    assert rows["c"].elementary is True
    assert rows["r.name"].actual == "'abc'"

"""Watch and modify of the S7-1200/1500 values: LREAL, LINT, ULINT, LWORD, LTIME (8 bytes, more
than one CPU access), SINT/USINT/UINT/UDINT and WCHAR with their own ranges, STRING/WSTRING as
their characters. A modified value is what the program computes with at its next scan, and a
64-bit integer beyond 2**53 reaches a browser exact (as its digits)."""

from __future__ import annotations

import struct
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.ir import Area, Direct, Program, Width
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.monitor import targets
from nasaq.monitor.block_info import block_info, read_slot
from nasaq.monitor.values import decode

sys.path.insert(0, str(Path(__file__).resolve().parent))
from live_server import LiveServer, running_server, source

PROGRAM = """
DATA_BLOCK "Data"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      x : LREAL := 1.5;
      big : LINT := 40000000000;
      u : ULINT;
      w : LWORD := LWORD#16#0123_4567_89AB_CDEF;
      lt : LTIME := LT#1S;
      si : SINT := -5;
      ui : UINT := 60000;
      ud : UDINT := 4000000000;
      us : USINT := 200;
      wc : WCHAR;
      s : STRING[8] := 'abc';
      ws : WSTRING[6];
      y : LREAL;
      sum : LINT;
      later : LTIME;
   END_VAR
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
BEGIN
  "Data".y := "Data".x * 2.0;
  "Data".sum := "Data".big + 1;
  "Data".later := "Data".lt + LT#1MS;
END_ORGANIZATION_BLOCK
"""


@pytest.fixture(scope="module")
def program() -> Program:
    result = compile_sources([SourceFile("prog.scl", PROGRAM)], profile="S7-1500")
    errors = [d.message for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    return result.program


@pytest.fixture
def cpu(program: Program) -> Cpu:
    cpu = Cpu(program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    return cpu


def _read(program: Program, cpu: Cpu, name: str) -> object:
    return targets.read(targets.resolve(f'"Data".{name}', program), cpu)


def _write(program: Program, cpu: Cpu, name: str, value: object) -> None:
    targets.write(targets.resolve(f'"Data".{name}', program), cpu, value)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("name", "type_name", "value"),
    [
        ("x", "LREAL", 1.5),
        ("big", "LINT", 40000000000),
        ("u", "ULINT", 0),
        ("w", "LWORD", str(0x0123_4567_89AB_CDEF)),  # above 2**53: digits
        ("lt", "LTIME", 1_000_000_000),  # nanoseconds
        ("si", "SINT", -5),
        ("ui", "UINT", 60000),
        ("ud", "UDINT", 4000000000),
        ("us", "USINT", 200),
        ("s", "STRING[8]", "abc"),
        ("ws", "WSTRING[6]", ""),
        ("y", "LREAL", 3.0),
        ("sum", "LINT", 40000000001),
    ],
)
def test_watch_reads_each_type_as_its_value(
    program: Program, cpu: Cpu, name: str, type_name: str, value: object
) -> None:
    target = targets.resolve(f'"Data".{name}', program)
    assert target.type == type_name
    assert targets.read(target, cpu) == value


def test_modified_64_bit_values_are_what_the_program_computes_with(
    program: Program, cpu: Cpu
) -> None:
    _write(program, cpu, "x", "-2.25E+300")
    _write(program, cpu, "big", "LINT#-9000000000000000000")
    _write(program, cpu, "lt", "LT#1D2H3M4S5MS6US7NS")
    cpu.run(1)
    assert _read(program, cpu, "y") == -4.5e300
    # beyond 2**53: sent as digits, exact
    assert _read(program, cpu, "sum") == "-8999999999999999999"
    assert _read(program, cpu, "later") == 93_784_006_006_007


@pytest.mark.parametrize(
    ("name", "typed", "shown"),
    [
        ("u", "16#FFFF_FFFF_FFFF_FFFF", "18446744073709551615"),
        ("u", 12, 12),
        ("w", -1, "18446744073709551615"),  # two's complement, as a negative WORD
        ("w", "LWORD#16#FF", 255),
        ("big", "-16#10", -16),
        ("big", 9007199254740991, 9007199254740991),
        ("big", "9007199254740992", "9007199254740992"),
        ("lt", "LTIME#-2S", -2_000_000_000),
        ("lt", "T#1M", 60_000_000_000),
        ("lt", 7, 7),
        ("x", "NaN", "NaN"),
        ("x", "-Inf", "-Inf"),
        ("x", "LREAL#0.1", 0.1),
        ("si", "SINT#-128", -128),
        ("si", "16#7F", 127),
        ("ui", "UINT#16#FFFF", 65535),
        ("ud", 4294967295, 4294967295),
        ("us", "255", 255),
        ("wc", "'ش'", "ش"),
        ("s", "'it''s'", "it's"),
        ("s", "12345678", "12345678"),
        ("ws", "سلام", "سلام"),
    ],
)
def test_typed_modify_values(
    program: Program, cpu: Cpu, name: str, typed: object, shown: object
) -> None:
    _write(program, cpu, name, typed)
    assert _read(program, cpu, name) == shown


@pytest.mark.parametrize(
    ("name", "value", "reason"),
    [
        ("ui", "70000", "70000 does not fit type UINT: 0 to 65535"),
        ("ui", -1, "does not fit type UINT"),
        ("si", 128, "does not fit type SINT: -128 to 127"),
        ("us", "abc", "'abc' is not a value of type USINT (e.g. 200)"),
        ("ud", 2.5, "2.5 is not a whole number"),
        ("u", -1, "does not fit type ULINT: 0 to 18446744073709551615"),
        ("big", "9223372036854775808", "does not fit type LINT"),
        ("big", True, "True is not a value of type LINT"),
        ("lt", "LT#1X", "is not a value of type LTIME (e.g. LT#1D2H3M4S5MS6US7NS)"),
        ("x", "1e999", "does not fit type LREAL"),
        ("x", "one", "is not a value of type LREAL"),
        ("x", None, "a value of type LREAL is needed"),
        ("wc", "AB", "is not a value of type WCHAR"),
        (
            "s",
            "123456789",
            "does not fit type STRING[8]: at most 8 character(s) are allowed",
        ),
        ("s", "ش", "does not fit type STRING[8]: one character of code 0 to 255"),
    ],
)
def test_values_that_do_not_fit_are_refused_and_leave_the_cpu_alone(
    program: Program, cpu: Cpu, name: str, value: object, reason: str
) -> None:
    before = _read(program, cpu, name)
    with pytest.raises(targets.TargetError) as caught:
        _write(program, cpu, name, value)
    assert caught.value.code == "MON606"
    assert reason in str(caught.value)
    assert _read(program, cpu, name) == before


def test_a_string_keeps_its_declared_maximum() -> None:
    source = """
DATA_BLOCK "D"
VERSION : 0.1
   VAR
      s : STRING[4];
   END_VAR
BEGIN
END_DATA_BLOCK
"""
    result = compile_sources([SourceFile("d.db", source)], profile="S7-1500")
    assert result.ok
    cpu = Cpu(result.program, profile=Profile("S7-1500"))
    cpu.start()
    target = targets.resolve('"D".s', result.program)
    targets.write(target, cpu, "ab")
    data = cpu.db_bytes(1)
    assert data is not None
    assert data[:4] == bytes([4, 2]) + b"ab"


@pytest.mark.parametrize(
    ("type_name", "pattern", "value"),
    [
        ("LINT", 2**64 - 1, -1),
        ("LINT", 2**63, "-9223372036854775808"),
        ("ULINT", 2**64 - 1, "18446744073709551615"),
        ("LWORD", 2**53, "9007199254740992"),
        ("LWORD", 2**53 - 1, 2**53 - 1),
        ("LTIME", 1_000_000, 1_000_000),
        ("LREAL", 0x3FF8_0000_0000_0000, 1.5),
        ("LREAL", 0x7FF0_0000_0000_0000, "+Inf"),
        ("WCHAR", 0x0634, "ش"),
    ],
)
def test_decode_keeps_64_bit_values_exact_for_a_browser(
    type_name: str, pattern: int, value: object
) -> None:
    assert decode(type_name, pattern) == value


def test_decode_lreal_nan() -> None:
    assert decode("LREAL", 0x7FF8_0000_0000_0000) == "NaN"
    assert decode("LREAL", 0xFFF0_0000_0000_0000) == "-Inf"


FB_PROGRAM = """
FUNCTION_BLOCK "Acc"
   VAR_INPUT
      step : LREAL;
   END_VAR
   VAR
      total : LREAL;
      count : LINT;
   END_VAR
BEGIN
  #total := #total + #step;
  #count := #count + 1;
END_FUNCTION_BLOCK

DATA_BLOCK "AccDb" "Acc"
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
BEGIN
  "AccDb"(step := 0.5);
END_ORGANIZATION_BLOCK
"""


def test_block_locals_of_64_bits_are_slots_of_the_monitor() -> None:
    result = compile_sources([SourceFile("acc.scl", FB_PROGRAM)], profile="S7-1500")
    assert result.ok, [d.message for d in result.diagnostics]
    fb = next(b for b in result.program.blocks.values() if b.kind.value == "FB")
    info = block_info(fb)
    slots = {slot.name: (slot.type, slot.bits) for slot in info.slots}
    assert slots["total"] == ("LREAL", 64)
    assert slots["count"] == ("LINT", 64)


def test_either_half_of_an_8_byte_local_names_the_whole_variable() -> None:
    # an SCL line moves an LREAL as two doublewords: its line value is the whole LREAL
    result = compile_sources([SourceFile("acc.scl", FB_PROGRAM)], profile="S7-1500")
    fb = next(b for b in result.program.blocks.values() if b.kind.value == "FB")
    info = block_info(fb)
    total = info.by_name["total"]
    for offset in (0, 4):
        half = Direct(Area.DI, Width.DWORD, total.bit_offset // 8 + offset)
        assert info.slot_at(half) is total
    assert info.slot_at(Direct(Area.DI, Width.WORD, total.bit_offset // 8)) is None
    instance = bytearray(64)
    instance[total.bit_offset // 8 : total.bit_offset // 8 + 8] = struct.pack(">d", 2.5)
    assert read_slot(total, bytearray(), instance, 0, []) == 2.5


@pytest.fixture(scope="module")
def live() -> Iterator[LiveServer]:
    with running_server() as server:
        yield server


def test_watch_and_modify_through_the_monitor_socket(live: LiveServer) -> None:
    # the first S7-1500 download of a fresh server loads the SCL compiler and its 64-bit
    # library: allowed more than the helper's 5 s on a busy machine
    created = live.http.post(
        "/api/sessions",
        json={"sources": [source("prog.scl", PROGRAM)], "profile": "S7-1500"},
        timeout=60,
    )
    assert created.status_code == 201, created.text
    session = created.json()["id"]
    try:
        with live.monitor(session) as client:
            client.ok("watch", entries=['"Data".y', '"Data".sum', '"Data".lt'])
            client.ok("run")
            client.until_value('"Data".y', 3.0)
            client.until_value('"Data".lt', 1_000_000_000)
            client.ok("modify", target='"Data".big', value="LINT#9000000000000000000")
            client.ok("modify", target='"Data".x', value=0.25)
            client.until_value('"Data".sum', "9000000000000000001")
            client.until_value('"Data".y', 0.5)
    finally:
        live.delete(session)

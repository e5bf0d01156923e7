"""The IEC library FCs (CONCAT FC 2, I_STRNG FC 16, AD_DT_TM FC 1 ...) called from STL programs on
the CPU: the compiler adds the library block, the CPU runs its Python body through the ordinary
FC call. Each case checks RET_VAL and BR (the FC's ENO) against System Software for S7-300/400,
System and Standard Functions, "IEC Functions" (choices where the manual is silent are marked in
``nasaq.cpu.iec_library``)."""

from __future__ import annotations

import struct

import pytest

from nasaq.cpu import Cpu, iec_library
from nasaq.headless.addresses import parse_address
from nasaq.ir import BlockKind, Direct
from nasaq.lang.iec_library import BY_NUMBER, FUNCTIONS
from nasaq.lang.stl import SourceFile, compile_sources

# What RET_VAL holds before the call: a function that converts nothing leaves it so.
_BEFORE = {"STRING": "'old'", "INT": "7777", "DINT": "L#7777", "REAL": "7.0", "BOOL": "FALSE"}


def run(source: str) -> Cpu:
    result = compile_sources([SourceFile("lib.awl", source)])
    errors = [f"{d.code} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def read(cpu: Cpu, text: str) -> int:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return cpu.read(address)


def call(name: str, args: str, result: str, room: int = 254) -> tuple[object, int]:
    """``CALL "name" (args, RET_VAL := DB1.r)``: (RET_VAL, BR). ``result``: STRING, INT, DINT,
    REAL, BOOL or the name of an 8-byte/4-byte type read as bytes (DT) or a number."""
    declared = f"STRING[{room}]" if result == "STRING" else result
    before = _BEFORE.get(result)
    init = f" := {before}" if before is not None and (result != "STRING" or room >= 3) else ""
    source = f"""DATA_BLOCK DB 1
STRUCT
  r : {declared}{init};
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
      CALL "{name}" ({args}, RET_VAL := DB1.r);
      A     BR;
      =     M 0.0;
END_ORGANIZATION_BLOCK
"""
    cpu = run(source)
    data = cpu.db_bytes(1)
    assert data is not None
    br = read(cpu, "M0.0")
    if result == "STRING":
        assert data[0] == room  # the maximum length is never written
        return data[2 : 2 + data[1]].decode("latin-1"), br
    if result == "INT":
        return int.from_bytes(data[0:2], "big", signed=True), br
    if result in ("DINT", "TIME"):
        return int.from_bytes(data[0:4], "big", signed=True), br
    if result == "REAL":
        return struct.unpack(">f", data[0:4])[0], br
    if result == "BOOL":
        return data[0] & 1, br
    if result in ("DATE",):
        return int.from_bytes(data[0:2], "big"), br
    if result in ("TIME_OF_DAY",):
        return int.from_bytes(data[0:4], "big"), br
    return bytes(data[0:8]).hex().upper(), br  # DATE_AND_TIME


# -- the library ----------------------------------------------------------------------------------


def test_every_library_function_has_a_body_and_its_siemens_number() -> None:
    assert set(iec_library.BODIES) | set(iec_library.REACHING) == set(FUNCTIONS)  # (ATH ...)
    numbers = {function.name: number for number, function in BY_NUMBER.items()}
    some = {name: numbers[name] for name in ("CONCAT", "I_STRNG", "RIGHT", "AD_DT_TM", "SB_DT_DT")}
    assert some == {"CONCAT": 2, "I_STRNG": 16, "RIGHT": 32, "AD_DT_TM": 1, "SB_DT_DT": 34}
    assert len(BY_NUMBER) == len(FUNCTIONS)
    # the 34 of the Standard Library and ATH, HTA (FC 94/95, its TI-S7 Converting Blocks);
    # FC 620-659 TIA's number/STRING and TIME conversions (``lang.number_text``); FC 660-676
    # the WSTRING versions of the STRING ones and the two conversions; from FC 700 on the
    # S7-1500 types' (``lang.long_library``)
    assert len([number for number in BY_NUMBER if number < 620]) == 36
    tia = {BY_NUMBER[number].name for number in BY_NUMBER if 620 <= number < 660}
    assert {"INT_TO_STRING", "STRING_TO_REAL", "UDINT_TO_TIME"} <= tia
    wide = {BY_NUMBER[number].name for number in range(660, 677)}
    assert {"LEN_WSTRING", "CONCAT_WSTRING", "EQ_WSTRING", "NE_WSTRING"} <= wide


def test_called_by_name_or_number_the_block_is_added_with_its_symbol() -> None:
    source = """DATA_BLOCK DB 1
STRUCT
  s : STRING[3];
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
      CALL "LEN" (S := 'abc', RET_VAL := MW 0);
      CALL "CONCAT" (IN1 := 'ab', IN2 := 'cd', RET_VAL := DB1.s);
      CALL FC 21 (S := DB1.s, RET_VAL := MW 2);
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("lib.awl", source)])
    assert not result.diagnostics
    program = result.program
    assert program.symbols["LEN"] == "FC 21"
    assert program.symbols["CONCAT"] == "FC 2"
    block = program.blocks[(BlockKind.FC, 2)]
    assert (block.name, block.attributes["FAMILY"], block.code) == ("CONCAT", "IEC", [])
    assert [(v.name, v.section, v.type) for v in block.interface] == [
        ("IN1", "IN", "STRING[254]"),
        ("IN2", "IN", "STRING[254]"),
        ("RET_VAL", "RETURN", "STRING[254]"),
    ]
    cpu = run(source)
    assert read(cpu, "MW0") == 3
    assert read(cpu, "MW2") == 3  # 'abc': cut to the 3 characters of DB1.s


def test_a_library_number_the_program_uses_moves_the_library_block() -> None:
    source = """FUNCTION FC 2 : INT
BEGIN
      L     5;
      T     #RET_VAL;
END_FUNCTION

DATA_BLOCK DB 1
STRUCT
  s : STRING[8];
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
      CALL FC 2 (RET_VAL := MW 0);
      CALL "CONCAT" (IN1 := 'ab', IN2 := 'cd', RET_VAL := DB1.s);
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("lib.awl", source)])
    assert not result.diagnostics
    assert result.program.symbols["CONCAT"] == "FC 1000"
    assert result.program.blocks[(BlockKind.FC, 1000)].name == "CONCAT"
    cpu = run(source)
    assert read(cpu, "MW0") == 5
    assert cpu.db_bytes(1)[:6] == b"\x08\x04abcd"  # type: ignore[index]


def test_the_symbol_table_numbers_the_library_block() -> None:
    source = """ORGANIZATION_BLOCK OB 1
BEGIN
      CALL "LEN" (S := 'abcd', RET_VAL := MW 0);
END_ORGANIZATION_BLOCK
"""
    symbols = SourceFile("symbols.csv", "name,address\nLEN,FC 121\n")
    result = compile_sources([SourceFile("lib.awl", source), symbols])
    assert not result.diagnostics
    assert result.program.blocks[(BlockKind.FC, 121)].name == "LEN"
    assert (BlockKind.FC, 21) not in result.program.blocks


def test_a_call_is_checked_against_the_library_interface() -> None:
    call_left = "  CALL \"LEFT\" (IN := 'abc', RET_VAL := MW 0)"
    source = f"ORGANIZATION_BLOCK OB 1\nBEGIN\n{call_left}\nEND_ORGANIZATION_BLOCK\n"
    result = compile_sources([SourceFile("lib.awl", source)])
    assert sorted(d.code for d in result.diagnostics) == ["STL210", "STL211"]


# -- STRING functions -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "args", "room", "expected"),
    [
        ("CONCAT", "IN1 := 'Motor', IN2 := '12'", 254, ("Motor12", 1)),
        ("CONCAT", "IN1 := '', IN2 := ''", 254, ("", 1)),
        ("CONCAT", "IN1 := 'abc', IN2 := 'def'", 6, ("abcdef", 1)),  # exactly the room
        ("CONCAT", "IN1 := 'abc', IN2 := 'def'", 4, ("abcd", 0)),  # too long: cut, BR 0
        ("LEFT", "IN := 'abcdef', L := 2", 254, ("ab", 1)),
        ("LEFT", "IN := 'abc', L := 9", 254, ("abc", 1)),  # L beyond the length: all of it
        ("LEFT", "IN := 'abc', L := 0", 254, ("", 1)),
        ("LEFT", "IN := 'abc', L := -1", 254, ("", 0)),
        ("LEFT", "IN := 'abcdef', L := 5", 3, ("abc", 0)),
        ("RIGHT", "IN := '+12', L := 2", 254, ("12", 1)),
        ("RIGHT", "IN := 'abc', L := 7", 254, ("abc", 1)),
        ("RIGHT", "IN := 'abc', L := 0", 254, ("", 1)),
        ("RIGHT", "IN := 'abc', L := -2", 254, ("", 0)),
        ("MID", "IN := 'abcdef', L := 2, P := 3", 254, ("cd", 1)),
        ("MID", "IN := 'abcdef', L := 9, P := 5", 254, ("ef", 1)),  # to the end
        ("MID", "IN := 'abcdef', L := 1, P := 6", 254, ("f", 1)),
        ("MID", "IN := 'abcdef', L := 1, P := 7", 254, ("", 0)),  # P past the end
        ("MID", "IN := 'abcdef', L := 0, P := 2", 254, ("", 0)),
        ("MID", "IN := 'abcdef', L := 2, P := 0", 254, ("", 0)),
        ("MID", "IN := 'abcdef', L := -1, P := 2", 254, ("", 0)),
        ("MID", "IN := '', L := 1, P := 1", 254, ("", 0)),
        ("INSERT", "IN1 := 'abef', IN2 := 'cd', P := 2", 254, ("abcdef", 1)),
        ("INSERT", "IN1 := 'abc', IN2 := 'x', P := 0", 254, ("xabc", 1)),  # before
        ("INSERT", "IN1 := 'abc', IN2 := 'x', P := 9", 254, ("abcx", 1)),  # appended
        ("INSERT", "IN1 := 'abc', IN2 := 'x', P := -1", 254, ("", 0)),
        ("INSERT", "IN1 := 'abc', IN2 := 'xyz', P := 1", 4, ("axyz", 0)),
        ("DELETE", "IN := 'abcdef', L := 2, P := 3", 254, ("abef", 1)),
        ("DELETE", "IN := 'abcdef', L := 9, P := 4", 254, ("abc", 1)),  # to the end
        ("DELETE", "IN := 'abcdef', L := 0, P := 3", 254, ("abcdef", 1)),
        ("DELETE", "IN := 'abcdef', L := 2, P := 0", 254, ("abcdef", 1)),
        ("DELETE", "IN := 'abcdef', L := 2, P := 7", 254, ("abcdef", 1)),  # P past the end
        ("DELETE", "IN := 'abcdef', L := -1, P := 2", 254, ("", 0)),
        ("DELETE", "IN := 'abcdef', L := 1, P := -2", 254, ("", 0)),
        ("REPLACE", "IN1 := 'abcdef', IN2 := 'XY', L := 3, P := 2", 254, ("aXYef", 1)),
        ("REPLACE", "IN1 := 'abcdef', IN2 := 'XY', L := 1, P := 0", 254, ("XYbcdef", 1)),
        ("REPLACE", "IN1 := 'abcdef', IN2 := 'XY', L := 1, P := 1", 254, ("XYbcdef", 1)),
        ("REPLACE", "IN1 := 'abc', IN2 := 'XY', L := 2, P := 9", 254, ("abcXY", 1)),
        ("REPLACE", "IN1 := 'abc', IN2 := 'XY', L := 0, P := 2", 254, ("abc", 1)),
        ("REPLACE", "IN1 := 'abc', IN2 := 'XY', L := 9, P := 2", 254, ("aXY", 1)),
        ("REPLACE", "IN1 := 'abc', IN2 := 'XY', L := -1, P := 2", 254, ("", 0)),
        ("REPLACE", "IN1 := 'abc', IN2 := 'XY', L := 1, P := -1", 254, ("", 0)),
        ("REPLACE", "IN1 := 'abc', IN2 := 'WXYZ', L := 1, P := 2", 5, ("aWXYZ", 0)),
    ],
)
def test_string_functions(name: str, args: str, room: int, expected: tuple[str, int]) -> None:
    assert call(name, args, "STRING", room) == expected


def test_a_string_of_254_characters_fits_a_string_254() -> None:
    text = "x" * 250
    assert call("CONCAT", f"IN1 := '{text}', IN2 := 'abcd'", "STRING") == (text + "abcd", 1)
    assert call("CONCAT", f"IN1 := '{text}', IN2 := 'abcde'", "STRING") == (text + "abcd", 0)


@pytest.mark.parametrize(
    ("name", "args", "expected"),
    [
        ("LEN", "S := 'abc'", 3),
        ("LEN", "S := ''", 0),
        ("FIND", "IN1 := 'abcabc', IN2 := 'ca'", 3),
        ("FIND", "IN1 := 'abcabc', IN2 := 'bc'", 2),  # the first one
        ("FIND", "IN1 := 'abc', IN2 := 'x'", 0),
        ("FIND", "IN1 := 'abc', IN2 := 'abcd'", 0),
        ("FIND", "IN1 := 'abc', IN2 := ''", 0),
        ("FIND", "IN1 := 'abc', IN2 := 'ABC'", 0),  # case-sensitive
    ],
)
def test_length_and_search(name: str, args: str, expected: int) -> None:
    assert call(name, args, "INT") == (expected, 1)


@pytest.mark.parametrize(
    ("left", "right", "less"),
    [
        ("'abc'", "'abd'", True),
        ("'ab'", "'abc'", True),  # a prefix is smaller
        ("''", "'a'", True),
        ("'B'", "'a'", True),  # by character code: 'B' 16#42 < 'a' 16#61
        ("'abc'", "'abc'", False),
        ("'b'", "'abc'", False),
    ],
)
def test_string_comparisons(left: str, right: str, less: bool) -> None:
    equal = left == right
    expected = {
        "EQ_STRNG": equal,
        "NE_STRNG": not equal,
        "LT_STRNG": less,
        "LE_STRNG": less or equal,
        "GT_STRNG": not less and not equal,
        "GE_STRNG": not less,
    }
    for name, value in expected.items():
        assert call(name, f"S1 := {left}, S2 := {right}", "BOOL") == (int(value), 1), name


# -- conversions ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "args", "room", "expected"),
    [
        ("I_STRNG", "I := 205", 254, ("+205", 1)),
        ("I_STRNG", "I := -32768", 254, ("-32768", 1)),
        ("I_STRNG", "I := 0", 254, ("+0", 1)),
        ("I_STRNG", "I := 12", 3, ("+12", 1)),
        ("I_STRNG", "I := 123", 3, ("old", 0)),  # RET_VAL too short: no conversion
        ("DI_STRNG", "I := L#-2147483648", 254, ("-2147483648", 1)),
        ("DI_STRNG", "I := L#70000", 254, ("+70000", 1)),
        ("R_STRNG", "IN := 123.4567", 254, ("+1.2345670E+02", 1)),
        ("R_STRNG", "IN := -0.001", 254, ("-1.0000000E-03", 1)),
        ("R_STRNG", "IN := 0.0", 254, ("+0.0000000E+00", 1)),
        ("R_STRNG", "IN := 1.0", 13, ("old", 0)),
    ],
)
def test_numbers_to_strings(name: str, args: str, room: int, expected: tuple[str, int]) -> None:
    assert call(name, args, "STRING", room) == expected


def test_r_strng_of_nan_converts_nothing() -> None:
    source = """DATA_BLOCK DB 1
STRUCT
  r : STRING[20] := 'old';
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
      L     DW#16#7FC00000;
      T     MD 20;
      CALL "R_STRNG" (IN := MD 20, RET_VAL := DB1.r);
      A     BR;
      =     M 0.0;
END_ORGANIZATION_BLOCK
"""
    cpu = run(source)
    assert cpu.db_bytes(1)[:5] == b"\x14\x03old"  # type: ignore[index]
    assert read(cpu, "M0.0") == 0


@pytest.mark.parametrize(
    ("name", "text", "result", "expected"),
    [
        ("STRNG_I", "'-123'", "INT", (-123, 1)),
        ("STRNG_I", "'+45'", "INT", (45, 1)),
        ("STRNG_I", "'007'", "INT", (7, 1)),
        ("STRNG_I", "'99999'", "INT", (32767, 0)),  # limited
        ("STRNG_I", "'-40000'", "INT", (-32768, 0)),
        ("STRNG_I", "''", "INT", (7777, 0)),  # empty: no conversion
        ("STRNG_I", "'1234567'", "INT", (7777, 0)),  # longer than 6
        ("STRNG_I", "'12a'", "INT", (7777, 0)),
        ("STRNG_I", "'+'", "INT", (7777, 0)),
        ("STRNG_I", "' 12'", "INT", (7777, 0)),
        ("STRNG_DI", "'-2147483648'", "DINT", (-(2**31), 1)),
        ("STRNG_DI", "'9999999999'", "DINT", (2**31 - 1, 0)),
        ("STRNG_DI", "'123456789012'", "DINT", (7777, 0)),  # longer than 11
        ("STRNG_R", "'+1.2345670E+02'", "REAL", (pytest.approx(123.4567), 1)),
        ("STRNG_R", "'-5.0000000E-01'", "REAL", (-0.5, 1)),
        ("STRNG_R", "'+1.0000000E+02xyz'", "REAL", (100.0, 1)),  # the first 14 characters
        ("STRNG_R", "'+9.9999999E+99'", "REAL", (pytest.approx(3.4028235e38), 0)),  # limited
        ("STRNG_R", "'-1.0000000E-45'", "REAL", (pytest.approx(-1.1754944e-38), 0)),
        ("STRNG_R", "'1.0000000E+02'", "REAL", (7.0, 0)),  # no sign: not the form
        ("STRNG_R", "'+1.00E+02'", "REAL", (7.0, 0)),  # shorter than 14
    ],
)
def test_strings_to_numbers(
    name: str, text: str, result: str, expected: tuple[object, int]
) -> None:
    assert call(name, f"S := {text}", result) == expected


# -- DATE_AND_TIME --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "args", "result", "expected"),
    [
        # 1995-01-01 is a Sunday (weekday 1), 1995-01-02 a Monday (2)
        ("AD_DT_TM", "T := DT#1995-01-01-00:00:00, D := T#1D", "DT", ("9501020000000002", 1)),
        ("AD_DT_TM", "T := DT#1999-12-31-23:59:59.999, D := T#1MS", "DT", ("0001010000000007", 1)),
        ("AD_DT_TM", "T := DT#2024-02-28-12:00:00, D := T#1D", "DT", ("2402291200000005", 1)),
        ("AD_DT_TM", "T := DT#2089-12-31-23:00:00, D := T#2H", "DT", ("8912312359599997", 0)),
        ("SB_DT_TM", "T := DT#1990-01-01-00:00:01, D := T#2S", "DT", ("9001010000000002", 0)),
        ("SB_DT_TM", "T := DT#2000-03-01-00:00:00, D := T#1MS", "DT", ("0002292359599993", 1)),
        (
            "SB_DT_DT",
            "T1 := DT#1995-01-02-06:30:00, T2 := DT#1995-01-01-00:00:00",
            "TIME",
            (109_800_000, 1),
        ),
        (
            "SB_DT_DT",
            "T1 := DT#1995-01-01-00:00:00, T2 := DT#1995-01-02-06:30:00",
            "TIME",
            (-109_800_000, 1),
        ),
        (
            "SB_DT_DT",
            "T1 := DT#2089-01-01-00:00:00, T2 := DT#1990-01-01-00:00:00",
            "TIME",
            (2**31 - 1, 0),
        ),
        ("D_TOD_DT", "IN1 := D#2006-12-11, IN2 := TOD#20:00:00.123", "DT", ("0612112000001232", 1)),
        ("DT_DATE", "IN := DT#2006-12-11-20:00:00", "DATE", (6188, 1)),
        ("DT_DAY", "IN := DT#2006-12-11-20:00:00", "INT", (2, 1)),  # a Monday
        ("DT_TOD", "IN := DT#2006-12-11-20:00:00.5", "TIME_OF_DAY", (72_000_500, 1)),
    ],
)
def test_date_and_time_functions(name: str, args: str, result: str, expected: object) -> None:
    assert call(name, args, "DATE_AND_TIME" if result == "DT" else result) == expected


@pytest.mark.parametrize(
    ("left", "right", "order"),
    [
        ("DT#1999-12-31-23:59:59.999", "DT#2000-01-01-00:00:00", -1),  # 99 is before 00
        ("DT#2020-05-05-10:00:00.001", "DT#2020-05-05-10:00:00", 1),
        ("DT#2020-05-05-10:00:00", "DT#2020-05-05-10:00:00", 0),
    ],
)
def test_date_and_time_comparisons(left: str, right: str, order: int) -> None:
    expected = {
        "EQ_DT": order == 0,
        "NE_DT": order != 0,
        "LT_DT": order < 0,
        "LE_DT": order <= 0,
        "GT_DT": order > 0,
        "GE_DT": order >= 0,
    }
    for name, value in expected.items():
        assert call(name, f"DT1 := {left}, DT2 := {right}", "BOOL") == (int(value), 1), name


def test_dt_bytes_and_milliseconds_are_inverse() -> None:
    for ms in (0, 1, 86_399_999, 86_400_000, 10**12, iec_library._LAST):
        assert iec_library.dt_ms(iec_library.dt_bytes(ms)) == ms
    assert iec_library.dt_bytes(0).hex() == "9001010000000002"  # 1990-01-01 was a Monday


def test_a_string_outside_its_data_block_is_an_area_length_error() -> None:
    with pytest.raises(iec_library.CpuError) as found:
        iec_library.BODIES["LEN"]([(bytearray(b"\x05\x09abc"), 0, 0), (bytearray(2), 0, 0)])
    assert found.value.code == "SIM503"


def test_a_library_number_alone_does_not_add_the_library_block() -> None:
    source = "ORGANIZATION_BLOCK OB 1\nBEGIN\n  CALL FC 2\nEND_ORGANIZATION_BLOCK\n"
    result = compile_sources([SourceFile("lib.awl", source)])
    assert [d.code for d in result.diagnostics] == ["STL213"]  # FC 2 is missing, as in STEP 7
    symbols = SourceFile("symbols.csv", "name,address\nMixer,FC 2\n")
    result = compile_sources([SourceFile("lib.awl", source), symbols])
    assert [d.code for d in result.diagnostics] == ["STL213"]  # FC 2 "Mixer" is missing

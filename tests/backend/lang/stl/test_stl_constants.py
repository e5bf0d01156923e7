"""Every constant format with the exact pattern ACCU1 receives (STEP 7 rules; cross-checked
with the values awlsim's own self-tests assert)."""

from __future__ import annotations

import pytest

from nasaq.ir import ConstType
from nasaq.lang.stl.constants import ConstantError, date_and_time_bytes, parse_literal

CASES = [
    ("NUMBER", "5", ConstType.INT, 0x00000005),
    # A 16-bit INT constant fills ACCU1-L only: L -1 / T MD 0 gives 16#0000FFFF (use L#-1).
    ("NUMBER", "-1", ConstType.INT, 0x0000FFFF),
    ("NUMBER", "-32768", ConstType.INT, 0x00008000),
    ("TYPED", "L#-5", ConstType.DINT, 0xFFFFFFFB),
    ("TYPED", "L#100000", ConstType.DINT, 100000),
    ("TYPED", "B#16#FF", ConstType.BYTE, 0xFF),
    ("TYPED", "W#16#1234", ConstType.WORD, 0x1234),
    ("TYPED", "DW#16#88776655", ConstType.DWORD, 0x88776655),
    ("TYPED", "16#FFFF", ConstType.WORD, 0xFFFF),
    ("TYPED", "16#1_0000", ConstType.DWORD, 0x10000),
    ("TYPED", "2#1010_1010", ConstType.WORD, 0xAA),
    ("TYPED", "W#2#1111_0000_1111_0000", ConstType.WORD, 0xF0F0),
    ("BYTES", "B#(1, 2)", ConstType.BYTES, 0x0102),
    ("BYTES", "B#(1,2,3,4)", ConstType.BYTES, 0x01020304),
    ("POINTER", "P#M10.0", ConstType.POINTER, 0x83000050),
    ("POINTER", "P#DBX2.1", ConstType.POINTER, 0x84000011),
    ("POINTER", "P#10.0", ConstType.POINTER, 0x00000050),
    ("POINTER", "P#I 0.0", ConstType.POINTER, 0x81000000),
    ("POINTER", "P#E 1.0", ConstType.POINTER, 0x81000008),
    ("POINTER", "P#L 4.2", ConstType.POINTER, 0x86000022),
    ("TYPED", "C#123", ConstType.COUNTER, 0x0123),
    ("TYPED", "S5T#1H", ConstType.S5TIME, 0x3360),
    ("TYPED", "S5T#2M", ConstType.S5TIME, 0x2120),
    ("TYPED", "S5T#3S", ConstType.S5TIME, 0x0300),
    ("TYPED", "S5T#400MS", ConstType.S5TIME, 0x0040),
    ("TYPED", "S5TIME#9S990MS", ConstType.S5TIME, 0x0999),
    ("TYPED", "S5T#10S", ConstType.S5TIME, 0x1100),
    ("TYPED", "S5T#1H2M3S400MS", ConstType.S5TIME, 0x3372),
    ("TYPED", "S5T#2H46M30S", ConstType.S5TIME, 0x3999),
    ("TYPED", "T#1D2H3M4S5MS", ConstType.TIME, 93_784_005),
    ("TYPED", "TIME#1s100ms", ConstType.TIME, 1100),
    ("TYPED", "T#-1S100MS", ConstType.TIME, 0xFFFFFBB4),
    ("TYPED", "D#1990-1-1", ConstType.DATE, 0),
    ("TYPED", "DATE#2000-12-31", ConstType.DATE, 4017),
    ("TYPED", "D#2168-12-31", ConstType.DATE, 65378),
    ("TYPED", "TOD#13:37:13.37", ConstType.TOD, 49_033_370),
    ("TYPED", "TIME_OF_DAY#23:59:59.999", ConstType.TOD, 86_399_999),
    ("REAL", "1.5", ConstType.REAL, 0x3FC00000),
    ("REAL", "1.0e-3", ConstType.REAL, 0x3A83126F),
    ("REAL", "-2.5E+2", ConstType.REAL, 0xC37A0000),
    ("CHARS", "'A'", ConstType.CHAR, 0x41),
    ("CHARS", "'AB'", ConstType.CHAR, 0x4142),
    ("CHARS", "'ABCD'", ConstType.CHAR, 0x41424344),
    ("CHARS", "''", ConstType.CHAR, 0),
    # actual parameters only (no accumulator value): a STRING, the 8 BCD bytes of a DT
    ("CHARS", "'ABCDE'", ConstType.STRING, 0x4142434445),
    ("TYPED", "DT#1998-02-03-16:17:20.211", ConstType.DATE_AND_TIME, 0x9802031617202113),
    ("TYPED", "DATE_AND_TIME#1990-1-1-0:0:0", ConstType.DATE_AND_TIME, 0x9001010000000002),
]


@pytest.mark.parametrize(("kind", "text", "type_", "pattern"), CASES)
def test_pattern(kind: str, text: str, type_: ConstType, pattern: int) -> None:
    constant = parse_literal(kind, text)
    assert constant.type is type_
    assert constant.pattern == pattern
    assert constant.text == text


@pytest.mark.parametrize(
    ("kind", "text", "code"),
    [
        ("NUMBER", "40000", "STL214"),
        ("NUMBER", "-32769", "STL214"),
        ("TYPED", "B#16#100", "STL214"),
        ("TYPED", "W#16#XYZ", "STL107"),
        ("TYPED", "C#1000", "STL214"),
        ("TYPED", "S5T#2H46M40S", "STL214"),
        ("TYPED", "D#2169-1-1", "STL214"),
        ("TYPED", "TOD#24:00:00", "STL214"),
        ("TYPED", "Q#5", "STL107"),
        ("TYPED", "DT#1990-13-1-0:0:0", "STL107"),
        ("TYPED", "DT#2090-1-1-0:0:0", "STL214"),
        ("POINTER", "P#M10.8", "STL107"),
        ("BYTES", "B#(1, 2, 3)", "STL107"),
        ("BYTES", "B#(1, 256)", "STL214"),
        ("CHARS", "'" + "x" * 255 + "'", "STL214"),
        ("REAL", "1.0e39", "STL214"),
    ],
)
def test_bad_constants(kind: str, text: str, code: str) -> None:
    with pytest.raises(ConstantError) as raised:
        parse_literal(kind, text)
    assert raised.value.code == code


def test_int_hint_suggests_a_dint() -> None:
    with pytest.raises(ConstantError) as raised:
        parse_literal("NUMBER", "40000")
    assert "L#40000" in str(raised.value.params["hint"])


def test_date_and_time_is_eight_bcd_bytes_with_weekday() -> None:
    assert date_and_time_bytes("1991-2-3-4:5:6.789", "DT#").hex() == "9102030405067891"
    assert date_and_time_bytes("2010-11-12-13:14:15.16", "DT#").hex() == "1011121314151606"

"""DATE_AND_TIME values and date arithmetic compiled by the SCL lowering (``lower/dates.py``) and
run on the CPU: DT constants in BCD, copies, comparisons and arithmetic through the IEC library
(AD_DT_TM, SB_DT_TM, SB_DT_DT, EQ_DT ...), DATE - DATE."""

from __future__ import annotations

from scl_run import build, ob1, read

from nasaq.cpu import Cpu

DATES = """DATA_BLOCK Dates
STRUCT
  a : DATE_AND_TIME;
  b : DATE_AND_TIME;
  list : ARRAY[1..3] OF DATE_AND_TIME;
  span : TIME;
  day : INT;
  flags : ARRAY[0..7] OF BOOL;
END_STRUCT
BEGIN
END_DATA_BLOCK
"""
# Dates (DB1): a 0, b 8, list[k] 16 + 8 (k - 1), span 40, day 44, flags 46


def dt(cpu: Cpu, db: int, byte: int) -> str:
    data = cpu.db_bytes(db)
    assert data is not None
    return bytes(data[byte : byte + 8]).hex().upper()


def test_an_undeclared_initial_value_is_1990_01_01_a_monday() -> None:
    cpu = build(DATES + ob1(""))
    assert dt(cpu, 1, 0) == dt(cpu, 1, 24) == "9001010000000002"


def test_constants_are_written_in_bcd_with_the_weekday() -> None:
    source = DATES + ob1(
        "Dates.a := DATE_AND_TIME#1995-01-01-12:12:12.2;\n"  # a Sunday
        "Dates.b := DT#95-02-02-11:11:11;\n"  # two digits: 1995, a Thursday
        "k := 3;\n"
        "Dates.list[k] := DT#2005-02-02-08:30:01.999;",  # a Wednesday
        "k : INT;",
    )
    cpu = build(source)
    assert dt(cpu, 1, 0) == "9501011212122001"
    assert dt(cpu, 1, 8) == "9502021111110005"
    assert dt(cpu, 1, 32) == "0502020830019994"


def test_copies_and_comparisons() -> None:
    source = (
        DATES
        + """FUNCTION Later : BOOL
VAR_INPUT
  x : DATE_AND_TIME;
END_VAR
VAR_IN_OUT
  y : DATE_AND_TIME;
END_VAR
  Later := x > y;
  y := x;
END_FUNCTION
"""
        + ob1(
            "Dates.a := DT#2020-05-05-10:00:00.001;\n"
            "Dates.b := DT#2020-05-05-10:00:00;\n"
            "FOR k := 1 TO 3 DO Dates.list[k] := Dates.b; END_FOR;\n"
            "local := Dates.a;\n"
            "Dates.flags[0] := Dates.a > Dates.b;\n"
            "Dates.flags[1] := Dates.list[2] = Dates.b;\n"
            "Dates.flags[2] := Dates.a <= local AND Dates.a >= local;\n"
            "Dates.flags[3] := DT#1999-12-31-23:59:59.999 < DT#2000-01-01-00:00:00;\n"
            "Dates.flags[4] := Dates.a <> local;\n"
            "Dates.flags[5] := Later(x := local, y := Dates.list[1]);\n"
            "Dates.flags[6] := Dates.list[1] = Dates.a;",  # copied back through y
            "k : INT; local : DATE_AND_TIME;",
        )
    )
    cpu = build(source)
    assert read(cpu, "DB1.DBB46") & 0xFF == 0b01101111
    assert dt(cpu, 1, 24) == "2005051000000003"  # 2020-05-05 was a Tuesday (3)


def test_arithmetic_calls_the_library() -> None:
    source = DATES + ob1(
        "Dates.a := DT#2020-02-28-23:00:00;\n"
        "Dates.b := Dates.a + T#2h;\n"  # into a leap day, a Saturday
        "Dates.list[1] := Dates.b - T#1d;\n"
        "Dates.span := Dates.b - Dates.a;\n"
        "Dates.day := DT_DAY(IN := Dates.b);\n"
        "Dates.flags[0] := Dates.a + T#1h > Dates.b - T#1h;\n"  # 00:00 > 00:00: FALSE
        "Dates.flags[1] := Dates.b - Dates.a = T#2h;\n"
        "Dates.list[2] := D_TOD_DT(IN1 := DT_DATE(IN := Dates.b), IN2 := TOD#12:00:00);\n"
        "k := 3;\n"
        "Dates.list[k] := Dates.a + (Dates.b - Dates.a);"
        "",
        "k : INT;",
    )
    cpu = build(source)
    assert dt(cpu, 1, 8) == "2002290100000007"
    assert dt(cpu, 1, 16) == "2002280100000006"
    assert read(cpu, "DB1.DBD40") == 7_200_000
    assert read(cpu, "DB1.DBW44") == 7
    assert read(cpu, "DB1.DBB46") & 0b11 == 0b10
    assert dt(cpu, 1, 24) == "2002291200000007"
    assert dt(cpu, 1, 32) == dt(cpu, 1, 8)


def test_date_minus_date_is_a_time_in_milliseconds() -> None:
    source = ob1(
        "a := D#1996-01-10;\nb := D#1996-01-01;\nMD0 := DINT_TO_DWORD(TIME_TO_DINT(a - b));\n"
        "MD4 := DINT_TO_DWORD(TIME_TO_DINT(TOD#12:00:00 - TOD#11:30:00));",
        "a : DATE; b : DATE;",
    )
    cpu = build(source)
    assert read(cpu, "MD0") == 9 * 86_400_000
    assert read(cpu, "MD4") == 1_800_000


def test_structures_with_strings_and_dates_copy_every_member() -> None:
    source = """TYPE Entry
STRUCT
  at : DATE_AND_TIME;
  what : STRING[6];
  code : INT;
END_STRUCT
END_TYPE

DATA_BLOCK Log
STRUCT
  first : Entry;
  second : Entry;
END_STRUCT
BEGIN
END_DATA_BLOCK
""" + ob1(
        "Log.first.at := DT#2001-01-01-01:01:01;\n"
        "Log.first.what := 'start';\n"
        "Log.first.code := 7;\n"
        "Log.second := Log.first;"
    )
    cpu = build(source)
    data = cpu.db_bytes(1)
    assert data is not None
    assert data[18:36] == data[0:18]
    assert dt(cpu, 1, 18) == "0101010101010002"


def test_two_digit_years_in_initial_values_and_db_assignments() -> None:
    source = """DATA_BLOCK DB7
STRUCT
  a : DT := DT#95-01-01-12:12:12.2;
  b : DATE_AND_TIME;
END_STRUCT
BEGIN
  b := DT#05-3-4-5:06:07.8;
END_DATA_BLOCK
""" + ob1("")
    cpu = build(source)
    assert dt(cpu, 7, 0) == "9501011212122001"
    assert dt(cpu, 7, 8) == "0503040506078006"  # 2005-03-04, a Friday

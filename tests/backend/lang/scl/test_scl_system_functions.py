"""The built-in instructions TIA Portal code calls (issue 20): TIA's conversion family, MAX/MIN
with many inputs, LIMIT, SEL, MUX with ELSE, SCALE_X, NORM_X, MOVE_BLK, UMOVE_BLK, FILL_BLK,
EN/ENO on built-ins, and writes to an input parameter (a warning, and the code runs).

Their calls are checked like an FC's (unknown names, missing inputs, wrong types); what they
compute is checked on the CPU here and in ``tests/selfcheck/functions``."""

from __future__ import annotations

import pytest
from scl_run import build, ob1, read, real

from nasaq.lang.scl import check_sources, parse_source
from nasaq.lang.stl import SourceFile, compile_sources

HEAD = """FUNCTION FC1 : VOID
VAR_TEMP
  b : BOOL; k : INT; d : DINT; r : REAL; w : WORD; y : BYTE; t : TIME; c : CHAR;
  a : ARRAY[0..4] OF INT; ra : ARRAY[0..4] OF REAL; ok : BOOL;
  dt : DATE_AND_TIME; tod : TIME_OF_DAY;
END_VAR
BEGIN
"""
TAIL = "\nEND_FUNCTION\n"
L = 8  # the line of the body

CASES: list[tuple[str, list[tuple[str, int, int]]]] = [
    # the forms that are right
    ("k := BYTE_TO_INT(y) + BOOL_TO_INT(IN := b) + DWORD_TO_INT(16#1);", []),
    (
        "y := INT_TO_BYTE(IN := k, ENO => ok); c := DINT_TO_CHAR(d); d := CHAR_TO_DINT(c);",
        [],
    ),
    ("d := CEIL(r) + FLOOR(IN := r) + TRUNC(r) + ROUND(r);", []),
    ("k := MAX(IN1 := k, IN2 := 3, IN3 := 7, ENO => ok); r := MIN(r, 2.5, k);", []),
    ("k := MUX(K := k, IN0 := 1, IN1 := 2, ELSE := 3); k := MUX(k, 1, 2);", []),
    ("k := SCALE_X(MIN := 0, VALUE := r, MAX := 27648);", []),
    ("r := NORM_X(MIN := 0, VALUE := k, MAX := 27648, ENO => ok);", []),
    (
        "MOVE_BLK(IN := a[1], COUNT := 3, OUT => a[0]);"
        " FILL_BLK(IN := 0, COUNT := 5, OUT => a[0]);",
        [],
    ),
    # unknown parameter names, parameters twice, missing inputs
    ("k := BYTE_TO_INT(IN := y, X := 1);", [("SCL223", L, 29)]),
    ("k := LIMIT(MN := 0, IN := k);", [("SCL227", L, 8)]),
    ("k := SCALE_X(MIN := 0, VALUE := r, MAX := 1, MAX := 2);", [("SCL228", L, 48)]),
    ("MOVE_BLK(IN := a[1], OUT => a[0]);", [("SCL227", L, 3)]),
    ("k := MAX(IN1 := k);", [("SCL227", L, 8)]),
    ("k := SEL(b, 1, 2, 3);", [("SCL229", L, 12)]),
    # wrong types
    ("y := INT_TO_BYTE(r);", [("SCL213", L, 20)]),
    ("k := MAX(IN1 := k, IN2 := w);", [("SCL214", L, 29)]),
    ("k := MAX(IN1 := k, IN2 := r);", [("SCL213", L, 8)]),
    ("k := SEL(G := k, IN0 := 1, IN1 := 2);", [("SCL214", L, 17)]),
    ("r := SCALE_X(MIN := 0.0, VALUE := t, MAX := 1.0);", [("SCL214", L, 37)]),
    ("MOVE_BLK(IN := ra[0], COUNT := 2, OUT => a[0]);", [("SCL214", L, 18)]),
    ("FILL_BLK(IN := 2.5, COUNT := 2, OUT => a[0]);", [("SCL213", L, 18)]),
    # clocks and time functions
    ("k := RD_SYS_T(OUT => dt) + READ_CLK(CDT => dt); t := TIME_TCK();", []),
    ("t := T_ADD(IN1 := t, IN2 := T#1S); tod := T_SUB(IN1 := tod, IN2 := t);", []),
    (
        "t := T_DIFF(IN1 := dt, IN2 := dt); dt := T_COMBINE(IN1 := D#2024-01-01, IN2 := tod);",
        [],
    ),
    ("k := RD_SYS_T(OUT => k);", [("SCL214", L, 8)]),
    ("k := RD_LOC_T();", [("SCL227", L, 8)]),
    ("t := T_ADD(IN1 := t, IN2 := k);", [("SCL214", L, 31)]),
    ("tod := T_ADD(IN1 := t, IN2 := t);", [("SCL214", L, 10)]),
    ("t := TIME_TCK(IN := 1);", [("SCL223", L, 17)]),
    # TIA's conversions exist, so an assignment names them
    ("k := y;", [("SCL213", L, 8)]),
    ("k := b;", [("SCL213", L, 8)]),
]


def _check(body: str) -> list[tuple[str, int, int]]:
    parsed = parse_source("test.scl", HEAD + "  " + body + TAIL)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source])
    return [(d.code, d.span.line, d.span.column) for d in diagnostics if d.span]


@pytest.mark.parametrize(("body", "expected"), CASES)
def test_call_snapshot(body: str, expected: list[tuple[str, int, int]]) -> None:
    assert _check(body) == expected


def test_messages_name_the_instruction_and_the_parameter() -> None:
    parsed = parse_source("test.scl", HEAD + "  k := LIMIT(MN := 0, IN := k, X := 1);" + TAIL)
    _index, diagnostics = check_sources([parsed.source])
    assert [d.message for d in diagnostics] == ["LIMIT has no parameter X."]


def test_a_block_of_the_program_with_the_name_is_that_block() -> None:
    source = """FUNCTION SCALE_X : INT
VAR_INPUT v : INT; END_VAR
BEGIN
  SCALE_X := v + 1;
END_FUNCTION
ORGANIZATION_BLOCK OB1
BEGIN
  MW0 := INT_TO_WORD(SCALE_X(v := 4));
END_ORGANIZATION_BLOCK
"""
    assert read(build(source), "MW0") == 5


# ---- writes to an input parameter ---------------------------------------------------------

WRITES = """FUNCTION Twice : INT
VAR_INPUT a : INT; END_VAR
BEGIN
  a := a + 1;
  Twice := a * 2;
END_FUNCTION
FUNCTION_BLOCK Adder
VAR_INPUT x : INT; END_VAR
VAR_OUTPUT y : INT; END_VAR
BEGIN
  x := x + 10;
  y := x;
END_FUNCTION_BLOCK
DATA_BLOCK AdderData Adder
BEGIN
END_DATA_BLOCK
"""


def test_a_write_to_an_input_is_a_warning_at_the_name() -> None:
    result = compile_sources([SourceFile("prog.scl", WRITES)])
    found = [(d.code, d.severity, d.span.line, d.span.column) for d in result.diagnostics]
    assert found == [("SCL215", "warning", 4, 3), ("SCL215", "warning", 11, 3)]
    assert "STEP 7 accepts this with a warning" in result.diagnostics[0].message


def test_a_write_to_an_input_runs_as_on_an_s7_300() -> None:
    """In an FC the input is a pointer to the caller's actual, so the caller's variable
    changes; in an FB the instance changes until the next call passes the input again."""
    main = ob1(
        "v := 4;\nMW0 := INT_TO_WORD(Twice(a := v));\nMW2 := INT_TO_WORD(v);\n"
        "Adder.AdderData(x := 1);\nMW4 := INT_TO_WORD(AdderData.y);\n"
        "MW6 := INT_TO_WORD(AdderData.x);",
        "v : INT;",
    )
    cpu = build(WRITES + main)
    assert [read(cpu, f"MW{n}") for n in (0, 2, 4, 6)] == [10, 5, 11, 11]


def test_a_write_to_an_input_through_an_output_actual_is_a_warning_too() -> None:
    source = WRITES.replace("  x := x + 10;\n  y := x;", "  Twice(a := 1, ENO => OK);\n  y := x;")
    source = source.replace("VAR_INPUT x : INT; END_VAR", "VAR_INPUT x : INT; e : BOOL; END_VAR")
    source = source.replace("ENO => OK", "ENO => e")
    result = compile_sources([SourceFile("prog.scl", source)])
    assert [(d.code, d.severity) for d in result.diagnostics] == [
        ("SCL215", "warning"),
        ("SCL215", "warning"),
    ]


# ---- values on the CPU ----------------------------------------------------------------------


def test_scale_and_norm_on_the_cpu() -> None:
    cpu = build(
        ob1(
            "r := 0.75;\nMW0 := INT_TO_WORD(SCALE_X(MIN := -100, VALUE := r, MAX := 100));\n"
            "MD2 := REAL_TO_DWORD(NORM_X(MIN := 0, VALUE := 6912, MAX := 27648));\n"
            "MD6 := REAL_TO_DWORD(SCALE_X(MIN := 4.0, VALUE := 0.5, MAX := 20.0));",
            "r : REAL;",
        )
    )
    assert read(cpu, "MW0") == 50
    assert real(cpu, "MD2") == 0.25
    assert real(cpu, "MD6") == 12.0


def test_en_false_skips_a_builtin_and_gives_eno_false() -> None:
    cpu = build(
        ob1(
            "go := FALSE;\nM0.0 := TRUE;\n"
            "MW2 := INT_TO_WORD(MAX(EN := go, IN1 := 5, IN2 := 9, ENO => M0.0));\n"
            "go := TRUE;\nMW4 := INT_TO_WORD(MAX(EN := go, IN1 := 5, IN2 := 9, ENO => M0.1));",
            "go : BOOL;",
        )
    )
    assert (read(cpu, "MB0") & 3, read(cpu, "MW2"), read(cpu, "MW4")) == (2, 0, 9)


def test_dtl_needs_the_s7_1500_profile() -> None:
    source = "FUNCTION FC1 : VOID\nVAR_TEMP now : DTL; END_VAR\nBEGIN\nEND_FUNCTION\n"
    classic = compile_sources([SourceFile("prog.scl", source)])
    assert [(d.code, d.span.line, d.span.column) for d in classic.diagnostics] == [
        ("SCL500", 2, 16)
    ]
    assert "DTL needs the S7-1200/1500 profile" in classic.diagnostics[0].message
    assert compile_sources([SourceFile("prog.scl", source)], profile="S7-1500").diagnostics == []


def test_rd_sys_t_into_a_dtl_element_of_a_db_array() -> None:
    """A DTL chosen by a run-time index in a DB: every field from one read of the clock."""
    source = """DATA_BLOCK Log
STRUCT stamps : ARRAY[1..3] OF DTL; END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
VAR_TEMP i : INT; d : DATE_AND_TIME; r : INT; END_VAR
BEGIN
  i := 2;
  r := RD_SYS_T(OUT => Log.stamps[i]);
  r := READ_CLK(CDT => d);
  MW0 := INT_TO_WORD(UINT_TO_INT(Log.stamps[2].YEAR));
  MW2 := INT_TO_WORD(DT_DAY(d) - USINT_TO_INT(Log.stamps[2].WEEKDAY));
  MW4 := INT_TO_WORD(UINT_TO_INT(Log.stamps[1].YEAR));
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    assert [d.code for d in result.diagnostics] == []
    from nasaq.cpu import Cpu
    from nasaq.cpu.profile import Profile

    cpu = Cpu(result.program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert 2024 <= read(cpu, "MW0") <= 2089
    assert read(cpu, "MW2") == 0
    assert read(cpu, "MW4") == 1970  # DTL#1970-01-01 until written


WIDE = """FUNCTION FC1 : VOID
VAR_TEMP w : WSTRING[10]; c : WCHAR; END_VAR
BEGIN
  w := WSTRING#'abc';
  c := WCHAR#'a';
END_FUNCTION
"""


@pytest.mark.parametrize("profile", ["S7-300", "S7-400"])
def test_wstring_and_wchar_are_refused_with_a_code_under_a_classic_profile(profile: str) -> None:
    """Not in S7-300/400: never a syntax error or an unknown type, at each use (the S7-1500
    profile runs them, ``test_scl_wstring``)."""
    code = "SCL500"
    result = compile_sources([SourceFile("prog.scl", WIDE)], profile=profile)
    found = [(d.code, d.span.line, d.span.column) for d in result.diagnostics]
    assert found == [(code, 2, 14), (code, 2, 31), (code, 4, 8), (code, 5, 8)]
    assert all(d.severity == "error" for d in result.diagnostics)
    assert "WSTRING" in result.diagnostics[0].message


def test_generated_stl_compiles_back_to_the_same_behaviour() -> None:
    """``nasaq compile --emit stl``: the STL of the instructions (SFC 1, the IEC library, the
    in-line loops) compiles again and computes the same."""
    from nasaq.cpu import Cpu
    from nasaq.lang.stl.format import format_block

    source = """DATA_BLOCK Data
STRUCT src : ARRAY[0..3] OF INT := 1, 2, 3, 4; dst : ARRAY[0..3] OF INT; END_STRUCT
BEGIN
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
VAR_TEMP a : DATE_AND_TIME; b : DATE_AND_TIME; r : INT; ok : BOOL; END_VAR
BEGIN
  MOVE_BLK(IN := Data.src[1], COUNT := 5, OUT => Data.dst[0], ENO => M0.0);
  r := READ_CLK(CDT => a);
  b := T_ADD(IN1 := a, IN2 := T#1H);
  MD2 := DINT_TO_DWORD(TIME_TO_DINT(T_DIFF(IN1 := b, IN2 := a)));
  MW6 := INT_TO_WORD(SCALE_X(MIN := 0, VALUE := 0.5, MAX := MAX(IN1 := 10, IN2 := 20, IN3 := r)));
  MW8 := INT_TO_WORD(MUX(K := 3, IN0 := 1, IN1 := 2, ELSE := 9, ENO => ok));
  M0.1 := ok;
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("prog.scl", source)])
    assert not [d for d in result.diagnostics if d.severity == "error"]
    printed = "\n".join(format_block(block) for _file, block in result.generated)
    assert "CALL SFC 1" in printed
    assert 'CALL "AD_DT_TM"' in printed
    again = compile_sources([SourceFile("prog.awl", printed)])
    assert not [d for d in again.diagnostics if d.severity == "error"]
    found = []
    for program in (result.program, again.program):
        cpu = Cpu(program, cycle_ms=10)
        cpu.start()
        cpu.run(1)
        found.append(
            (
                read(cpu, "MB0") & 3,
                read(cpu, "MD2"),
                read(cpu, "MW6"),
                read(cpu, "MW8"),
                *tuple(read(cpu, f"DB1.DBW{2 * n + 8}") for n in range(4)),
            )
        )
    assert found[0] == found[1] == (0, 3_600_000, 10, 9, 2, 3, 4, 0)


def test_concat_takes_more_inputs_only_on_the_s7_1500_profile() -> None:
    source = """FUNCTION FC1 : VOID
VAR_TEMP s : STRING[20]; END_VAR
BEGIN
  s := CONCAT(IN1 := 'a', IN2 := 'b', IN3 := 'c');
END_FUNCTION
"""
    classic = compile_sources([SourceFile("prog.scl", source)])
    assert [(d.code, d.span.line, d.span.column) for d in classic.diagnostics] == [
        ("SCL223", 4, 39)
    ]
    assert compile_sources([SourceFile("prog.scl", source)], profile="S7-1500").diagnostics == []


def test_a_system_instruction_nasaq_does_not_simulate_is_named_as_such() -> None:
    source = """FUNCTION_BLOCK FB1
VAR t : REAL; d : DINT; END_VAR
BEGIN
  d := GET_ERR_ID(t);
  d := d + GET_ERR_ID(t);
  S_CONV(IN := 1.0, OUT => d);
END_FUNCTION_BLOCK
"""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    found = [(d.code, d.span.line, d.span.column) for d in result.diagnostics]
    assert found == [("SCL920", 4, 8), ("SCL920", 6, 3)]  # once per name
    message = result.diagnostics[0].message
    assert message.startswith("GET_ERR_ID is a ")
    assert "does not simulate" in message

"""Leftovers of the S7-1200/1500 types in SCL (issue 20): bit strings compared with constants
above 2**31, the standard functions of LREAL/LINT (through ``nasaq.lang.long_functions``),
CASE selectors of the 32-bit integers, and TIME mixed with DINT as TIA Portal allows on
S7-1200/1500 (and S7-SCL Classic does not)."""

from __future__ import annotations

import math
import struct

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.iec_library import BODIES
from nasaq.cpu.profile import Profile
from nasaq.lang.iec_library import FUNCTIONS
from nasaq.lang.long_functions import BASE, signatures
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block


def _errors(text: str, profile: str) -> list[tuple[str, int, str]]:
    result = compile_sources([SourceFile("t.scl", text)], profile=profile)
    return [
        (d.code, d.span.line if d.span else 0, d.message)
        for d in result.diagnostics
        if d.severity == "error"
    ]


def _stl(text: str, profile: str) -> str:
    result = compile_sources([SourceFile("t.scl", text)], profile=profile)
    assert not [d for d in result.diagnostics if d.severity == "error"]
    return "\n".join(format_block(block) for _file, block in result.generated)


def _run(text: str, profile: str = "S7-1500") -> Cpu:
    result = compile_sources([SourceFile("prog.scl", text)], profile=profile)
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def _db(cpu: Cpu, start: int, size: int) -> bytes:
    data = cpu.db_bytes(1)
    assert data is not None
    return bytes(data[start : start + size])


def _program(declarations: str, body: str, temps: str = "") -> str:
    temp = f"VAR_TEMP\n{temps}\nEND_VAR\n" if temps else ""
    return (
        f"DATA_BLOCK DB1\nSTRUCT\n{declarations}\nEND_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
        f"ORGANIZATION_BLOCK OB1\n{temp}BEGIN\n{body}\nEND_ORGANIZATION_BLOCK\n"
    )


# ---- 1. DWORD compared with a bit-string constant above 2**31 -----------------------------------

_BIG_BITS = """FUNCTION F1 : BOOL
VAR_INPUT
  dw : DWORD;
END_VAR
BEGIN
  IF dw = 16#FFFF_FFFF THEN F1 := TRUE; END_IF;
  F1 := F1 AND dw <> DW#16#8000_0000 AND 4294967295 = dw;
END_FUNCTION
"""


@pytest.mark.parametrize("profile", ["S7-300", "S7-1500"])
def test_a_dword_compares_with_a_constant_above_2_31_as_its_bits(profile: str) -> None:
    text = _stl(_BIG_BITS, profile)
    assert "DW#16#FFFFFFFF" in text
    assert "DW#16#80000000" in text
    assert "L#4294967295" not in text
    cpu = _run(
        _BIG_BITS
        + _program(
            "a : BOOL; b : BOOL; c : BOOL;",
            "DB1.a := F1(dw := 16#FFFF_FFFF);\nDB1.b := F1(dw := 16#7FFF_FFFF);\n"
            "DB1.c := (16#FFFF_0000 AND 16#8000_0000) = 16#8000_0000;",
        ),
        profile,
    )
    assert _db(cpu, 0, 1)[0] & 0b111 == 0b101


# ---- 2. the standard functions of LREAL and LINT ------------------------------------------------

_LREAL_CALLS = {
    "SQRT(x)": math.sqrt(2.0),
    "SQR(x)": 4.0,
    "EXP(x)": math.exp(2.0),
    "LN(x)": math.log(2.0),
    "LOG(x)": math.log10(2.0),
    "SIN(x)": math.sin(2.0),
    "COS(x)": math.cos(2.0),
    "TAN(x)": math.tan(2.0),
    "ASIN(x / 4.0)": math.asin(0.5),
    "ACOS(x / 4.0)": math.acos(0.5),
    "ATAN(x)": math.atan(2.0),
    "ABS(-x)": 2.0,
    "x ** LREAL#0.5": math.sqrt(2.0),
    "MAX(x, LREAL#1.0e300, -x)": 1.0e300,
    "MIN(IN1 := x, IN2 := -x)": -2.0,
    "LIMIT(MN := LREAL#0.0, IN := x * 10.0, MX := LREAL#3.0)": 3.0,
    "SEL(G := x > 1.0, IN0 := LREAL#0.0, IN1 := x)": 2.0,
}


@pytest.mark.parametrize(("call", "expected"), list(_LREAL_CALLS.items()))
def test_lreal_functions_compute_in_double_precision(call: str, expected: float) -> None:
    cpu = _run(_program("r : LREAL;", f"x := LREAL#2.0;\nDB1.r := {call};", "x : LREAL;"))
    (value,) = struct.unpack(">d", _db(cpu, 0, 8))
    assert value == pytest.approx(expected, rel=1e-15)


def test_the_functions_call_their_library_fc_and_give_an_lreal() -> None:
    text = _stl(
        "FUNCTION F1 : LREAL\nVAR_INPUT\n  x : LREAL;\nEND_VAR\nBEGIN\n"
        "  F1 := SQRT(x) + MIN(x, x, x);\nEND_FUNCTION\n",
        "S7-1500",
    )
    assert 'CALL "SQRT_LREAL"' in text
    assert text.count('CALL "MIN_LREAL"') == 2
    assert "SQRT  ;" not in text  # not the REAL instruction


@pytest.mark.parametrize(
    ("call", "expected"),
    [
        ("TRUNC(LREAL#-7.9)", -7),
        ("ROUND(LREAL#2.5)", 2),  # a half to the even neighbour
        ("ROUND(LREAL#-3.5)", -4),
        ("CEIL(LREAL#-7.9)", -7),
        ("FLOOR(LREAL#-7.1)", -8),
        ("TRUNC(LREAL#2147483647.9)", 2147483647),
    ],
)
def test_lreal_roundings_give_a_dint(call: str, expected: int) -> None:
    cpu = _run(_program("d : DINT; l : LINT;", f"DB1.d := {call};\nDB1.l := {call};"))
    assert int.from_bytes(_db(cpu, 0, 4), "big", signed=True) == expected
    assert int.from_bytes(_db(cpu, 4, 8), "big", signed=True) == expected  # DINT → LINT


@pytest.mark.parametrize(
    ("call", "expected"),
    [
        ("ABS(LINT#-9000000000)", 9_000_000_000),
        ("MIN(LINT#-9000000000, LINT#5)", -9_000_000_000),
        ("MAX(LINT#1, LINT#9000000000, LINT#5)", 9_000_000_000),
        ("LIMIT(MN := LINT#0, IN := LINT#-9000000000, MX := LINT#7)", 0),
        ("SEL(G := TRUE, IN0 := LINT#1, IN1 := LINT#9000000000)", 9_000_000_000),
    ],
)
def test_lint_functions(call: str, expected: int) -> None:
    cpu = _run(_program("l : LINT;", f"DB1.l := {call};"))
    assert int.from_bytes(_db(cpu, 0, 8), "big", signed=True) == expected


def test_a_function_outside_its_domain_gives_nan_and_eno_false() -> None:
    ref = bytearray(16)
    ref[0:8] = struct.pack(">d", -1.0)
    assert BODIES["SQRT_LREAL"]([(ref, 0, 0), (ref, 8, 0)]) == 0
    assert math.isnan(struct.unpack(">d", ref[8:16])[0])
    ref[0:8] = struct.pack(">d", 3.0e9)
    assert BODIES["TRUNC_LREAL"]([(ref, 0, 0), (ref, 8, 0)]) == 0  # beyond DINT


def test_the_function_fcs_are_numbered_after_the_operators() -> None:
    names = {name for name, _result, _inputs in signatures()}
    assert {FUNCTIONS[name].number for name in names} == set(range(BASE, BASE + len(names)))
    assert names <= set(BODIES)


# ---- 3. CASE selectors and FOR counters ---------------------------------------------------------

_CASE = """FUNCTION F1 : INT
VAR_INPUT
  d : DINT;
END_VAR
BEGIN
  CASE d OF
    100000..200000: F1 := 1;
  ELSE
    F1 := 2;
  END_CASE;
END_FUNCTION
"""


def test_a_dint_case_selector_needs_the_s7_1500_profile() -> None:
    assert _errors(_CASE, "S7-1500") == []
    classic = _errors(_CASE, "S7-300")
    assert classic[0] == ("SCL235", 6, "The CASE selector must be INT; it is DINT.")
    assert [code for code, _line, _message in classic[1:]] == [
        "SCL218",
        "SCL218",
    ]  # INT labels


def test_a_udint_case_selector_compares_unsigned() -> None:
    cpu = _run(
        "FUNCTION F1 : INT\nVAR_INPUT\n  u : UDINT;\nEND_VAR\nBEGIN\n"
        "  CASE u OF\n    0..2147483647: F1 := 1;\n    4000000000..4100000000: F1 := 2;\n"
        "  ELSE\n    F1 := 3;\n  END_CASE;\nEND_FUNCTION\n"
        + _program(
            "a : INT; b : INT; c : INT;",
            "DB1.a := F1(u := UDINT#5);\nDB1.b := F1(u := UDINT#4050000000);\n"
            "DB1.c := F1(u := UDINT#2147483648);",
        )
    )
    assert [int.from_bytes(_db(cpu, i, 2), "big") for i in (0, 2, 4)] == [1, 2, 3]


@pytest.mark.parametrize("profile", ["S7-300", "S7-1500"])
def test_a_dint_for_counter_runs_in_both_dialects(profile: str) -> None:
    cpu = _run(
        _program(
            "sum : DINT;",
            "DB1.sum := 0;\nFOR i := 100000 TO 100004 DO\n  DB1.sum := DB1.sum + i;\nEND_FOR;",
            "i : DINT;",
        ),
        profile,
    )
    assert int.from_bytes(_db(cpu, 0, 4), "big") == 500010


# ---- 4. TIME and DINT ---------------------------------------------------------------------------

_TIME_DINT = """FUNCTION F1 : DINT
VAR_TEMP
  start : DINT;
  now : TIME;
END_VAR
BEGIN
  start := TIME_TCK();
  now := T#2S;
  IF now - start > 0 THEN
    F1 := now - start;
  END_IF;
END_FUNCTION
"""


def test_time_and_dint_mix_on_s7_1500_only() -> None:
    assert _errors(_TIME_DINT, "S7-1500") == []
    assert [code for code, _line, _message in _errors(_TIME_DINT, "S7-300")] == [
        "SCL213",
        "SCL211",
        "SCL211",
    ]


def test_time_minus_dint_is_a_time_in_milliseconds() -> None:
    cpu = _run(
        _program(
            "d : DINT; t : TIME; ok : BOOL;",
            "start := T#1S;\nnow := T#3S500MS;\nDB1.d := now - start;\nDB1.t := now - start;\n"
            "DB1.ok := now - start >= T#2S500MS AND start < now AND start = 1000;",
            "start : DINT;\nnow : TIME;",
        )
    )
    assert int.from_bytes(_db(cpu, 0, 4), "big") == 2500
    assert int.from_bytes(_db(cpu, 4, 4), "big") == 2500
    assert _db(cpu, 8, 1)[0] & 1 == 1


def test_an_input_parameter_takes_time_for_dint_and_back() -> None:
    blocks = (
        "FUNCTION Fd : DINT\nVAR_INPUT\n  x : DINT;\nEND_VAR\nBEGIN\n  Fd := x + 1;\nEND_FUNCTION\n"
        "FUNCTION Ft : TIME\nVAR_INPUT\n  x : TIME;\nEND_VAR\nBEGIN\n  Ft := x + T#1S;\n"
        "END_FUNCTION\n"
    )
    body = "t := T#2S;\nd := 500;\nDB1.a := Fd(x := t);\nDB1.b := Ft(x := d);"
    text = blocks + _program("a : DINT; b : TIME;", body, "t : TIME;\nd : DINT;")
    assert [code for code, _line, _message in _errors(text, "S7-300")] == [
        "SCL213",
        "SCL213",
    ]
    cpu = _run(text)
    assert int.from_bytes(_db(cpu, 0, 4), "big") == 2001
    assert int.from_bytes(_db(cpu, 4, 4), "big") == 1500

"""The 64-bit leftovers of SCL on the S7-1200/1500 profile (issue 20, second round): FOR with a
UDINT, LINT or ULINT control variable and CASE over a LINT or ULINT selector
(``nasaq.lang.scl.lower.wide_control``)."""

from __future__ import annotations

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block
from nasaq.monitor import targets


def _errors(text: str, profile: str = "S7-1500") -> list[tuple[str, int]]:
    result = compile_sources([SourceFile("t.scl", text)], profile=profile)
    return [
        (d.code, d.span.line if d.span else 0) for d in result.diagnostics if d.severity == "error"
    ]


def _run(text: str, names: list[str], scans: int = 1) -> dict[str, object]:
    result = compile_sources([SourceFile("t.scl", text)], profile="S7-1500")
    errors = [f"{d.code} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(scans)
    assert cpu.mode == "RUN", cpu.stop_reason
    return {
        name: targets.read(targets.resolve(f'"D".{name}', result.program), cpu) for name in names
    }


def _program(declarations: str, body: str) -> str:
    return f"""
DATA_BLOCK "D"
VERSION : 0.1
   VAR
{declarations}
   END_VAR
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
BEGIN
{body}
END_ORGANIZATION_BLOCK
"""


# ---- FOR ----------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kind", "start", "end", "step", "passes", "after"),
    [
        ("LINT", "LINT#4294967290", "LINT#4294967300", "5", 3, 4294967305),
        ("LINT", "10", "1", "-3", 4, -2),
        ("LINT", "-3", "3", None, 7, 4),
        ("UDINT", "UDINT#4294967290", "UDINT#4294967294", None, 5, 4294967295),
        ("UDINT", "5", "4", None, 0, 5),
        (
            "ULINT",
            "ULINT#18446744073709551600",
            "ULINT#18446744073709551610",
            "4",
            3,
            None,
        ),
        ("ULINT", "1", "3", None, 3, 4),
    ],
)
def test_for_counts_with_a_wide_control_variable(
    kind: str, start: str, end: str, step: str | None, passes: int, after: int | None
) -> None:
    by = f" BY {step}" if step is not None else ""
    values = _run(
        _program(
            f"      i : {kind};\n      n : INT;",
            f'  "D".n := 0;\n  FOR "D".i := {start} TO {end}{by} DO "D".n := "D".n + 1; END_FOR;',
        ),
        ["i", "n"],
    )
    assert values["n"] == passes
    if after is not None:
        assert values["i"] == after
    else:  # ULINT#18446744073709551612, beyond 2**53: sent as digits
        assert values["i"] == "18446744073709551612"


def test_for_takes_the_end_and_step_once_and_honours_exit_and_continue() -> None:
    values = _run(
        _program(
            "      i : LINT;\n      stop : LINT := -10;\n      step : LINT := -4;\n"
            "      n : INT;\n      odd : INT;",
            """  "D".n := 0; "D".odd := 0; "D".stop := -10; "D".step := -4;
  FOR "D".i := 2 TO "D".stop BY "D".step DO
    "D".stop := 100; "D".step := 1;       // too late: taken before the first pass
    "D".n := "D".n + 1;
    IF "D".i = -6 THEN CONTINUE; END_IF;
    "D".odd := "D".odd + 1;
    IF "D".i = -10 THEN EXIT; END_IF;
  END_FOR;""",
        ),
        ["i", "n", "odd"],
    )
    assert values == {"i": -10, "n": 4, "odd": 3}


def test_a_wide_for_runs_every_scan_without_leaking_temporaries() -> None:
    # the temporaries of the end, the step and the comparisons are released after the loop:
    # many loops in one block still fit the L stack
    loops = "\n".join(
        '  FOR "D".i := 1 TO "D".e BY "D".s DO "D".n := "D".n + 1; END_FOR;' for _ in range(40)
    )
    values = _run(
        _program(
            "      i : LINT;\n      e : LINT := 3;\n      s : LINT := 1;\n      n : DINT;",
            '  "D".n := 0;\n' + loops,
        ),
        ["n"],
        scans=3,
    )
    assert values["n"] == 120


def test_lreal_and_other_counters_stay_refused() -> None:
    source = _program(
        "      x : LREAL;\n      w : LWORD;",
        """  FOR "D".x := 1 TO 3 DO END_FOR;
  FOR "D".w := 1 TO 3 DO END_FOR;""",
    )
    assert _errors(source) == [("SCL221", 13), ("SCL221", 14)]


def test_wide_counters_need_the_s7_1500_profile() -> None:
    source = _program("      i : LINT;", '  FOR "D".i := 1 TO 3 DO END_FOR;')
    assert {code for code, _line in _errors(source, "S7-300")} == {"SCL500"}


def test_a_lint_for_lowers_to_library_comparisons() -> None:
    result = compile_sources(
        [
            SourceFile(
                "t.scl",
                _program("      i : LINT;", '  FOR "D".i := 1 TO 9 DO END_FOR;'),
            )
        ],
        profile="S7-1500",
    )
    assert result.ok
    stl = "\n".join(format_block(block) for _file, block in result.generated)
    assert '"LE_LINT"' in stl
    assert '"ADD_LINT"' in stl


# ---- CASE ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kind", "value", "branch"),
    [
        ("LINT", "LINT#40000000000", 2),
        ("LINT", "-5", 3),
        ("LINT", "1", 1),
        ("LINT", "0", 9),
        ("ULINT", "ULINT#18446744073709551615", 4),
        ("ULINT", "7", 9),
    ],
)
def test_case_over_a_wide_selector(kind: str, value: str, branch: int) -> None:
    labels = (
        '    1, 2: "D".k := 1;\n    LINT#39999999999..LINT#40000000001: "D".k := 2;\n'
        '    -10..-5: "D".k := 3;'
        if kind == "LINT"
        else '    1, 2: "D".k := 1;\n'
        '    ULINT#18446744073709551600..ULINT#18446744073709551615: "D".k := 4;'
    )
    values = _run(
        _program(
            f"      s : {kind};\n      k : INT;",
            f'  "D".s := {value};\n  CASE "D".s OF\n{labels}\n  ELSE "D".k := 9;\n  END_CASE;',
        ),
        ["k"],
    )
    assert values["k"] == branch


def test_case_lint_labels_are_checked_for_overlaps() -> None:
    source = _program(
        "      s : LINT;\n      k : INT;",
        '  CASE "D".s OF\n    1..LINT#50000000000: "D".k := 1;\n'
        '    LINT#40000000000: "D".k := 2;\n  END_CASE;',
    )
    assert _errors(source) == [("SCL236", 15)]


def test_case_over_lreal_stays_refused() -> None:
    source = _program(
        "      x : LREAL;\n      k : INT;", '  CASE "D".x OF 1: "D".k := 1; END_CASE;'
    )
    assert _errors(source) == [("SCL235", 13)]


# ---- IEC counters of the other integer types, LTIME timers --------------------------------------


def _fb_program(statics: str, body: str) -> str:
    return f"""
FUNCTION_BLOCK "F"
   VAR
{statics}
   END_VAR
BEGIN
{body}
END_FUNCTION_BLOCK

DATA_BLOCK "D" "F"
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
BEGIN
  "D"();
END_ORGANIZATION_BLOCK
"""


@pytest.mark.parametrize(
    ("kind", "pv", "start", "counted"),
    [
        ("USINT", "USINT#250", 250, 255),  # stops at the type's highest value
        ("SINT", "SINT#120", 120, 127),
        ("UINT", "UINT#65530", 65530, 65535),
        ("UDINT", "UDINT#4294967290", 4294967290, 4294967295),
        ("DINT", "2147483640", 2147483640, 2147483647),
        (
            "LINT",
            "LINT#9223372036854775800",
            9223372036854775800,
            "9223372036854775807",
        ),
        (
            "ULINT",
            "ULINT#18446744073709551610",
            18446744073709551610,
            "18446744073709551615",
        ),
    ],
)
def test_a_typed_ctud_counts_within_its_type(
    kind: str, pv: str, start: int, counted: object
) -> None:
    values = _run(
        _fb_program(
            f"      c : CTUD_{kind};\n      go : BOOL;\n      n : INT;",
            f"""  #n := #n + 1;
  #go := NOT #go;
  #c(CU := #go, CD := FALSE, R := FALSE, LD := #n = 1, PV := {pv});""",
        ),
        ["c.CV", "c.QU", "c.QD"],
        scans=21,  # loaded at the first scan, then 10 rising edges
    )
    assert values["c.CV"] == counted
    assert values["c.QU"] is True
    assert values["c.QD"] is (isinstance(counted, int) and counted <= 0)
    assert start != counted


def test_typed_ctu_and_ctd_reset_and_load() -> None:
    values = _run(
        _fb_program(
            "      u : CTU_UDINT;\n      d : CTD_LINT;\n      go : BOOL;\n      n : INT;",
            """  #n := #n + 1;
  #go := NOT #go;
  #u(CU := #go, R := #n = 5, PV := UDINT#2);      // reset at scan 5: counts scans 7 and 9 only
  #d(CD := #go, LD := #n = 3, PV := LINT#-4294967296);""",
        ),
        ["u.CV", "u.Q", "d.CV", "d.Q"],
        scans=10,
    )
    assert values == {"u.CV": 2, "u.Q": True, "d.CV": -4294967299, "d.Q": True}


def test_ltime_timers_count_nanoseconds() -> None:
    values = _run(
        _fb_program(
            "      on : TON_LTIME;\n      off : TOF_LTIME;\n      pulse : TP_LTIME;\n"
            "      any : IEC_LTIMER;\n      n : INT;",
            """  #n := #n + 1;
  #on(IN := TRUE, PT := LT#35MS);
  #off(IN := #n < 3, PT := LT#1S);
  #pulse(IN := TRUE, PT := LTIME#1D);
  #any.TON(IN := TRUE, PT := LT#2MS500US);""",
        ),
        ["on.Q", "on.ET", "off.Q", "off.ET", "pulse.Q", "pulse.ET", "any.Q", "any.ET"],
        scans=6,  # 10 ms a scan: 50 ms after the first call
    )
    assert values == {
        "on.Q": True,
        "on.ET": 35_000_000,
        "off.Q": True,  # IN fell at the third scan: 30 ms of its 1 s delay are gone
        "off.ET": 30_000_000,
        "pulse.Q": True,
        "pulse.ET": 50_000_000,
        "any.Q": True,
        "any.ET": 2_500_000,
    }


def test_a_counter_call_on_an_instance_of_another_kind_is_refused() -> None:
    source = _fb_program(
        "      c : CTU_DINT;\n      t : IEC_LTIMER;",
        "  #c.CTD(CD := TRUE);\n  #t.CTU(CU := TRUE);",
    )
    assert [code for code, _line in _errors(source)] == ["SCL703", "SCL703"]


def test_typed_counters_take_their_own_types() -> None:
    source = _fb_program(
        "      c : CTU_USINT;\n      t : TON_LTIME;",
        "  #c(CU := TRUE, PV := 300);\n  #t(IN := TRUE, PT := 5);",
    )
    # 300 is no USINT; an INT is no LTIME (write LT#5MS)
    assert [code for code, _line in _errors(source)] == ["SCL218", "SCL214"]


@pytest.mark.parametrize(
    "name", ["CTU_DINT", "CTD_ULINT", "IEC_DCOUNTER", "TON_LTIME", "IEC_LTIMER"]
)
def test_typed_counters_and_ltime_timers_need_the_s7_1500_profile(name: str) -> None:
    source = _fb_program(f"      x : {name};", "  ;")
    assert [code for code, _line in _errors(source, "S7-300")] == ["SCL500"]


# ---- T_ADD / T_SUB of an LTIME, ** of the 64-bit integers ---------------------------------------


def test_t_add_and_t_sub_of_an_ltime() -> None:
    values = _run(
        _program(
            "      a : LTIME := LT#1S;\n      b : LTIME := LT#250MS;\n      t : TIME := T#1S;\n"
            "      s : LTIME;\n      d : LTIME;\n      m : LTIME;\n      ok : BOOL;",
            """  "D".s := T_ADD(IN1 := "D".a, IN2 := "D".b);
  "D".d := T_SUB(IN1 := "D".a, IN2 := "D".b);
  "D".m := T_ADD(IN1 := "D".a, IN2 := "D".t);      // a TIME duration into an LTIME
  "D".ok := T_SUB("D".a, LT#1S) = LT#0S;""",
        ),
        ["s", "d", "m", "ok"],
    )
    assert values == {
        "s": 1_250_000_000,
        "d": 750_000_000,
        "m": 2_000_000_000,
        "ok": True,
    }


def test_an_ltime_duration_needs_an_ltime_point() -> None:
    source = _program(
        "      t : TIME;\n      tod : TIME_OF_DAY;\n      b : LTIME;",
        """  "D".t := T_ADD(IN1 := "D".t, IN2 := "D".b);
  "D".tod := T_SUB(IN1 := "D".tod, IN2 := LT#1S);""",
    )
    assert _errors(source) == [("SCL213", 14), ("SCL213", 15)]


def test_power_of_a_64_bit_integer_is_an_lreal() -> None:
    values = _run(
        _program(
            "      a : LINT := 3;\n      u : ULINT := 10;\n      r : LREAL := 1.5;\n"
            "      p : LREAL;\n      q : LREAL;\n      w : LREAL;",
            """  "D".p := "D".a ** 2;
  "D".q := "D".u ** 15;
  "D".w := "D".r ** "D".a;""",
        ),
        ["p", "q", "w"],
    )
    assert values == {"p": 9.0, "q": 1e15, "w": 3.375}

"""TIA Portal's implicit conversions with the IEC check off (``typecheck.implicit``): accepted
under the S7-1500 profile with the warning where a value may change, compiled as the explicit
conversion they equal and run with TIA's values; S7-SCL Classic's rules unchanged under
S7-300/400."""

from __future__ import annotations

import pytest
from scl_run import build, ob1, read

from nasaq.lang.scl.typecheck.implicit import conversion, lossless, operand_types
from nasaq.lang.stl import SourceFile, compile_sources


def codes(text: str, profile: str = "S7-1500") -> list[tuple[str, str, int]]:
    result = compile_sources([SourceFile("prog.scl", text)], profile=profile)
    return [(d.code, d.severity, d.span.line) for d in result.diagnostics if d.span]


def fc(body: str, temps: str, returns: str = "VOID") -> str:
    return f'FUNCTION "F" : {returns}\nVAR_TEMP\n{temps}\nEND_VAR\nBEGIN\n{body}\nEND_FUNCTION\n'


# ---- the table ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("source", "goal", "chain"),
    [
        ("INT", "USINT", ("INT_TO_USINT",)),
        ("UINT", "INT", ("UINT_TO_INT",)),
        ("WORD", "INT", ("WORD_TO_INT",)),
        ("WORD", "SINT", ("WORD_TO_SINT",)),  # the low byte
        ("SINT", "WORD", ("SINT_TO_BYTE",)),  # then zero-filled, as BYTE into WORD
        ("INT", "DWORD", ("INT_TO_WORD",)),
        ("REAL", "DINT", ("REAL_TO_DINT",)),
        ("REAL", "USINT", ("REAL_TO_DINT", "DINT_TO_USINT")),
        ("LREAL", "UDINT", ("LREAL_TO_LINT", "LINT_TO_UDINT")),
        ("LREAL", "REAL", ("LREAL_TO_REAL",)),
        ("DWORD", "REAL", ("DWORD_TO_UDINT", "UDINT_TO_REAL")),
        ("INT", "DINT", ()),  # S7-SCL's own widening: no code
        (
            "SINT",
            "CHAR",
            ("SINT_TO_BYTE", "BYTE_TO_CHAR"),
        ),  # the code, as its bit pattern
        ("CHAR", "UDINT", ("CHAR_TO_BYTE", "BYTE_TO_UDINT")),
    ],
)
def test_the_conversion_each_implicit_one_equals(source: str, goal: str, chain: tuple) -> None:
    assert conversion(source, goal) == chain


@pytest.mark.parametrize(
    ("source", "goal"),
    [
        ("BOOL", "INT"),
        ("INT", "BOOL"),
        ("DINT", "BOOL"),
        ("WORD", "REAL"),
        ("REAL", "WORD"),
        ("CHAR", "WCHAR"),
        ("CHAR", "REAL"),
    ],
)
def test_what_tia_never_converts_implicitly(source: str, goal: str) -> None:
    assert conversion(source, goal) is None


def test_lossless_pairs_are_those_no_value_changes_in() -> None:
    assert lossless("WORD", "DINT")
    assert lossless("USINT", "INT")
    assert lossless("INT", "LREAL")
    assert not lossless("INT", "USINT")
    assert not lossless("LINT", "REAL")
    assert lossless("DINT", "REAL")  # S7-SCL's own widening, silent as in STEP 7 Classic
    assert not lossless("LREAL", "REAL")
    assert not lossless("WORD", "INT")


def test_operands_as_tia_reads_them() -> None:
    assert operand_types("+", "DINT", "WORD") == ("DINT", "UINT")
    assert operand_types("-", "DWORD", "UDINT") == ("UDINT", "UDINT")
    assert operand_types("XOR", "INT", "INT") == ("WORD", "WORD")
    assert operand_types("AND", "UDINT", "DWORD") == ("DWORD", "DWORD")
    assert operand_types("+", "WORD", "WORD") is None  # two bit strings: no arithmetic
    assert operand_types("AND", "BOOL", "INT") is None


# ---- checking -----------------------------------------------------------------------------------


def test_narrowing_is_accepted_with_a_warning_under_s7_1500() -> None:
    text = fc(
        "u := i;\nd := r;\nr := l;\ni := w;\nd := w;",
        "i : INT; u : USINT; d : DINT; r : REAL; l : LREAL; w : WORD;",
    )
    found = codes(text)
    assert ("SCL705", "warning", 6) in found
    assert ("SCL705", "warning", 7) in found
    assert ("SCL705", "warning", 8) in found
    assert ("SCL705", "warning", 9) in found
    assert not [c for c in found if c[1] == "error"]
    assert not [c for c in found if c[2] == 10]  # WORD into DINT changes no value


def test_classic_profiles_keep_s7_scl_rules() -> None:
    text = fc("i := w;\nd := d + w;\ni := i XOR i;", "i : INT; w : WORD; d : DINT;")
    assert [(c, line) for c, _, line in codes(text, "S7-300")] == [
        ("SCL213", 6),
        ("SCL211", 7),
        ("SCL211", 8),
    ]


def test_bool_and_conditions_stay_errors_under_s7_1500() -> None:
    text = fc("i := b;\nIF d THEN i := 1; END_IF;", "i : INT; b : BOOL; d : DINT;")
    assert [(c, line) for c, sev, line in codes(text) if sev == "error"] == [
        ("SCL213", 6),
        ("SCL220", 7),
    ]


def test_a_negative_constant_into_an_unsigned_type() -> None:
    text = 'FUNCTION "F" : USINT\nBEGIN\n#F := -1;\nEND_FUNCTION\n'
    assert codes(text) == [("SCL706", "warning", 3)]
    assert [c for c, *_ in codes(text.replace("-1", "-200"))] == ["SCL218"]
    assert [c for c, *_ in codes(text, "S7-300")] == ["SCL500"]


# ---- running ------------------------------------------------------------------------------------


def run_1500(body: str, temps: str) -> object:
    return build(ob1(body, temps), profile="S7-1500")


def test_narrowing_keeps_the_low_bits() -> None:
    cpu = run_1500(
        "i := -1; u := i; MW10 := USINT_TO_INT(u);\n"
        "w := UINT#60000; i := w; MW12 := i;\n"
        "wd := 16#FFFF; i := wd; MW14 := i;",
        "i : INT; u : USINT; w : UINT; wd : WORD;",
    )
    assert (read(cpu, "MW10"), read(cpu, "MW12"), read(cpu, "MW14")) == (255, -5536, -1)


def test_real_into_integers_rounds_half_to_even_then_wraps() -> None:
    cpu = run_1500(
        "r := 2.5; d := r; MD10 := d;\nr := -2.5; d := r; MD14 := d;\n"
        "r := 305.5; d := r; MD18 := d; u := r; MW22 := USINT_TO_INT(u);",
        "r : REAL; d : DINT; u : USINT;",
    )
    assert [read(cpu, a) for a in ("MD10", "MD14", "MD18", "MW22")] == [2, -2, 306, 50]


def test_integers_into_wider_bit_strings_are_zero_filled() -> None:
    cpu = run_1500(
        "s := -1; w := s; MW10 := w;\ni := -2; dw := i; MD12 := dw;",
        "s : SINT; w : WORD; i : INT; dw : DWORD;",
    )
    assert read(cpu, "MW10") == 0xFF
    assert read(cpu, "MD12") == 0xFFFE


def test_bit_strings_compute_as_unsigned_and_integers_as_bits() -> None:
    cpu = run_1500(
        "d := 10; w := 16#FFFF; d := d + w; MD10 := d;\n"
        "u := UDINT#5; dw := 16#FFFFFFFF; u := dw - u; MD14 := UDINT_TO_DINT(u);\n"
        "a := 5; b := 3; a := a XOR b; MW18 := a;\n"
        "dw := UDINT#6 AND dw; MD20 := dw;\n"
        "M24.0 := w = i;",
        "d : DINT; w : WORD; u : UDINT; dw : DWORD; a : INT; b : INT; i : INT;",
    )
    assert read(cpu, "MD10") == 65545
    assert read(cpu, "MD14") == -6
    assert read(cpu, "MW18") == 6
    assert read(cpu, "MD20") == 6


def test_case_on_a_word_compares_it_unsigned() -> None:
    cpu = run_1500(
        "w := 16#8070;\nCASE w OF\n  0: MW10 := 1;\n  32880: MW10 := 2;\n"
        "ELSE MW10 := 3;\nEND_CASE;",
        "w : WORD;",
    )
    assert read(cpu, "MW10") == 2


def test_an_input_parameter_takes_the_converted_value() -> None:
    text = (
        'FUNCTION "Twice" : INT\nVAR_INPUT x : INT; END_VAR\nBEGIN\n#Twice := x * 2;\n'
        "END_FUNCTION\n" + ob1('d := 70000; MW10 := "Twice"(x := d);', "d : DINT;")
    )
    cpu = build(text, profile="S7-1500")
    assert read(cpu, "MW10") == (70000 - 65536) * 2


# ---- constants and RE_TRIGR ---------------------------------------------------------------------


def test_a_var_constant_without_a_value_is_its_types_default() -> None:
    text = (
        'FUNCTION "F" : VOID\nVAR CONSTANT\n  IDLE : INT;\n  OFF : BOOL;\n  NOTHING : STRING;\n'
        "END_VAR\nBEGIN\nMW10 := #IDLE + 7;\nM12.0 := TRUE;\nM12.0 := #OFF;\n"
        "M12.1 := #NOTHING = '';\n"
        "END_FUNCTION\n" + ob1('"F"();')
    )
    cpu = build(text, profile="S7-1500")
    assert read(cpu, "MW10") == 7
    assert read(cpu, "M12.0") == 0
    assert read(cpu, "M12.1") == 1


@pytest.mark.parametrize("profile", ["S7-300", "S7-1500"])
def test_re_trigr_is_accepted_and_does_nothing(profile: str) -> None:
    cpu = build(ob1("RE_TRIGR();\nMW10 := 5;"), profile=profile)
    assert read(cpu, "MW10") == 5
    assert [c for c, *_ in codes(ob1("RE_TRIGR(X := 1);"), profile)] == ["SCL223"]


def test_based_constants_take_the_unsigned_operands_type() -> None:
    cpu = run_1500(
        "s := UDINT#10;\ns := (16#FFFFFFFF - s) + 1;\nMD10 := UDINT_TO_DINT(s);\n"
        "u := UDINT#4000000000;\nu := u AND 16#7FFFFFFF;\nMD14 := UDINT_TO_DINT(u);",
        "s : UDINT; u : UDINT;",
    )
    assert read(cpu, "MD10") == -10
    assert read(cpu, "MD14") == 4000000000 & 0x7FFFFFFF


def test_multiple_assignment_converts_the_value_not_between_targets() -> None:
    cpu = run_1500("r := 2.5;\na := b := r;\nMW10 := a;\nMW12 := b;", "r : REAL; a : INT; b : INT;")
    assert read(cpu, "MW10") == 2
    assert read(cpu, "MW12") == 2
    text = fc("a := d := 70000;", "a : INT; d : DINT;")
    assert [c for c, severity, _ in codes(text) if severity == "error"] == ["SCL213"]


def test_times_convert_with_the_integers_of_their_width() -> None:
    assert conversion("UDINT", "TIME") == ("UDINT_TO_DINT", "DINT_TO_TIME")
    assert conversion("TIME_OF_DAY", "DWORD") == ("TOD_TO_DINT", "DINT_TO_DWORD")
    assert conversion("LWORD", "LTIME") == ("LWORD_TO_LINT", "LINT_TO_LTIME")
    assert conversion("TIME", "INT") is None
    assert conversion("LTIME", "DINT") is None
    cpu = run_1500(
        "u := UDINT#1500; t := u; MD10 := TIME_TO_DINT(t);\n"
        "td := TOD#01:00:00; dw := td; MD14 := dw;\n"
        "t := T#2S; u := t; MD18 := UDINT_TO_DINT(u);",
        "u : UDINT; t : TIME; td : TOD; dw : DWORD;",
    )
    assert [read(cpu, a) for a in ("MD10", "MD14", "MD18")] == [1500, 3_600_000, 2000]

"""TIA Portal's text instructions and conversions in SCL (issue 20, second round): VAL_STRG and
STRG_VAL, the number and character conversions with WSTRING/WCHAR, CONCAT of WSTRINGs with
IN1 .. INn, the typed forms (``CONCAT_STRING``, ``SCALE_X_REAL``), ``LEN(IN := ...)``,
``STRING#'...'``, DTL_TO_TOD/DTL_TO_DATE: each checked, lowered (the generated STL calls the
library FC the call means) and run on the CPU; what a classic profile lacks is SCL500."""

from __future__ import annotations

import pytest
from scl_run import build, ob1, read

from nasaq.lang.iec_library import FUNCTIONS
from nasaq.lang.stl import SourceFile, compile_sources


def problems(text: str, profile: str = "S7-1500") -> list[tuple[str, int]]:
    result = compile_sources([SourceFile("prog.scl", text)], profile=profile)
    return [(d.code, d.span.line) for d in result.diagnostics if d.severity == "error"]


def fc(body: str, temps: str) -> str:
    return f"FUNCTION F : VOID\nVAR_TEMP\n{temps}\nEND_VAR\nBEGIN\n{body}\nEND_FUNCTION\n"


# ---- VAL_STRG, STRG_VAL -------------------------------------------------------------------------


def test_val_strg_calls_the_fc_of_its_input_type_and_runs() -> None:
    text = ob1(
        "r := 12.5;\ns := 'v=';\n"
        "VAL_STRG(IN := r, SIZE := 6, PREC := 1, FORMAT := 0, P := 3, OUT => s);\n"
        "i := -7;\nt := '';\n"
        "VAL_STRG(IN := i, SIZE := 4, PREC := 0, FORMAT := 16#0004, P := 1, OUT => t);\n"
        "M0.0 := (s = 'v=  12.5') AND (t = '  -7');",
        "r : REAL; i : INT; s : STRING[20]; t : STRING[8];",
    )
    cpu = build(text, profile="S7-1500")
    assert read(cpu, "M0.0") == 1
    result = compile_sources([SourceFile("prog.scl", text)], profile="S7-1500")
    names = {block.attributes.get("NAME") for block in result.program.blocks.values()}
    assert {"VAL_STRG_REAL", "VAL_STRG_INT"} <= names  # one library FC per input type


def test_strg_val_writes_the_number_and_moves_p() -> None:
    text = ob1(
        "s := 'x=1.5;y=20';\np := 3;\n"
        "STRG_VAL(IN := s, FORMAT := 0, P := p, OUT => r);\n"
        "p := p + 3;\n"
        "STRG_VAL(IN := s, FORMAT := 0, P := p, OUT => d, ENO => ok);\n"
        "M0.0 := (r = 1.5) AND (d = 20) AND (p = 11) AND ok;",
        "s : STRING[20]; p : UINT; r : REAL; d : DINT; ok : BOOL;",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


@pytest.mark.parametrize("profile", ["S7-300", "S7-400"])
def test_val_strg_and_strg_val_need_the_s7_1500_profile(profile: str) -> None:
    text = fc(
        "VAL_STRG(IN := r, SIZE := 6, PREC := 1, FORMAT := 0, P := 1, OUT => s);\n"
        "STRG_VAL(IN := s, FORMAT := 0, P := p, OUT => r);",
        "r : REAL; s : STRING[10]; p : INT;",
    )
    assert problems(text, profile) == [("SCL500", 6), ("SCL500", 7)]


def test_val_strg_and_strg_val_parameters_are_checked() -> None:
    text = fc(
        "VAL_STRG(IN := r, SIZE := 6, PREC := 1, FORMAT := 0, P := 1, OUT => s, WIDTH := 3);\n"
        "STRG_VAL(IN := s, FORMAT := 0, P := 1, OUT => r);\n"
        "VAL_STRG(IN := r, SIZE := 6, PREC := 1, FORMAT := 0, OUT => s);\n"
        "VAL_STRG(IN := r, SIZE := 6, PREC := 1, FORMAT := 0, P := 1);",
        "r : REAL; s : STRING[10];",
    )
    found = problems(text)
    assert ("SCL223", 6) in found  # no parameter WIDTH
    assert any(line == 7 for _code, line in found)  # P is in/out: a constant cannot be written
    assert ("SCL227", 8) in found  # P missing
    assert ("SCL227", 9) in found  # OUT missing (an FC's parameters are all assigned)


def test_val_strg_is_no_longer_an_unsimulated_system_name() -> None:
    text = fc(
        "VAL_STRG(IN := r, SIZE := 6, PREC := 1, FORMAT := 0, P := 1, OUT => s);",
        "r : REAL; s : STRING[10];",
    )
    assert problems(text) == []


# ---- conversions with WSTRING and WCHAR ---------------------------------------------------------


def test_number_conversions_with_wstring_run() -> None:
    text = ob1(
        "u := 7;\nw := RIGHT(IN := UINT_TO_WSTRING(u), L := 1);\n"
        "r := WSTRING_TO_REAL(WSTRING#'-2.25');\n"
        "M0.0 := (w = WSTRING#'7') AND (r = -2.25)\n"
        "  AND (DINT_TO_WSTRING(DINT#5) = STRING_TO_WSTRING(DINT_TO_STRING(DINT#5)));",
        "u : UINT; w : WSTRING[10]; r : REAL;",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


def test_character_conversions_run() -> None:
    text = ob1(
        "b := 16#41;\nc := BYTE_TO_WCHAR(b);\nw := WCHAR_TO_WSTRING(c);\n"
        "d := WSTRING_TO_WCHAR(WSTRING#'xyz');\n"
        "M0.0 := (w = WSTRING#'A') AND (d = WCHAR#'x') AND (WCHAR_TO_BYTE(c) = 16#41);",
        "b : BYTE; c : WCHAR; d : WCHAR; w : WSTRING[4];",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


@pytest.mark.parametrize("profile", ["S7-300", "S7-400"])
def test_wstring_conversions_need_the_s7_1500_profile(profile: str) -> None:
    text = fc("i := 5;\nMW0 := INT_TO_WORD(LEN(INT_TO_WSTRING(i)));", "i : INT;")
    assert ("SCL500", 7) in problems(text, profile)


# ---- CONCAT with IN1 .. INn, the typed forms, LEN(IN := ...), STRING# ---------------------------


def test_concat_wstring_takes_more_than_two_inputs() -> None:
    text = ob1(
        "x := WSTRING#'c';\n"
        "w := CONCAT_WSTRING(IN1 := WSTRING#'a', IN2 := WSTRING#'b', IN3 := x, IN4 := 'd');\n"
        "v := CONCAT(IN1 := x, IN2 := x, IN3 := x);\n"
        "M0.0 := (w = WSTRING#'abcd') AND (v = WSTRING#'ccc');",
        "w : WSTRING[10]; v : WSTRING[10]; x : WSTRING[2];",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


def test_typed_forms_are_the_instructions_they_name() -> None:
    text = ob1(
        "raw := 50;\ns := CONCAT_STRING(IN1 := STRING#'ab', IN2 := 'c');\n"
        "r := SCALE_X_REAL(VALUE := NORM_X_REAL(VALUE := raw, MIN := 0, MAX := 100),"
        " MIN := 0.0, MAX := 2.0);\n"
        "M0.0 := (s = 'abc') AND (LEN_STRING(s) = 3) AND (r = 1.0);",
        "s : STRING[10]; raw : INT; r : REAL;",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


def test_a_typed_form_of_no_instruction_stays_undeclared() -> None:
    text = fc("r := SCALE_X_TEXT(VALUE := 0.5, MIN := 0.0, MAX := 1.0);", "r : REAL;")
    assert problems(text) == [("SCL201", 6)]


def test_len_takes_tia_s_in_as_well_as_the_library_s() -> None:
    text = ob1(
        "s := 'abcd';\nMW0 := INT_TO_WORD(LEN(IN := s));\nMW2 := INT_TO_WORD(LEN(S := s));\n"
        "MW4 := INT_TO_WORD(LEN(s));",
        "s : STRING[10];",
    )
    cpu = build(text, profile="S7-1500")
    assert [read(cpu, w) for w in ("MW0", "MW2", "MW4")] == [4, 4, 4]
    twice = fc("i := LEN(IN := s, S := s);", "i : INT; s : STRING[4];")
    assert problems(twice) == [("SCL228", 6)]


def test_string_typed_constant() -> None:
    text = ob1("s := STRING#'OB';\nM0.0 := s = 'OB';", "s : STRING[4];")
    assert read(build(text), "M0.0") == 1


# ---- DTL_TO_TOD, DTL_TO_DATE --------------------------------------------------------------------


def test_dtl_to_tod_and_date() -> None:
    text = ob1(
        "t.YEAR := 2030;\nt.MONTH := 12;\nt.DAY := 31;\nt.HOUR := 23;\nt.MINUTE := 59;\n"
        "t.SECOND := 58;\nt.NANOSECOND := 5000000;\n"
        "M0.0 := (DTL_TO_TOD(IN := t) = TOD#23:59:58.005) AND (DTL_TO_DATE(t) = D#2030-12-31);",
        "t : DTL;",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


def test_dtl_to_tod_takes_a_dtl_only() -> None:
    text = fc("t := DTL_TO_TOD(IN := d);", "t : TIME_OF_DAY; d : DATE;")
    assert [code for code, _line in problems(text)] == ["SCL214"]


def test_the_hidden_fcs_are_library_functions_with_outputs() -> None:
    function = FUNCTIONS["STRG_VAL_REAL"]
    assert [name for name, _type in function.inputs] == ["IN", "FORMAT"]
    assert [(section, name) for section, name, _type in function.others] == [
        ("OUT", "OUT"),
        ("IN_OUT", "P"),
    ]


# ---- Strg_TO_Chars, Chars_TO_Strg, ATH, HTA -----------------------------------------------------


def test_strg_to_chars_and_back_run_on_temporaries() -> None:
    text = ob1(
        "s := 'Nasaq';\nStrg_TO_Chars(Strg := s, pChars := 1, Cnt => n, Chars := chars);\n"
        "Chars_TO_Strg(Chars := chars, pChars := 2, Cnt := 3, Strg => t, ENO => ok);\n"
        "M0.0 := (n = 5) AND (chars[0] = '$00') AND (chars[1] = 'N') AND (chars[5] = 'q')\n"
        "  AND (t = 'asa') AND ok;",
        "s : STRING[10]; chars : ARRAY[0..7] OF CHAR; n : UINT; t : STRING[10]; ok : BOOL;",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


def test_a_wstring_calls_the_wide_fcs() -> None:
    text = ob1(
        "w := WSTRING#'ab';\nStrg_TO_Chars(Strg := w, pChars := 0, Cnt => n, Chars := wide);\n"
        "Chars_TO_Strg(Chars := wide, pChars := 0, Cnt := 2, Strg => v);\n"
        "M0.0 := (n = 2) AND (wide[1] = WCHAR#'b') AND (v = WSTRING#'ab');",
        "w : WSTRING[4]; wide : ARRAY[0..3] OF WCHAR; n : UINT; v : WSTRING[4];",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1
    result = compile_sources([SourceFile("prog.scl", text)], profile="S7-1500")
    names = {block.attributes.get("NAME") for block in result.program.blocks.values()}
    assert {"STRG_TO_CHARS_WSTRING", "CHARS_TO_STRG_WSTRING"} <= names


def test_ath_and_hta_run_on_a_global_db_and_report_bad_characters() -> None:
    db = (
        'DATA_BLOCK "D"\nSTRUCT\n  chars : ARRAY[0..3] OF CHAR;\n  value : WORD;\n'
        "  back : ARRAY[0..3] OF CHAR;\n  r1 : WORD;\n  r2 : WORD;\nEND_STRUCT;\nBEGIN\n"
        "END_DATA_BLOCK\n"
    )
    text = db + ob1(
        "\"D\".chars[0] := '4'; \"D\".chars[1] := 'e'; \"D\".chars[2] := 'Z'; "
        "\"D\".chars[3] := '1';\n"
        '"D".r1 := ATH(IN := "D".chars, N := 4, OUT => "D".value, ENO => bad);\n'
        '"D".r2 := HTA(IN := "D".value, N := 2, OUT => "D".back);\n'
        'M0.0 := ("D".value = 16#4E01) AND ("D".r1 = 16#0007) AND NOT bad AND ("D".r2 = 0)\n'
        "  AND (\"D\".back[1] = 'E') AND (\"D\".back[2] = '0');",
        "bad : BOOL;",
    )
    assert read(build(text, profile="S7-1500"), "M0.0") == 1


@pytest.mark.parametrize("profile", ["S7-300", "S7-1500"])
def test_ath_and_hta_are_the_converting_blocks_fc_94_and_95(profile: str) -> None:
    text = ob1(
        "chars[0] := 'A'; chars[1] := '5';\nr := ATH(IN := chars, N := 2, OUT => b);\n"
        "M0.0 := (b = 16#A5) AND (r = 0);",
        "chars : ARRAY[0..1] OF CHAR; b : BYTE; r : WORD;",
    )
    assert read(build(text, profile=profile), "M0.0") == 1
    blocks = compile_sources([SourceFile("p.scl", text)], profile=profile).program.blocks
    assert any(b.number == 94 and b.attributes.get("NAME") == "ATH" for b in blocks.values())
    assert FUNCTIONS["HTA"].number == 95


@pytest.mark.parametrize("profile", ["S7-300", "S7-400"])
def test_strg_to_chars_and_chars_to_strg_need_the_s7_1500_profile(profile: str) -> None:
    text = fc(
        "Strg_TO_Chars(Strg := s, pChars := 0, Cnt => n, Chars := c);\n"
        "Chars_TO_Strg(Chars := c, pChars := 0, Cnt := 0, Strg => s);",
        "s : STRING[4]; n : INT; c : ARRAY[0..3] OF CHAR;",
    )
    assert problems(text, profile) == [("SCL500", 6), ("SCL500", 7)]


def test_the_character_instructions_check_their_parameters() -> None:
    text = fc(
        "Strg_TO_Chars(Strg := s, pChars := 0, Cnt => n);\n"
        "Chars_TO_Strg(Chars := c, pChars := 0, Cnt := 0, Strg => s, Size := 3);\n"
        "r := ATH(IN := c, N := 2);\n"
        "r := HTA(IN := c, N := 2, OUT => c, ENO => s);",
        "s : STRING[4]; n : UINT; c : ARRAY[0..3] OF CHAR; r : WORD;",
    )
    found = problems(text)
    assert ("SCL227", 6) in found  # Chars missing
    assert ("SCL223", 7) in found  # no parameter Size
    assert ("SCL227", 8) in found  # OUT missing
    assert any(line == 9 for _code, line in found)  # ENO is a BOOL


def test_a_constant_or_an_array_parameter_of_the_caller_is_refused_with_a_code() -> None:
    text = (
        "FUNCTION F : VOID\nVAR_IN_OUT\n  buf : ARRAY[0..3] OF CHAR;\nEND_VAR\n"
        "VAR_INPUT\n  w : WORD;\nEND_VAR\nVAR_TEMP\n  n : UINT;\n  r : WORD;\n"
        "  t : ARRAY[0..3] OF CHAR;\nEND_VAR\nBEGIN\n"
        "Strg_TO_Chars(Strg := 'ab', pChars := 0, Cnt => n, Chars := buf);\n"
        "r := HTA(IN := w, N := 2, OUT => t);\n"  # an elementary parameter: its width is known
        "r := ATH(IN := buf, N := 4, OUT => w);\n"
        "r := HTA(IN := 16#12, N := 1, OUT => t);\n"  # a constant: no variable to point to
        "END_FUNCTION\n"
    )
    assert problems(text) == [("SCL801", 14), ("SCL801", 16), ("SCL554", 17)]


def test_the_character_instructions_are_no_longer_unsimulated_system_names() -> None:
    from nasaq.lang.tia_system import tia_system

    assert [tia_system(n) for n in ("ATH", "HTA", "Strg_TO_Chars", "Chars_TO_Strg")] == [None] * 4

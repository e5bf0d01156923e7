"""STEP 7's ``L#`` DINT constants and TIA Portal's number/STRING and TIME conversions in SCL
(issue 20): each checked, lowered and run on the CPU under the profiles that have it."""

from __future__ import annotations

import pytest
from scl_run import build, ob1, read

from nasaq.lang.stl import SourceFile, compile_sources


def problems(text: str, profile: str = "S7-300") -> list[tuple[str, int]]:
    result = compile_sources([SourceFile("prog.scl", text)], profile=profile)
    return [(d.code, d.span.line) for d in result.diagnostics if d.span and d.severity == "error"]


# ---- L# -----------------------------------------------------------------------------------------


@pytest.mark.parametrize("profile", ["S7-300", "S7-400", "S7-1500"])
def test_l_prefix_is_a_dint_constant_under_every_profile(profile: str) -> None:
    text = ob1(
        "d := L#2000;\nMD10 := DINT_TO_DWORD(d + L#-5);\nMD14 := DINT_TO_DWORD(L#100000 * 3);",
        "d : DINT;",
    )
    cpu = build(text, profile=profile)
    assert read(cpu, "MD10") == 1995
    assert read(cpu, "MD14") == 300000


def test_l_prefix_as_an_initial_value_and_out_of_range() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nVAR\n  delay : DINT := L#2000;\nEND_VAR\nBEGIN\n"
        "MD20 := DINT_TO_DWORD(delay);\n"
        "END_FUNCTION_BLOCK\nDATA_BLOCK DB1 FB1\nBEGIN\nEND_DATA_BLOCK\n" + ob1("FB1.DB1();")
    )
    assert read(build(text), "MD20") == 2000
    assert problems(ob1("MD0 := DINT_TO_DWORD(L#3000000000);")) == [("SCL218", 3)]


# ---- numbers to STRING and back -----------------------------------------------------------------

_TEXTS = "s : STRING[40];\ni : INT;\nd : DINT;\nr : REAL;"


def test_int_dint_real_to_string_give_the_sign_and_digits() -> None:
    text = ob1(
        "i := -42;\ns := INT_TO_STRING(i);\nM0.0 := s = '-42';\n"
        "s := INT_TO_STRING(IN := 7);\nM0.1 := s = '+7';\n"
        "s := DINT_TO_STRING(L#123456);\nM0.2 := s = '+123456';\n"
        "s := DINT_TO_STRING(L#-2147483648);\nM0.3 := s = '-2147483648';\n"
        "s := REAL_TO_STRING(-1.5);\nM0.4 := s = ' -1.500000E+00';\n"
        "s := REAL_TO_STRING(1234.5);\nM0.5 := s = ' +1.234500E+03';\n"
        "s := CONCAT(IN1 := 'n=', IN2 := INT_TO_STRING(0));\nM0.6 := s = 'n=+0';",
        _TEXTS,
    )
    for profile in ("S7-300", "S7-1500"):
        cpu = build(text, profile=profile)
        assert [read(cpu, f"M0.{bit}") for bit in range(7)] == [1] * 7, profile


def test_string_to_int_dint_real_read_blanks_and_a_sign() -> None:
    text = ob1(
        "i := STRING_TO_INT(' 42');\nMW0 := INT_TO_WORD(i);\n"
        "i := STRING_TO_INT('-17 ');\nM30.0 := ENO;\nMW2 := INT_TO_WORD(i);\n"
        "d := STRING_TO_DINT(DINT_TO_STRING(L#-99999));\nMD4 := DINT_TO_DWORD(d);\n"
        "r := STRING_TO_REAL(' 12.5');\nMD8 := DINT_TO_DWORD(REAL_TO_DINT(r * 10.0));\n"
        "r := STRING_TO_REAL('-2.5E+02');\nMD12 := DINT_TO_DWORD(REAL_TO_DINT(r));\n"
        "i := STRING_TO_INT('12ab');\nMW16 := INT_TO_WORD(i);\n"
        "i := STRING_TO_INT(IN := 'x1');\nM30.1 := ENO;\nMW20 := INT_TO_WORD(i);\n"
        "i := STRING_TO_INT('99999');\nMW18 := INT_TO_WORD(i);",
        _TEXTS,
    )
    cpu = build(text)
    assert [read(cpu, "MW0"), read(cpu, "MW2"), read(cpu, "MD4")] == [42, -17, -99999]
    assert [read(cpu, "MD8"), read(cpu, "MD12")] == [125, -250]
    assert read(cpu, "MW16") == 12  # up to the first character of no number
    assert read(cpu, "MW20") == 0  # no number at all
    assert [read(cpu, "M30.0"), read(cpu, "M30.1")] == [1, 0]
    assert read(cpu, "MW18") == 32767  # limited to INT


def test_s7_1500_types_to_string() -> None:
    text = ob1(
        "s := UINT_TO_STRING(u);\nM0.0 := s = '+65535';\n"
        "s := USINT_TO_STRING(us);\nM0.1 := s = '+200';\n"
        "s := SINT_TO_STRING(ss);\nM0.2 := s = '-128';\n"
        "s := UDINT_TO_STRING(ud);\nM0.3 := s = '+4000000000';\n"
        "s := LINT_TO_STRING(li);\nM0.4 := s = '-9000000000';\n"
        "s := ULINT_TO_STRING(ul);\nM0.5 := s = '+18000000000000000000';",
        "s : STRING[40];\nu : UINT;\nus : USINT;\nss : SINT;\nud : UDINT;\nli : LINT;\nul : ULINT;",
    )
    text = text.replace(
        "BEGIN\n",
        "BEGIN\nu := UINT#65535;\nus := USINT#200;\nss := SINT#-128;\nud := UDINT#4000000000;\n"
        "li := LINT#-9000000000;\nul := ULINT#18000000000000000000;\n",
    )
    cpu = build(text, profile="S7-1500")
    assert [read(cpu, f"M0.{bit}") for bit in range(6)] == [1] * 6


def test_s7_1500_type_conversions_need_the_profile() -> None:
    text = ob1("s := UINT_TO_STRING(IN := 5);", "s : STRING[30];")
    assert problems(text) == [("SCL500", 6)]
    assert problems(text, "S7-1500") == []


# ---- TIME conversions of the S7-1200/1500 -------------------------------------------------------


def test_time_to_and_from_numbers_on_s7_1500() -> None:
    text = ob1(
        "u := UDINT#5000;\nt := UDINT_TO_TIME(u);\nM0.0 := t = T#5S;\n"
        "u := TIME_TO_UDINT(T#2S_5MS);\nMD4 := UDINT_TO_DWORD(u);\n"
        "i := TIME_TO_INT(T#1S);\nMW8 := INT_TO_WORD(i);\n"
        "i := TIME_TO_INT(T#40S);\nMW10 := INT_TO_WORD(i);\nM0.1 := ENO;\n"
        "l := TIME_TO_LINT(T#-3S);\nM0.2 := l = LINT#-3000;\n"
        "t := TOD_TO_TIME(TOD#01:00:00.5);\nM0.3 := t = T#1H500MS;",
        "t : TIME;\nu : UDINT;\ni : INT;\nl : LINT;",
    )
    cpu = build(text, profile="S7-1500")
    assert [read(cpu, "M0.0"), read(cpu, "M0.2"), read(cpu, "M0.3")] == [1, 1, 1]
    assert [read(cpu, "MD4"), read(cpu, "MW8")] == [2005, 1000]
    assert read(cpu, "MW10") == 40000 - 65536  # out of INT: its low bits, ENO false
    assert read(cpu, "M0.1") == 0


def test_time_conversions_need_the_s7_1500_profile() -> None:
    text = ob1("t := TOD_TO_TIME(TOD#01:00:00);\ni := TIME_TO_INT(t);", "t : TIME;\ni : INT;")
    assert problems(text) == [("SCL500", 7), ("SCL500", 8)]
    assert problems(text, "S7-1500") == []


def test_string_to_s7_1500_integers_and_more_time_conversions() -> None:
    text = ob1(
        "us := STRING_TO_USINT(' 200');\nM0.0 := us = USINT#200;\n"
        "us := STRING_TO_USINT('300');\nM0.1 := us = USINT#255;\n"
        "ul := STRING_TO_ULINT('18000000000000000000');\n"
        "M0.2 := ul = ULINT#18000000000000000000;\n"
        "t := UINT_TO_TIME(UINT#60000);\nM0.3 := t = T#1M;\n"
        "t := INT_TO_TIME(-250);\nM0.4 := t = T#-250MS;\n"
        "ul := TIME_TO_ULINT(T#3S);\nM0.5 := ul = ULINT#3000;",
        "us : USINT;\nul : ULINT;\nt : TIME;",
    )
    cpu = build(text, profile="S7-1500")
    assert [read(cpu, f"M0.{bit}") for bit in range(6)] == [1] * 6
    classic = ob1("i := STRING_TO_UINT('5');\nt := INT_TO_TIME(i);", "i : INT;\nt : TIME;")
    assert problems(classic) == [("SCL500", 7), ("SCL500", 8)]

"""The compilers protect themselves (``nasaq.lang.limits``): deep nesting, endless numbers,
addresses past the CPU and huge sources get a diagnostic with a code, never an exception."""

from __future__ import annotations

import time

import pytest

from nasaq.lang import limits
from nasaq.lang.scl.parse import parse_source as parse_scl
from nasaq.lang.stl import SourceFile, compile_sources


def codes(name: str, text: str, profile: str = "S7-300") -> list[str]:
    result = compile_sources([SourceFile(name, text)], profile=profile)
    return [found.code for found in result.diagnostics]


def scl(body: str, decl: str = "") -> str:
    return (
        "FUNCTION FC1 : VOID\nVAR_TEMP\n x : INT;\n i : INT;\n b : BOOL;\n"
        f"{decl}END_VAR\nBEGIN\n{body}END_FUNCTION\n"
    )


def stl(body: str, decl: str = "") -> str:
    return f"FUNCTION FC 1 : VOID\n{decl}BEGIN\nNETWORK\nTITLE =\n{body}END_FUNCTION\n"


NESTED = {
    "IF": lambda d: "IF b THEN\n" * d + "x := 1;\n" + "END_IF;\n" * d,
    "FOR": lambda d: "FOR i := 0 TO 1 DO\n" * d + "x := 1;\n" + "END_FOR;\n" * d,
    "WHILE": lambda d: "WHILE b DO\n" * d + "x := 1;\n" + "END_WHILE;\n" * d,
    "CASE": lambda d: "CASE x OF 1:\n" * d + "x := 1;\n" + "END_CASE;\n" * d,
    "REPEAT": lambda d: "REPEAT\n" * d + "x := 1;\n" + "UNTIL b END_REPEAT;\n" * d,
}


@pytest.mark.parametrize("kind", sorted(NESTED))
def test_scl_statements_nested_past_the_limit_get_scl150(kind: str) -> None:
    limit = limits.MAX_STATEMENT_NESTING
    assert "SCL150" not in codes("a.scl", scl(NESTED[kind](limit)))
    found = codes("a.scl", scl(NESTED[kind](3000)))
    assert found.count("SCL150") == 1


@pytest.mark.parametrize(
    "expression",
    [
        "(" * 3000 + "1" + ")" * 3000,
        " + ".join(["1"] * 3000),
        "-" * 3000 + "1",
        "ABS(" * 1000 + "1" + ")" * 1000,
    ],
)
def test_scl_expressions_past_the_limit_get_scl151(expression: str) -> None:
    found = codes("a.scl", scl(f"x := {expression};\n"))
    assert found.count("SCL151") == 1


def test_scl_expressions_within_the_limit_compile() -> None:
    depth = limits.MAX_EXPRESSION_DEPTH - 2
    assert codes("a.scl", scl("x := " + "(" * depth + "1" + ")" * depth + ";\n")) == []


def test_scl_struct_nesting_past_the_limit_gets_scl152() -> None:
    def nest(depth: int) -> str:
        return " s : " + "STRUCT a : " * depth + "INT;" + " END_STRUCT;" * depth + "\n"

    assert "SCL152" not in codes("a.scl", scl("x := 1;\n", nest(limits.MAX_STRUCT_NESTING)))
    assert codes("a.scl", scl("x := 1;\n", nest(2000))).count("SCL152") == 1


def test_scl_numbers_of_thousands_of_digits_get_scl153() -> None:
    assert "SCL153" in codes("a.scl", scl("x := " + "9" * 5000 + ";\n"))
    assert "SCL153" in codes(
        "a.scl", scl("x := 1;\n", " y : ARRAY[0.." + "9" * 5000 + "] OF INT;\n")
    )
    assert "SCL153" in codes("a.scl", scl("FOR i := 1 TO " + "1" * 5000 + " DO\nEND_FOR;\n"))
    elsif = "IF b THEN x := 1; ELSIF x <> " + "9" * 5000 + " THEN x := 2; END_IF;\n"
    assert "SCL153" in codes("a.scl", scl(elsif))
    case = "CASE x OF 1, " + "9" * 5000 + ":\n x := 2;\nEND_CASE;\n"
    assert "SCL153" in codes("a.scl", scl(case))
    assert "SCL153" not in codes("a.scl", scl("x := 32767;\n"))


def _parse_seconds(text: str) -> float:
    started = time.perf_counter()
    parse_scl("a.scl", text)
    return time.perf_counter() - started


def test_scl_recovery_from_stray_comment_ends_is_linear() -> None:
    """32 KB of stray ``*)`` took minutes (each token's fallback lexing scanned the rest of the
    line); four times the text may take about four times as long, not sixteen."""
    parse_scl("a.scl", scl("x := 1;\n"))  # the lexer's regular expressions are built once

    def stray(pairs: int) -> str:
        return scl("*)" * pairs + "\n")

    small = min(_parse_seconds(stray(2048)) for _ in range(2))
    large = _parse_seconds(stray(8192))
    assert large < 10 * small + 0.5
    assert _parse_seconds(stray(16384)) < 60


def test_stl_struct_nesting_past_the_limit_gets_stl150() -> None:
    def nest(depth: int) -> str:
        return (
            "VAR_TEMP\n s : "
            + "STRUCT\n a : " * depth
            + "INT;\n"
            + "END_STRUCT;\n" * depth
            + "END_VAR\n"
        )

    assert "STL150" not in codes(
        "a.awl", stl("A I 0.0\n= Q 0.0\n", nest(limits.MAX_STRUCT_NESTING))
    )
    assert codes("a.awl", stl("A I 0.0\n= Q 0.0\n", nest(3000))).count("STL150") == 1


@pytest.mark.parametrize(
    "line",
    [
        "A M " + "9" * 5000 + ".0",
        "L MW " + "9" * 5000,
        "OPN DB " + "9" * 5000,
        "A DB" + "9" * 5000 + ".DBX 0.0",
        "A DB70000.DBX 0.0",
        "L " + "9" * 5000,
        "L P#" + "9" * 5000 + ".0",
        "L T#" + "9" * 500 + "D",
        "L B#(" + "9" * 5000 + ", 1)",
        "L B#(x, 1)",
        "L D#" + "9" * 5000 + "-1-1",
        "L D#99999999999-1-1",
        "L TOD#" + "9" * 5000 + ":0:0",
        "L S5T#" + "9" * 400 + "S",
    ],
)
def test_stl_numbers_and_addresses_past_the_cpu_are_refused(line: str) -> None:
    found = codes("a.awl", stl(f"{line}\nT MW 10\n"))
    assert found, line
    assert all(code.startswith("STL") for code in found)


def test_stl_array_bounds_of_thousands_of_digits_are_refused() -> None:
    decl = "VAR_TEMP\n a : ARRAY[0.." + "9" * 5000 + "] OF INT;\nEND_VAR\n"
    found = codes("a.awl", stl("L #a[1]\nT MW 0\n", decl))
    assert "STL153" in found
    assert all(code.startswith("STL") for code in found)
    assert "STL153" not in codes("a.awl", stl("L #a[1]\nT MW 0\n", decl.replace("9" * 5000, "9")))


def test_a_million_line_source_is_refused_at_once() -> None:
    started = time.perf_counter()
    for name in ("a.awl", "a.scl", "a.lad"):
        assert codes(name, "\n" * 1_000_000) == ["STL151"]
    assert time.perf_counter() - started < 5
    assert codes("a.awl", stl("NOP 0\n" * 1000)) == []


DB_END = "BEGIN\nEND_DATA_BLOCK\n"


@pytest.mark.parametrize(
    ("name", "text"),
    [
        (
            "a.awl",
            "DATA_BLOCK DB 1\nSTRUCT\n a : ARRAY[0..{n}] OF INT;\nEND_STRUCT;\n" + DB_END,
        ),
        (
            "a.scl",
            "DATA_BLOCK DB1\nSTRUCT\n a : ARRAY[0..{n}] OF INT;\nEND_STRUCT\n" + DB_END,
        ),
        (
            "a.scl",
            "FUNCTION_BLOCK FB1\nVAR\n a : ARRAY[0..{n}] OF INT;\nEND_VAR\nBEGIN\n"
            "a[1] := 2;\nEND_FUNCTION_BLOCK\nDATA_BLOCK DB2 FB1\nBEGIN\nEND_DATA_BLOCK\n",
        ),
    ],
)
def test_a_data_block_over_the_profile_limit_gets_stl152(name: str, text: str) -> None:
    """A DB image is built at its declared size: 64 KB on the S7-300/400, 5 MB on the S7-1500,
    and an ARRAY[0..2000000000] is refused instead of taking gigabytes."""
    assert "STL152" not in codes(name, text.format(n=32000))
    assert "STL152" in codes(name, text.format(n=40000))
    assert "STL152" not in codes(name, text.format(n=40000), profile="S7-1500")
    assert "STL152" in codes(name, text.format(n=2_000_000_000), profile="S7-1500")


def test_a_huge_repeat_factor_in_initial_values_does_not_loop() -> None:
    text = (
        "DATA_BLOCK DB 1\nSTRUCT\n y : ARRAY[1..2] OF BOOL := 2147483648 (TRUE);\n"
        "END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
    )
    started = time.perf_counter()
    found = codes("a.awl", text)
    assert found
    assert time.perf_counter() - started < 5

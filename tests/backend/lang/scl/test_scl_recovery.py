"""Syntax errors in SCL: one mistake gives one diagnostic at the right place, and parsing goes
on at the next ``;`` or END_xxx, so the blocks after the mistake are still there."""

from __future__ import annotations

import pytest

from nasaq.lang.scl import ast, parse_source


def _fc(body: str, decls: str = "") -> str:
    return f"FUNCTION FC1 : VOID\n{decls}BEGIN\n{body}\nEND_FUNCTION\n"


CASES = [
    # (source, [(code, line, column)], statements left in FC1's code)
    (_fc("  x := 1 +;\n  y := 2;"), [("SCL101", 3, 11)], 1),
    (_fc("  x := 1\n  y := 2;"), [("SCL101", 4, 3)], 0),
    (_fc("  IF a THEN x := 1;"), [("SCL101", 4, 1)], 1),
    (_fc("  x := 1 ? 2;\n  y := 2;"), [("SCL102", 3, 10)], 1),
    (_fc("  FOR i := 1 TO 5 DO x := 1; END_WHILE;\n  y := 1;"), [("SCL101", 3, 30)], 2),
    (_fc("  IF a THEN x := 1; END_IF\n  y := 1;"), [("SCL101", 4, 3)], 1),
    (_fc("  CASE x OF 1: y := 1; a b; 2: y := 2; END_CASE;"), [("SCL101", 3, 26)], 1),
    (_fc("  x := 1;", "VAR_INPUT a : : INT; b : INT; END_VAR\n"), [("SCL101", 2, 15)], 1),
    (_fc("  x := 1;", "VAR_INPUT a : INT;\n"), [("SCL101", 3, 1)], 1),
    (_fc("  x := 1;", "  := 5\n"), [("SCL101", 2, 3)], 1),
    ("FUNCTION FC1 : VOID\nBEGIN\n  x := 1;\n", [("SCL103", 3, 9)], 1),
    (_fc("  END_IF;\n  x := 1;"), [("SCL101", 3, 3)], 1),
    (_fc("  x := (a + b;\n  y := 1;"), [("SCL101", 3, 14)], 1),
    (_fc("  x := 1;\n  y := 'open;\n  z := 2;"), [("SCL102", 4, 8)], 2),
]


@pytest.mark.parametrize(("text", "expected", "statements"), CASES)
def test_one_mistake_gives_one_diagnostic(
    text: str, expected: list[tuple[str, int, int]], statements: int
) -> None:
    result = parse_source("test.scl", text)
    found = [
        (item.code, item.span.line, item.span.column) for item in result.diagnostics if item.span
    ]
    assert found == expected, [item.message for item in result.diagnostics]
    [block] = result.source.blocks
    assert block.name.text == "FC1"
    real = [item for item in block.code if not isinstance(item, ast.Bad | ast.Empty)]
    assert len(real) == statements


def test_the_blocks_after_a_mistake_are_parsed() -> None:
    text = (
        "FUNCTION FC1 : VOID\nBEGIN\n  FOR i := 1 TO 5 DO x := 1; END_WHILE;\nEND_FUNCTION\n"
        "FUNCTION FC2 : VOID\nBEGIN\n  x := 1;\nEND_FUNCTION\n"
    )
    result = parse_source("test.scl", text)
    assert [item.code for item in result.diagnostics] == ["SCL101"]
    assert [block.name.text for block in result.source.blocks] == ["FC1", "FC2"]


def test_messages_name_the_token_and_what_was_expected() -> None:
    result = parse_source("test.scl", _fc("  IF a THEN x := 1; END_IF\n  y := 1;"))
    [found] = result.diagnostics
    assert found.message == "Syntax error: unexpected 'y'; expected ';'."
    assert found.key == "scl_unexpected_token"
    assert found.span is not None
    assert found.span.file == "test.scl"
    missing = parse_source("test.scl", "ORGANIZATION_BLOCK OB1\nBEGIN\n  IF a THEN\n")
    assert [item.message for item in missing.diagnostics] == [
        "The source ends inside IF: END_IF is missing."
    ]


def test_too_many_errors_stop_the_parse() -> None:
    body = "\n".join("  x := := 1;\n  y := 2;" for _ in range(60))
    result = parse_source("many.scl", _fc(body))
    codes = [item.code for item in result.diagnostics]
    assert codes[-1] == "SCL104"
    assert codes.count("SCL101") == 50


def test_a_byte_order_mark_is_ignored() -> None:
    result = parse_source("bom.scl", "\ufeff" + _fc("  x := 1;"))
    assert result.diagnostics == []

"""Bracket and MCR nesting is checked when a block compiles, as STEP 7 does."""

import pytest

from nasaq.lang.stl import SourceFile, compile_sources


def _codes(body: str) -> list[tuple[str, int]]:
    source = f"ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n{body}END_ORGANIZATION_BLOCK\n"
    result = compile_sources([SourceFile("OB1.awl", source)])
    return [(d.code, d.span.line if d.span and d.span.line else 0) for d in result.diagnostics]


def test_balanced_brackets_and_mcr_areas_compile() -> None:
    body = "A(;\nO I 0.0;\nO(;\nA I 0.1;\n);\n);\n= Q 0.0;\nMCRA;\nMCR(;\n)MCR;\nMCRD;\n"
    assert _codes(body) == []


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        ("A(;\nO I 0.0;\n= Q 0.0;\n", [("STL238", 4)]),
        ("A I 0.0;\n);\n= Q 0.0;\n", [("STL239", 5)]),
        ("MCR(;\n", [("STL238", 4)]),
        (")MCR;\n", [("STL239", 4)]),
        ("A(;\n" * 8 + ");\n" * 8, [("STL240", 11)]),
    ],
)
def test_unbalanced_or_too_deep_nesting_is_one_error_at_its_line(
    body: str, expected: list[tuple[str, int]]
) -> None:
    assert _codes(body) == expected


def test_a_source_without_blocks_is_a_warning() -> None:
    result = compile_sources([SourceFile("empty.awl", "// nothing here\n")])
    assert [d.code for d in result.diagnostics] == ["STL112"]
    assert result.ok

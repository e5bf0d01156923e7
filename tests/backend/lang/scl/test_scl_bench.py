"""The benchmark's generated sources are valid SCL (a broken generator would measure recovery)."""

from __future__ import annotations

from nasaq.lang.scl import ast
from nasaq.lang.scl.bench import dense, program
from nasaq.lang.scl.parse import parse_source
from nasaq.lang.stl import SourceFile, compile_sources


def test_the_mixed_bench_source_parses_without_diagnostics() -> None:
    text = program(1500)
    result = parse_source("bench.scl", text)
    assert result.diagnostics == []
    assert text.count("\n") >= 1500
    kinds = {block.kind for block in result.source.blocks}
    assert kinds == {"DATA_BLOCK", "FUNCTION_BLOCK", "FUNCTION"}  # the DBs the code addresses


def test_the_dense_bench_source_parses_without_diagnostics() -> None:
    result = parse_source("dense.scl", dense(5))
    assert result.diagnostics == []
    (block,) = result.source.blocks
    assert len(block.code) == 5
    assert all(isinstance(stmt, ast.If) for stmt in block.code)


def test_the_benchmark_source_compiles_without_problems() -> None:
    """``make bench`` compiles it whole (check and lowering too): it must stay valid SCL."""
    result = compile_sources([SourceFile("bench.scl", program(600))])
    assert [str(item) for item in result.diagnostics] == []
    assert result.generated

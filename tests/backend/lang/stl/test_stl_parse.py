# ruff: noqa: E501  (test sources are easier to read on one line)
"""Text → AST: block forms, line endings, recovery (one typo, one message), bad input."""

from __future__ import annotations

import gc
import random
import time

import pytest
from stl_helpers import codes, compile_text, ob1

from nasaq.lang.stl import SourceFile, ast, compile_sources
from nasaq.lang.stl.bench import SYMBOLS, mixed_program
from nasaq.lang.stl.bench import main as bench_main
from nasaq.lang.stl.parse import parse_source


def test_blocks_headers_and_networks() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nTITLE =\nAUTHOR : IJ\nVERSION : 0.1\n\nVAR_OUTPUT\n  SSL_error : BOOL ;\n"
        "END_VAR\nVAR\n  t_lvw : INT ;\nEND_VAR\nVAR_TEMP\n  v_max_l : INT ;\n  v_min_l : INT ;\n"
        'END_VAR\nBEGIN\nNETWORK\nTITLE =\n  A "DO_SpLVw";\n  JNB _001;\n_001: NOP 0;\n'
        "END_FUNCTION_BLOCK\n"
    )
    result = parse_source("fb1.awl", text)
    assert result.diagnostics == []
    (block,) = result.source.blocks
    assert (block.keyword, block.ident) == ("FUNCTION_BLOCK", "FB1")
    sections = [item for item in block.head if isinstance(item, ast.VarSectionNode)]
    assert [section.kind for section in sections] == ["VAR_OUTPUT", "VAR", "VAR_TEMP"]
    assert [type(item).__name__ for item in block.code] == [
        "NetworkNode",
        "TitleNode",
        "InstrNode",
        "InstrNode",
        "LabelNode",
        "InstrNode",
    ]


def test_crlf_and_lf_give_the_same_tree() -> None:
    text = ob1("  A I 0.0\n  = Q 4.0;\n  L 'A;B'   // comment ; with semicolon")
    lf = parse_source("a.awl", text)
    crlf = parse_source("a.awl", text.replace("\n", "\r\n"))
    assert lf.diagnostics == crlf.diagnostics == []
    assert lf.source.blocks[0].code == crlf.source.blocks[0].code


def test_statements_end_at_semicolon_or_newline_and_calls_span_lines() -> None:
    text = ob1(
        "  A I 0.0; A I 0.1\n  CALL FC 1 (\n    X := M 0.0,  // first\n    Y := MW 2,\n  )\n  NOP 0"
    )
    (block,) = parse_source("a.awl", text).source.blocks
    instructions = [item for item in block.code if isinstance(item, ast.InstrNode)]
    assert [item.mnemonic for item in instructions] == ["A", "A", "CALL", "NOP"]
    assert [arg.name for arg in instructions[2].args or []] == ["X", "Y"]


def test_code_outside_blocks_is_an_implicit_ob1() -> None:
    result = compile_text("  SET\n  = M 0.0\n")
    assert result.ok
    assert [item.op for item in result.program.get("OB", 1).code] == ["SET", "="]  # type: ignore[arg-type,union-attr]


def test_one_typo_gives_exactly_one_diagnostic_and_later_errors_are_found() -> None:
    text = ob1("  A I 0.0 0.0\n  A I 0.1\n  = Q 4.0\n  L DBW [AR1 P#0.0]\n  A M 0.0")
    result = compile_text(text)
    assert codes(result) == [("STL101", 3, 11), ("STL101", 6, 15)]


def test_recovery_inside_declarations_and_at_keywords() -> None:
    text = (
        "FUNCTION FC 1 : VOID\nVAR_INPUT\n  x : INT;\n  y : ;\nBEGIN\n  L #x\n  A I 0.0 1\n"
        "END_FUNCTION\n"
    )
    result = compile_text(text)
    # the missing END_VAR before BEGIN belongs to the same broken declaration: no second message
    assert codes(result) == [("STL101", 4, 7), ("STL101", 7, 11)]


def test_missing_end_keyword_is_reported_once_and_next_block_still_parses() -> None:
    text = "ORGANIZATION_BLOCK OB 1\nBEGIN\n  A I 0.0\nFUNCTION FC 2 : VOID\nBEGIN\n  NOP 0\nEND_FUNCTION\n"
    result = parse_source("t.awl", text)
    assert [item.code for item in result.diagnostics] == ["STL101"]
    assert [block.ident for block in result.source.blocks] == ["OB 1", "FC 2"]


def test_end_of_file_inside_a_block() -> None:
    result = compile_text("FUNCTION FC 2 : VOID\nBEGIN\n  NOP 0\n")
    assert [(code, line) for code, line, _ in codes(result)] == [("STL103", 3)]
    assert "END_FUNCTION" in result.diagnostics[0].message


def test_binary_input_is_one_diagnostic() -> None:
    result = compile_sources([SourceFile("x.awl", bytes(range(256)) * 4000)])
    assert [item.code for item in result.diagnostics] == ["STL105"]


def test_garbage_input_stops_after_many_errors_without_an_exception() -> None:
    rng = random.Random(7)
    junk = "".join(rng.choice("abcxyz ;:=()[]#\"'\n0123456789.,") for _ in range(200_000))
    result = compile_sources([SourceFile("junk.awl", junk)])
    assert not result.ok
    assert result.diagnostics[-1].code == "STL104" or len(result.diagnostics) < 60


def test_ten_megabytes_of_garbage_is_fast() -> None:
    rng = random.Random(3)
    chunk = "".join(rng.choice('abcdefgh ijk;:=()[]#"\n0123456789') for _ in range(100_000))
    started = time.perf_counter()
    result = compile_sources([SourceFile("big.awl", chunk * 100)])
    assert time.perf_counter() - started < 5
    assert not result.ok


def test_five_thousand_lines_parse_well_under_a_second() -> None:
    network = "NETWORK\nTITLE = Motor\n  A I 0.0;\n  O M 10.1;\n  AN I 0.1;\n  = M 10.1;\n  L MW 20;\n  +I ;\n  T MW 20;\n"
    text = "FUNCTION FC 1 : VOID\nBEGIN\n" + network * 560 + "END_FUNCTION\n"
    assert text.count("\n") > 5000
    parse_source("warm.awl", "")
    started = time.perf_counter()
    result = parse_source("big.awl", text)
    assert time.perf_counter() - started < 0.8
    assert result.diagnostics == []


def test_five_thousand_mixed_lines_compile_well_under_a_second() -> None:
    text = mixed_program(100_000)  # FBs, FCs and OBs: locals, symbols, DB members, calls
    assert text.count("\n") > 5000
    compile_sources([SourceFile("warm.awl", "NOP 0\n")])
    started = time.perf_counter()
    result = compile_sources([SourceFile("big.awl", text), SourceFile("s.csv", SYMBOLS)])
    assert time.perf_counter() - started < 1.0
    assert result.ok, result.diagnostics[:3]
    assert gc.isenabled()  # switched off while compiling only


def test_the_compile_benchmark_runs(capsys: pytest.CaptureFixture[str]) -> None:
    assert bench_main(["bench", "0.02"]) == 0
    assert "lines/s" in capsys.readouterr().out

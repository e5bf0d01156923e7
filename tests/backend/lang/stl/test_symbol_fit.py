"""A symbol's data type must fit its address (STEP 7's symbol editor rule): the loader reports
SYT001 with the table's line, the table editor SYT002 on the type cell, and every symbol table
shipped with Nasaq (examples, course programs, scenarios) still loads without one."""

from __future__ import annotations

from pathlib import Path

import pytest
from stl_helpers import compile_text, ob1

from nasaq.lang.stl import SourceFile
from nasaq.lang.stl.addresses import parse_address
from nasaq.lang.stl.symbol_fit import misfit
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES, SymbolTable, read_symbol_table
from nasaq.workbench.symbol_table import SymbolRow, problems

ROOT = Path(__file__).resolve().parents[4]


@pytest.mark.parametrize(
    ("address", "type_text"),
    [
        ("M 1.0", "BOOL"),
        ("E 0.0", "bool"),
        ("MB 2", "BYTE"),
        ("QB 4", "CHAR"),
        ("MW 10", "INT"),
        ("PIW 256", "WORD"),
        ("MW 12", "S5TIME"),
        ("MW 14", "DATE"),
        ("MD 4", "REAL"),
        ("MD 8", "DINT"),
        ("MD 12", "TIME"),
        ("MD 16", "TOD"),
        ("MD 20", "TIME_OF_DAY"),
        ("T 1", "TIMER"),
        ("Z 2", "COUNTER"),
        ("FB 10", "FB 10"),
        ("DB 10", "FB10"),
        ("DB 11", "SFB 4"),
        ("DB 12", "UDT 1"),
        ("DB 1", "DB 1"),
        ("OB 1", "OB 1"),
        ("MW 10", ""),  # no type: not judged here
        ("MW 10", "FLOAT"),  # unknown: the table editor's API123
    ],
)
def test_types_that_fit(address: str, type_text: str) -> None:
    assert misfit(parse_address(address), type_text) is None


@pytest.mark.parametrize(
    ("address", "type_text", "allowed"),
    [
        ("M 1.0", "INT", "BOOL"),
        ("MW 10", "BOOL", "WORD, INT, S5TIME, DATE"),
        ("I 0.0", "REAL", "BOOL"),
        ("MD 4", "INT", "DWORD, DINT, REAL, TIME, TIME_OF_DAY"),
        ("MB 1", "WORD", "BYTE, CHAR"),
        ("MD 4", "DATE_AND_TIME", "DWORD, DINT, REAL, TIME, TIME_OF_DAY"),
        ("T 1", "INT", "TIMER"),
        ("C 1", "TIMER", "COUNTER"),
        ("M 0.0", "TIMER", "BOOL"),
        ("FB 1", "FC 1", "FB 1"),
        ("FC 2", "FC 3", "FC 2"),
        ("DB 5", "FC 1", "DB 5, FB n, SFB n, UDT n"),
    ],
)
def test_types_that_do_not_fit(address: str, type_text: str, allowed: str) -> None:
    assert misfit(parse_address(address), type_text) == allowed


def test_the_loader_reports_the_line_and_keeps_the_symbol() -> None:
    table = SymbolTable()
    text = "Start,I 0.0,BOOL\nCount,M 1.0,INT\nSpeed,MW 10,BOOL\n"
    found = read_symbol_table("symbols.csv", text, table)
    assert [(d.code, d.severity, d.span and d.span.line) for d in found] == [
        ("SYT001", "error", 2),
        ("SYT001", "error", 3),
    ]
    assert found[0].params == {
        "file": "symbols.csv",
        "line": 2,
        "name": "Count",
        "type": "INT",
        "address": "M 1.0",
        "allowed": "BOOL",
    }
    # Still defined: its uses are not reported as undefined on top.
    assert table.get("count") is not None


def test_a_program_with_such_a_table_does_not_compile() -> None:
    result = compile_text(
        ob1('      A     "Count"\n      =     Q 4.0'),
        SourceFile("symbols.sdf", '"Count","M 1.0","INT",""\n'),
    )
    errors = [(d.code, d.span and d.span.file, d.span and d.span.line) for d in result.diagnostics]
    assert ("SYT001", "symbols.sdf", 1) in errors
    assert not any(code == "STL205" for code, _file, _line in errors)


def test_the_table_editor_marks_the_type_cell() -> None:
    rows = [
        SymbolRow(name="Count", address="M 1.0", type="INT"),
        SymbolRow(name="Level", address="MD 4", type="REAL"),
        SymbolRow(name="Speed", address="MW 10", type="BOOL"),
        SymbolRow(name="Bad", address="X 9", type="INT"),  # the address is the problem
    ]
    found = [(p.row, p.field, p.problem.code, p.problem.severity) for p in problems(rows)]
    assert found == [
        (0, "type", "SYT002", "error"),
        (2, "type", "SYT002", "error"),
        (3, "address", "API120", "error"),
    ]
    assert problems(rows)[0].problem.params == {
        "row": 1,
        "type": "INT",
        "address": "M 1.0",
        "allowed": "BOOL",
    }


def _shipped_tables() -> list[Path]:
    found = []
    for folder in ("examples", "tests/scenarios", "frontend/public"):
        base = ROOT / folder
        if base.is_dir():
            found += [p for p in base.rglob("*") if p.suffix.lower() in SYMBOL_TABLE_SUFFIXES]
    return sorted(found)


def test_every_shipped_symbol_table_fits() -> None:
    tables = _shipped_tables()
    assert len(tables) >= 30  # the examples, the course programs and the SCL scenarios
    for path in tables:
        found = read_symbol_table(
            path.name, path.read_text("utf-8", errors="replace"), SymbolTable()
        )
        assert [d.message for d in found if d.code == "SYT001"] == [], path

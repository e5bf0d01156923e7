"""The SCL type checker: each rule with a failing and a passing case, as snapshots of
(code, line, column). One mistake gives one diagnostic: nothing built on an expression whose
type is already an error is reported again."""

from __future__ import annotations

from pathlib import Path

import pytest

from nasaq.lang.scl import check_sources, parse_source
from nasaq.lang.stl.symbols import SymbolTable, read_symbol_table

# Line 5 is the statement under test; column 3 is where it starts.
HEAD = (
    "FUNCTION_BLOCK FB1\n"
    "VAR_INPUT inp : INT; pin : STRUCT v : INT; END_STRUCT; END_VAR\n"
    "VAR k : INT; d : DINT; r : REAL; w : WORD; b : BYTE; x : BOOL; dw : DWORD; t : TIME;"
    " s5 : S5TIME; c : CHAR; s : STRING[10]; a : ARRAY[1..5] OF INT;"
    " mx : ARRAY[1..3, 1..4] OF INT; row : ARRAY[1..4] OF INT; rec : STRUCT v : INT; END_STRUCT;"
    " END_VAR\n"
    "BEGIN\n"
)
TAIL = """
END_FUNCTION_BLOCK
FUNCTION Half : INT
VAR_INPUT v : INT; END_VAR
BEGIN
  Half := v DIV 2;
END_FUNCTION
DATA_BLOCK "Data"
STRUCT count : INT; flags : ARRAY[0..7] OF BOOL; END_STRUCT
BEGIN
END_DATA_BLOCK
"""
SYMBOLS = "Start button,I 0.0,BOOL,\nSpeed,MW 10,INT,\nLevel,IW 4,,\n"

CASES = [
    # issue 20b: a DB without source (SCL923), a STRING's character needs S7-1200/1500
    ("k := DB77.cnt;", [("SCL923", 5, 13)]),
    ("c := s[2];", [("SCL500", 5, 8)]),
    # undeclared names: once per name and block
    ("zz := 1;", [("SCL201", 5, 3)]),
    ("zz := zz + 1;", [("SCL201", 5, 3)]),
    ("k := #zz;", [("SCL201", 5, 8)]),
    ('k := "Nowhere";', [("SCL201", 5, 8)]),
    ('k := #k + "Speed" + Speed + "Data".count + Half(v := k);', []),
    ("OK := FALSE; x := OK AND ENO; ENO := x;", []),  # the OK flag and ENO are predefined
    # no cascade: the unknown name is the only message
    ("k := zz + 1 + w;", [("SCL201", 5, 8)]),
    # operand types, implicit conversions (class A) in operations
    ("k := w + k;", [("SCL211", 5, 8)]),
    ("x := w = -23;", [("SCL211", 5, 8)]),  # 0..65535 compares as a WORD (issue 20, forms)
    ("x := 'A' + 'B';", [("SCL211", 5, 8)]),
    ("x := (k <= 0) + (d > 0);", [("SCL211", 5, 8)]),
    ("d := k + d;", []),
    ("r := k * r + d / 2;", []),
    ("x := b <> w;", []),
    ("t := t + T#1s;", []),
    ("r := SQRT(k) + ABS(r) ** 2;", []),
    ("dw := SHL(IN := w, N := 2) OR b;", []),
    ("x := NOT k;", [("SCL212", 5, 8)]),
    ("w := NOT b;", []),
    # assignment compatibility
    ("k := w;", [("SCL213", 5, 8)]),
    ("k := r;", [("SCL213", 5, 8)]),
    ("k := MW10;", [("SCL213", 5, 8)]),
    ("k := Level;", [("SCL213", 5, 8)]),
    ("k := DB1.DW2;", [("SCL213", 5, 8)]),
    ("k := b;", [("SCL213", 5, 8)]),  # TIA Portal has BYTE_TO_INT
    ("k := t;", [("SCL214", 5, 8)]),
    ("x := 2;", [("SCL214", 5, 8)]),
    ("c := 'AB';", [("SCL214", 5, 8)]),
    ("a := rec;", [("SCL214", 5, 8)]),
    ("k := WORD_TO_INT(w);", []),
    ("w := b; dw := w; r := d; d := k;", []),
    ("x := 1; M0.0 := 1; MW[k] := w; Q[k, 0] := TRUE;", []),
    ("c := 'A'; s := 'hello'; s := c;", []),
    ("s5 := T#1H_20M_10S_30MS;", []),
    ("mx[2] := row; k := mx[2, 3];", []),
    # assignment to an input parameter
    ("inp := 1;", [("SCL215", 5, 3)]),
    ("pin.v := 1;", [("SCL215", 5, 3)]),
    ("k := inp + pin.v;", []),
    # number of indices
    ("k := a[1, 2];", [("SCL216", 5, 8)]),
    ("x := I[k];", [("SCL216", 5, 8)]),
    ("k := k[1];", [("SCL217", 5, 8)]),
    ("k := a[r];", [("SCL213", 5, 10)]),
    ('x := I[k, 1] AND "Data".flags[k];', []),
    # constant indices within the bounds of each dimension
    ('k := a[5] + mx[3, 4] + a[k + 10] + a[2 * 3 - 5]; x := "Data".flags[0];', []),
    ("k := a[6];", [("SCL249", 5, 10)]),
    ("a[0] := 1;", [("SCL249", 5, 5)]),
    ("k := a[6] + w;", [("SCL249", 5, 10)]),
    ("k := mx[4, 0];", [("SCL249", 5, 11), ("SCL249", 5, 14)]),
    ("mx[4] := row;", [("SCL249", 5, 6)]),
    (
        "k := a[2 * 3] + a[-1] + a[INT#7] + a[16#A];",
        [("SCL249", 5, 10), ("SCL249", 5, 21), ("SCL249", 5, 29), ("SCL249", 5, 40)],
    ),
    ('x := "Data".flags[8];', [("SCL249", 5, 21)]),
    ("k := a[1, 9];", [("SCL216", 5, 8)]),
    # members
    ("k := rec.zz;", [("SCL222", 5, 12)]),
    ('k := "Data".nothing;', [("SCL222", 5, 15)]),
    ("k := rec.v + DB1.count;", []),
    # constants: out of range, invalid
    ("k := 40000;", [("SCL218", 5, 8)]),
    ("k := INT#40000;", [("SCL218", 5, 8)]),
    ("b := B#16#1FF;", [("SCL218", 5, 8)]),
    ("t := D#1989-12-31 - D#1990-01-01;", [("SCL218", 5, 8)]),
    ("s5 := T#3h;", [("SCL218", 5, 9)]),
    ("x := BOOL#2;", [("SCL219", 5, 8)]),
    ("d := 40000; k := -32768; k := INT#-32768; b := BYTE#255; w := W#16#FFFF;", []),
    ("w := B#(25, 25); dw := 16#FFFF_FFFF; t := T#-24d20h31m23s647ms;", []),
    # conditions must be BOOL
    ("IF k THEN x := TRUE; END_IF;", [("SCL220", 5, 6)]),
    ("IF x THEN k := 0; ELSIF w THEN k := 1; END_IF;", [("SCL220", 5, 27)]),
    ("WHILE w DO k := 1; END_WHILE;", [("SCL220", 5, 9)]),
    ("REPEAT k := k + 1; UNTIL k END_REPEAT;", [("SCL220", 5, 28)]),
    ("IF k > 0 AND x THEN k := 0; ELSIF NOT x THEN k := 1; END_IF;", []),
    ("WHILE k < 10 DO k := k + 1; END_WHILE; REPEAT k := k - 1; UNTIL k = 0 END_REPEAT;", []),
    # FOR variable
    ("FOR r := 1 TO 10 DO k := 1; END_FOR;", [("SCL221", 5, 7)]),
    ("FOR k := 1 TO d DO x := TRUE; END_FOR;", [("SCL213", 5, 17)]),
    ("FOR k := 10 TO 1 BY -2 DO a[k] := k; END_FOR; FOR d := 1 TO k DO ; END_FOR;", []),
    # nested statements are checked too
    (
        "IF x THEN FOR k := 1 TO 2 DO CASE k OF 1: w := k; END_CASE; END_FOR; END_IF;",
        [("SCL213", 5, 50)],
    ),
]

# Whole blocks: CONST names in indices and bounds, an array the lexer read as an area (m[4]).
BLOCK_CASES: list[tuple[str, list[tuple[str, int, int]]]] = [
    (
        "FUNCTION_BLOCK FB1\nCONST N := 10; HALF := N DIV 2; END_CONST\n"
        "VAR a : ARRAY[1..N] OF INT; m : ARRAY[0..3] OF INT; k : INT; END_VAR\nBEGIN\n"
        "  a[N] := a[HALF] + m[3] + m[HALF - 2];\n"
        "  a[N + 1] := 0;\n  k := a[HALF * 3];\n  k := m[4] + m[HALF - 6];\n"
        "END_FUNCTION_BLOCK\n",
        [("SCL249", 6, 5), ("SCL249", 7, 10), ("SCL249", 8, 10), ("SCL249", 8, 17)],
    ),
    (  # a variable hides the CONST of its name: its index is not constant
        "FUNCTION_BLOCK FB1\nCONST N := 10; END_CONST\n"
        "VAR a : ARRAY[1..3] OF INT; END_VAR\nVAR_TEMP n : INT; END_VAR\nBEGIN\n"
        "  a[n] := 1;\nEND_FUNCTION_BLOCK\n",
        [],
    ),
]

# The complete programs, for the count of erroneous programs (test_scl_check_corpus.py).
PROGRAMS = [(HEAD + "  " + body + TAIL, expected) for body, expected in CASES] + BLOCK_CASES


def _symbols() -> SymbolTable:
    table = SymbolTable()
    assert read_symbol_table("symbols.csv", SYMBOLS, table) == []
    return table


@pytest.mark.parametrize(("body", "expected"), CASES)
def test_rule_snapshot(body: str, expected: list[tuple[str, int, int]]) -> None:
    parsed = parse_source("test.scl", HEAD + "  " + body + TAIL)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source], _symbols())
    found = [(item.code, item.span.line, item.span.column) for item in diagnostics if item.span]
    assert found == expected, [item.message for item in diagnostics]


@pytest.mark.parametrize(("text", "expected"), BLOCK_CASES)
def test_block_snapshot(text: str, expected: list[tuple[str, int, int]]) -> None:
    parsed = parse_source("test.scl", text)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source])
    found = [(item.code, item.span.line, item.span.column) for item in diagnostics if item.span]
    assert found == expected, [item.message for item in diagnostics]


def test_index_out_of_bounds_message() -> None:
    parsed = parse_source("test.scl", HEAD + "  k := mx[2, 5];" + TAIL)
    _index, diagnostics = check_sources([parsed.source])
    assert [item.message for item in diagnostics] == [
        "The index 5 is outside the bounds 1..4 of mx."
    ]


def test_messages_name_the_types_and_the_conversion() -> None:
    parsed = parse_source("test.scl", HEAD + "  k := w; k := zz;" + TAIL)
    _index, diagnostics = check_sources([parsed.source])
    assert [item.message for item in diagnostics] == [
        "WORD is not converted to INT implicitly: write WORD_TO_INT(...).",
        "zz is not declared in FB 1.",
    ]


def test_fc_return_value() -> None:
    text = (
        "FUNCTION FC1 : INT\nVAR_TEMP r : REAL; END_VAR\nBEGIN\n"
        "  FC1 := 1;\n  FC1 := r;\nEND_FUNCTION\n"
    )
    parsed = parse_source("fc.scl", text)
    _index, diagnostics = check_sources([parsed.source])
    assert [(item.code, item.span.line) for item in diagnostics if item.span] == [("SCL213", 5)]


def test_an_area_next_to_a_variable_of_its_name() -> None:
    """``I[i, k]`` reads the input area although a variable ``i`` exists (names are
    case-insensitive); ``m[2]`` of an array ``m`` is the array (the lexer read both as areas)."""
    text = (
        "FUNCTION_BLOCK FB1\nVAR i, k : INT; m : ARRAY[0..3] OF INT; x : BOOL; END_VAR\nBEGIN\n"
        "  x := I[i, k];\n  k := m[2];\n  k := m[1, 2];\nEND_FUNCTION_BLOCK\n"
    )
    parsed = parse_source("areas.scl", text)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source])
    assert [(item.code, item.span.line) for item in diagnostics if item.span] == [("SCL216", 6)]


CORPUS = Path(__file__).parent / "corpus"


X10_SYMBOLS = """CYCLE,OB 1,OB 1,
ACQUIRE,FB 10,FB 10,
ACQUIRE_DATA,DB 10,FB 10,
input,IW 0,WORD,
Input 0.0,I 0.0,BOOL,
Sort_switch,I 0.1,BOOL,
Function_switch,I 0.2,BOOL,
Coding_switch,I 0.3,BOOL,
Coding,IW 2,WORD,
Output_switch,I 0.4,BOOL,
Output,QW 4,INT,
"""


def test_book_examples_type_check() -> None:
    """E72 checks cleanly; X10's OB CYCLE and its operands need the book's symbol table."""
    sources = [
        parse_source(name, (CORPUS / name).read_text("utf-8")).source
        for name in ("e72_textgenerator.scl", "x10_measured_values.scl")
    ]
    _index, diagnostics = check_sources(sources)
    assert [item.code for item in diagnostics] == ["SCL205"]
    symbols = SymbolTable()
    assert read_symbol_table("symbols.csv", X10_SYMBOLS, symbols) == []
    index, diagnostics = check_sources(sources[1:], symbols)
    # The book names the FB RECORD but its symbol table ACQUIRE (FB 10): the members of its
    # instance DB 10 are unknown without FB 10's source (SCL923, a block from elsewhere).
    assert [(item.code, item.span.line) for item in diagnostics if item.span] == [
        ("SCL923", 162),
        ("SCL923", 164),
    ]
    assert [block.label for block in index] == ["FB 1", "FB 2", "FC 1", "OB 1"]

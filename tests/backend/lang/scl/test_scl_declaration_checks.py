"""The SCL rules for initial values in declarations and for the assignment section of DATA_BLOCKs
(``initial_values``, ``db_values``), as snapshots of (code, line, column): range,
convertibility, constants only, the number of array values, where initial values are allowed;
and where multi-instances may be declared (``temp_instances``)."""

from __future__ import annotations

import pytest

from nasaq.lang.scl import check_sources, parse_source

HEAD = "FUNCTION_BLOCK FB1\nCONST N := 3; END_CONST\nVAR\n"
TAIL = "\nEND_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n"
L = 4  # the declaration under test; it starts in column 3

DECLARATIONS: list[tuple[str, list[tuple[str, int, int]]]] = [
    ("a : INT := 5; r : REAL := 1; w : WORD := 16#FFFF; x : BOOL := 1; y : BOOL := FALSE;", []),
    ("s : STRING[5] := 'hello'; c : CHAR := 'A'; t : TIME := T#1s; s5 : S5TIME := T#1s;", []),
    ("n1 : INT := N; m1 : INT := -N + 1; day : DATE := D#1996-01-10; dd : DINT := 40000;", []),
    ("data : ARRAY[1..12] OF REAL := 0.0, 10(100.0), 1.0; few : ARRAY[1..4] OF INT := 1, 2;", []),
    ("a2 : ARRAY[1..4] OF INT := 2(1, 2); m2 : ARRAY[1..2, 1..3] OF BYTE := 6(16#FF);", []),
    ("rec : STRUCT v : INT := 5; b : ARRAY[1..2] OF BOOL := TRUE, 0; END_STRUCT;", []),
    ("recs : ARRAY[1..2] OF STRUCT b : BOOL := TRUE; END_STRUCT; p, q : INT := 1;", []),
    ("a : INT := 40000;", [("SCL218", L, 14)]),
    ("b : BYTE := 16#1FF;", [("SCL218", L, 15)]),
    ("n1 : INT := N * 20000;", [("SCL218", L, 15)]),
    ("s : STRING[3] := 'hello';", [("SCL218", L, 20)]),
    ("x : BOOL := 2;", [("SCL214", L, 15)]),
    ("r : REAL := 'A';", [("SCL214", L, 15)]),
    ("t : TIME := 5;", [("SCL214", L, 15)]),
    ("a : INT := 1.5;", [("SCL213", L, 14)]),
    ("w : WORD := -5;", [("SCL218", L, 15)]),  # 0..65535 fits (issue 20, tia_forms)
    ("k : INT; a : INT := k;", [("SCL243", L, 23)]),
    ("a : INT := zz + 1;", [("SCL243", L, 14)]),
    ("a : INT := WORD_TO_INT(W#16#1);", [("SCL243", L, 14)]),
    ("arr : ARRAY[1..3] OF INT := 1, 2, 3, 4;", [("SCL244", L, 31)]),
    ("arr : ARRAY[1..3] OF INT := 2(1, 2);", [("SCL244", L, 31)]),
    ("a : INT := 1, 2;", [("SCL244", L, 14)]),
    ("arr : ARRAY[1..3] OF INT := 1, 2, 'x';", [("SCL213", L, 37)]),
    ("rec : STRUCT v : INT := 1.5; END_STRUCT;", [("SCL213", L, 27)]),
    ("recs : ARRAY[1..2] OF STRUCT b : BOOL := 5; END_STRUCT;", [("SCL214", L, 44)]),
    ("rec : STRUCT v : INT; END_STRUCT := 1;", [("SCL214", L, 39)]),
    ("p, q : INT := 40000;", [("SCL218", L, 17)]),
]

PROGRAMS_OF_BLOCKS: list[tuple[str, list[tuple[str, int, int]]]] = [
    # where initial values are allowed
    (
        "FUNCTION_BLOCK FB1\nVAR_INPUT i : INT := 1; END_VAR\nVAR_OUTPUT o : INT := 2; END_VAR\n"
        "VAR s : INT := 3; END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n",
        [],
    ),
    (
        "FUNCTION_BLOCK FB1\nVAR_TEMP t : INT := 1; END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n",
        [("SCL245", 2, 21)],
    ),
    # an FB's elementary in/out is kept in the instance (TIA's start value); a structured one
    # is a pointer (issue 20, the gaps part)
    (
        "FUNCTION_BLOCK FB1\nVAR_IN_OUT io : INT := 1; END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n",
        [],
    ),
    (
        (
            "FUNCTION_BLOCK FB1\nVAR_IN_OUT s : STRUCT a : INT; END_STRUCT := 1; END_VAR\n"
            "BEGIN\nEND_FUNCTION_BLOCK\n"
        ),
        [("SCL245", 2, 46)],
    ),
    # STEP 7 accepts an FC input's initial value, which does nothing: a warning, once per line
    (
        "FUNCTION F : VOID\nVAR_INPUT p, q : INT := 1; END_VAR\nBEGIN\nEND_FUNCTION\n",
        [("SCL921", 2, 25)],
    ),
    (
        "FUNCTION F : VOID\nVAR_IN_OUT p : INT := 1; END_VAR\nBEGIN\nEND_FUNCTION\n",
        [("SCL245", 2, 23)],
    ),
    (
        "FUNCTION F : VOID\nVAR v : BOOL := TRUE; END_VAR\nBEGIN\nEND_FUNCTION\n",
        [("SCL245", 2, 17)],
    ),
    (
        "ORGANIZATION_BLOCK OB1\nVAR_TEMP t : INT := 0; END_VAR\nBEGIN\nEND_ORGANIZATION_BLOCK\n",
        [("SCL245", 2, 21)],
    ),
    # multi-instances (FBs, IEC timers and counters) need static memory: VAR of an FB only
    (
        "FUNCTION_BLOCK M\nBEGIN\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK FB2\n"
        "VAR m : M; t : TON; c : ARRAY[1..2] OF CTU; END_VAR\nVAR_TEMP k : INT; END_VAR\n"
        "BEGIN\n  m(); t(IN := TRUE, PT := T#1s);\nEND_FUNCTION_BLOCK\n",
        [],
    ),
    (
        "FUNCTION_BLOCK FB1\nVAR_TEMP k : INT; t : TON; END_VAR\nBEGIN\n"
        "  t(IN := TRUE, PT := T#1s);\nEND_FUNCTION_BLOCK\n",
        [("SCL252", 2, 19)],
    ),
    (
        "FUNCTION_BLOCK M\nBEGIN\nEND_FUNCTION_BLOCK\nFUNCTION F : VOID\n"
        "VAR m : M; n : INT; c : ARRAY[1..2] OF CTU; END_VAR\nBEGIN\nEND_FUNCTION\n",
        [("SCL252", 5, 5), ("SCL252", 5, 21)],
    ),
    (
        "ORGANIZATION_BLOCK OB1\nVAR_TEMP s : STRUCT t : TP; END_STRUCT; END_VAR\nBEGIN\n"
        "END_ORGANIZATION_BLOCK\n",
        [("SCL252", 2, 10)],
    ),
    # UDTs and DBs
    ("TYPE U\nSTRUCT a : INT := 1; b : STRING[2] := 'ab'; END_STRUCT\nEND_TYPE\n", []),
    ("TYPE U\nSTRUCT a : INT := 1.5; END_STRUCT\nEND_TYPE\n", [("SCL213", 2, 19)]),
    (
        "DATA_BLOCK DB1\nSTRUCT v : BYTE := B#16#100; END_STRUCT\nBEGIN\nEND_DATA_BLOCK\n",
        [("SCL218", 2, 20)],
    ),
    ("DATA_BLOCK DB1\nVAR v : INT := 'A'; END_VAR\nBEGIN\nEND_DATA_BLOCK\n", [("SCL213", 2, 16)]),
]

DB = """TYPE U
STRUCT a : INT; b : REAL; END_STRUCT
END_TYPE
FUNCTION_BLOCK Motor
VAR_INPUT speed : INT; END_VAR
VAR count : DINT; END_VAR
BEGIN
END_FUNCTION_BLOCK
DATA_BLOCK DB3 U
BEGIN
END_DATA_BLOCK
DATA_BLOCK DB4 Motor
BEGIN
END_DATA_BLOCK
DATA_BLOCK DB1
STRUCT v : INT; arr : ARRAY[1..3] OF INT; s : STRING[4]; rec : STRUCT x : BOOL; END_STRUCT;
m : ARRAY[1..2, 1..2] OF WORD; END_STRUCT
BEGIN
  """
DB_TAIL = "\nEND_DATA_BLOCK\n"
D = DB.count("\n") + 1  # the DB assignment under test; it starts in column 3

DB_VALUES: list[tuple[str, list[tuple[str, int, int]]]] = [
    ("v := 1; arr[2] := -5; s := 'four'; rec.x := 1; m[2, 1] := W#16#FF; M[1, 2] := 16#1;", []),
    ("v := 40000;", [("SCL218", D, 8)]),
    ("s := 'hello';", [("SCL218", D, 8)]),
    ("arr[2] := 'x';", [("SCL213", D, 13)]),
    ("rec.x := 2;", [("SCL214", D, 12)]),
    ("zz := 1;", [("SCL201", D, 3)]),
    ("rec.y := 1;", [("SCL222", D, 7)]),
    ("v := v;", [("SCL243", D, 8)]),
    ("arr[1, 2] := 1;", [("SCL216", D, 3)]),
    ("arr[4] := 1; m[2, 0] := W#16#1;", [("SCL249", D, 7), ("SCL249", D, 21)]),
]

DB_BLOCKS: list[tuple[str, list[tuple[str, int, int]]]] = [
    # an instance DB has the FB's members, a DB of a UDT the UDT's
    ("DATA_BLOCK DB5 Motor\nBEGIN\n  speed := 5; count := 40000;\nEND_DATA_BLOCK\n", []),
    ("DATA_BLOCK DB5 Motor\nBEGIN\n  speed := TRUE;\nEND_DATA_BLOCK\n", [("SCL213", 3, 12)]),
    ("DATA_BLOCK DB5 U\nBEGIN\n  a := 1; b := 2.5;\nEND_DATA_BLOCK\n", []),
    ("DATA_BLOCK DB5 U\nBEGIN\n  a := 2.5;\nEND_DATA_BLOCK\n", [("SCL213", 3, 8)]),
]

PREFIX = DB.split("DATA_BLOCK DB1", 1)[0].replace("DATA_BLOCK DB3 U\nBEGIN\nEND_DATA_BLOCK\n", "")
PROGRAMS = (
    [(HEAD + "  " + decl + TAIL, expected) for decl, expected in DECLARATIONS]
    + PROGRAMS_OF_BLOCKS
    + [(DB + body + DB_TAIL, expected) for body, expected in DB_VALUES]
    + [(PREFIX + text, [(c, n + PREFIX.count("\n"), k) for c, n, k in e]) for text, e in DB_BLOCKS]
)


def _found(text: str) -> list[tuple[str, int, int]]:
    parsed = parse_source("decl.scl", text)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source])
    return [(item.code, item.span.line or 0, item.span.column or 0) for item in diagnostics]


@pytest.mark.parametrize(("declaration", "expected"), DECLARATIONS)
def test_initial_value_snapshot(declaration: str, expected: list[tuple[str, int, int]]) -> None:
    assert _found(HEAD + "  " + declaration + TAIL) == expected


@pytest.mark.parametrize(("text", "expected"), PROGRAMS_OF_BLOCKS)
def test_initial_values_of_blocks(text: str, expected: list[tuple[str, int, int]]) -> None:
    assert _found(text) == expected


@pytest.mark.parametrize(("body", "expected"), DB_VALUES)
def test_db_assignment_snapshot(body: str, expected: list[tuple[str, int, int]]) -> None:
    assert _found(DB + body + DB_TAIL) == expected


@pytest.mark.parametrize(("text", "expected"), DB_BLOCKS)
def test_instance_and_udt_db_values(text: str, expected: list[tuple[str, int, int]]) -> None:
    shift = PREFIX.count("\n")
    assert _found(PREFIX + text) == [
        (code, line + shift, column) for code, line, column in expected
    ]


def test_temp_instance_message() -> None:
    text = (
        "FUNCTION_BLOCK Motor\nBEGIN\nEND_FUNCTION_BLOCK\n"
        "FUNCTION F : VOID\nVAR t : TOF; m : Motor; END_VAR\nBEGIN\nEND_FUNCTION\n"
    )
    parsed = parse_source("decl.scl", text)
    _index, diagnostics = check_sources([parsed.source])
    tail = (
        "needs static memory: declare it in the VAR section of a function block, not among the"
        " temporary variables of FC 1."
    )
    assert [item.message for item in diagnostics] == [
        f"t is an instance of TOF and {tail}",
        f"m is an instance of Motor (FB 1) and {tail}",
    ]


def test_declaration_messages() -> None:
    text = HEAD + "  arr : ARRAY[1..3] OF INT := 2(1, 2); k : INT; a : INT := k;" + TAIL
    parsed = parse_source("decl.scl", text)
    _index, diagnostics = check_sources([parsed.source])
    assert [item.message for item in diagnostics] == [
        "arr has 3 element(s) but 4 initial values are given.",
        "The value of a must be a constant.",
    ]

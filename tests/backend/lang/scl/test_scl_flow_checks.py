"""The SCL control-flow rules: CASE selector, labels and ranges, EXIT/CONTINUE outside loops,
GOTO and jump labels, the FC return value, and the warnings for the FOR variable written inside
its loop and for ``A * -B``. Each rule has failing and passing snapshots of (code, line,
column); one mistake gives one diagnostic."""

from __future__ import annotations

import pytest

from nasaq.diagnostics import Severity
from nasaq.lang.scl import check_sources, parse_source

HEAD = """FUNCTION_BLOCK FB1
VAR k : INT; d : DINT; r : REAL; w : WORD; x : BOOL; END_VAR
LABEL L1, L2, L3; END_LABEL
BEGIN
"""
TAIL = "\nEND_FUNCTION_BLOCK\n"
L = HEAD.count("\n") + 1  # the line of the statement under test; it starts in column 3

CASES: list[tuple[str, list[tuple[str, int, int]]]] = [
    # CASE: the selector is an INT, label values are INT constants, each once
    ("CASE k OF 1: x := TRUE; 2, 3: ; 4..9: ; -5..-1: ; ELSE ; END_CASE;", []),
    ("CASE WORD_TO_INT(w) OF 16#10: ; INT#7: ; 8: ; END_CASE;", []),
    ("CASE 2 * k + 1 OF 1: CASE k OF 1: ; END_CASE; END_CASE;", []),
    ("CASE w OF 1: ; END_CASE;", [("SCL235", L, 8)]),
    ("CASE d OF 1: ; END_CASE;", [("SCL235", L, 8)]),
    ("CASE r OF 1: ; END_CASE;", [("SCL235", L, 8)]),
    ("CASE x OF 1: ; END_CASE;", [("SCL235", L, 8)]),
    ("CASE k OF 1: ; 1: ; END_CASE;", [("SCL236", L, 18)]),
    ("CASE k OF 1..5: ; 5..9: ; END_CASE;", [("SCL236", L, 21)]),
    ("CASE k OF 2, 4..6, 3..4: ; END_CASE;", [("SCL236", L, 22)]),
    ("CASE k OF 16#10: ; 16: ; END_CASE;", [("SCL236", L, 22)]),
    ("CASE k OF 7: ; ELSE CASE k OF 7: ; 7: ; END_CASE; END_CASE;", [("SCL236", L, 38)]),
    ("CASE k OF 40000: ; END_CASE;", [("SCL218", L, 13)]),
    ("CASE k OF T#1s: ; END_CASE;", [("SCL214", L, 13)]),
    ("CASE zz OF 1: ; 1: ; END_CASE;", [("SCL201", L, 8), ("SCL236", L, 19)]),
    # a range runs upwards: a reversed one is empty, and overlaps nothing
    ("CASE k OF 3..3: ; 4..16#10: ; END_CASE;", []),
    ("CASE k OF 5..1: ; END_CASE;", [("SCL248", L, 13)]),
    ("CASE k OF -1..-5: x := TRUE; END_CASE;", [("SCL248", L, 13)]),
    ("CASE k OF 1..5: ; 9..6, 7: ; END_CASE;", [("SCL248", L, 21)]),
    (
        "CASE k OF 16#10..9: ; ELSE CASE k OF 2..1: ; END_CASE; END_CASE;",
        [("SCL248", L, 13), ("SCL248", L, 40)],
    ),
    ("CASE k OF 9..T#1s: ; END_CASE;", [("SCL214", L, 16)]),
    # EXIT and CONTINUE inside a loop only; RETURN anywhere
    ("FOR k := 1 TO 5 DO IF x THEN EXIT; END_IF; CONTINUE; END_FOR;", []),
    ("WHILE x DO CASE k OF 1: EXIT; END_CASE; END_WHILE; REPEAT CONTINUE; UNTIL x END_REPEAT;", []),
    ("IF x THEN RETURN; END_IF; RETURN;", []),
    ("EXIT;", [("SCL237", L, 3)]),
    ("IF x THEN CONTINUE; END_IF;", [("SCL237", L, 13)]),
    ("CASE k OF 1: EXIT; END_CASE;", [("SCL237", L, 16)]),
    ("FOR k := 1 TO 5 DO ; END_FOR; EXIT;", [("SCL237", L, 33)]),
    # GOTO: declared labels, each set once, never into a loop
    ("L1: k := 1; GOTO L1; GOTO L1;", []),
    ("GOTO L2; L2: ;", []),
    ("FOR k := 1 TO 5 DO IF x THEN GOTO L2; END_IF; END_FOR; L2: ;", []),
    ("FOR k := 1 TO 5 DO L3: ; WHILE x DO GOTO L3; END_WHILE; END_FOR;", []),
    ("GOTO L9;", [("SCL238", L, 3)]),
    ("L9: k := 1;", [("SCL238", L, 3)]),
    ("L9: ; GOTO L9; GOTO L9;", [("SCL238", L, 3)]),
    ("L1: ; L1: k := 1;", [("SCL239", L, 9)]),
    ("GOTO L2;", [("SCL240", L, 3)]),
    ("GOTO L3; WHILE x DO L3: ; END_WHILE;", [("SCL241", L, 3)]),
    ("FOR k := 1 TO 2 DO GOTO L3; END_FOR; WHILE x DO L3: ; END_WHILE;", [("SCL241", L, 22)]),
    # the FOR variable is not written inside its own loop (a warning), nested statements too
    ("FOR k := 1 TO 5 DO d := k; x := k > 2; END_FOR; k := 0; FOR k := 1 TO 2 DO ; END_FOR;", []),
    ("FOR d := 1 TO 5 DO FOR k := 1 TO 2 DO d := d + k; END_FOR; END_FOR;", [("SCL250", L, 41)]),
    ("FOR k := 1 TO 5 DO k := k + 1; END_FOR;", [("SCL250", L, 22)]),
    ("FOR k := 1 TO 5 DO IF x THEN #k := 0; END_IF; END_FOR;", [("SCL250", L, 32)]),
    ("FOR #k := 1 TO 5 DO CASE k OF 1: k := 9; END_CASE; END_FOR;", [("SCL250", L, 36)]),
    (
        "FOR k := 1 TO 5 DO WHILE x DO FOR k := 1 TO 2 DO ; END_FOR; END_WHILE; END_FOR;",
        [("SCL250", L, 37)],
    ),
    ("FOR k := 1 TO 5 DO k := r; END_FOR;", [("SCL250", L, 22), ("SCL213", L, 27)]),
    ("FOR r := 1 TO 5 DO r := 2.0; END_FOR;", [("SCL221", L, 7)]),
    ("FOR zz := 1 TO 5 DO zz := 2; END_FOR;", [("SCL201", L, 7)]),
    # a sign right after a binary operator: a warning
    ("k := k * (-k); k := -k * 2; k := k * -5; x := x AND NOT x; r := -r;", []),
    ("k := k * -k;", [("SCL246", L, 12)]),
    ("k := k + -k * 2;", [("SCL246", L, 12)]),
    ("x := k < -k;", [("SCL246", L, 12)]),
    ("r := r - +r;", [("SCL246", L, 12)]),
]

# Whole blocks: the return value of an FC, the LABEL section.
FC_CASES: list[tuple[str, list[tuple[str, int, int]]]] = [
    # the return value of an FC must be set
    (
        "FUNCTION F : INT\nVAR_TEMP k : INT; END_VAR\nBEGIN\n  k := 1;\nEND_FUNCTION\n",
        [("SCL242", 5, 1)],
    ),
    ("FUNCTION F : INT\nBEGIN\n  RETURN;\nEND_FUNCTION\n", [("SCL242", 4, 1)]),
    ("FUNCTION F : VOID\nBEGIN\n  RETURN;\nEND_FUNCTION\n", []),
    (
        "FUNCTION F : INT\nVAR_INPUT x : BOOL; END_VAR\nBEGIN\n  IF x THEN F := 1; END_IF;\n"
        "END_FUNCTION\n",
        [],
    ),
    ("FUNCTION FC1 : REAL\nBEGIN\n  FC1 := 1.0;\nEND_FUNCTION\n", []),
    ('FUNCTION "Calc" : INT\nBEGIN\n  "Calc" := 1;\nEND_FUNCTION\n', []),
    (
        "TYPE U\nSTRUCT a : INT; END_STRUCT\nEND_TYPE\nFUNCTION F : U\nBEGIN\n  F.a := 1;\n"
        "END_FUNCTION\n",
        [],
    ),
    (
        "FUNCTION G : VOID\nVAR_OUTPUT q : INT; END_VAR\nBEGIN\n  q := 1;\nEND_FUNCTION\n"
        "FUNCTION F : INT\nBEGIN\n  G(q => F);\nEND_FUNCTION\n",
        [],
    ),
    (
        "FUNCTION F : INT\nVAR_TEMP f2 : INT; END_VAR\nBEGIN\n  f2 := 1;\n  WHILE f2 > 0 DO\n"
        "    f2 := f2 - 1;\n  END_WHILE;\nEND_FUNCTION\n",
        [("SCL242", 8, 1)],
    ),
    # a label declared twice
    (
        "FUNCTION_BLOCK FB1\nLABEL A, B, A; END_LABEL\nBEGIN\n  A: ;\nEND_FUNCTION_BLOCK\n",
        [("SCL206", 2, 1)],
    ),
]

PROGRAMS = [(HEAD + "  " + body + TAIL, expected) for body, expected in CASES] + FC_CASES


def _found(text: str) -> list[tuple[str, int, int]]:
    parsed = parse_source("flow.scl", text)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source])
    return [(item.code, item.span.line or 0, item.span.column or 0) for item in diagnostics]


@pytest.mark.parametrize(("body", "expected"), CASES)
def test_flow_snapshot(body: str, expected: list[tuple[str, int, int]]) -> None:
    assert _found(HEAD + "  " + body + TAIL) == expected


@pytest.mark.parametrize(("text", "expected"), FC_CASES)
def test_block_snapshot(text: str, expected: list[tuple[str, int, int]]) -> None:
    assert _found(text) == expected


def test_sign_after_operator_is_a_warning() -> None:
    parsed = parse_source("flow.scl", HEAD + "  k := k * -k; EXIT;" + TAIL)
    _index, diagnostics = check_sources([parsed.source])
    assert [(item.code, item.severity) for item in diagnostics] == [
        ("SCL246", Severity.WARNING),
        ("SCL237", Severity.ERROR),
    ]
    assert diagnostics[0].message == "-k follows the operator * directly: write * (-k)."


def test_writing_the_for_variable_is_a_warning() -> None:
    parsed = parse_source("flow.scl", HEAD + "  FOR k := 1 TO 5 DO k := 5; END_FOR;" + TAIL)
    _index, diagnostics = check_sources([parsed.source])
    assert [(item.code, item.severity) for item in diagnostics] == [("SCL250", Severity.WARNING)]
    assert diagnostics[0].message == (
        f"k is the control variable of the FOR loop in line {L}: changing it inside the loop"
        " changes how often the loop runs."
    )


def test_flow_messages() -> None:
    body = "CASE k OF 1: ; 1: ; 16#10..-2: ; END_CASE; GOTO L3; WHILE x DO L3: ; END_WHILE;"
    parsed = parse_source("flow.scl", HEAD + "  " + body + TAIL)
    _index, diagnostics = check_sources([parsed.source])
    assert [item.message for item in diagnostics] == [
        f"The CASE value 1 occurs twice (first in line {L}).",
        "The CASE range 16#10..-2 is empty: its first value must not be greater than its last.",
        "GOTO L3 jumps into a loop; a jump may only leave a loop.",
    ]

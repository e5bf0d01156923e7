# ruff: noqa: E501  (test sources are easier to read on one line)
"""Diagnostics snapshots: (code, line, column) for each required check."""

from __future__ import annotations

import pytest
from stl_helpers import codes, compile_text, ob1

from nasaq.lang.stl import SourceFile

FC1 = "FUNCTION FC 1 : VOID\nVAR_INPUT\n  x : INT;\n  b : BOOL;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"

CASES = [
    ("unknown instruction", ob1("  FOO M 0.0"), [("STL201", 3, 3)]),
    ("other mnemonic set", ob1("  A I 0.0\n  SPB M001\nM001: NOP 0"), [("STL201", 4, 3)]),
    ("bit instruction on a word", ob1("  A MW 10"), [("STL204", 3, 5)]),
    ("assign to a word", ob1("  = IW 0"), [("STL204", 3, 5)]),
    ("transfer to an input byte is fine", ob1("  T IB 0"), []),
    ("timer instruction on a counter", ob1("  SP C 1"), [("STL204", 3, 6)]),
    ("load from peripheral outputs", ob1("  L PQW 256"), [("STL204", 3, 5)]),
    ("missing operand", ob1("  L"), [("STL202", 3, 3)]),
    ("operand not allowed", ob1("  SET M 0.0"), [("STL203", 3, 7)]),
    ("undefined symbol", ob1('  A "Nowhere"'), [("STL205", 3, 5)]),
    ("undefined local", ob1("  L #nothing"), [("STL206", 3, 5)]),
    ("undefined label", ob1("  JU M002"), [("STL207", 3, 6)]),
    ("duplicate label", ob1("M001: NOP 0\nM001: NOP 1"), [("STL208", 4, 1)]),
    ("long label", ob1("LONGER: NOP 0"), [("STL209", 3, 1)]),
    ("INT out of range", ob1("  L 40000"), [("STL214", 3, 5)]),
    ("bad address", ob1("  A I 0.8"), [("STL106", 3, 5)]),
    ("bad constant", ob1("  L W#16#XYZ"), [("STL107", 3, 5)]),
    ("missing block", ob1("  CALL FC 9"), [("STL213", 3, 3)]),  # FC 9 of the IEC library too
    (
        "FB without instance",
        "FUNCTION_BLOCK FB 1\nBEGIN\n  NOP 0\nEND_FUNCTION_BLOCK\n" + ob1("  CALL FB 1"),
        [("STL221", 7, 3)],
    ),
    ("param type", FC1 + ob1("  CALL FC 1 (x := M 0.0, b := I 0.0)"), [("STL210", 11, 19)]),
    ("param missing", FC1 + ob1("  CALL FC 1 (x := MW 0)"), [("STL211", 11, 3)]),
    (
        "param unknown",
        FC1 + ob1("  CALL FC 1 (x := MW 0, b := M 0.0, zz := 1)"),
        [("STL212", 11, 37)],
    ),
    ("constant to INT param", FC1 + ob1("  CALL FC 1 (x := L#5, b := TRUE)"), [("STL210", 11, 19)]),
    ("INC range", ob1("  INC 300"), [("STL214", 3, 7)]),
    ("duplicate block", ob1("  NOP 0") + ob1("  NOP 0"), [("STL215", 5, 1)]),
    (
        "undefined member",
        "DATA_BLOCK DB 3\n  STRUCT\n    a : INT;\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
        + ob1("  L DB3.zz"),
        [("STL216", 9, 5)],
    ),
    ("test op outside test mode", ob1("  __STWRST"), [("STL218", 3, 3)]),
    (
        "struct operand",
        "FUNCTION FC 2 : VOID\nVAR_TEMP\n  s : STRUCT\n    a : INT;\n  END_STRUCT;\nEND_VAR\nBEGIN\n  L #s\nEND_FUNCTION\n",
        [("STL228", 8, 5)],
    ),
    ("label without instruction", ob1("  NOP 0\nM001:"), [("STL230", 4, 1)]),
    (
        "unknown type",
        "FUNCTION FC 2 : VOID\nVAR_TEMP\n  s : FOO;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n",
        [("STL224", 3, 7)],
    ),
    (
        "bad DB value",
        "DATA_BLOCK DB 3\n  STRUCT\n    a : INT := 'x';\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n",
        [("STL226", 3, 16)],
    ),
]


@pytest.mark.parametrize(
    ("text", "expected"), [case[1:] for case in CASES], ids=[c[0] for c in CASES]
)
def test_snapshot(text: str, expected: list[tuple[str, int, int]]) -> None:
    assert codes(compile_text(text)) == expected


def test_jump_into_another_block() -> None:
    text = "FUNCTION FC 2 : VOID\nBEGIN\nDEST: NOP 0\nEND_FUNCTION\n" + ob1("  JU DEST")
    assert codes(compile_text(text)) == [("STL219", 7, 6)]


def test_call_across_files_and_symbolic_block_ids() -> None:
    library = SourceFile(
        "lib.awl", 'FUNCTION "Add" : INT\nBEGIN\n  L 1\n  T #RET_VAL\nEND_FUNCTION\n'
    )
    symbols = SourceFile("symbols.csv", "Add,FC 7,FC 7,adds\n")
    result = compile_text(ob1('  CALL "Add" (RET_VAL := MW 0)'), library, symbols)
    assert result.ok, result.diagnostics


def test_messages_are_rendered_and_sorted() -> None:
    result = compile_text(ob1("  L 40000\n  A MW 2"))
    assert [item.span.line for item in result.diagnostics if item.span] == [3, 4]
    assert "L#40000" in result.diagnostics[0].message

"""The project outline the editor completes and explains from: symbols, blocks, members."""

from __future__ import annotations

from pathlib import Path

import pytest

from nasaq.workbench import outline as outline_module
from nasaq.workbench.names import language_of
from nasaq.workbench.outline import OutlineBlock, ProjectOutline, outline

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "projects"

SYMBOLS = '"Motor","FB 2","FB 2","the motor block"\n"Start","I 0.0","BOOL","push button"\n'
MOTOR = """\
FUNCTION_BLOCK "Motor"
VAR_INPUT
  Start : BOOL;   // start request
END_VAR
VAR
  State : STRUCT  // what the motor does
    Speed : INT;  // rpm
    Running : BOOL;
  END_STRUCT;
END_VAR
BEGIN
  State.Running := Start;
END_FUNCTION_BLOCK

DATA_BLOCK DB 3 "Motor"
BEGIN
END_DATA_BLOCK
"""
CALC = """\
FUNCTION FC 7 : INT
VAR_INPUT
  a : INT ;
END_VAR
VAR_TEMP
  t : INT ;
END_VAR
BEGIN
NETWORK
      L     #a;
      T     #t;
      L     #t;
      T     #RET_VAL;
END_FUNCTION
"""


def _example(name: str) -> list[tuple[str, str]]:
    folder = EXAMPLES / name
    return [
        (path.name, path.read_text())
        for path in sorted(folder.iterdir())
        if path.is_file() and language_of(path.name) is not None
    ]


def _block(found: ProjectOutline, kind: str, number: int) -> OutlineBlock:
    return next(block for block in found.blocks if block.kind == kind and block.number == number)


def test_symbols_keep_their_table_line_and_comment() -> None:
    found = outline([("symbols.sdf", SYMBOLS), ("motor.scl", MOTOR)])
    assert [(s.name, s.address, s.type, s.comment, s.file, s.line) for s in found.symbols] == [
        ("Motor", "FB 2", "FB 2", "the motor block", "symbols.sdf", 1),
        ("Start", "I 0.0", "BOOL", "push button", "symbols.sdf", 2),
    ]


def test_scl_members_are_flattened_with_their_declarations() -> None:
    found = outline([("symbols.sdf", SYMBOLS), ("motor.scl", MOTOR)])
    fb = _block(found, "FB", 2)
    assert (fb.name, fb.language, fb.file, fb.line, fb.return_type) == (
        "Motor",
        "scl",
        "motor.scl",
        1,
        None,
    )
    rows = [(m.path, m.section, m.depth, m.type, m.comment, m.line) for m in fb.members]
    assert rows == [
        ("Start", "IN", 0, "BOOL", "start request", 3),
        ("State", "STAT", 0, "STRUCT", "what the motor does", 6),
        ("State.Speed", "STAT", 1, "INT", "rpm", 7),
        ("State.Running", "STAT", 1, "BOOL", "", 8),
    ]


def test_an_instance_db_lists_its_fbs_members() -> None:
    found = outline([("symbols.sdf", SYMBOLS), ("motor.scl", MOTOR)])
    db = _block(found, "DB", 3)
    assert db.instance_of == "FB 2"
    assert [m.path for m in db.members] == ["Start", "State", "State.Speed", "State.Running"]


def test_an_stl_fc_has_its_return_type_and_temps() -> None:
    fc = _block(outline([("calc.awl", CALC)]), "FC", 7)
    assert fc.return_type == "INT"
    assert [(m.name, m.section, m.line) for m in fc.members] == [
        ("a", "IN", 3),
        ("RET_VAL", "RETURN", None),
        ("t", "TEMP", 6),
    ]


def test_the_tank_example() -> None:
    found = outline(_example("tank-level"))
    assert {s.name for s in found.symbols} >= {"Auto", "Level sensor", "TankSettings"}
    settings = _block(found, "DB", 1)
    assert [(m.path, m.section, m.comment) for m in settings.members] == [
        ("LowLevel", "DATA", "the pump starts below this level"),
        ("HighLevel", "DATA", "the pump stops at or above this level"),
        ("AlarmLevel", "DATA", "the alarm sounds at or above this level"),
    ]
    scale = _block(found, "FC", 10)
    # the SCL compiler's own temporaries (_t1) are not offered to the user
    assert [m.name for m in scale.members] == ["Raw", "Low", "High", "RET_VAL"]
    assert scale.members[0].comment == "value of the analog input, nominal range 0..27648"
    assert [(b.kind, b.number) for b in found.blocks] == [
        ("OB", 1),
        ("FB", 10),
        ("FC", 10),
        ("DB", 1),
        ("DB", 10),
    ]


def test_broken_sources_still_give_what_they_can() -> None:
    found = outline([("symbols.sdf", SYMBOLS + "no address\n"), ("bad.scl", "FUNCTION_BLOCK")])
    assert [s.name for s in found.symbols] == ["Motor", "Start"]
    assert found.blocks == []


def test_the_same_sources_are_compiled_once(monkeypatch: pytest.MonkeyPatch) -> None:
    sources = [("calc.awl", CALC.replace("FC 7", "FC 8"))]
    first = outline(sources)
    calls: list[object] = []
    monkeypatch.setattr(outline_module, "compile_project", lambda *args: calls.append(args))
    assert outline(list(sources)) is first
    assert calls == []

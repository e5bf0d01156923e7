"""One exit status for every ``nasaq`` command (``nasaq.cli.EXIT_STATUS``): 0 all is well, 1 what
the command was given has errors, 2 it was called wrongly. ``nasaq compile`` and ``nasaq run``
used to disagree about sources that do not compile (1 and 2)."""

from __future__ import annotations

from pathlib import Path

import pytest

from nasaq.cli import EXIT_STATUS, build_parser, main

GOOD = """ORGANIZATION_BLOCK OB 1
BEGIN
      SET   ;
      =     M 0.0;
END_ORGANIZATION_BLOCK
"""
BROKEN = GOOD.replace("SET   ;", "XYZ   M 0.1;")
STOPS = GOOD.replace("SET   ;", "OPN   DB 77;\n      L     DBW 0;")  # DB 77 does not exist
SCENARIO = """name: marker
sources: [{source}]
steps:
  - run: 1
  - expect: {{M0.0: {value}}}
"""


def _write(tmp_path: Path, name: str, text: str) -> str:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


def _exit(argv: list[str]) -> int:
    """The status, whether the command returns it or argparse exits with it."""
    try:
        return main(argv)
    except SystemExit as stop:
        return int(stop.code or 0)


def test_compile_exits_0_1_2(tmp_path: Path) -> None:
    assert _exit(["compile", _write(tmp_path, "good.awl", GOOD)]) == 0
    assert _exit(["compile", _write(tmp_path, "bad.awl", BROKEN)]) == 1
    assert _exit(["compile", str(tmp_path / "missing.awl")]) == 2
    assert _exit(["compile", "--emit", "lad", str(tmp_path / "good.awl")]) == 2


def test_run_exits_like_compile(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert _exit(["run", _write(tmp_path, "good.awl", GOOD)]) == 0
    assert _exit(["run", _write(tmp_path, "bad.awl", BROKEN)]) == 1
    out = capsys.readouterr().out
    assert out.count('"cycles"') == 1  # JSON for the run that compiled only
    assert _exit(["run", _write(tmp_path, "stops.awl", STOPS)]) == 1  # a CPU STOP on an error
    assert '"mode":"STOP"' in capsys.readouterr().out
    assert _exit(["run", str(tmp_path / "missing.awl")]) == 2
    assert _exit(["run", "--set", "MW10", str(tmp_path / "good.awl")]) == 2
    assert _exit(["run", "--cycles", "many", str(tmp_path / "good.awl")]) == 2


def test_compile_and_run_agree_on_every_source(tmp_path: Path) -> None:
    for name, text in (("good.awl", GOOD), ("bad.awl", BROKEN)):
        path = _write(tmp_path, name, text)
        assert _exit(["compile", path]) == _exit(["run", path]), name


def test_convert_exits_0_1_2(tmp_path: Path) -> None:
    good = _write(tmp_path, "good.awl", GOOD)
    assert _exit(["convert", good, "--to", "lad", "--out", str(tmp_path / "good.lad")]) == 0
    assert _exit(["convert", good, "--to", "graph"]) == 1  # nothing converts to S7-Graph
    assert _exit(["convert", str(tmp_path / "missing.awl"), "--to", "lad"]) == 2


def test_test_exits_0_1_2(tmp_path: Path) -> None:
    _write(tmp_path, "prog.awl", GOOD)
    passing = _write(tmp_path, "pass.yaml", SCENARIO.format(source="prog.awl", value=1))
    failing = _write(tmp_path, "fail.yaml", SCENARIO.format(source="prog.awl", value=0))
    _write(tmp_path, "bad.awl", BROKEN)
    broken = _write(tmp_path, "broken.yaml", SCENARIO.format(source="bad.awl", value=1))
    assert _exit(["test", passing]) == 0
    assert _exit(["test", failing]) == 1
    assert _exit(["test", broken]) == 1  # its sources do not compile: errors, not a usage error
    empty = tmp_path / "empty"
    empty.mkdir()
    assert _exit(["test", str(empty)]) == 2


def test_lessons_exit_1_for_a_broken_course() -> None:
    fixtures = Path(__file__).parent / "lessons" / "fixtures"
    assert _exit(["lessons", "check", str(fixtures / "course" / "fa9" / "fa9-01")]) == 0
    assert _exit(["lessons", "check", str(fixtures / "course")]) == 1  # a malformed lesson
    assert _exit(["lessons", "lint", str(fixtures / "bad")]) == 1
    assert _exit(["lessons", "frobnicate"]) == 2


def test_the_help_of_every_command_states_the_exit_status() -> None:
    parser = build_parser()
    assert "0 all is well" in EXIT_STATUS
    assert "2 a usage error" in EXIT_STATUS
    assert parser.epilog == EXIT_STATUS
    commands = next(
        action for action in parser._actions if action.__class__.__name__ == "_SubParsersAction"
    )
    for name, command in commands.choices.items():  # type: ignore[attr-defined]
        assert command.epilog == EXIT_STATUS, name

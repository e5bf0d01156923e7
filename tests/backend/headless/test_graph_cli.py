"""``nasaq run``, ``compile --emit stl``, ``convert`` and ``test`` take S7-Graph sources: the STL
a Graph FB lowers to is printed with the Graph line of each part, written to a file that
compiles and runs exactly as the ``.graph`` file does, and converting to anything else than STL
(or from anything to S7-Graph) is refused with its code."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nasaq.cli import main

CONVEYOR = """\
FUNCTION_BLOCK FB 1
TITLE = One conveyor
BEGIN
SEQUENCER Conveyor
INITIAL_STEP Idle (1)
ACTIONS
  N Q 4.2;
END_ACTIONS
END_STEP

TRANSITION Go (1) FROM Idle TO Running
CONDITION Contact(I 0.0) END_CONDITION
END_TRANSITION

STEP Running (2)
ACTIONS
  N Q 4.0;  // the belt
  D Q 4.1, T#50MS;
END_ACTIONS
END_STEP

TRANSITION Halt (2) FROM Running JUMP Idle
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""
OB1 = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE =
      CALL FB 1 , DB 1;
END_ORGANIZATION_BLOCK

DATA_BLOCK DB 1
FB 1
BEGIN
END_DATA_BLOCK
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "conveyor.graph").write_text(CONVEYOR, encoding="utf-8")
    (tmp_path / "ob1.awl").write_text(OB1, encoding="utf-8")
    return tmp_path


def _run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, dict[str, object]]:
    code = main(["run", *args])
    return code, json.loads(capsys.readouterr().out)


def test_run_takes_a_graph_source(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sources = [str(project / "conveyor.graph"), str(project / "ob1.awl")]
    code, state = _run(capsys, *sources, "--cycles", "2")
    assert code == 0
    assert state["Q"] == {"4": 0b100}  # the initial step's N action
    code, state = _run(capsys, *sources, "--cycles", "10", "--at", "3:I0.0=1")
    assert code == 0
    assert state["Q"] == {"4": 0b011}  # Running: the belt, and Q 4.1 after 50 ms


def test_compile_emits_the_stl_with_the_graph_lines(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    graph = project / "conveyor.graph"
    assert main(["compile", str(graph), str(project / "ob1.awl"), "--emit", "stl"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("FUNCTION_BLOCK FB 1\n")
    lines = CONVEYOR.split("\n")
    marks = [line for line in out.split("\n") if line.startswith("// ")]
    for number in (7, 11, 17, 18, 22):  # action rows, a transition, the jump
        assert f"// {number}: {lines[number - 1].strip()}" in marks
    assert "ORGANIZATION_BLOCK" not in out  # STL sources are not repeated
    assert main(["compile", str(graph), str(project / "ob1.awl")]) == 0
    assert capsys.readouterr().out == ""


def test_the_converted_stl_runs_as_the_graph_source_does(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = project / "conveyor.awl"
    assert (
        main(
            [
                "convert",
                str(project / "conveyor.graph"),
                "--to",
                "stl",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    capsys.readouterr()
    assert out.read_text(encoding="utf-8").startswith("FUNCTION_BLOCK FB 1\n")
    inputs = [
        "--cycles",
        "40",
        "--at",
        "3:I0.0=1",
        "--at",
        "20:I0.1=1",
        "--at",
        "22:I0.1=0",
    ]
    inputs += ["--at", "30:I0.0=1"]
    graph = _run(capsys, str(project / "conveyor.graph"), str(project / "ob1.awl"), *inputs)
    stl = _run(capsys, str(out), str(project / "ob1.awl"), *inputs)
    assert graph == stl
    assert graph[1]["Q"] == {"4": 0b011}


def test_convert_refuses_what_has_no_graph_form(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["convert", str(project / "conveyor.graph"), "--to", "lad"]) == 1
    captured = capsys.readouterr()
    assert "LAD502" in captured.err
    assert captured.out == ""
    assert main(["convert", str(project / "ob1.awl"), "--to", "graph"]) == 1
    captured = capsys.readouterr()
    assert "ob1.awl:1:1: LAD503" in captured.err
    assert captured.out == ""


def test_a_graph_source_with_errors_is_reported_with_its_line(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = project / "bad.graph"
    bad.write_text(CONVEYOR.replace("FROM Running JUMP Idle", "FROM Runing JUMP Idle"), "utf-8")
    assert main(["compile", str(bad), str(project / "ob1.awl"), "--emit", "stl"]) == 1
    err = capsys.readouterr().err
    assert f"{bad}:22" in err  # the transition that names a missing step
    assert main(["convert", str(bad), "--to", "stl"]) == 1


def test_nasaq_test_runs_a_scenario_of_a_graph_program(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scenario = project / "conveyor.yaml"
    scenario.write_text(
        """\
name: the belt runs after Start
sources: [conveyor.graph, ob1.awl]
steps:
  - run: 2
  - expect: {DB1.Idle.X: 1, Q4.0: 0}
  - set: {I0.0: 1}
  - run: 1
  - expect: {DB1.Idle.X: 0, DB1.Running.X: 1, Q4.0: 1, DB1.Go.TT: 1}
  - run: 1
  - expect: {DB1.Running.X: 1, DB1.Go.TT: 0}
""",
        encoding="utf-8",
    )
    assert main(["test", str(scenario)]) == 0
    assert capsys.readouterr().out == "1 passed, 0 failed\n"

"""``nasaq run`` and ``nasaq test`` with a ``cpu.properties`` beside the sources: its properties
apply, options on the command line (or in the scenario) win, a bad file stops with its lines."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from nasaq.cli import main
from nasaq.scenarios.runner import run_scenario

# Counts the rising edges of M 100.5 (the 1 Hz bit of clock memory MB 100) in MW 10, and
# counts the scans in MW 2 (MB 2-3 are retentive by default, MB 20 is not).
PROGRAM = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     M    100.5;
      FP    M    101.0;
      JCN   skip;
      L     MW    10;
      +     1;
      T     MW    10;
skip: L     MW     2;
      +     1;
      T     MW     2;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK OB 102
BEGIN
NETWORK
      L     102;
      T     MW    20;
END_ORGANIZATION_BLOCK
"""


def _run(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    properties: str | None,
    *args: str,
) -> tuple[int, dict[str, Any] | None, str]:
    source = tmp_path / "prog.awl"
    source.write_text(PROGRAM, encoding="utf-8")
    if properties is not None:
        (tmp_path / "cpu.properties").write_text(properties, encoding="utf-8")
    code = main(["run", str(source), *args])
    out, err = capsys.readouterr()
    return code, (json.loads(out) if out.strip() else None), err


def test_the_file_beside_the_sources_sets_cycle_clock_memory_and_startup(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    properties = "clock_memory = MB100\ncycle_time = 20\nstartup = cold\n"
    code, state, err = _run(tmp_path, capsys, properties, "--cycles", "150")
    assert code == 0, err
    assert state is not None
    assert state["time_ms"] == 3000  # 150 scans of 20 ms
    assert state["M"]["11"] == 3  # M 100.5 rose at 0.5 s, 1.5 s and 2.5 s
    assert state["M"]["21"] == 102  # a cold restart ran OB102
    (tmp_path / "cpu.properties").unlink()
    code, state, _ = _run(tmp_path, capsys, None, "--cycles", "150")
    assert state is not None
    assert "11" not in state["M"]
    assert state["time_ms"] == 1500
    assert "21" not in state["M"]


def test_command_line_options_win_over_the_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    properties = "clock_memory = MB100\ncycle_time = 20\nstartup = cold\n"
    args = (
        "--cycles",
        "150",
        "--cycle-ms",
        "10",
        "--restart",
        "warm",
        "--clock-memory",
        "MB50",
    )
    code, state, err = _run(tmp_path, capsys, properties, *args)
    assert code == 0, err
    assert state is not None
    assert state["time_ms"] == 1500
    assert "11" not in state["M"]  # the clock memory is MB 50 now, M 100.5 never rises
    assert "21" not in state["M"]  # warm restart: no OB102


def test_the_file_may_also_be_given_as_a_source(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    elsewhere = tmp_path / "config"
    elsewhere.mkdir()
    (elsewhere / "cpu.properties").write_text("cycle_time = 50\n", encoding="utf-8")
    code, state, err = _run(
        tmp_path, capsys, None, str(elsewhere / "cpu.properties"), "--cycles", "4"
    )
    assert code == 0, err
    assert state is not None
    assert state["time_ms"] == 200


def test_a_file_with_errors_stops_the_run_with_file_line_and_code(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, state, err = _run(tmp_path, capsys, "cycle_time = 20\nstartup = hot\n", "--cycles", "2")
    assert (code, state) == (1, None)  # the project has errors, as a source that fails to compile
    assert f"{tmp_path / 'cpu.properties'}:2:11: PRJ906:" in err


def test_retentive_ranges_of_the_file_apply_to_the_scenario(tmp_path: Path) -> None:
    (tmp_path / "prog.awl").write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "cpu.properties").write_text("clock_memory = MB100\n", encoding="utf-8")
    scenario = tmp_path / "clock.yaml"
    scenario.write_text(
        "name: clock\nsources: [prog.awl]\nsteps:\n  - run: {ms: 3000}\n  - expect: {MW10: 3}\n",
        encoding="utf-8",
    )
    result = run_scenario(scenario)
    assert result.passed, (result.error, result.failures, result.diagnostics)
    # the scenario's own cycle_ms wins over the file's: 3000 ms are still 3000 ms
    (tmp_path / "cpu.properties").write_text("clock_memory = MB100\ncycle_time = 30\n", "utf-8")
    scenario.write_text(scenario.read_text("utf-8").replace("steps:", "cycle_ms: 5\nsteps:"))
    result = run_scenario(scenario)
    assert result.passed, (result.error, result.failures)
    # a bad file is an error of the scenario, with its line
    (tmp_path / "cpu.properties").write_text("clock_memory = MX100\n", encoding="utf-8")
    result = run_scenario(scenario)
    assert result.error == "the CPU properties file has errors"
    assert any(":1:16: PRJ904:" in line for line in result.diagnostics)

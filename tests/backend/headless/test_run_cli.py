"""``nasaq run``: the JSON contract and exit statuses that outside checks rely on."""

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

CONTRACT_KEYS = {
    "cycles", "time_ms", "mode", "stop_reason", "I", "Q", "M", "DB", "T", "C",
    "ACCU1", "ACCU2", "STW",
}  # fmt: skip

LATCH = """\
ORGANIZATION_BLOCK OB 1
TITLE = Start/stop latch
VERSION : 0.1
BEGIN
NETWORK
TITLE = Motor
      A(    ;
      O     I      0.0;
      O     Q      4.0;
      )     ;
      AN    I      0.1;
      =     Q      4.0;
NETWORK
TITLE = Count scans
      L     MW    10;
      +     1;
      T     MW    10;
END_ORGANIZATION_BLOCK
"""


def _run(tmp_path: Path, source: str, *args: str) -> tuple[int, dict[str, Any] | None, str]:
    path = tmp_path / "prog.awl"
    path.write_text(source, encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-m", "nasaq", "run", str(path), *args],
        capture_output=True,
        text=True,
        timeout=60,
    )
    state = json.loads(result.stdout) if result.stdout.strip() else None
    return result.returncode, state, result.stderr


def test_scans_run_and_the_state_has_exactly_the_contract_keys(tmp_path: Path) -> None:
    code, state, _ = _run(tmp_path, LATCH, "--cycles", "3", "--set", "I0.0=1")
    assert code == 0
    assert state is not None
    assert set(state) == CONTRACT_KEYS
    assert state["cycles"] == 3
    assert state["time_ms"] == 30
    assert state["mode"] == "RUN"
    assert state["stop_reason"] is None
    assert state["I"] == {"0": 1}
    assert state["Q"] == {"4": 1}
    assert state["M"] == {"11": 3}  # MW10 = 3 after three scans: low byte at MB11
    assert state["DB"] == {}
    assert state["T"] == {}
    assert state["C"] == {}
    assert state["ACCU1"] == 3


def test_at_changes_an_input_before_the_given_scan(tmp_path: Path) -> None:
    code, state, _ = _run(
        tmp_path, LATCH, "--cycles", "5", "--at", "2:I0.0=1", "--at", "3:I0.0=0", "--at", "5:I0.1=1"
    )
    assert code == 0
    assert state is not None
    assert state["Q"] == {}  # latched in scans 2-4, released by stop in scan 5
    assert state["I"] == {"0": 2}


def test_set_of_a_marker_is_written_once_after_ob100(tmp_path: Path) -> None:
    code, state, _ = _run(tmp_path, LATCH, "--cycles", "2", "--set", "MW10=100")
    assert code == 0
    assert state is not None
    assert state["M"] == {"11": 102}


def test_compile_errors_exit_1_with_file_line_column_code(tmp_path: Path) -> None:
    broken = LATCH.replace("AN    I      0.1;", "XYZ   I      0.1;")
    code, state, stderr = _run(tmp_path, broken)
    assert code == 1  # as nasaq compile (tests/backend/test_cli_exit_codes.py)
    assert state is None
    lines = stderr.strip().splitlines()
    assert len(lines) == 1
    where, diag_code, _message = lines[0].split(": ", 2)
    assert where == f"{tmp_path / 'prog.awl'}:11:7"
    assert diag_code.startswith("STL")


def test_sfc46_stops_the_cpu_normally(tmp_path: Path) -> None:
    source = LATCH.replace("      T     MW    10;", "      T     MW    10;\n      CALL  SFC   46;")
    code, state, _ = _run(tmp_path, source, "--cycles", "10")
    assert code == 0
    assert state is not None
    assert state["mode"] == "STOP"
    assert state["cycles"] == 1


def test_a_runtime_error_stops_with_block_and_line_and_exit_1(tmp_path: Path) -> None:
    source = LATCH.replace("      L     MW    10;", "      OPN   DB    99;\n      L     MW    10;")
    code, state, _ = _run(tmp_path, source, "--cycles", "3")
    assert code == 1
    assert state is not None
    assert state["mode"] == "STOP"
    assert "OB1" in state["stop_reason"]
    assert "line 15" in state["stop_reason"]  # the line of OPN DB 99


def test_an_endless_loop_stops_the_cpu_quickly(tmp_path: Path) -> None:
    source = LATCH.replace("      L     MW    10;", "M001: JU    M001;\n      L     MW    10;")
    code, state, _ = _run(tmp_path, source, "--cycles", "3")
    assert code == 1
    assert state is not None
    assert state["mode"] == "STOP"
    assert state["cycles"] == 1


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--set", "I0=1"], "bit number"),
        (["--set", "MW10"], "ADDR=VALUE"),
        (["--at", "0:I0.0=1"], "scan number"),
        (["--set", "T1=5"], "cannot be set"),
    ],
)
def test_bad_arguments_exit_2_with_a_reason(tmp_path: Path, args: list[str], message: str) -> None:
    code, state, stderr = _run(tmp_path, LATCH, *args)
    assert code == 2
    assert state is None
    assert message in stderr


STARTUP = """\
ORGANIZATION_BLOCK OB 100
BEGIN
      L     100;
      T     MW    0;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK OB 102
BEGIN
      L     102;
      T     MW    0;
END_ORGANIZATION_BLOCK
"""


@pytest.mark.parametrize(("args", "value"), [([], 100), (["--restart", "cold"], 102)])
def test_restart_type_and_a_program_without_ob1(
    tmp_path: Path, args: list[str], value: int
) -> None:
    """Warm restart runs OB100, cold restart OB102; without OB1 the CPU still goes to RUN."""
    code, state, _ = _run(tmp_path, STARTUP, "--cycles", "2", *args)
    assert code == 0
    assert state is not None
    assert (state["mode"], state["cycles"]) == ("RUN", 2)
    assert state["M"] == {"1": value}


def test_setting_a_missing_db_is_a_bad_argument(tmp_path: Path) -> None:
    code, state, stderr = _run(tmp_path, LATCH, "--set", "DB5.DBW0=1")
    assert (code, state) == (2, None)
    assert "DB 5 is not loaded" in stderr


def test_a_simulator_bug_is_stop_sim500_not_a_traceback(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import io

    from nasaq.headless import run

    def broken(*args: object, **kwargs: object) -> None:
        raise RuntimeError("boom")

    monkeypatch.setattr(run, "Cpu", broken)
    path = tmp_path / "prog.awl"
    path.write_text(LATCH, encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    assert run.execute(run.RunOptions(sources=[path]), out, err) == 1
    state = json.loads(out.getvalue())
    assert set(state) == CONTRACT_KEYS
    assert state["mode"] == "STOP"
    assert state["stop_reason"].endswith("(SIM500)")
    assert "boom" in err.getvalue()


CLOCK = """\
ORGANIZATION_BLOCK OB 1
BEGIN
      A     M    100.0;
      FN    M    101.0;
      JCN   skip;
      L     MW    10;
      +     1;
      T     MW    10;
skip: NOP   0;
END_ORGANIZATION_BLOCK
"""


def test_clock_memory_option_drives_the_marker_byte(tmp_path: Path) -> None:
    """``--clock-memory 100``: M 100.0 is the 10 Hz bit; 1 s of scans sees 10 falling edges."""
    code, state, _ = _run(tmp_path, CLOCK, "--cycles", "101", "--clock-memory", "MB100")
    assert code == 0
    assert state is not None
    assert state["M"]["11"] == 10
    code, state, _ = _run(tmp_path, CLOCK, "--cycles", "101")
    assert code == 0
    assert state is not None
    assert "11" not in state["M"]


@pytest.mark.parametrize("value", ["2048", "MX1", "-1"])
def test_a_bad_clock_memory_byte_is_refused(tmp_path: Path, value: str) -> None:
    code, state, err = _run(tmp_path, CLOCK, "--clock-memory", value)
    assert code == 2
    assert state is None
    assert "clock memory" in err or "--clock-memory" in err

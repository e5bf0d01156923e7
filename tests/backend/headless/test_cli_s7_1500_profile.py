"""``nasaq run --cpu S7-1500`` and ``nasaq compile`` on the S7-1200/1500 profile: chosen on the
command line (``--profile`` is the old spelling) or by the sources' cpu.properties."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

SOURCE = """\
DATA_BLOCK DB1
STRUCT
  total : LREAL;
  count : UINT;
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  DB1.total := DB1.total + LREAL#0.25;
  DB1.count := DB1.count + 1;
END_ORGANIZATION_BLOCK
"""


def _nasaq(*args: str) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "nasaq", *args]
    return subprocess.run(command, check=False, capture_output=True, text=True, timeout=120)


def test_run_with_the_cpu_option(tmp_path: Path) -> None:
    path = tmp_path / "prog.scl"
    path.write_text(SOURCE, encoding="utf-8")
    for option in ("--cpu", "--profile"):
        done = _nasaq("run", str(path), "--cycles", "4", option, "S7-1500")
        assert done.returncode == 0, done.stderr
        data = json.loads(done.stdout)["DB"]["1"]
        total = bytes(data.get(str(i), 0) for i in range(8))
        assert total == bytes.fromhex("3ff0000000000000")  # 4 x 0.25 = 1.0, an IEEE double
        assert (data.get("8", 0), data.get("9", 0)) == (0, 4)
    classic = _nasaq("run", str(path))
    assert classic.returncode != 0  # (the exit status of errors is the defects part's)
    assert "SCL500: LREAL needs the S7-1200/1500 profile" in classic.stderr


def test_the_properties_file_chooses_the_profile_for_run_and_compile(
    tmp_path: Path,
) -> None:
    path = tmp_path / "prog.scl"
    path.write_text(SOURCE, encoding="utf-8")
    (tmp_path / "cpu.properties").write_text("profile = S7-1500\n", encoding="utf-8")
    assert _nasaq("run", str(path)).returncode == 0
    assert _nasaq("compile", str(path)).returncode == 0
    overridden = _nasaq("compile", str(path), "--cpu", "S7-300")
    assert overridden.returncode == 1
    assert "SCL500" in overridden.stderr


def test_a_scenario_runs_on_the_profile_it_names_or_its_folders(tmp_path: Path) -> None:
    from nasaq.scenarios.runner import run_scenario

    (tmp_path / "prog.scl").write_text(SOURCE, encoding="utf-8")
    scenario = tmp_path / "count.yaml"
    body = "sources: [prog.scl]\nsteps:\n  - run: 3\n  - expect: {DB1.DBW8: 3}\n"
    scenario.write_text("name: count\nprofile: S7-1500\n" + body, encoding="utf-8")
    result = run_scenario(scenario)
    assert result.passed, (result.error, result.diagnostics, result.failures)
    scenario.write_text("name: count\n" + body, encoding="utf-8")
    assert "SCL500" in " ".join(run_scenario(scenario).diagnostics)
    (tmp_path / "cpu.properties").write_text("profile = S7-1500\n", encoding="utf-8")
    assert run_scenario(scenario).passed

"""``nasaq test``: scenarios run against the real compiler and CPU, failures reported precisely."""

import subprocess
import sys
from pathlib import Path

from nasaq.scenarios.runner import run_scenario

TIMER = """\
ORGANIZATION_BLOCK OB 1
TITLE = On-delay lamp
VERSION : 0.1
BEGIN
NETWORK
TITLE = 2 s on-delay
      A     I      0.0;
      L     S5T#2S;
      SD    T      1;
      A     T      1;
      =     Q      4.0;
NETWORK
TITLE = A real
      L     2.500000e+000;
      T     MD    20;
END_ORGANIZATION_BLOCK
"""

SCENARIO = """\
name: on-delay lamp
sources: [lamp.awl]
steps:
  - set: {I0.0: 1}
  - run: {ms: 1980}
  - expect: {Q4.0: 0, T1: {q: 0}}
  - note: two seconds have passed
  - run: 5
  - expect: {Q4.0: 1, T1: {q: 1}, MD20: {real: 2.5, tolerance: 0}, mode: RUN}
"""


def _files(tmp_path: Path, scenario: str, source: str = TIMER) -> Path:
    (tmp_path / "lamp.awl").write_text(source, encoding="utf-8")
    path = tmp_path / "lamp.yaml"
    path.write_text(scenario, encoding="utf-8")
    return path


def test_a_correct_scenario_passes(tmp_path: Path) -> None:
    result = run_scenario(_files(tmp_path, SCENARIO))
    assert result.error is None, result.diagnostics
    assert result.failures == []
    assert result.passed


def test_each_mismatch_is_reported_with_step_note_address_and_values(tmp_path: Path) -> None:
    wrong = SCENARIO.replace("{Q4.0: 1, T1: {q: 1}", "{Q4.0: 0, T1: {q: 0}").replace(
        "real: 2.5", "real: 3.5"
    )
    result = run_scenario(_files(tmp_path, wrong))
    assert not result.passed
    described = [failure.describe() for failure in result.failures]
    assert described == [
        "step 6 (two seconds have passed): Q4.0 expected 0, got 1",
        "step 6 (two seconds have passed): T1 expected {'q': 0}, got {'q': 1}",
        "step 6 (two seconds have passed): MD20 expected 3.5 ± 0.0, got 2.5",
    ]


def test_sources_that_do_not_compile_are_an_error_with_diagnostics(tmp_path: Path) -> None:
    result = run_scenario(_files(tmp_path, SCENARIO, TIMER.replace("SD    T", "SDX   T")))
    assert result.error == "the sources do not compile"
    assert result.diagnostics
    assert result.diagnostics[0].startswith(f"{tmp_path / 'lamp.awl'}:9:7: STL")


def test_missing_source_is_an_error_not_a_crash(tmp_path: Path) -> None:
    path = tmp_path / "lonely.yaml"
    path.write_text(SCENARIO, encoding="utf-8")
    result = run_scenario(path)
    assert result.error is not None
    assert "lamp.awl" in result.error


def test_nasaq_test_prints_failures_and_the_closing_count(tmp_path: Path) -> None:
    good = _files(tmp_path, SCENARIO)
    bad = tmp_path / "bad.yaml"
    bad.write_text(SCENARIO.replace("Q4.0: 0, T1", "Q4.0: 1, T1"), encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-m", "nasaq", "test", str(good), str(bad)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert result.returncode == 1
    lines = result.stdout.strip().splitlines()
    assert lines[-1] == "1 passed, 1 failed"
    assert lines[0] == f"{bad}: on-delay lamp: step 3: Q4.0 expected 1, got 0"


def test_a_note_per_language_is_reported_in_english_by_nasaq_test(tmp_path: Path) -> None:
    """A lesson's check may write its notes per language; ``nasaq test`` speaks English."""
    translated = SCENARIO.replace(
        "note: two seconds have passed",
        'note: {fa: "دو ثانیه گذشت", en: two seconds have passed}',
    ).replace("{Q4.0: 1, T1: {q: 1}", "{Q4.0: 0, T1: {q: 1}")
    path = _files(tmp_path, translated)
    result = subprocess.run(
        [sys.executable, "-m", "nasaq", "test", str(path)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert result.returncode == 1
    first = result.stdout.splitlines()[0]
    english = "step 6 (two seconds have passed): Q4.0 expected 0, got 1"
    assert first == f"{path}: on-delay lamp: {english}"
    [failure] = run_scenario(path).failures
    assert failure.describe("fa") == "step 6 (دو ثانیه گذشت): Q4.0 expected 0, got 1"

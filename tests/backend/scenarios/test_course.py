"""Every example program of the course, as a scenario under tests/scenarios/, behaves as a real
S7-300 would (corrected where the books are wrong; tests/scenarios/course/README.md says where)."""

from pathlib import Path

import pytest

from nasaq.scenarios.report import scenario_files
from nasaq.scenarios.runner import run_scenario

FOLDER = Path(__file__).resolve().parents[2] / "scenarios"
SCENARIOS = scenario_files([FOLDER])


def test_the_course_is_covered() -> None:
    assert len(SCENARIOS) >= 30


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda path: str(path.relative_to(FOLDER)))
def test_course_scenario(path: Path) -> None:
    result = run_scenario(path)
    problems = [result.error] if result.error else []
    problems += result.diagnostics + [failure.describe() for failure in result.failures]
    assert result.passed, "\n".join(str(problem) for problem in problems)

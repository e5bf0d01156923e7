"""``nasaq test``: runs scenario files (or every ``*.yaml`` below given folders) and reports."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TextIO

from nasaq.scenarios.runner import ScenarioResult, run_scenario


def scenario_files(targets: Iterable[Path]) -> list[Path]:
    files: list[Path] = []
    for target in targets:
        if target.is_dir():
            files.extend(sorted(target.rglob("*.yaml")))
        else:
            files.append(target)
    return files


def report(results: Sequence[ScenarioResult], out: TextIO) -> None:
    for result in results:
        if result.error is not None:
            print(f"{result.path}: ERROR: {result.error}", file=out)
            for line in result.diagnostics:
                print(f"  {line}", file=out)
        for failure in result.failures:
            print(f"{result.path}: {result.name}: {failure.describe()}", file=out)
            if place := failure.place():
                print(f"  {place}", file=out)
        if result.stop is not None:
            print(f"  the CPU went to STOP: {result.stop[1]}", file=out)
    passed = sum(result.passed for result in results)
    print(f"{passed} passed, {len(results) - passed} failed", file=out)


def _is_course(path: Path) -> bool:
    """A folder of lessons (``examples/lessons``, a unit, a lesson): its scenarios run against
    each lesson's solution, start and wrong programs (``nasaq lessons check``)."""
    return path.is_dir() and (
        (path / "lesson.yaml").is_file()
        or (path / "unit.yaml").is_file()
        or any(child.is_dir() and (child / "unit.yaml").is_file() for child in path.iterdir())
    )


def main(targets: Sequence[str], out: TextIO) -> int:
    """Exit status, as every ``nasaq`` command (``nasaq.cli``): 0 all passed, 1 some failed or
    a scenario or its sources have errors, 2 no scenario file was found."""
    courses = [target for target in targets if _is_course(Path(target))]
    if courses:
        from nasaq.lessons.report import check_main

        status = check_main(courses, Path(courses[0]), out)
        others = [target for target in targets if target not in courses]
        return max(status, main(others, out)) if others else status
    files = scenario_files(Path(target) for target in targets)
    if not files:
        print("nasaq test: no scenario files found", file=out)
        return 2
    results = [run_scenario(path) for path in files]
    report(results, out)
    return 0 if all(result.passed for result in results) else 1

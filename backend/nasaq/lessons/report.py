"""``nasaq lessons check|lint|list``: the course checked from the command line.

``check`` proves every check can fail: the reference solution must pass every check (quizzes
with their right answers), and ``start/`` (and ``wrong/`` when present) must fail at least one,
so no check passes an empty or unfinished program. One line per lesson, then a summary. Exit
status: 0 all good, 1 a lesson's solution failed or its start passed, 2 a lesson folder or a
check is broken.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TextIO

from nasaq.lessons.check import LessonCheck, check_lesson
from nasaq.lessons.lint import lint_course
from nasaq.lessons.load import Course, Lesson, read_course
from nasaq.lessons.model import Problem
from nasaq.lessons.quiz import QuizError, right_answers


def _failing(report: LessonCheck) -> str:
    """A short account of what failed: the first failing check and its first failure."""
    for check in report.checks:
        if check.passed:
            continue
        if check.error:
            return f"{check.name}: {check.error}"
        for step in check.steps:
            for failure in step.failures:
                return (
                    f"{check.name}: step {step.step}: {failure.address} expected "
                    f"{failure.expected}, got {failure.actual}"
                )
        if check.stop is not None:
            return f"{check.name}: STOP {check.stop.reason}"
        return f"{check.name}: failed"
    return report.status


def verify(lesson: Lesson) -> tuple[str, str]:
    """("ok" | "fail" | "error", what went wrong) for one lesson."""
    try:
        answers = right_answers(lesson, lesson.quiz) if lesson.quiz is not None else {}
    except QuizError as exc:
        return "error", f"quiz: {exc}"
    solution = check_lesson(lesson, lesson.files("solution") or [], answers)
    if solution.status == "error":
        return "error", f"solution: {_failing(solution)}"
    if solution.status != "passed":
        return "fail", f"the solution does not pass: {_failing(solution)}"
    for part in ("start", "wrong"):
        files = lesson.files(part)
        if files is None and part == "wrong":
            continue
        found = check_lesson(lesson, files or [], {})
        if found.status == "error":
            return "error", f"{part}: {_failing(found)}"
        if found.status == "passed":
            return "fail", f"{part}/ passes every check: a check must fail it"
    return "ok", ""


@dataclass(frozen=True, slots=True)
class _Target:
    course: Course
    only: set[str] | None  # the lesson ids asked for; None: all
    prefix: str  # the target's folder in the course ("", "fa2/", "fa2/fa2-01/")

    def problems(self) -> list[Problem]:
        return [p for p in self.course.problems if p.file.startswith(self.prefix)]

    def lessons(self) -> list[Lesson]:
        return [x for x in self.course.lessons() if self.only is None or x.id in self.only]


def _targets(paths: Sequence[str], default: Path) -> list[_Target]:
    """Each path is the course folder, a unit folder or a lesson folder."""
    found: list[_Target] = []
    for given in [Path(t) for t in paths] or [default]:
        path = given.resolve()
        if (path / "lesson.yaml").is_file():
            course = read_course(path.parent.parent)
            found.append(_Target(course, {path.name}, f"{path.parent.name}/{path.name}/"))
        elif (path / "unit.yaml").is_file():
            course = read_course(path.parent)
            ids = {x.id for unit in course.units if unit.folder == path for x in unit.lessons}
            found.append(_Target(course, ids, f"{path.name}/"))
        else:
            found.append(_Target(read_course(path), None, ""))
    return found


def check_main(targets: Sequence[str], default: Path, out: TextIO) -> int:
    counts = {"ok": 0, "fail": 0, "error": 0}
    broken = 0
    for target in _targets(targets, default):
        for problem in target.problems():
            print(problem.text(), file=out)
            broken += 1
        for lesson in target.lessons():
            verdict, why = verify(lesson)
            counts[verdict] += 1
            tail = f": {why}" if why else ""
            print(f"{lesson.id}: {verdict.upper()}{tail}", file=out)
    total = sum(counts.values())
    print(
        f"{counts['ok']} of {total} lessons ok, {counts['fail']} failed, "
        f"{counts['error'] + broken} broken",
        file=out,
    )
    if total == 0 and not broken:
        print("nasaq lessons check: no lessons found", file=out)
        return 2
    # 1 for a lesson that fails or is broken (the course has errors), as every nasaq command
    return 1 if counts["fail"] or counts["error"] or broken else 0


def lint_main(targets: Sequence[str], default: Path, out: TextIO) -> int:
    problems = 0
    lessons = 0
    for target in _targets(targets, default):
        lessons += len(target.lessons())
        found = target.problems() + lint_course(target.course, target.only, reading=False)
        for problem in found:
            print(problem.text(), file=out)
            problems += 1
    print(f"{lessons} lessons, {problems} problems", file=out)
    return 1 if problems else 0


def list_main(default: Path, language: str, out: TextIO) -> int:
    course = read_course(default)
    for unit in course.units:
        title = unit.meta.title.get(language) or unit.meta.title.get("en", "")
        print(f"{unit.meta.id}  {title}", file=out)
        for lesson in unit.lessons:
            meta = lesson.meta
            name = meta.title.get(language) or meta.title.get("en", "")
            plant = f" [{meta.plant.kind}]" if meta.plant else ""
            print(f"  {meta.id:<8} {meta.works_in:<4} {meta.form:<14} {name}{plant}", file=out)
    for problem in course.problems:
        print(problem.text(), file=out)
    return 1 if course.problems else 0

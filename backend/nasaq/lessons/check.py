"""The "Check" of a lesson: every check of ``lesson.yaml`` against a set of project files.

- ``scenario``: the scenario file runs against the files with the lesson's plant in closed loop
  (unless the scenario names its own ``plant`` or ``none``).
- ``convert``: ``conversion.check_conversion``.
- ``quiz``: the learner's answers (``quiz.grade``).

Statuses: ``compile_error`` when the program does not compile (the compiler's diagnostics, no
scenario is run: a learner sees their mistake, not a failed check); ``error`` when a check
itself is broken (a lesson bug); ``passed`` when every check passed; else ``failed``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Literal

from pydantic import BaseModel, Field

from nasaq.diagnostics import Diagnostic, Severity
from nasaq.lessons.conversion import check_conversion
from nasaq.lessons.load import Lesson
from nasaq.lessons.model import CheckSpec, Texts
from nasaq.lessons.quiz import QuizError, grade
from nasaq.scenarios.model import note_text
from nasaq.scenarios.runner import ScenarioResult, run_scenario

Status = Literal["passed", "failed", "compile_error", "error"]


class DiagnosticOut(BaseModel):
    code: str
    severity: str
    message: str
    file: str | None
    line: int | None
    column: int | None
    key: str = ""
    params: dict[str, Any] = Field(default_factory=dict)
    network: int | None = None
    element: str | None = None

    @classmethod
    def of(cls, diagnostic: Diagnostic) -> DiagnosticOut:
        span = diagnostic.span
        return cls(
            code=diagnostic.code,
            severity=str(diagnostic.severity.value),
            message=diagnostic.message,
            file=span.file if span else None,
            line=span.line if span else None,
            column=span.column if span else None,
            key=diagnostic.key,
            params=diagnostic.params,
            network=span.network if span else None,
            element=span.element if span else None,
        )


class WhereOut(BaseModel):
    file: str
    line: int
    network: int | None
    element: str | None


class FailureOut(BaseModel):
    address: str
    expected: str
    actual: str
    at_ms: int | None
    where: WhereOut | None


class StepOut(BaseModel):
    step: int
    note: str | None
    passed: bool
    failures: list[FailureOut]


class StopOut(BaseModel):
    code: str
    reason: str
    key: str = ""
    params: dict[str, Any] = Field(default_factory=dict)


class CheckOut(BaseModel):
    kind: Literal["scenario", "convert", "quiz"]
    name: str
    passed: bool
    error: str | None = None
    diagnostics: list[DiagnosticOut] = Field(default_factory=list)
    stop: StopOut | None = None
    steps: list[StepOut] = Field(default_factory=list)


class QuizOut(BaseModel):
    id: str
    correct: bool
    expected_shown: str | None
    explain: Texts | None


class LessonCheck(BaseModel):
    status: Status
    checks: list[CheckOut]
    quiz: list[QuizOut]


def _steps(result: ScenarioResult, language: str) -> list[StepOut]:
    """The checking steps with their failures, each note in ``language`` (else English)."""
    by_step: dict[int, list[FailureOut]] = {}
    for failure in result.failures:
        where = failure.where
        by_step.setdefault(failure.step, []).append(
            FailureOut(
                address=failure.address,
                expected=failure.expected,
                actual=failure.actual,
                at_ms=failure.at_ms,
                where=WhereOut(
                    file=where.file, line=where.line, network=where.network, element=where.element
                )
                if where is not None
                else None,
            )
        )
    notes = dict(result.steps)
    numbers = sorted(set(notes) | set(by_step))
    return [
        StepOut(
            step=number,
            note=note_text(
                notes.get(number)
                or next((f.note for f in result.failures if f.step == number), None),
                language,
            ),
            passed=number not in by_step,
            failures=by_step.get(number, []),
        )
        for number in numbers
    ]


def _scenario(
    lesson: Lesson, check: CheckSpec, files: Sequence[tuple[str, str]], language: str
) -> tuple[CheckOut, bool]:
    """The check's outcome, and whether the program did not compile."""
    assert check.scenario is not None
    result = run_scenario(lesson.folder / check.scenario, files, lesson.meta.plant)
    shown = [d for d in result.problems if d.severity is not Severity.INFO]
    out = CheckOut(kind="scenario", name=check.scenario, passed=result.passed)
    if result.error is not None:
        out.error = result.error.replace(str(lesson.folder) + "/", "")
        out.diagnostics = [DiagnosticOut.of(d) for d in shown]
    if result.stop is not None:
        out.stop = StopOut(
            code=result.stop[0],
            reason=result.stop[1],
            key=result.stop_key,
            params=result.stop_params,
        )
    out.steps = _steps(result, language)
    return out, result.compile_failed


def check_lesson(
    lesson: Lesson,
    files: Sequence[tuple[str, str]],
    answers: dict[str, Any] | None = None,
    reveal: bool = False,
    language: str = "en",
) -> LessonCheck:
    """Runs every check; ``reveal`` shows the right quiz answers (passed or given up); the
    steps' notes come in ``language`` (else English, else any language the note has)."""
    checks: list[CheckOut] = []
    quiz: list[QuizOut] = []
    status: Status = "passed"
    for check in lesson.meta.checks:
        if check.scenario is not None:
            if not (lesson.folder / check.scenario).is_file():
                error = f"{check.scenario}: missing"
                checks.append(CheckOut(kind="scenario", name=check.name, passed=False, error=error))
                status = "error"
                continue
            out, compile_failed = _scenario(lesson, check, files, language)
            checks.append(out)
            if compile_failed:
                return LessonCheck(status="compile_error", checks=checks, quiz=[])
            if out.error is not None:
                status = "error"
        elif check.convert is not None:
            found = check_conversion(files, check.convert)
            checks.append(
                CheckOut(
                    kind="convert",
                    name=check.name,
                    passed=found.passed,
                    error=found.error,
                    diagnostics=[DiagnosticOut.of(d) for d in found.diagnostics],
                )
            )
        elif lesson.quiz is not None:
            try:
                verdicts = grade(lesson, lesson.quiz, answers or {})
            except QuizError as exc:
                checks.append(CheckOut(kind="quiz", name=check.name, passed=False, error=str(exc)))
                status = "error"
                continue
            quiz = [
                QuizOut(
                    id=verdict.id,
                    correct=verdict.correct,
                    expected_shown=verdict.expected if reveal else None,
                    explain=verdict.explain if verdict.answered else None,
                )
                for verdict in verdicts
            ]
            passed = all(verdict.correct for verdict in verdicts)
            checks.append(CheckOut(kind="quiz", name=check.name, passed=passed))
        else:
            error = f"{check.quiz}: missing"
            checks.append(CheckOut(kind="quiz", name=check.name, passed=False, error=error))
            status = "error"
    if status == "passed" and not all(check.passed for check in checks):
        status = "failed"
    return LessonCheck(status=status, checks=checks, quiz=quiz)

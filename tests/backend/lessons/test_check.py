"""Check of a lesson against project files: scenarios with the lesson's plant, conversion
checks and quizzes, with the statuses the lesson pane shows."""

from pathlib import Path

import pytest

from nasaq.lessons.check import check_lesson
from nasaq.lessons.conversion import check_conversion
from nasaq.lessons.load import Lesson, read_course
from nasaq.lessons.model import ConvertSpec
from nasaq.lessons.quiz import grade, predict_truth, right_answers

COURSE = read_course(Path(__file__).parent / "fixtures" / "course")


def _lesson(lesson_id: str) -> Lesson:
    found = COURSE.lesson(lesson_id)
    assert found is not None
    return found


def test_the_solution_passes_with_the_plant_in_closed_loop() -> None:
    lesson = _lesson("fa9-01")
    report = check_lesson(lesson, lesson.files("solution") or [])
    assert report.status == "passed"
    [scenario] = report.checks
    assert scenario.passed
    assert scenario.steps
    assert all(step.passed for step in scenario.steps)


def test_the_wrong_program_fails_and_points_at_the_line_that_writes_the_pump() -> None:
    lesson = _lesson("fa9-01")
    report = check_lesson(lesson, lesson.files("wrong") or [])
    assert report.status == "failed"
    failing = [step for step in report.checks[0].steps if not step.passed]
    assert failing[0].note == "the tank fills up and the pump stops by itself"
    failure = failing[0].failures[0]
    assert (failure.address, failure.actual) == ("Q4.0", "1")
    assert failure.at_ms is not None
    assert failure.at_ms > 10_000
    assert failure.where is not None
    assert (failure.where.file, failure.where.line, failure.where.network) == (
        "OB1.awl",
        10,
        1,
    )


def test_the_step_notes_come_in_the_language_asked_for_else_in_english() -> None:
    lesson = _lesson("fa9-01")
    files = lesson.files("wrong") or []

    def failing_note(language: str) -> str | None:
        report = check_lesson(lesson, files, language=language)
        return next(step.note for step in report.checks[0].steps if not step.passed)

    assert failing_note("fa") == "مخزن پر می‌شود و پمپ خودبه‌خود خاموش می‌شود"
    assert failing_note("en") == "the tank fills up and the pump stops by itself"
    assert failing_note("vi") == "the tank fills up and the pump stops by itself"
    passed = check_lesson(lesson, lesson.files("solution") or [], language="fa")
    assert passed.checks[0].steps[0].note == "در حالت سکون"


def test_the_start_program_fails() -> None:
    lesson = _lesson("fa9-01")
    assert check_lesson(lesson, lesson.files("start") or []).status == "failed"


def test_a_program_that_does_not_compile_gets_the_diagnostics_not_a_failed_check() -> None:
    lesson = _lesson("fa9-01")
    broken = [
        (
            "OB1.awl",
            "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n  AX I 0.0\nEND_ORGANIZATION_BLOCK\n",
        )
    ]
    report = check_lesson(lesson, broken)
    assert report.status == "compile_error"
    [check] = report.checks
    assert check.diagnostics
    assert check.diagnostics[0].file == "OB1.awl"
    assert check.diagnostics[0].line == 4
    assert check.diagnostics[0].severity == "error"


def test_a_program_that_stops_the_cpu_fails_with_the_stop_reason() -> None:
    lesson = _lesson("fa9-01")
    runaway = [
        (
            "OB1.awl",
            "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nL1:   JU    L1\nEND_ORGANIZATION_BLOCK\n",
        )
    ]
    report = check_lesson(lesson, runaway)
    assert report.status == "failed"
    assert report.checks[0].stop is not None
    assert report.checks[0].stop.reason
    assert report.checks[0].stop.key  # the pane says it in the interface language


def test_lad_solution_passes_the_scenario_and_the_conversion() -> None:
    lesson = _lesson("fa9-03")
    passed = check_lesson(lesson, lesson.files("solution") or [])
    assert passed.status == "passed", passed
    assert [c.kind for c in passed.checks] == ["scenario", "convert"]
    started = check_lesson(lesson, lesson.files("start") or [])
    assert started.status == "failed"
    assert started.checks[1].passed  # the start rung converts; its logic is what fails


def test_a_conversion_with_a_network_that_has_no_lad_form_fails_with_its_reason() -> None:
    stl = """ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     I 0.0
      X     I 0.1
      =     Q 4.0
END_ORGANIZATION_BLOCK
"""
    found = check_conversion([("OB1.awl", stl)], ConvertSpec(file="OB1.awl", to="LAD"))
    assert not found.passed
    assert found.error
    assert "stay STL" in found.error
    assert [d.code for d in found.diagnostics] == ["LAD305"]
    drawable = stl.replace("X     I 0.1", "A     I 0.1")
    assert check_conversion([("OB1.awl", drawable)], ConvertSpec(file="OB1.awl", to="LAD")).passed
    missing = check_conversion([], ConvertSpec(file="OB1.awl", to="LAD"))
    assert not missing.passed
    assert "no file" in (missing.error or "")


def test_predict_runs_the_program_for_the_truth() -> None:
    lesson = _lesson("fa9-02")
    assert lesson.quiz is not None
    question = lesson.quiz.questions[4]
    assert predict_truth(lesson, question) == {"Q4.0": 1, "MW10": 0xFFF9}


@pytest.mark.parametrize(
    ("answers", "correct"),
    [
        (
            {
                "q1": "b",
                "q2": "2.5",
                "q3": "w#16#0250",
                "q4": ["c", "a"],
                "q5": {"Q4.0": 1, "MW10": -7},
            },
            [True] * 5,
        ),
        (
            {
                "q1": "a",
                "q2": "2.6",
                "q3": "0250",
                "q4": ["a"],
                "q5": {"Q4.0": 1, "MW10": 7},
            },
            [False] * 5,
        ),
        (
            {"q2": "۲٫۵", "q3": "16# 0250", "q5": {"q 4.0": "1", "mw10": "16#FFF9"}},
            [False, True, True, False, True],
        ),
        ({"q2": "2,5"}, [False, True, False, False, False]),
    ],
)
def test_quiz_answers_are_graded_on_the_server(
    answers: dict[str, object], correct: list[bool]
) -> None:
    lesson = _lesson("fa9-02")
    assert lesson.quiz is not None
    assert [v.correct for v in grade(lesson, lesson.quiz, answers)] == correct


def test_a_quiz_lesson_passes_with_the_right_answers_and_reveals_only_when_asked() -> None:
    lesson = _lesson("fa9-02")
    assert lesson.quiz is not None
    answers = right_answers(lesson, lesson.quiz)
    report = check_lesson(lesson, [], answers)
    assert report.status == "passed"
    assert all(item.expected_shown is None for item in report.quiz)
    wrong = check_lesson(lesson, [], {"q1": "a"}, reveal=True)
    assert wrong.status == "failed"
    first = wrong.quiz[0]
    assert (first.correct, first.expected_shown) == (False, "b")
    assert first.explain is not None
    assert wrong.quiz[1].explain is None

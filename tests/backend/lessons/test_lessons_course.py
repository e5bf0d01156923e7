"""The real course (``examples/lessons``): every lesson passes the lint, its solution passes
every check and its start (and wrong) program fails one. One test per lesson, so a broken
lesson is named; lessons being written may be added any time."""

from pathlib import Path

import pytest

from nasaq.lessons.lint import lint_course
from nasaq.lessons.load import read_course
from nasaq.lessons.report import verify

ROOT = Path(__file__).resolve().parents[3] / "examples" / "lessons"
COURSE = read_course(ROOT)


def test_the_course_exists_and_every_folder_reads() -> None:
    assert COURSE.units, f"no units under {ROOT}"
    assert [p.text() for p in COURSE.problems] == []


@pytest.mark.parametrize("lesson_id", [lesson.id for lesson in COURSE.lessons()])
def test_each_lesson_passes_lint_and_its_checks(lesson_id: str) -> None:
    lesson = COURSE.lesson(lesson_id)
    assert lesson is not None
    problems = [p.text() for p in lint_course(COURSE, [lesson_id], reading=False)]
    assert problems == []
    verdict, why = verify(lesson)
    assert verdict == "ok", why

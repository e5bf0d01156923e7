"""Finding the course: units and lessons in order, a malformed folder reported and left out."""

import shutil
from pathlib import Path

from nasaq.lessons.load import load_course, read_course

COURSE = Path(__file__).parent / "fixtures" / "course"


def test_units_and_lessons_in_order_with_hints_and_quiz() -> None:
    course = read_course(COURSE)
    assert [unit.meta.id for unit in course.units] == ["fa9"]
    assert [lesson.id for lesson in course.lessons()] == ["fa9-01", "fa9-02", "fa9-03"]
    first = course.lesson("fa9-01")
    assert first is not None
    assert len(first.hints) == 2
    assert first.hints[0]["fa"]
    assert first.figures() == ["tank.svg"]
    assert (first.text("fa") or "").startswith("# پرکردن مخزن")
    assert first.files("wrong") is not None
    assert first.files("nothing") is None
    quiz_lesson = course.lesson("fa9-02")
    assert quiz_lesson is not None
    assert quiz_lesson.quiz is not None
    assert [q.kind for q in quiz_lesson.quiz.questions] == [
        "choice",
        "number",
        "text",
        "multi",
        "predict",
    ]


def test_a_malformed_lesson_is_a_problem_with_file_and_line_not_a_crash() -> None:
    course = read_course(COURSE)
    assert course.lesson("fa9-99") is None
    [problem] = course.problems
    assert (problem.file, problem.line, problem.code) == (
        "fa9/fa9-99/lesson.yaml",
        6,
        "LSN202",
    )


def test_a_missing_folder_is_an_empty_course(tmp_path: Path) -> None:
    course = read_course(tmp_path / "nothing")
    assert course.units == []
    assert course.problems == []


def test_folder_and_id_must_agree_and_ids_be_unique(tmp_path: Path) -> None:
    root = tmp_path / "course"
    shutil.copytree(COURSE, root)
    shutil.copytree(root / "fa9" / "fa9-03", root / "fa9" / "fa9-04")
    (root / "fa9" / "fa9-99" / "lesson.yaml").unlink()
    course = read_course(root)
    [problem] = course.problems
    assert (problem.file, problem.code) == ("fa9/fa9-04/lesson.yaml", "LSN204")
    assert [lesson.id for lesson in course.lessons()] == ["fa9-01", "fa9-02", "fa9-03"]


def test_the_course_is_read_again_when_a_file_changes(tmp_path: Path) -> None:
    root = tmp_path / "course"
    shutil.copytree(COURSE, root)
    first = load_course(root)
    assert load_course(root) is first
    path = root / "fa9" / "fa9-99" / "lesson.yaml"
    path.write_text(
        (root / "fa9" / "fa9-03" / "lesson.yaml").read_text("utf-8").replace("fa9-03", "fa9-99"),
        encoding="utf-8",
    )
    again = load_course(root)
    assert again is not first
    assert again.problems == []
    assert again.lesson("fa9-99") is not None

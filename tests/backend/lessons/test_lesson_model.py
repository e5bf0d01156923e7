"""Reading lesson files: every problem names its file and line, with a catalogue code."""

from pathlib import Path

import pytest

from nasaq.lessons.model import (
    LessonFileError,
    LessonMeta,
    Quiz,
    UnitMeta,
    load_hints,
    load_model,
)

FIXTURES = Path(__file__).parent / "fixtures"


def _write(tmp_path: Path, text: str, name: str = "lesson.yaml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


LESSON = """id: vi9-01
unit: vi9
order: 1
languages: [vi, en]
title: {vi: "Bài", en: "Lesson"}
works_in: LAD
open: OB1.lad
checks:
  - scenario: checks/a.yaml
  - convert: {file: OB1.awl, to: LAD}
  - quiz: quiz.yaml
"""


OPTIONS = "options: [{id: a, text: {en: a}}, {id: b, text: {en: b}}]"


def test_a_lesson_loads_with_its_checks() -> None:
    meta = load_model(LessonMeta, FIXTURES / "course/fa9/fa9-01/lesson.yaml", "x")
    assert meta.plant is not None
    assert meta.plant.kind == "tank"
    assert [(c.kind, c.name) for c in meta.checks] == [("scenario", "checks/fill.yaml")]


def test_check_kinds_and_names(tmp_path: Path) -> None:
    meta = load_model(LessonMeta, _write(tmp_path, LESSON), "l.yaml")
    assert [(c.kind, c.name) for c in meta.checks] == [
        ("scenario", "checks/a.yaml"),
        ("convert", "OB1.awl -> LAD"),
        ("quiz", "quiz.yaml"),
    ]


@pytest.mark.parametrize(
    ("text", "code", "line", "words"),
    [
        (LESSON.replace("order: 1", "order: first"), "LSN203", 3, "order"),
        (LESSON.replace("works_in: LAD", "works_in: LADDER"), "LSN203", 6, "works_in"),
        (LESSON.replace("open: OB1.lad\n", ""), "LSN203", 1, "open"),
        (
            LESSON.replace("  - quiz: quiz.yaml", "  - {quiz: q.yaml, scenario: a.yaml}"),
            "LSN203",
            11,
            "one of",
        ),
        (
            LESSON.replace('title: {vi: "Bài", en: "Lesson"}', 'title: {vi: "Bài", en: "Lesson"'),
            "LSN202",
            6,
            "YAML",
        ),
        (LESSON + "colour: red\n", "LSN203", 12, "colour"),
        ("- a list\n", "LSN203", 1, "mapping"),
    ],
)
def test_a_bad_lesson_names_file_line_and_code(
    tmp_path: Path, text: str, code: str, line: int, words: str
) -> None:
    with pytest.raises(LessonFileError) as error:
        load_model(LessonMeta, _write(tmp_path, text), "vi9/vi9-01/lesson.yaml")
    problem = error.value.problem
    assert (problem.file, problem.code, problem.line) == (
        "vi9/vi9-01/lesson.yaml",
        code,
        line,
    )
    assert words in problem.message
    assert problem.key
    assert problem.text().startswith(f"vi9/vi9-01/lesson.yaml:{line}: {code}")


def test_a_unit_needs_its_title(tmp_path: Path) -> None:
    path = _write(tmp_path, 'id: u\norder: 1\nseed: "000"\nlanguage: ar\n', "unit.yaml")
    with pytest.raises(LessonFileError, match="title"):
        load_model(UnitMeta, path, "u/unit.yaml")


def test_hints_are_texts_per_language_and_an_empty_one_is_refused(
    tmp_path: Path,
) -> None:
    good = _write(tmp_path, '- {fa: "الف", en: "a"}\n- {fa: "ب", en: "b"}\n', "hints.yaml")
    assert load_hints(good, "h") == [{"fa": "الف", "en": "a"}, {"fa": "ب", "en": "b"}]
    assert load_hints(tmp_path / "none.yaml", "h") == []
    bad = _write(tmp_path, '- {fa: "الف", en: "a"}\n- {fa: "", en: "b"}\n', "hints.yaml")
    with pytest.raises(LessonFileError) as error:
        load_hints(bad, "h")
    assert error.value.problem.line == 2


@pytest.mark.parametrize(
    ("question", "words"),
    [
        (
            f"{{id: q, kind: choice, prompt: {{en: x}}, {OPTIONS}, answer: c}}",
            "choice",
        ),
        (
            f"{{id: q, kind: multi, prompt: {{en: x}}, {OPTIONS}, answer: a}}",
            "multi",
        ),
        (
            "{id: q, kind: predict, prompt: {en: x}, program: p.awl, ask: [Q4.0], answer: 1}",
            "no answer",
        ),
        ("{id: q, kind: predict, prompt: {en: x}}", "program and ask"),
        ("{id: q, kind: text, prompt: {en: x}}", "spellings"),
        (
            "{id: q, kind: number, prompt: {en: x}, answer: {value: 1, tolerance: -1}}",
            "tolerance",
        ),
    ],
)
def test_quiz_answers_are_validated(tmp_path: Path, question: str, words: str) -> None:
    path = _write(tmp_path, f"questions:\n  - {question}\n", "quiz.yaml")
    with pytest.raises(LessonFileError) as error:
        load_model(Quiz, path, "quiz.yaml")
    assert words in error.value.problem.message
    assert error.value.problem.line == 2

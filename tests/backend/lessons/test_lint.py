"""The lesson lint: each rule of the issue's lint test, on a folder made to break them."""

from pathlib import Path

from nasaq.lessons.lint import lint_course, normal_operand, operands, task_section
from nasaq.lessons.load import read_course

FIXTURES = Path(__file__).parent / "fixtures"


def test_the_good_fixture_lessons_have_no_problem_but_the_malformed_one() -> None:
    problems = lint_course(read_course(FIXTURES / "course"))
    assert [(p.file, p.code) for p in problems] == [("fa9/fa9-99/lesson.yaml", "LSN202")]


def test_every_rule_reports_its_file_and_code() -> None:
    problems = lint_course(read_course(FIXTURES / "bad"))
    found = {(p.file, p.line, p.code) for p in problems}
    lesson = "fa8/fa8-01"
    assert found >= {
        (
            f"{lesson}/lesson.yaml",
            None,
            "LSN301",
        ),  # languages: en first, the unit says fa
        (f"{lesson}/lesson.yaml", None, "LSN304"),  # title without fa
        (f"{lesson}/lesson.yaml", None, "LSN315"),  # unknown prerequisite
        (f"{lesson}/en.md", 1, "LSN303"),  # no "# title" line
        (f"{lesson}/en.md", 5, "LSN306"),  # link to a missing file
        (f"{lesson}/fa.md", None, "LSN305"),  # Persian written in Latin letters
        (f"{lesson}/vi.md", None, "LSN302"),  # a language without its text
        (f"{lesson}/lesson.yaml", None, "LSN307"),  # a sensor wired to an output
        (f"{lesson}/solution", None, "LSN312"),  # no solution
        (f"{lesson}/lesson.yaml", None, "LSN311"),  # open names no start/ file
        (f"{lesson}/lesson.yaml", None, "LSN310"),  # a check file that does not exist
        (
            f"{lesson}/checks/broken.yaml",
            None,
            "LSN313",
        ),  # a scenario that does not load
        (
            f"{lesson}/quiz.yaml",
            None,
            "LSN314",
        ),  # a predict question without its program
        (f"{lesson}/hints.yaml", 1, "LSN308"),  # a hint names I1.7, the task does not
        ("fa8/fa8-02/hints.yaml", 2, "LSN309"),  # a hint gives a solution line away
        ("fa8/fa8-02/checks/out.yaml", 3, "LSN304"),  # a plain-text note: English only
        ("fa8/fa8-02/checks/out.yaml", 6, "LSN304"),  # a step note without its fa text
    }
    plant = next(p for p in problems if p.code == "LSN307")
    assert "ls_high" in plant.message
    named = next(p for p in problems if p.code == "LSN308")
    assert named.params["operand"] == "I1.7"
    assert named.params["language"] == "en"


def test_operands_are_compared_in_one_spelling() -> None:
    assert normal_operand("E 0.1") == "I0.1"
    assert normal_operand("AW 4") == "QW4"
    assert normal_operand("Z 3") == "C3"
    text = 'Set `Q 4.0` from "Start" and I0.1, T 5 and MW10; S5T#2S is no timer.'
    assert operands(text, {"start": "I 0.0"}) == {"Q4.0", "I0.0", "I0.1", "T5", "MW10"}


def test_the_task_section_is_found_by_its_heading_in_each_language() -> None:
    text = "# T\n\n## الفكرة\n\n`I0.5`\n\n## المهمة\n\nشغّل `Q4.0`.\n"
    assert "Q4.0" in task_section(text, "ar")
    assert "I0.5" not in task_section(text, "ar")
    assert task_section("# T\n\nno sections `I0.5`\n", "vi").endswith("`I0.5`\n")


def test_a_step_note_needs_every_language_of_the_lesson() -> None:
    """The Check result shows the notes in the learner's language: a lesson's check has them in
    all of its languages (``vi`` is no language of fa8-02 and does not count)."""
    problems = lint_course(read_course(FIXTURES / "bad"), ["fa8-02"], reading=False)
    notes = [p for p in problems if p.file.endswith("checks/out.yaml")]
    assert [(p.line, p.params["field"], p.params["language"]) for p in notes] == [
        (3, "step 1 note", "fa"),  # plain text counts as English only
        (6, "step 4 note", "fa"),
    ]

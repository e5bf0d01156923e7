"""``nasaq lessons check|lint|list``: one line per lesson, a summary, exit 0/1/2."""

from pathlib import Path

import pytest

from nasaq.cli import main

FIXTURES = Path(__file__).parent / "fixtures"
COURSE = FIXTURES / "course"


def test_check_passes_a_good_lesson(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["lessons", "check", str(COURSE / "fa9" / "fa9-01")]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert lines == ["fa9-01: OK", "1 of 1 lessons ok, 0 failed, 0 broken"]


def test_check_of_the_course_reports_the_malformed_folder(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["lessons", "check", str(COURSE)]) == 1
    out = capsys.readouterr().out
    assert "fa9/fa9-99/lesson.yaml:6: LSN202" in out
    assert "fa9-01: OK\nfa9-02: OK\nfa9-03: OK\n" in out
    assert out.strip().endswith("3 of 3 lessons ok, 0 failed, 1 broken")


def test_a_start_program_that_passes_fails_the_check(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["lessons", "check", str(FIXTURES / "bad" / "fa8" / "fa8-02")]) == 1
    out = capsys.readouterr().out
    assert "fa8-02: FAIL: start/ passes every check" in out


def test_lint_prints_file_line_code_and_exits_1(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["lessons", "lint", str(FIXTURES / "bad")]) == 1
    out = capsys.readouterr().out
    assert "fa8/fa8-02/hints.yaml:2: LSN309:" in out
    assert main(["lessons", "lint", str(COURSE / "fa9" / "fa9-01")]) == 0
    assert capsys.readouterr().out.strip() == "1 lessons, 0 problems"


def test_list_shows_units_and_lessons_in_a_language(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("NASAQ_LESSONS_DIR", str(COURSE))
    from nasaq.settings import get_settings

    get_settings.cache_clear()
    try:
        assert main(["lessons", "list", "--lang", "fa"]) == 1  # the malformed lesson
    finally:
        get_settings.cache_clear()
    out = capsys.readouterr().out
    assert "fa9  واحد آزمایشی" in out
    assert "fa9-01   STL  program        پرکردن مخزن [tank]" in out


def test_nasaq_test_on_a_lesson_folder_checks_the_lessons(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["test", str(COURSE / "fa9" / "fa9-03")]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "fa9-03: OK",
        "1 of 1 lessons ok, 0 failed, 0 broken",
    ]

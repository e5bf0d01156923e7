"""Progress per (project, lesson): attempts, the pass kept once reached, the migration."""

from datetime import timedelta
from pathlib import Path

from alembic import command
from sqlalchemy import create_engine, inspect
from sqlalchemy.orm import Session

from nasaq.lessons import progress
from nasaq.lessons.load import read_course
from nasaq.settings import Settings
from nasaq.storage.migrate import alembic_config, upgrade_to_head
from nasaq.storage.models import LessonProgress, utc_now

COURSE = read_course(Path(__file__).parent / "fixtures" / "course")


def test_checks_count_attempts_and_a_pass_is_kept() -> None:
    row = LessonProgress(
        project_id=1,
        lesson_id="fa9-01",
        status="not_started",
        attempts=0,
        time_s=0,
        hints_revealed=0,
        gave_up=False,
        started_at=utc_now() - timedelta(seconds=90),
    )
    assert progress.Progress.of(row).status == "not_started"
    progress.record_check(row, passed=False)
    assert (progress.Progress.of(row).status, row.attempts) == ("tried", 1)
    assert 89 <= row.time_s <= 120
    assert not progress.may_see_solution(row)
    progress.record_check(row, passed=True)
    passed_at = row.passed_at
    assert (row.status, row.attempts) == ("passed", 2)
    assert passed_at is not None
    progress.record_check(row, passed=False)  # checking again after the pass changes nothing
    assert (row.status, row.attempts, row.passed_at) == ("passed", 2, passed_at)
    assert progress.may_see_solution(row)
    assert progress.reveal_hint(row, 2) == 1
    assert progress.reveal_hint(row, 2) == progress.reveal_hint(row, 2) == 2


def test_the_plant_file_is_the_lessons_plant() -> None:
    lesson = COURSE.lesson("fa9-01")
    assert lesson is not None
    name, text = progress.plant_file(lesson) or ("", "")
    assert name == "tank.plant"
    assert text.startswith("kind: tank\n")
    assert [n for n, _ in progress.start_files(lesson)] == ["OB1.awl", "tank.plant"]
    no_plant = COURSE.lesson("fa9-03")
    assert no_plant is not None
    assert progress.plant_file(no_plant) is None


def test_open_makes_one_project_per_lesson(settings: Settings) -> None:
    upgrade_to_head(settings)
    engine = create_engine(settings.effective_database_url)
    lesson = COURSE.lesson("fa9-03")
    assert lesson is not None
    try:
        with Session(engine) as session, session.begin():
            project, row = progress.open_project(session, lesson, reset=False)
            again, same = progress.open_project(session, lesson, reset=False)
            assert (again.id, same.id) == (project.id, row.id)
            assert project.name == "lesson fa9-03"
            assert progress.linked(session, "fa9-03", project.id) is not None
            assert progress.linked(session, "fa9-01", project.id) is None
    finally:
        engine.dispose()


def test_0003_adds_lesson_progress_and_downgrades_to_0002(settings: Settings) -> None:
    upgrade_to_head(settings)
    engine = create_engine(settings.effective_database_url)
    try:
        assert "lesson_progress" in inspect(engine).get_table_names()
        command.downgrade(alembic_config(settings), "0002")
        tables = set(inspect(engine).get_table_names())
        assert "lesson_progress" not in tables
        assert {"projects", "project_files"} <= tables
        command.upgrade(alembic_config(settings), "head")
        assert "lesson_progress" in inspect(engine).get_table_names()
    finally:
        engine.dispose()

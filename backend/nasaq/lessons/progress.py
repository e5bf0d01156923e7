"""A learner's progress per (project, lesson), stored in ``lesson_progress``.

Opening a lesson makes its project (from ``start/``) and the progress row that links them;
every Check counts an attempt ("tried"), the first pass freezes the time ("passed"); hints
revealed and giving up are remembered, so the solution is shown only when earned. Nasaq has
no user accounts: the project is the learner's workspace, as a STEP 7 project on a lab PC.
"""

from __future__ import annotations

from collections.abc import Sequence
from datetime import datetime
from typing import Literal

import yaml
from pydantic import BaseModel
from sqlalchemy import select
from sqlalchemy.orm import Session

from nasaq.lessons.load import PLANT_SUFFIX, Lesson
from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.models import LessonProgress, Project, utc_now

ProgressStatus = Literal["not_started", "tried", "passed"]


class Progress(BaseModel):
    status: ProgressStatus
    attempts: int
    time_s: int
    hints_revealed: int
    gave_up: bool
    passed_at: datetime | None

    @classmethod
    def of(cls, row: LessonProgress) -> Progress:
        status: ProgressStatus = (
            "passed" if row.status == "passed" else "tried" if row.attempts else "not_started"
        )
        return cls(
            status=status,
            attempts=row.attempts,
            time_s=row.time_s,
            hints_revealed=row.hints_revealed,
            gave_up=row.gave_up,
            passed_at=row.passed_at,
        )


def row_of(session: Session, lesson_id: str) -> LessonProgress | None:
    """The progress of the lesson's project (the first one made, should there be several)."""
    query = (
        select(LessonProgress)
        .where(LessonProgress.lesson_id == lesson_id)
        .order_by(LessonProgress.id)
        .limit(1)
    )
    return session.scalars(query).first()


def linked(session: Session, lesson_id: str, project_id: int) -> LessonProgress | None:
    query = select(LessonProgress).where(
        LessonProgress.lesson_id == lesson_id, LessonProgress.project_id == project_id
    )
    return session.scalars(query).first()


def all_rows(session: Session) -> dict[str, LessonProgress]:
    """Every lesson's progress, by lesson id."""
    found: dict[str, LessonProgress] = {}
    for row in session.scalars(select(LessonProgress).order_by(LessonProgress.id)):
        found.setdefault(row.lesson_id, row)
    return found


def plant_file(lesson: Lesson) -> tuple[str, str] | None:
    """The lesson's plant as the project's ``<kind>.plant`` file."""
    plant = lesson.meta.plant
    if plant is None:
        return None
    text = yaml.safe_dump(plant.model_dump(), sort_keys=False, allow_unicode=True)
    return f"{plant.kind}{PLANT_SUFFIX}", text


def start_files(lesson: Lesson) -> list[tuple[str, str]]:
    files = list(lesson.files("start") or [])
    plant = plant_file(lesson)
    if plant is not None and plant[0] not in {name for name, _ in files}:
        files.append(plant)
    return files


def _free_name(session: Session, lesson_id: str) -> str:
    base = f"lesson {lesson_id}"
    taken = {project.name.casefold() for project in project_store.list_projects(session)}
    name, number = base, 2
    while name.casefold() in taken:
        name, number = f"{base}-{number}", number + 1
    return name


def open_project(session: Session, lesson: Lesson, reset: bool) -> tuple[Project, LessonProgress]:
    """The lesson's project, made from ``start/`` the first time; ``reset`` puts its files
    back to ``start/`` (progress stays)."""
    row = row_of(session, lesson.id)
    project = project_store.get_project(session, row.project_id) if row is not None else None
    if row is None or project is None:
        if row is not None:  # its project was deleted (a database without cascading deletes)
            session.delete(row)
            session.flush()
        title = lesson.meta.title.get("en", lesson.id)
        project = project_store.create_project(session, _free_name(session, lesson.id), title)
        file_store.add_files(session, project, start_files(lesson))
        row = LessonProgress(project_id=project.id, lesson_id=lesson.id)
        session.add(row)
        session.flush()
        return project, row
    if reset:
        wanted = dict(start_files(lesson))
        for found in file_store.all_files(session, project.id):
            if found.name not in wanted:
                file_store.delete_file(session, project, found)
        for name, text in wanted.items():
            file_store.save_file(session, project, name, text)
    return project, row


def record_check(row: LessonProgress, passed: bool) -> None:
    now = utc_now()
    if row.status == "passed":
        return  # a pass is kept; checks after it change nothing
    row.attempts += 1
    row.time_s = max(0, int((now - row.started_at).total_seconds()))
    if passed:
        row.status = "passed"
        row.passed_at = now
    else:
        row.status = "tried"


def reveal_hint(row: LessonProgress, total: int) -> int:
    """Reveals the next hint (if any is left); how many are revealed now."""
    row.hints_revealed = min(total, row.hints_revealed + 1)
    return row.hints_revealed


def give_up(row: LessonProgress) -> None:
    row.gave_up = True


def may_see_solution(row: LessonProgress) -> bool:
    return row.status == "passed" or row.gave_up


def project_sources(session: Session, project_id: int) -> Sequence[tuple[str, str]]:
    return file_store.sources(session, project_id)

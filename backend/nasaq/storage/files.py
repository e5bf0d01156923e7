"""Reading and writing a project's source files.

Names are unique in a project regardless of letter case (an export must unpack on Windows and
macOS too), while lookups are exact. Every change stamps the project's ``updated_at``. Saves are
checked against the version the editor loaded, so a stale tab cannot silently overwrite a newer
save.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from datetime import datetime

from sqlalchemy import func, select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session
from sqlalchemy.orm.exc import StaleDataError

from nasaq.storage.models import Project, ProjectFile, utc_now


class FileNameTakenError(Exception):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


class StaleFileError(Exception):
    """The save started from ``expected`` but the file is at ``current`` (None: it is gone)."""

    def __init__(self, name: str, expected: int, current: int | None) -> None:
        super().__init__(name)
        self.name = name
        self.expected = expected
        self.current = current


@dataclass(frozen=True, slots=True)
class FileSummary:
    name: str
    size: int  # characters
    version: int
    created_at: datetime
    updated_at: datetime


def list_files(session: Session, project_id: int) -> list[FileSummary]:
    """The files by name, without loading their texts."""
    query = (
        select(
            ProjectFile.name,
            func.length(ProjectFile.text),
            ProjectFile.version,
            ProjectFile.created_at,
            ProjectFile.updated_at,
        )
        .where(ProjectFile.project_id == project_id)
        .order_by(func.lower(ProjectFile.name), ProjectFile.name)
    )
    return [FileSummary(*row) for row in session.execute(query)]


def count_files(session: Session, project_id: int) -> int:
    query = select(func.count()).where(ProjectFile.project_id == project_id)
    return session.scalar(query) or 0


def sources(session: Session, project_id: int) -> list[tuple[str, str]]:
    """Every file as (name, text), by name: what the compiler and an export take."""
    query = (
        select(ProjectFile.name, ProjectFile.text)
        .where(ProjectFile.project_id == project_id)
        .order_by(func.lower(ProjectFile.name), ProjectFile.name)
    )
    return [(name, text) for name, text in session.execute(query)]


def get_file(session: Session, project_id: int, name: str) -> ProjectFile | None:
    query = select(ProjectFile).where(
        ProjectFile.project_id == project_id, ProjectFile.name == name
    )
    return session.scalar(query)


def _ensure_name_free(
    session: Session, project_id: int, name: str, exclude_id: int | None = None
) -> None:
    query = select(ProjectFile.id).where(
        ProjectFile.project_id == project_id, func.lower(ProjectFile.name) == name.lower()
    )
    if exclude_id is not None:
        query = query.where(ProjectFile.id != exclude_id)
    if session.scalar(query) is not None:
        raise FileNameTakenError(name)


def _flush(session: Session, project: Project, name: str) -> None:
    project.updated_at = utc_now()
    try:
        session.flush()
    except IntegrityError as exc:  # another request created the same name meanwhile
        raise FileNameTakenError(name) from exc


def save_file(
    session: Session, project: Project, name: str, text: str, base_version: int | None = None
) -> tuple[ProjectFile, bool]:
    """Creates or replaces ``name``; True when it was created. With ``base_version`` (the version
    the editor loaded) the save is refused if the file changed or vanished since."""
    found = get_file(session, project.id, name)
    if found is None:
        if base_version is not None:
            raise StaleFileError(name, base_version, None)
        return add_file(session, project, name, text), True
    if base_version is not None and base_version != found.version:
        raise StaleFileError(name, base_version, found.version)
    if found.text != text:
        found.text = text
        try:
            _flush(session, project, name)
        except StaleDataError as exc:  # a concurrent save won the race
            raise StaleFileError(name, found.version, None) from exc
    return found, False


def add_file(session: Session, project: Project, name: str, text: str) -> ProjectFile:
    _ensure_name_free(session, project.id, name)
    created = ProjectFile(project_id=project.id, name=name, text=text)
    session.add(created)
    _flush(session, project, name)
    return created


def add_files(session: Session, project: Project, files: Iterable[tuple[str, str]]) -> None:
    for name, text in files:
        add_file(session, project, name, text)


def rename_file(session: Session, project: Project, found: ProjectFile, name: str) -> None:
    if name == found.name:
        return
    _ensure_name_free(session, project.id, name, exclude_id=found.id)
    found.name = name
    _flush(session, project, name)


def duplicate_file(
    session: Session, project: Project, found: ProjectFile, name: str
) -> ProjectFile:
    return add_file(session, project, name, found.text)


def replace_file(
    session: Session, project: Project, found: ProjectFile, name: str, text: str
) -> ProjectFile:
    """``found`` becomes the new file ``name`` with ``text`` (a conversion): both changes in the
    session's one transaction, so neither is kept without the other."""
    created = add_file(session, project, name, text)
    delete_file(session, project, found)
    return created


def delete_file(session: Session, project: Project, found: ProjectFile) -> None:
    session.delete(found)
    project.updated_at = utc_now()
    session.flush()


def all_files(session: Session, project_id: int) -> Sequence[ProjectFile]:
    query = select(ProjectFile).where(ProjectFile.project_id == project_id)
    return session.scalars(query.order_by(ProjectFile.name)).all()

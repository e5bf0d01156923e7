"""Reading and writing projects. Names are unique regardless of letter case."""

from __future__ import annotations

from collections.abc import Sequence

from sqlalchemy import func, select
from sqlalchemy.orm import Session

from nasaq.storage.models import Project


class ProjectNameTakenError(Exception):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


def list_projects(session: Session) -> Sequence[Project]:
    return session.scalars(select(Project).order_by(func.lower(Project.name), Project.id)).all()


def get_project(session: Session, project_id: int) -> Project | None:
    return session.get(Project, project_id)


def _ensure_name_free(session: Session, name: str, exclude_id: int | None = None) -> None:
    query = select(Project.id).where(func.lower(Project.name) == name.lower())
    if exclude_id is not None:
        query = query.where(Project.id != exclude_id)
    if session.scalar(query) is not None:
        raise ProjectNameTakenError(name)


def create_project(session: Session, name: str, description: str = "") -> Project:
    _ensure_name_free(session, name)
    project = Project(name=name, description=description)
    session.add(project)
    session.flush()
    return project


def update_project(
    session: Session, project: Project, name: str | None = None, description: str | None = None
) -> Project:
    if name is not None and name != project.name:
        _ensure_name_free(session, name, exclude_id=project.id)
        project.name = name
    if description is not None:
        project.description = description
    session.flush()
    return project


def delete_project(session: Session, project: Project) -> None:
    session.delete(project)
    session.flush()

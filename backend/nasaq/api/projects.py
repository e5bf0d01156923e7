"""``/api/projects``: create, list, rename and delete PLC projects."""

from __future__ import annotations

import re
from datetime import datetime
from typing import Annotated

from fastapi import APIRouter, Response, status
from pydantic import AfterValidator, BaseModel, ConfigDict, Field

from nasaq.api.deps import DbSession
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.diagnostics.phrases import phrase
from nasaq.storage import projects as store
from nasaq.storage.models import Project

router = APIRouter(prefix="/projects", tags=["projects"])

# Project names become folder names on export, so they avoid what any file system forbids.
_FORBIDDEN = re.compile(r'[\x00-\x1f\x7f/\\:*?"<>|]')


def _clean_name(value: str) -> str:
    value = value.strip()
    if not value:
        raise ValueError(phrase("name_empty"))
    if _FORBIDDEN.search(value):
        raise ValueError(phrase("name_characters"))
    return value


ProjectName = Annotated[str, Field(min_length=1, max_length=64), AfterValidator(_clean_name)]


class ProjectCreate(BaseModel):
    name: ProjectName
    description: str = Field(default="", max_length=2000)


class ProjectUpdate(BaseModel):
    name: ProjectName | None = None
    description: str | None = Field(default=None, max_length=2000)


class ProjectOut(BaseModel):
    model_config = ConfigDict(from_attributes=True)

    id: int
    name: str
    description: str
    created_at: datetime
    updated_at: datetime


_ERRORS: dict[int | str, dict[str, object]] = {
    404: {"model": ApiErrorBody, "description": "No such project (API104)"},
    409: {"model": ApiErrorBody, "description": "Name already used (API105)"},
    422: {"model": ApiErrorBody, "description": "Invalid request (API103)"},
}


def found_project(session: DbSession, project_id: int) -> Project:
    """The project, or the API104 answer every project route gives."""
    project = store.get_project(session, project_id)
    if project is None:
        raise ApiError("API104", 404, id=project_id)
    return project


@router.get("", response_model=list[ProjectOut], summary="All projects, by name")
def list_projects(session: DbSession) -> list[ProjectOut]:
    return [ProjectOut.model_validate(p) for p in store.list_projects(session)]


@router.post(
    "",
    response_model=ProjectOut,
    status_code=status.HTTP_201_CREATED,
    responses=_ERRORS,
    summary="Create a project",
)
def create_project(body: ProjectCreate, session: DbSession, response: Response) -> ProjectOut:
    try:
        project = store.create_project(session, body.name, body.description)
    except store.ProjectNameTakenError as exc:
        raise ApiError("API105", 409, ["body", "name"], name=exc.name) from exc
    response.headers["Location"] = f"/api/projects/{project.id}"
    return ProjectOut.model_validate(project)


@router.get("/{project_id}", response_model=ProjectOut, responses=_ERRORS, summary="One project")
def get_project(project_id: int, session: DbSession) -> ProjectOut:
    return ProjectOut.model_validate(found_project(session, project_id))


@router.patch(
    "/{project_id}", response_model=ProjectOut, responses=_ERRORS, summary="Rename or describe"
)
def update_project(project_id: int, body: ProjectUpdate, session: DbSession) -> ProjectOut:
    project = found_project(session, project_id)
    try:
        store.update_project(session, project, body.name, body.description)
    except store.ProjectNameTakenError as exc:
        raise ApiError("API105", 409, ["body", "name"], name=exc.name) from exc
    return ProjectOut.model_validate(project)


@router.delete(
    "/{project_id}",
    status_code=status.HTTP_204_NO_CONTENT,
    responses=_ERRORS,
    summary="Delete a project",
)
def delete_project(project_id: int, session: DbSession) -> Response:
    store.delete_project(session, found_project(session, project_id))
    return Response(status_code=status.HTTP_204_NO_CONTENT)

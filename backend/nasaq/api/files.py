"""``/api/projects/{id}/files``: a project's source files: list, read, autosave (create or
replace, refused with API111 when the editor's copy is stale), rename, duplicate, delete."""

from __future__ import annotations

from datetime import datetime
from urllib.parse import quote

from fastapi import APIRouter, Response, status
from pydantic import BaseModel, Field

from nasaq.api.deps import DbSession
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.api.projects import found_project
from nasaq.storage import files as store
from nasaq.storage.models import Project, ProjectFile
from nasaq.workbench.names import (
    MAX_FILES,
    MAX_NAME_CHARS,
    MAX_TEXT_CHARS,
    Language,
    is_valid_name,
    language_of,
)

router = APIRouter(prefix="/projects/{project_id}/files", tags=["files"])


class FileInfo(BaseModel):
    name: str
    language: Language
    size: int = Field(description="Length of the text in characters")
    version: int = Field(description="Counts the saves; send it back as base_version")
    created_at: datetime
    updated_at: datetime


class FileOut(FileInfo):
    text: str


class FileSave(BaseModel):
    text: str
    base_version: int | None = Field(
        default=None,
        ge=1,
        description="The version the editor loaded; the save is refused (409, API111) when the "
        "file changed or vanished since. Without it the save is unconditional.",
    )


class FileName(BaseModel):
    name: str = Field(description="The new file name, e.g. 'OB1.awl', 'Motor.scl', 'symbols.sdf'")


_ERRORS: dict[int | str, dict[str, object]] = {
    404: {"model": ApiErrorBody, "description": "No such project or file (API104, API107)"},
    409: {"model": ApiErrorBody, "description": "Name taken or stale save (API108, API111)"},
    413: {"model": ApiErrorBody, "description": "Text too large (API110)"},
    422: {"model": ApiErrorBody, "description": "Invalid name or request (API109, API117, API103)"},
}


def checked_name(name: str, location: list[str | int]) -> str:
    if not is_valid_name(name):
        raise ApiError("API109", 422, location, name=name, limit=MAX_NAME_CHARS)
    return name


def checked_text(name: str, text: str) -> str:
    if len(text) > MAX_TEXT_CHARS:
        size = {"size_kb": len(text) // 1024, "limit_kb": MAX_TEXT_CHARS // 1024}
        raise ApiError("API110", 413, ["body", "text"], name=name, **size)
    return text


def found_file(session: DbSession, project_id: int, name: str) -> tuple[Project, ProjectFile]:
    project = found_project(session, project_id)
    found = store.get_file(session, project_id, name)
    if found is None:
        raise ApiError("API107", 404, project=project_id, name=name)
    return project, found


def _room_for_one(session: DbSession, project: Project) -> None:
    if store.count_files(session, project.id) >= MAX_FILES:
        raise ApiError("API117", 422, limit=MAX_FILES)


def file_info(found: ProjectFile | store.FileSummary) -> FileInfo:
    size = len(found.text) if isinstance(found, ProjectFile) else found.size
    return FileInfo(
        name=found.name,
        language=language_of(found.name) or "stl",
        size=size,
        version=found.version,
        created_at=found.created_at,
        updated_at=found.updated_at,
    )


def file_location(project_id: int, name: str) -> str:
    return f"/api/projects/{project_id}/files/{quote(name)}"  # headers are Latin-1: quote


def name_taken(exc: store.FileNameTakenError, location: list[str | int]) -> ApiError:
    return ApiError("API108", 409, location, name=exc.name)


@router.get("", response_model=list[FileInfo], responses=_ERRORS, summary="The files, by name")
def list_files(project_id: int, session: DbSession) -> list[FileInfo]:
    found_project(session, project_id)
    return [file_info(item) for item in store.list_files(session, project_id)]


@router.get("/{name}", response_model=FileOut, responses=_ERRORS, summary="One file with its text")
def get_file(project_id: int, name: str, session: DbSession) -> FileOut:
    _, found = found_file(session, project_id, name)
    return FileOut(**file_info(found).model_dump(), text=found.text)


@router.put(
    "/{name}",
    response_model=FileInfo,
    responses={**_ERRORS, 201: {"model": FileInfo, "description": "Created"}},
    summary="Create or replace a file (autosave)",
)
def save_file(
    project_id: int, name: str, body: FileSave, session: DbSession, response: Response
) -> FileInfo:
    project = found_project(session, project_id)
    checked_name(name, ["path", "name"])
    checked_text(name, body.text)
    if body.base_version is None and store.get_file(session, project_id, name) is None:
        _room_for_one(session, project)
    try:
        saved, created = store.save_file(session, project, name, body.text, body.base_version)
    except store.FileNameTakenError as exc:
        raise name_taken(exc, ["path", "name"]) from exc
    except store.StaleFileError as exc:
        raise ApiError(
            "API111", 409, ["body", "base_version"], name=name, current_version=exc.current
        ) from exc
    if created:
        response.status_code = status.HTTP_201_CREATED
        response.headers["Location"] = file_location(project_id, name)
    return file_info(saved)


@router.patch("/{name}", response_model=FileInfo, responses=_ERRORS, summary="Rename a file")
def rename_file(project_id: int, name: str, body: FileName, session: DbSession) -> FileInfo:
    project, found = found_file(session, project_id, name)
    try:
        store.rename_file(session, project, found, checked_name(body.name, ["body", "name"]))
    except store.FileNameTakenError as exc:
        raise name_taken(exc, ["body", "name"]) from exc
    return file_info(found)


@router.post(
    "/{name}/duplicate",
    response_model=FileInfo,
    status_code=status.HTTP_201_CREATED,
    responses=_ERRORS,
    summary="Copy a file under a new name",
)
def duplicate_file(
    project_id: int, name: str, body: FileName, session: DbSession, response: Response
) -> FileInfo:
    project, found = found_file(session, project_id, name)
    new_name = checked_name(body.name, ["body", "name"])
    _room_for_one(session, project)
    try:
        copy = store.duplicate_file(session, project, found, new_name)
    except store.FileNameTakenError as exc:
        raise name_taken(exc, ["body", "name"]) from exc
    response.headers["Location"] = file_location(project_id, new_name)
    return file_info(copy)


@router.delete(
    "/{name}", status_code=status.HTTP_204_NO_CONTENT, responses=_ERRORS, summary="Delete a file"
)
def delete_file(project_id: int, name: str, session: DbSession) -> Response:
    project, found = found_file(session, project_id, name)
    store.delete_file(session, project, found)
    return Response(status_code=status.HTTP_204_NO_CONTENT)

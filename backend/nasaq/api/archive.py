"""``GET /api/projects/{id}/export.zip`` and ``POST /api/projects/import``: a whole project as a
zip of plain sources (one folder named after the project), git-friendly and readable by STEP 7.

The upload is the raw zip body (``Content-Type: application/zip``), not a multipart form: the
server then needs no form parser, and ``curl --data-binary @plant.zip`` works as well as a
browser's ``fetch``.
"""

from __future__ import annotations

import asyncio
from typing import Annotated
from urllib.parse import quote

from fastapi import APIRouter, Query, Request, Response, status
from pydantic import BaseModel, Field, ValidationError
from sqlalchemy.orm import Session, sessionmaker

from nasaq.api.deps import DbSession
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.api.projects import ProjectCreate, ProjectName, ProjectOut, found_project
from nasaq.diagnostics.validation import validation_reason
from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.workbench.archive import (
    MAX_ENTRIES,
    MAX_UNPACKED_BYTES,
    MAX_UPLOAD_BYTES,
    ArchiveError,
    folder_name,
    read_zip,
    write_zip,
)

router = APIRouter(prefix="/projects", tags=["projects"])

_STATUS = {"API110": 413, "API114": 413, "API108": 409}


class ImportOut(BaseModel):
    project: ProjectOut
    files: list[str] = Field(description="The source files imported, by name")
    skipped: list[str] = Field(description="Entries that are not sources (README, scenarios...)")


@router.get(
    "/{project_id}/export.zip",
    responses={
        200: {"content": {"application/zip": {}}, "description": "The project as a zip"},
        404: {"model": ApiErrorBody, "description": "No such project (API104)"},
    },
    summary="Download the project as a zip of its source files",
)
def export_zip(project_id: int, session: DbSession) -> Response:
    project = found_project(session, project_id)
    files = file_store.all_files(session, project_id)
    folder = folder_name(project.name)
    data = write_zip(folder, ((item.name, item.text, item.updated_at) for item in files))
    ascii_name = folder.encode("ascii", "replace").decode().replace("?", "_").replace('"', "_")
    disposition = f"attachment; filename=\"{ascii_name}.zip\"; filename*=UTF-8''{quote(folder)}.zip"
    return Response(
        data, media_type="application/zip", headers={"Content-Disposition": disposition}
    )


async def _body(request: Request) -> bytes:
    """The upload, refused as soon as it passes the limit rather than after reading it all."""
    parts: list[bytes] = []
    size = 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > MAX_UPLOAD_BYTES:
            limit_mb = MAX_UNPACKED_BYTES // (1024 * 1024)
            raise ApiError("API114", 413, ["body"], limit_mb=limit_mb, limit_entries=MAX_ENTRIES)
        parts.append(chunk)
    return b"".join(parts)


def _project_name(given: str | None, folder: str | None) -> str:
    if given is not None:
        return given
    if folder is None:
        raise ApiError("API115", 422, ["query", "name"])
    try:
        return ProjectCreate(name=folder).name
    except ValidationError as exc:
        reason = validation_reason(exc.errors()[0])
        raise ApiError("API103", 422, ["query", "name"], field="name", reason=reason) from exc


@router.post(
    "/import",
    response_model=ImportOut,
    status_code=status.HTTP_201_CREATED,
    responses={
        409: {"model": ApiErrorBody, "description": "Name taken (API105, API108)"},
        413: {"model": ApiErrorBody, "description": "Too large (API114, API110)"},
        422: {
            "model": ApiErrorBody,
            "description": "Not an acceptable zip (API112, API113, API115, API116, API117)",
        },
    },
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {"application/zip": {"schema": {"type": "string", "format": "binary"}}},
        }
    },
    summary="Create a project from a zip of sources (the raw zip as the request body)",
)
async def import_zip(
    request: Request,
    response: Response,
    name: Annotated[
        ProjectName | None,
        Query(description="The project's name; default: the zip's one top folder"),
    ] = None,
) -> ImportOut:
    data = await _body(request)
    found = await asyncio.to_thread(_import, request.app.state.sessions, data, name)
    response.headers["Location"] = f"/api/projects/{found.project.id}"
    return found


def _import(factory: sessionmaker[Session], data: bytes, name: str | None) -> ImportOut:
    """Unpacks and stores the project in one transaction (in a thread: it may take a while)."""
    try:
        unpacked = read_zip(data)
    except ArchiveError as exc:
        raise ApiError(exc.code, _STATUS.get(exc.code, 422), ["body"], **exc.params) from exc
    project_name = _project_name(name, unpacked.folder)
    with transaction(factory) as session:
        try:
            project = project_store.create_project(session, project_name)
        except project_store.ProjectNameTakenError as exc:
            raise ApiError("API105", 409, ["query", "name"], name=exc.name) from exc
        file_store.add_files(session, project, unpacked.files)
        out = ProjectOut.model_validate(project)
    return ImportOut(project=out, files=[n for n, _ in unpacked.files], skipped=unpacked.skipped)

"""What a project's files become: ``/blocks`` (the project tree and the diagnostics),
``/check`` (the same with one unsaved editor text in place of its file: diagnostics while typing,
before the autosave) and ``/sessions`` (a simulated CPU running the project).

Compiling takes from milliseconds to a second for a large plant, so it runs in a thread, never on
the event loop that serves every socket and request.
"""

from __future__ import annotations

import asyncio

from fastapi import APIRouter, Request, status
from pydantic import BaseModel
from sqlalchemy.orm import Session, sessionmaker

from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.api.files import checked_name, checked_text
from nasaq.api.sessions import SessionOptions, SessionOut, start_session
from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.workbench.tree import ProjectBuild, build

router = APIRouter(prefix="/projects/{project_id}", tags=["workbench"])


class UnsavedFile(BaseModel):
    name: str
    text: str


_ERRORS: dict[int | str, dict[str, object]] = {
    404: {"model": ApiErrorBody, "description": "No such project (API104)"},
    413: {"model": ApiErrorBody, "description": "Text too large (API110)"},
    422: {"model": ApiErrorBody, "description": "Invalid file name or request (API109, API103)"},
}


def _load(factory: sessionmaker[Session], project_id: int) -> list[tuple[str, str]]:
    with transaction(factory) as session:
        if project_store.get_project(session, project_id) is None:
            raise ApiError("API104", 404, id=project_id)
        return file_store.sources(session, project_id)


async def _sources(request: Request, project_id: int) -> list[tuple[str, str]]:
    return await asyncio.to_thread(_load, request.app.state.sessions, project_id)


@router.get(
    "/blocks",
    response_model=ProjectBuild,
    responses=_ERRORS,
    summary="The blocks the project's files define, and the compiler's diagnostics",
)
async def blocks(project_id: int, request: Request) -> ProjectBuild:
    return await asyncio.to_thread(build, await _sources(request, project_id))


@router.post(
    "/check",
    response_model=ProjectBuild,
    responses=_ERRORS,
    summary="Compile the project with one unsaved file text in place of the stored one",
)
async def check(project_id: int, request: Request, body: UnsavedFile | None = None) -> ProjectBuild:
    sources = await _sources(request, project_id)
    if body is not None:
        checked_name(body.name, ["body", "name"])
        checked_text(body.name, body.text)
        sources = [item for item in sources if item[0] != body.name] + [(body.name, body.text)]
    return await asyncio.to_thread(build, sources)


@router.post(
    "/sessions",
    response_model=SessionOut,
    status_code=status.HTTP_201_CREATED,
    responses={
        **_ERRORS,
        422: {"model": ApiErrorBody, "description": "The program does not compile (MON611)"},
        503: {"model": ApiErrorBody, "description": "Too many sessions (MON610)"},
    },
    summary="Compile the project's saved files into a new simulated CPU (in STOP)",
)
async def create_session(
    project_id: int, request: Request, body: SessionOptions | None = None
) -> SessionOut:
    sources = await _sources(request, project_id)
    return await start_session(request, sources, body or SessionOptions(), project_id)

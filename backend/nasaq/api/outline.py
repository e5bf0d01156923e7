"""``/outline``: what the editor completes, explains on hover and jumps to in a project: its
symbols and its blocks with their interface members (see ``nasaq.workbench.outline``)."""

from __future__ import annotations

import asyncio

from fastapi import APIRouter, Request
from sqlalchemy.orm import Session, sessionmaker

from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.workbench.outline import ProjectOutline, outline

router = APIRouter(prefix="/projects/{project_id}", tags=["workbench"])


def _outline(factory: sessionmaker[Session], project_id: int) -> ProjectOutline:
    with transaction(factory) as session:
        if project_store.get_project(session, project_id) is None:
            raise ApiError("API104", 404, id=project_id)
        sources = file_store.sources(session, project_id)
    return outline(sources)


@router.get(
    "/outline",
    response_model=ProjectOutline,
    responses={404: {"model": ApiErrorBody, "description": "No such project (API104)"}},
    summary="The project's symbols and blocks with their interface members, for the editor",
)
async def project_outline(project_id: int, request: Request) -> ProjectOutline:
    # Compiling may take a while for a large plant: in a thread, off the event loop.
    return await asyncio.to_thread(_outline, request.app.state.sessions, project_id)

"""The example projects offered on the Start page, each in the interface language.

``GET /api/examples?lang=fa`` lists them with their Persian titles and descriptions;
``POST /api/examples/{name}/open?lang=fa`` makes the Persian variant a project (or returns the one
made before). See :mod:`nasaq.workbench.example_variants`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from fastapi import APIRouter, Request, Response, status
from pydantic import BaseModel
from sqlalchemy import func, select

from nasaq.api.deps import DbSession
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.api.projects import ProjectOut
from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.models import Project
from nasaq.workbench.example_variants import about, find_example, main_source, variant_sources
from nasaq.workbench.examples import example_folders

router = APIRouter(prefix="/examples", tags=["examples"])

Language = Literal["en", "ar", "fa", "vi"]


class ExampleOut(BaseModel):
    name: str
    title: str
    description: str
    project: str
    project_id: int | None = None
    main: str | None = None  # the file to open first (OB 1's source)


def _root(request: Request) -> Path:
    root: Path = request.app.state.settings.examples_dir
    return root


def _project_named(session: DbSession, name: str) -> Project | None:
    query = select(Project).where(func.lower(Project.name) == name.lower())
    return session.scalars(query).first()


@router.get("", response_model=list[ExampleOut], summary="The example projects, in a language")
def list_examples(request: Request, session: DbSession, lang: Language = "en") -> list[ExampleOut]:
    out = []
    for folder in example_folders(_root(request)):
        found = about(folder, lang)
        project = _project_named(session, found.project)
        out.append(
            ExampleOut(
                name=found.name,
                title=found.title,
                description=found.description,
                project=found.project,
                project_id=project.id if project else None,
                main=main_source(folder),
            )
        )
    return out


@router.post(
    "/{name}/open",
    response_model=ProjectOut,
    responses={404: {"model": ApiErrorBody}},
    summary="The example as a project in a language (made on the first call)",
)
def open_example(
    name: str, request: Request, session: DbSession, response: Response, lang: Language = "en"
) -> ProjectOut:
    folder = find_example(_root(request), name)
    if folder is None:
        raise ApiError("API101", 404, ["path", "name"], path=request.url.path)
    found = about(folder, lang)
    project = _project_named(session, found.project)
    if project is None:
        project = project_store.create_project(session, found.project, found.description)
        file_store.add_files(session, project, variant_sources(folder, lang))
        response.status_code = status.HTTP_201_CREATED
    return ProjectOut.model_validate(project)

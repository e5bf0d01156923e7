"""Cross-references, the assignment list and rename of a project (``nasaq.workbench.xref`` and
``nasaq.workbench.rename``).

Rename is a preview, then an apply that checks every file it changes is still at the version
the preview saw (XRF709, nothing written otherwise), all in one transaction. The apply answers
with what undo needs: each changed file's old text and the version the rename gave it; undo
restores them only if no file changed since (XRF713), so it never overwrites newer work.
"""

from __future__ import annotations

import asyncio

from fastapi import APIRouter, Query, Request
from pydantic import BaseModel, Field
from sqlalchemy.orm import Session, sessionmaker

from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.storage import files as file_store
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.storage.models import Project
from nasaq.workbench.rename import RenameChange, RenamePlan, plan_rename
from nasaq.workbench.xref import AssignmentList, XrefError, XrefResult, assignment_list, references

router = APIRouter(prefix="/projects/{project_id}", tags=["workbench"])

_NOT_FOUND = ("XRF701", "XRF703")
_ERRORS: dict[int | str, dict[str, object]] = {
    404: {"model": ApiErrorBody, "description": "No such project (API104) or name (XRF701/703)"},
    409: {"model": ApiErrorBody, "description": "A file changed meanwhile (XRF709, XRF713)"},
    422: {"model": ApiErrorBody, "description": "The new name is refused (XRF702..XRF712)"},
}


class RenameRequest(BaseModel):
    target: str = Field(description="'\"Motor\"', 'Q 4.0', '\"Data\".Speed', 'FB 10'")
    new_name: str = Field(description="The new symbol, block or member name, without quotes")


class FileVersion(BaseModel):
    name: str
    version: int


class RenamePreview(BaseModel):
    target: str
    kind: str = Field(description="symbol, block or member")
    old_name: str
    new_name: str
    changes: list[RenameChange]
    files: list[FileVersion] = Field(description="The files it changes, at the versions seen")


class RenameApply(RenameRequest):
    files: list[FileVersion] = Field(description="The preview's files and versions")


class UndoFile(BaseModel):
    name: str
    text: str = Field(description="The text before the rename")
    version: int = Field(description="The version the rename gave the file")


class RenameApplied(RenamePreview):
    undo: list[UndoFile] = Field(description="Send back to /rename/undo to restore every file")


class UndoRequest(BaseModel):
    files: list[UndoFile]


class UndoDone(BaseModel):
    files: list[FileVersion]


def _problem(error: XrefError) -> ApiError:
    status = 404 if error.code in _NOT_FOUND else 422
    return ApiError(error.code, status, ["body"], **error.params)


def _project(session: Session, project_id: int) -> Project:
    project = project_store.get_project(session, project_id)
    if project is None:
        raise ApiError("API104", 404, id=project_id)
    return project


def _sources(factory: sessionmaker[Session], project_id: int) -> list[tuple[str, str]]:
    with transaction(factory) as session:
        _project(session, project_id)
        return file_store.sources(session, project_id)


def _plan(sources: list[tuple[str, str]], body: RenameRequest) -> RenamePlan:
    try:
        return plan_rename(sources, body.target, body.new_name)
    except XrefError as error:
        raise _problem(error) from error


def _preview(plan: RenamePlan, versions: dict[str, int]) -> RenamePreview:
    return RenamePreview(
        target=plan.target,
        kind=plan.kind,
        old_name=plan.old_name,
        new_name=plan.new_name,
        changes=plan.changes,
        files=[FileVersion(name=name, version=versions[name]) for name in sorted(plan.texts)],
    )


def _versions(session: Session, project_id: int) -> dict[str, int]:
    return {item.name: item.version for item in file_store.list_files(session, project_id)}


@router.get(
    "/xref",
    response_model=XrefResult,
    responses=_ERRORS,
    summary="Where a symbol, address, block or DB member is used (cross-references)",
)
async def cross_references(
    project_id: int,
    request: Request,
    target: str = Query(description="'\"Motor\"', 'Q 4.0', 'FB 10', '\"Data\".Speed'"),
) -> XrefResult:
    sources = await asyncio.to_thread(_sources, request.app.state.sessions, project_id)
    try:
        return await asyncio.to_thread(references, sources, target)
    except XrefError as error:
        raise _problem(error) from error


@router.get(
    "/assignments",
    response_model=AssignmentList,
    responses=_ERRORS,
    summary="Which I/Q/M bytes and bits, timers and counters the program uses, and how",
)
async def assignments(project_id: int, request: Request) -> AssignmentList:
    sources = await asyncio.to_thread(_sources, request.app.state.sessions, project_id)
    return await asyncio.to_thread(assignment_list, sources)


def _do_preview(
    factory: sessionmaker[Session], project_id: int, body: RenameRequest
) -> RenamePreview:
    with transaction(factory) as session:
        _project(session, project_id)
        sources = file_store.sources(session, project_id)
        versions = _versions(session, project_id)
    return _preview(_plan(sources, body), versions)


@router.post(
    "/rename/preview",
    response_model=RenamePreview,
    responses=_ERRORS,
    summary="Every change a rename would make (nothing is written)",
)
async def rename_preview(project_id: int, body: RenameRequest, request: Request) -> RenamePreview:
    return await asyncio.to_thread(_do_preview, request.app.state.sessions, project_id, body)


def _do_apply(factory: sessionmaker[Session], project_id: int, body: RenameApply) -> RenameApplied:
    with transaction(factory) as session:
        project = _project(session, project_id)
        sources = file_store.sources(session, project_id)
        plan = _plan(sources, body)
        seen = {item.name: item.version for item in body.files}
        old = dict(sources)
        undo: list[UndoFile] = []
        written: dict[str, int] = {}
        for name in sorted(plan.texts):
            found = file_store.get_file(session, project_id, name)
            if found is None or seen.get(name) != found.version:
                raise ApiError("XRF709", 409, ["body", "files"], name=name)
        for name in sorted(plan.texts):
            saved, _ = file_store.save_file(session, project, name, plan.texts[name], seen[name])
            written[name] = saved.version
            undo.append(UndoFile(name=name, text=old[name], version=saved.version))
        preview = _preview(plan, written)
        return RenameApplied(**preview.model_dump(), undo=undo)


@router.post(
    "/rename",
    response_model=RenameApplied,
    responses=_ERRORS,
    summary="Rename everywhere, if no file changed since the preview; returns what undo needs",
)
async def rename_apply(project_id: int, body: RenameApply, request: Request) -> RenameApplied:
    return await asyncio.to_thread(_do_apply, request.app.state.sessions, project_id, body)


def _do_undo(factory: sessionmaker[Session], project_id: int, body: UndoRequest) -> UndoDone:
    with transaction(factory) as session:
        project = _project(session, project_id)
        for item in body.files:
            found = file_store.get_file(session, project_id, item.name)
            if found is None or found.version != item.version:
                raise ApiError("XRF713", 409, ["body", "files"], name=item.name)
        done: list[FileVersion] = []
        for item in body.files:
            saved, _ = file_store.save_file(session, project, item.name, item.text, item.version)
            done.append(FileVersion(name=item.name, version=saved.version))
        return UndoDone(files=done)


@router.post(
    "/rename/undo",
    response_model=UndoDone,
    responses=_ERRORS,
    summary="Restore the files of a rename, if none changed since",
)
async def rename_undo(project_id: int, body: UndoRequest, request: Request) -> UndoDone:
    return await asyncio.to_thread(_do_undo, request.app.state.sessions, project_id, body)

"""``POST /api/projects/{id}/files/{name}/convert``: an STL source of code blocks becomes a LAD or
FBD source, ``<stem>.lad``/``<stem>.fbd`` (``nasaq.lang.lad.convert``; a network without LAD shape
stays STL inside it, with its reason). The new file is stored and the STL one deleted in one
transaction. A source that would lose something is refused: anything but OB/FB/FC (a LAD source
holds code blocks only) or syntax errors (the parser skipped part of it)."""

from __future__ import annotations

from typing import Literal

from fastapi import APIRouter, Response, status
from pydantic import BaseModel

from nasaq.api.deps import DbSession
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.api.files import (
    FileInfo,
    checked_name,
    checked_text,
    file_info,
    file_location,
    found_file,
    name_taken,
)
from nasaq.diagnostics import Severity
from nasaq.lang.lad.convert import convert
from nasaq.lang.stl.parse import parse_source
from nasaq.storage import files as store
from nasaq.workbench.names import language_of

router = APIRouter(prefix="/projects/{project_id}/files", tags=["files"])

_CODE_BLOCKS = frozenset({"ORGANIZATION_BLOCK", "FUNCTION_BLOCK", "FUNCTION"})


class ConvertFile(BaseModel):
    to: Literal["lad", "fbd"]


@router.post(
    "/{name}/convert",
    response_model=FileInfo,
    status_code=status.HTTP_201_CREATED,
    responses={
        404: {"model": ApiErrorBody, "description": "No such project or file (API104, API107)"},
        409: {"model": ApiErrorBody, "description": "The new file's name is taken (API108)"},
        413: {"model": ApiErrorBody, "description": "The converted text is too large (API110)"},
        422: {
            "model": ApiErrorBody,
            "description": "Not an STL source of code blocks without syntax errors "
            "(API130, API131, API132), or an invalid request (API103)",
        },
    },
    summary="Turn an STL source into a LAD or FBD source",
)
def convert_file(
    project_id: int, name: str, body: ConvertFile, session: DbSession, response: Response
) -> FileInfo:
    project, found = found_file(session, project_id, name)
    if language_of(name) != "stl":
        raise ApiError("API130", 422, ["path", "name"], name=name)
    parsed = parse_source(name, found.text)
    for block in parsed.source.blocks:
        if block.keyword.upper() not in _CODE_BLOCKS:
            label = f"{block.keyword.upper()} {block.ident}"
            raise ApiError("API131", 422, ["path", "name"], name=name, block=label)
    errors = [d for d in parsed.diagnostics if d.severity is Severity.ERROR]
    if errors:
        first = errors[0]
        line = first.span.line if first.span is not None else None
        raise ApiError("API132", 422, ["path", "name"], name=name, line=line, problem=first.code)
    target = checked_name(f"{name[: name.rfind('.')]}.{body.to}", ["path", "name"])
    text = checked_text(target, convert(name, found.text, body.to).text)
    try:
        created = store.replace_file(session, project, found, target, text)
    except store.FileNameTakenError as exc:
        raise name_taken(exc, ["path", "name"]) from exc
    response.headers["Location"] = file_location(project_id, target)
    return file_info(created)

"""The symbol table editor's and the DB editor's API.

``/api/projects/{id}/symbols/{file}``: a symbol table file as checked rows (read, save with the
same version check as ``/files``, download in a STEP 7 format, import an uploaded table); the file
stays the project's source, written in its own format.
``/api/projects/{id}/blocks/{block}/members``: a data block's variables with offsets, initial and
compiled values (the DB editor's rows).

An import is the raw file body (like a project import), named by ``?name=`` so its format is known.
"""

from __future__ import annotations

import asyncio
from typing import Annotated, Literal
from urllib.parse import quote

from fastapi import APIRouter, Query, Request, Response
from pydantic import BaseModel, Field
from sqlalchemy.orm import Session, sessionmaker

from nasaq.api.deps import DbSession
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.api.files import checked_name, checked_text
from nasaq.api.projects import found_project
from nasaq.ir import BlockKind, Program
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.storage import files as store
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction
from nasaq.workbench import symbol_table as table
from nasaq.workbench.members import Member, block_members
from nasaq.workbench.project_compile import compile_project
from nasaq.workbench.symbol_table import Format, RowProblem, SymbolRow, TableError
from nasaq.workbench.tree import header_line, header_lines

router = APIRouter(prefix="/projects/{project_id}", tags=["symbols"])

MAX_ROWS = 20_000
MAX_UPLOAD_BYTES = 4 * 1024 * 1024


class SymbolTableOut(BaseModel):
    name: str
    format: Format
    version: int = Field(description="Send it back as base_version with the next save")
    rows: list[SymbolRow]
    problems: list[RowProblem]


class SymbolTableSave(BaseModel):
    rows: list[SymbolRow] = Field(max_length=MAX_ROWS)
    base_version: int | None = Field(
        default=None, ge=1, description="The version loaded; stale saves are refused (API111)"
    )


class DbMembersOut(BaseModel):
    kind: Literal["DB"]
    number: int
    name: str = Field(description="Symbolic name, empty when the DB has none")
    file: str
    line: int | None = Field(description="Line of the DB's header in its file")
    instance_of: int | None = Field(description="Instance DBs: the FB's number")
    members: list[Member]


_ERRORS: dict[int | str, dict[str, object]] = {
    404: {"model": ApiErrorBody, "description": "No such project, file or DB (API104/107/128)"},
    409: {"model": ApiErrorBody, "description": "Stale save (API111)"},
    413: {"model": ApiErrorBody, "description": "Too large (API110)"},
    422: {
        "model": ApiErrorBody,
        "description": "Not a symbol table, unreadable or not writable (API109, API124-API127)",
    },
}


def _format(name: str) -> Format:
    kind = table.format_of(name)
    if kind is None:
        raise ApiError("API127", 422, ["path", "file"], name=name)
    return kind


def _out(name: str, version: int, rows: list[SymbolRow]) -> SymbolTableOut:
    kind = _format(name)
    return SymbolTableOut(
        name=name, format=kind, version=version, rows=rows, problems=table.problems(rows, kind)
    )


def _writable(name: str, rows: list[SymbolRow]) -> str:
    try:
        return checked_text(name, table.write_rows(name, rows))
    except TableError as error:
        raise ApiError(error.code, 422, ["body", "rows"], **error.params) from error


def _save(
    session: DbSession, project_id: int, name: str, rows: list[SymbolRow], base: int | None
) -> SymbolTableOut:
    project = found_project(session, project_id)
    checked_name(name, ["path", "file"])
    _format(name)
    text = _writable(name, rows)
    try:
        saved, _created = store.save_file(session, project, name, text, base)
    except store.StaleFileError as exc:
        raise ApiError(
            "API111", 409, ["body", "base_version"], name=name, current_version=exc.current
        ) from exc
    return _out(name, saved.version, table.read_rows(name, text))


@router.get(
    "/symbols/{file}",
    response_model=SymbolTableOut,
    responses=_ERRORS,
    summary="A symbol table as rows, with each row's problems",
)
def get_symbols(project_id: int, file: str, session: DbSession) -> SymbolTableOut:
    found_project(session, project_id)
    _format(file)
    found = store.get_file(session, project_id, file)
    if found is None:
        raise ApiError("API107", 404, project=project_id, name=file)
    return _out(file, found.version, table.read_rows(file, found.text))


@router.put(
    "/symbols/{file}",
    response_model=SymbolTableOut,
    responses=_ERRORS,
    summary="Save rows into the symbol table file, written in its own format (autosave)",
)
def put_symbols(
    project_id: int, file: str, body: SymbolTableSave, session: DbSession
) -> SymbolTableOut:
    return _save(session, project_id, file, body.rows, body.base_version)


@router.get(
    "/symbols/{file}/export",
    responses={
        **_ERRORS,
        200: {"content": {"text/plain": {}}, "description": "The table as STEP 7 reads it"},
    },
    summary="Download the table as .sdf, .asc, .seq or .csv (Windows-1252, CRLF)",
)
def export_symbols(
    project_id: int,
    file: str,
    session: DbSession,
    format: Annotated[Format, Query(description="The file format to write")] = "sdf",
) -> Response:
    found_project(session, project_id)
    _format(file)
    found = store.get_file(session, project_id, file)
    if found is None:
        raise ApiError("API107", 404, project=project_id, name=file)
    try:
        data = table.export_bytes(format, table.read_rows(file, found.text))
    except TableError as error:
        raise ApiError(error.code, 422, ["query", "format"], **error.params) from error
    stem = file[: file.rfind(".")]
    download = f"{stem}.{format}"
    ascii_name = download.encode("ascii", "replace").decode().replace("?", "_").replace('"', "_")
    disposition = f"attachment; filename=\"{ascii_name}\"; filename*=UTF-8''{quote(download)}"
    return Response(
        data,
        media_type=f"{table.MEDIA_TYPES[format]}; charset=windows-1252",
        headers={"Content-Disposition": disposition},
    )


async def _upload(request: Request) -> bytes:
    parts: list[bytes] = []
    size = 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > MAX_UPLOAD_BYTES:
            raise ApiError(
                "API110", 413, ["body"], name="upload", size_kb=size // 1024, limit_kb=4096
            )
        parts.append(chunk)
    return b"".join(parts)


@router.post(
    "/symbols/{file}/import",
    response_model=SymbolTableOut,
    responses=_ERRORS,
    summary="Import an uploaded table (raw body) into the file: replace it, or merge by name",
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {"application/octet-stream": {"schema": {"type": "string"}}},
        }
    },
)
async def import_symbols(
    project_id: int,
    file: str,
    request: Request,
    session: DbSession,
    name: Annotated[str, Query(description="The uploaded file's name: its suffix is its format")],
    mode: Annotated[Literal["replace", "merge"], Query()] = "replace",
    base_version: Annotated[int | None, Query(ge=1)] = None,
) -> SymbolTableOut:
    if table.format_of(name) is None:
        raise ApiError("API127", 422, ["query", "name"], name=name)
    data = await _upload(request)
    try:
        rows = table.read_rows(name, table.decode_upload(name, data))
    except TableError as error:
        raise ApiError(error.code, 422, ["body"], **error.params) from error
    if not rows:
        raise ApiError("API126", 422, ["body"], name=name, reason="it holds no rows")
    if mode == "merge":
        found = store.get_file(session, project_id, file)
        old = table.read_rows(file, found.text) if found is not None else []
        rows = table.merged(old, rows)
    return _save(session, project_id, file, rows, base_version)


# -- the DB editor ---------------------------------------------------------------------------


def _compiled(factory: sessionmaker[Session], project_id: int) -> tuple[Program, dict[str, str]]:
    with transaction(factory) as session:
        if project_store.get_project(session, project_id) is None:
            raise ApiError("API104", 404, id=project_id)
        sources = store.sources(session, project_id)
    result = compile_project(sources)
    return result.program, dict(sources)


def _db_number(block: str, program: Program) -> int | None:
    text = block.strip()
    unquoted = text[1:-1] if len(text) > 1 and text[0] == text[-1] == '"' else text
    address = next(
        (value for key, value in program.symbols.items() if key.casefold() == unquoted.casefold()),
        unquoted,
    )
    try:
        parsed = parse_address(" ".join(address.split()))
    except AddressError:
        compact = address.replace(" ", "").upper()
        if compact.startswith("DB") and compact[2:].isdigit():
            return int(compact[2:])
        return None
    return parsed.number if parsed.kind == "block" and parsed.block is BlockKind.DB else None


def _members(factory: sessionmaker[Session], project_id: int, block: str) -> DbMembersOut:
    program, texts = _compiled(factory, project_id)
    number = _db_number(block, program)
    found = program.get(BlockKind.DB, number) if number is not None else None
    if found is None:
        raise ApiError("API128", 404, ["path", "block"], block=block)
    text = texts.get(found.file)
    return DbMembersOut(
        kind="DB",
        number=found.number,
        name=found.name,
        file=found.file,
        line=header_line(found, header_lines(text)) if text is not None else None,
        instance_of=found.instance_of,
        members=block_members(found, program, texts),
    )


@router.get(
    "/blocks/{block}/members",
    response_model=DbMembersOut,
    responses=_ERRORS,
    summary="A data block's variables: offsets, initial and compiled actual values",
)
async def db_members(project_id: int, block: str, request: Request) -> DbMembersOut:
    return await asyncio.to_thread(_members, request.app.state.sessions, project_id, block)

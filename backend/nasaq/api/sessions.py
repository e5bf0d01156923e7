"""``/api/sessions``: simulation sessions (create by download, replace the program in STOP,
diagnostic buffer, trend CSV, delete) and their monitoring WebSocket at ``/api/sessions/{id}/ws``
(protocol: ``nasaq/monitor/PROTOCOL.md``).

A session made from a project belongs to that project, not to the browser tab that downloaded
it: ``GET /api/sessions?project_id=N`` finds it again after a reload, in a second tab or another
browser. A project runs one simulated CPU, as a project in TIA Portal has one PLCSIM instance: a
new download into a new session closes the project's older ones. There are no user accounts yet
(issue 22), so every session on the server counts as the user's own: the list, with each
session's project name, CPU mode and age, is what the IDE offers to close when the server is full
(MON610).
"""

from __future__ import annotations

import asyncio
import time
from datetime import UTC, datetime
from typing import Annotated, Any

from fastapi import APIRouter, Query, Request, Response, WebSocket, status
from pydantic import BaseModel, Field

from nasaq.api.cpu_properties import checked as checked_properties
from nasaq.api.cpu_properties import with_properties
from nasaq.api.errors import ApiError, ApiErrorBody
from nasaq.lang.limits import MAX_SOURCE_CHARS
from nasaq.lang.profiles import ProfileName
from nasaq.monitor.connection import Connection
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.pool import WorkerPool
from nasaq.monitor.protocol import CpuState, DiagnosticEntry, TimeModeName
from nasaq.storage import projects as project_store
from nasaq.storage.database import transaction

router = APIRouter(prefix="/sessions", tags=["simulation"])

_STATUS = {"MON609": 404, "MON610": 503, "MON611": 422, "MON616": 413, "MON607": 409}


class Source(BaseModel):
    name: str = Field(min_length=1, max_length=255, description="File name; .scl is SCL, else STL")
    text: str = Field(max_length=MAX_SOURCE_CHARS)


class SessionOptions(BaseModel):
    profile: ProfileName = "S7-300"
    cycle_ms: float = Field(default=10, ge=1, le=60_000)
    time_mode: TimeModeName = "virtual"


class SessionCreate(SessionOptions):
    sources: list[Source] = Field(min_length=1, max_length=500)


class Download(BaseModel):
    sources: list[Source] = Field(min_length=1, max_length=500)


class SessionOut(BaseModel):
    id: str
    blocks: list[str]
    cpu: CpuState
    clients: list[int] = Field(description="The connected sockets (their hello's client)")
    websocket: str
    project_id: int | None = Field(
        default=None, description="The project the session was made from (None: plain sources)"
    )
    project_name: str | None = Field(default=None, description="That project's name now")
    profile: ProfileName = "S7-300"
    started_at: datetime = Field(description="When the session was created (UTC)")
    age_seconds: float = Field(description="Seconds since it was created")


class DownloadOut(BaseModel):
    changed: list[str] = Field(description="Blocks added, changed or removed by the download")


_ERRORS: dict[int | str, dict[str, object]] = {
    404: {"model": ApiErrorBody, "description": "No such session (MON609)"},
    409: {"model": ApiErrorBody, "description": "Not possible in this CPU mode (MON607)"},
    413: {"model": ApiErrorBody, "description": "Program too large (MON616)"},
    422: {"model": ApiErrorBody, "description": "The program does not compile (MON611)"},
    503: {"model": ApiErrorBody, "description": "Too many sessions (MON610)"},
}


def pool_of(state: object) -> WorkerPool:
    found: WorkerPool = state.simulations  # type: ignore[attr-defined]
    return found


def _api_error(error: MonitorError) -> ApiError:
    # A plant file that cannot run (PLT###, nasaq.plants.plant_file) is refused as a program
    # that does not compile is.
    fallback = 422 if error.code.startswith("PLT") else 400
    return ApiError(error.code, _STATUS.get(error.code, fallback), **error.params)


def _sources(items: list[Source]) -> list[tuple[str, str]]:
    return [(item.name, item.text) for item in items]


def _out(found: dict[str, Any], names: dict[int, str] | None = None) -> SessionOut:
    project_id = found.get("project_id")
    started = float(found.get("started_at", time.time()))
    return SessionOut(
        id=found["id"],
        blocks=found["blocks"],
        cpu=CpuState.model_validate(found["cpu"]),
        clients=found["clients"],
        websocket=f"/api/sessions/{found['id']}/ws",
        project_id=project_id,
        project_name=None if project_id is None or names is None else names.get(project_id),
        profile=found.get("profile", "S7-300"),
        started_at=datetime.fromtimestamp(started, UTC),
        age_seconds=round(max(0.0, time.time() - started), 1),
    )


def _names(request: Request, project_ids: set[int]) -> dict[int, str]:
    """The current names of the projects (a project may have been renamed or deleted)."""
    found: dict[int, str] = {}
    with transaction(request.app.state.sessions) as db:
        for project_id in project_ids:
            project = project_store.get_project(db, project_id)
            if project is not None:
                found[project_id] = project.name
    return found


async def _described(request: Request, infos: list[dict[str, Any]]) -> list[SessionOut]:
    wanted = {info["project_id"] for info in infos if info.get("project_id") is not None}
    names = await asyncio.to_thread(_names, request, wanted) if wanted else {}
    return [_out(info, names) for info in infos]


@router.post(
    "",
    response_model=SessionOut,
    status_code=status.HTTP_201_CREATED,
    responses=_ERRORS,
    summary="Compile and download a program into a new simulated CPU (in STOP)",
)
async def create_session(body: SessionCreate, request: Request) -> SessionOut:
    return await start_session(request, _sources(body.sources), body)


async def start_session(
    request: Request,
    sources: list[tuple[str, str]],
    options: SessionOptions,
    project_id: int | None = None,
) -> SessionOut:
    """Compiles ``sources`` into a new simulated CPU; also how a project starts a session (then
    tagged with ``project_id``, and the project's older sessions are closed once it runs)."""
    options = with_properties(sources, options)  # the sources' cpu.properties (PRJ908)
    pool = pool_of(request.app.state)
    older = pool.ids(project_id) if project_id is not None else []
    try:
        found = await pool.create(
            sources, options.profile, options.cycle_ms, options.time_mode, project_id
        )
    except MonitorError as error:
        raise _api_error(error) from None
    for session_id in older:
        try:
            await pool.delete(session_id)
        except MonitorError:
            continue  # closed meanwhile
    return (await _described(request, [found]))[0]


async def _call(request: Request, session_id: str, op: str, *args: Any) -> Any:
    try:
        return await pool_of(request.app.state).call(session_id, op, *args)
    except MonitorError as error:
        raise _api_error(error) from None


@router.get(
    "",
    response_model=list[SessionOut],
    summary="The running sessions, newest first (project_id: only that project's)",
)
async def list_sessions(
    request: Request, project_id: Annotated[int | None, Query(ge=1)] = None
) -> list[SessionOut]:
    pool = pool_of(request.app.state)
    infos: list[dict[str, Any]] = []
    for session_id in pool.ids(project_id):
        try:
            infos.append(await pool.call(session_id, "info"))
        except MonitorError:
            continue  # closed meanwhile
    infos.sort(key=lambda info: float(info.get("started_at", 0)), reverse=True)
    return await _described(request, infos)


@router.get("/{session_id}", response_model=SessionOut, responses=_ERRORS, summary="One session")
async def get_session(session_id: str, request: Request) -> SessionOut:
    return (await _described(request, [await _call(request, session_id, "info")]))[0]


@router.put(
    "/{session_id}/program",
    response_model=DownloadOut,
    responses=_ERRORS,
    summary="Download a changed program (CPU in STOP)",
)
async def download(session_id: str, body: Download, request: Request) -> DownloadOut:
    checked_properties(_sources(body.sources))  # a cpu.properties with errors: PRJ908
    result = await _call(request, session_id, "download", _sources(body.sources))
    return DownloadOut.model_validate(result)


@router.get(
    "/{session_id}/diagnostics",
    response_model=list[DiagnosticEntry],
    responses=_ERRORS,
    summary="The CPU's diagnostic buffer, oldest first",
)
async def diagnostics(session_id: str, request: Request) -> list[DiagnosticEntry]:
    found = await _call(request, session_id, "diagnostics")
    return [DiagnosticEntry.model_validate(entry) for entry in found]


@router.get(
    "/{session_id}/trend.csv",
    responses={**_ERRORS, 200: {"content": {"text/csv": {}}}},
    summary="A client's trend samples as CSV (scan, time in ms, one column per value)",
)
async def trend_csv(
    session_id: str, request: Request, client: Annotated[int, Query(ge=1)]
) -> Response:
    try:
        text = await pool_of(request.app.state).call(session_id, "trend_csv", client)
    except MonitorError as error:
        status_code = 404 if error.code == "MON603" else _STATUS.get(error.code, 400)
        raise ApiError(error.code, status_code, **error.params) from None
    return Response(
        text,
        media_type="text/csv",
        headers={"Content-Disposition": f'attachment; filename="trend-{session_id}.csv"'},
    )


@router.delete(
    "/{session_id}",
    status_code=status.HTTP_204_NO_CONTENT,
    responses=_ERRORS,
    summary="Close a session",
)
async def delete_session(session_id: str, request: Request) -> Response:
    try:
        await pool_of(request.app.state).delete(session_id)
    except MonitorError as error:
        raise _api_error(error) from None
    return Response(status_code=status.HTTP_204_NO_CONTENT)


@router.websocket("/{session_id}/ws")
async def monitor_socket(socket: WebSocket, session_id: str) -> None:
    pool = pool_of(socket.app.state)
    if not pool.exists(session_id):
        await socket.close(code=1008, reason=str(MonitorError("MON609", id=session_id))[:120])
        return
    timeout = socket.app.state.settings.slow_client_seconds
    await Connection(socket, pool, session_id, timeout).serve()

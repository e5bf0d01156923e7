"""The FastAPI application: API under ``/api``, docs at ``/api/docs``, the IDE at ``/``."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import APIRouter, FastAPI
from fastapi.middleware.gzip import GZipMiddleware

from nasaq import __version__
from nasaq.api import (
    archive,
    convert,
    cpu_properties,
    examples,
    file_convert,
    files,
    graph,
    health,
    lad,
    lessons,
    outline,
    plants,
    projects,
    sessions,
    symbols,
    workbench,
    xref,
)
from nasaq.api.docs import install_docs
from nasaq.api.errors import install_error_handlers
from nasaq.api.frontend import install_frontend
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.pool import WorkerPool
from nasaq.settings import Settings, get_settings
from nasaq.storage.database import create_db_engine, session_factory
from nasaq.storage.migrate import upgrade_to_head
from nasaq.workbench.examples import seed_examples


def create_app(settings: Settings | None = None) -> FastAPI:
    settings = settings or get_settings()

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        # The schema is brought up to date before the first request, on every start.
        upgrade_to_head(settings)
        engine = create_db_engine(settings)
        app.state.engine = engine
        app.state.sessions = session_factory(engine)
        seed_examples(app.state.sessions, settings.examples_dir)
        simulations: WorkerPool = app.state.simulations
        simulations.start(asyncio.get_running_loop())
        reaper = asyncio.create_task(_reap(simulations))
        try:
            yield
        finally:
            reaper.cancel()
            await asyncio.to_thread(simulations.stop)
            engine.dispose()

    app = FastAPI(
        title="Nasaq",
        version=__version__,
        summary="Web IDE and S7-300/400 CPU simulator",
        openapi_url="/api/openapi.json",
        docs_url=None,
        redoc_url=None,
        lifespan=lifespan,
    )
    app.state.settings = settings
    app.state.simulations = WorkerPool(
        settings.session_workers, settings.max_sessions, settings.session_idle_seconds
    )
    app.add_middleware(GZipMiddleware, minimum_size=1024)
    install_error_handlers(app)

    api = APIRouter(prefix="/api")
    api.include_router(health.router)
    api.include_router(archive.router)  # before projects: /projects/import is no project id
    api.include_router(projects.router)
    api.include_router(files.router)
    api.include_router(file_convert.router)
    api.include_router(workbench.router)
    api.include_router(symbols.router)
    api.include_router(outline.router)
    api.include_router(sessions.router)
    api.include_router(cpu_properties.router)
    api.include_router(convert.router)
    api.include_router(lad.router)
    api.include_router(graph.router)
    api.include_router(xref.router)
    api.include_router(examples.router)
    api.include_router(lessons.router)
    api.include_router(plants.router)
    app.include_router(api)
    install_docs(app)
    install_frontend(app, settings.frontend_dist)  # last: its catch-all route must come after
    return app


async def _reap(simulations: WorkerPool) -> None:
    """Closes abandoned simulation sessions once a minute."""
    while True:
        await asyncio.sleep(min(60.0, simulations.idle_seconds / 2))
        with contextlib.suppress(MonitorError):  # a worker ended meanwhile; it was replaced
            await simulations.reap()

"""Serves the built front end: hashed assets cached for a year, every other page gets index.html.

Long-lived caching of the content-hashed files matters on a slow classroom network: after the first
visit a reload fetches only index.html.
"""

from __future__ import annotations

from pathlib import Path

from fastapi import FastAPI, Request
from fastapi.responses import FileResponse, HTMLResponse, Response
from fastapi.staticfiles import StaticFiles
from starlette.types import Scope

from nasaq.api.errors import error_response

_IMMUTABLE = "public, max-age=31536000, immutable"

_NOT_BUILT = """<!doctype html><html lang="en"><head><meta charset="utf-8">
<title>Nasaq</title></head><body><h1>Nasaq</h1>
<p>The front end has not been built yet. Run <code>make install</code>
(or <code>make run</code>) in the repository, then reload this page.</p>
<p>The API is up: <a href="/api/docs">/api/docs</a>.</p></body></html>"""


class _HashedAssets(StaticFiles):
    async def get_response(self, path: str, scope: Scope) -> Response:
        response = await super().get_response(path, scope)
        if response.status_code == 200:
            response.headers["Cache-Control"] = _IMMUTABLE
        return response


def install_frontend(app: FastAPI, dist: Path) -> None:
    dist = dist.resolve()
    index = dist / "index.html"
    if (dist / "assets").is_dir():
        app.mount("/assets", _HashedAssets(directory=dist / "assets"), name="assets")

    @app.get("/{path:path}", include_in_schema=False)
    def page(path: str, request: Request) -> Response:
        if path == "api" or path.startswith("api/"):
            return error_response("API101", 404, path=request.url.path)
        if not index.is_file():
            return HTMLResponse(_NOT_BUILT, status_code=503)
        wanted = (dist / path).resolve()
        if path and wanted.is_relative_to(dist) and wanted.is_file():
            return FileResponse(wanted, headers={"Cache-Control": "public, max-age=3600"})
        return FileResponse(index, headers={"Cache-Control": "no-cache"})

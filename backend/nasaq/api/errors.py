"""Every API error leaves as ``{"error": Diagnostic}``, with a catalogue code, never a bare 500.

Routers raise :class:`ApiError`; framework errors (unknown route, validation) are mapped to the
same shape here so the front end has one way to show them.
"""

from __future__ import annotations

import logging
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from pydantic import BaseModel, Field
from starlette.exceptions import HTTPException as StarletteHTTPException

from nasaq.diagnostics import Diagnostic, render
from nasaq.diagnostics.phrases import Phrase
from nasaq.diagnostics.validation import validation_reason

log = logging.getLogger(__name__)


class ApiProblem(Diagnostic):
    location: list[str | int] | None = Field(
        default=None, description="Path of the offending request field, e.g. ['body', 'name']."
    )


class ApiErrorBody(BaseModel):
    error: ApiProblem


class ApiError(Exception):
    def __init__(
        self,
        code: str,
        status: int,
        location: list[str | int] | None = None,
        **params: Any,
    ) -> None:
        super().__init__(code)
        self.code = code
        self.status = status
        self.location = location
        self.params = params


def error_response(
    code: str, status: int, location: list[str | int] | None = None, **params: Any
) -> JSONResponse:
    problem = ApiProblem(**render(code, **params).model_dump(), location=location)
    body = ApiErrorBody(error=problem)
    return JSONResponse(body.model_dump(mode="json"), status_code=status)


# What a client sees when the route exists but not the thing, or when no route matches.
def _http_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, StarletteHTTPException)
    if exc.status_code == 405:
        return error_response("API102", 405, method=request.method, path=request.url.path)
    if exc.status_code == 404:
        return error_response("API101", 404, path=request.url.path)
    reason = Phrase("request_refused", english=str(exc.detail))
    return error_response("API103", exc.status_code, field="request", reason=reason)


def _api_error(_request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, ApiError)
    return error_response(exc.code, exc.status, exc.location, **exc.params)


def _validation_error(_request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestValidationError)
    first = exc.errors()[0] if exc.errors() else {"loc": ["request"], "msg": "invalid"}
    location = [part for part in first.get("loc", ()) if isinstance(part, str | int)]
    field = ".".join(str(part) for part in location if part != "body") or "request"
    return error_response("API103", 422, location, field=field, reason=validation_reason(first))


def _unexpected_error(request: Request, exc: Exception) -> JSONResponse:
    log.exception("unhandled error on %s %s", request.method, request.url.path, exc_info=exc)
    return error_response("API199", 500)


def install_error_handlers(app: FastAPI) -> None:
    app.add_exception_handler(ApiError, _api_error)
    app.add_exception_handler(StarletteHTTPException, _http_error)
    app.add_exception_handler(RequestValidationError, _validation_error)
    app.add_exception_handler(Exception, _unexpected_error)

"""``/api/health``: is the server up and can it reach its database."""

from __future__ import annotations

from typing import Literal

from fastapi import APIRouter, Request
from pydantic import BaseModel
from sqlalchemy import text
from sqlalchemy.exc import SQLAlchemyError

from nasaq import __version__
from nasaq.api.errors import ApiError

router = APIRouter(tags=["health"])


class Health(BaseModel):
    status: Literal["ok"]
    version: str
    database: Literal["ok"]


@router.get("/health", response_model=Health, summary="Server and database status")
def health(request: Request) -> Health:
    try:
        with request.app.state.engine.connect() as connection:
            connection.execute(text("SELECT 1"))
    except SQLAlchemyError as exc:
        raise ApiError("API106", 503, reason=type(exc).__name__) from exc
    return Health(status="ok", version=__version__, database="ok")

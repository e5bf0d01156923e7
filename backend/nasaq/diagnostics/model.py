"""What a reported problem looks like, wherever it comes from (compiler, CPU, API)."""

from __future__ import annotations

from enum import StrEnum
from typing import Any

from pydantic import BaseModel, Field


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"


class Span(BaseModel):
    """Where a problem sits: a source file position (1-based) and, for diagrams, a network and
    the element in it."""

    file: str | None = None
    line: int | None = Field(default=None, ge=1)
    column: int | None = Field(default=None, ge=1)
    end_line: int | None = Field(default=None, ge=1)
    end_column: int | None = Field(default=None, ge=1)
    network: int | None = Field(default=None, ge=1)
    element: str | None = Field(
        default=None, description="The LAD/FBD element id in its network (e1, e2 ...)"
    )


class Diagnostic(BaseModel):
    code: str = Field(description="Stable code from the catalogue, e.g. 'API104'.")
    severity: Severity
    key: str = Field(description="Message key the UI translates.")
    message: str = Field(description="The message in English, parameters filled in.")
    params: dict[str, Any] = Field(default_factory=dict)
    span: Span | None = None

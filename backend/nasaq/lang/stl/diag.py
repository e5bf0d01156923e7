"""Diagnostics of the STL compiler: catalogue codes ``STL1xx``/``STL2xx`` with a source span."""

from __future__ import annotations

from typing import Any

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.lang.stl.ast import Loc


def span(file: str, loc: Loc | None) -> Span:
    if loc is None:
        return Span(file=file)
    return Span(
        file=file,
        line=loc.line,
        column=loc.column,
        end_line=loc.end_line,
        end_column=loc.end_column,
    )


def problem(code: str, source: str, loc: Loc | None, **params: Any) -> Diagnostic:
    return render(code, span(source, loc), **params)


def sort_key(diagnostic: Diagnostic) -> tuple[str, int, int, str]:
    where = diagnostic.span or Span()
    return (where.file or "", where.line or 0, where.column or 0, diagnostic.code)

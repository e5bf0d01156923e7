"""Loads ``catalogue.csv`` once and renders its messages."""

from __future__ import annotations

import csv
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from nasaq.diagnostics.model import Diagnostic, Severity, Span


@dataclass(frozen=True, slots=True)
class CatalogueEntry:
    code: str
    severity: Severity
    key: str
    template: str


@cache
def _entries() -> dict[str, CatalogueEntry]:
    text = resources.files(__package__).joinpath("catalogue.csv").read_text(encoding="utf-8")
    entries: dict[str, CatalogueEntry] = {}
    for row in csv.DictReader(text.splitlines()):
        code = row["code"]
        if code in entries:
            raise ValueError(f"diagnostic code {code} appears twice in catalogue.csv")
        entries[code] = CatalogueEntry(code, Severity(row["severity"]), row["key"], row["message"])
    return entries


def entry(code: str) -> CatalogueEntry:
    """The catalogue entry of ``code``; an unknown code is a programming error (KeyError)."""
    return _entries()[code]


def all_entries() -> list[CatalogueEntry]:
    return list(_entries().values())


def render(code: str, span: Span | None = None, **params: Any) -> Diagnostic:
    """A diagnostic for ``code`` with its English message filled in from ``params``."""
    found = entry(code)
    return Diagnostic(
        code=found.code,
        severity=found.severity,
        key=found.key,
        message=found.template.format(**params),
        params=params,
        span=span,
    )

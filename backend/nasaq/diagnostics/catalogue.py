"""Loads the catalogue once and renders its messages.

The catalogue is every ``*.csv`` beside this module (``api.csv``, ``stl.csv``, ``sim.csv`` ...), one
file per family of codes, all with the columns ``code,severity,key,message``. A code or key that
appears twice anywhere is an error.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from nasaq.diagnostics.model import Diagnostic, Severity, Span
from nasaq.diagnostics.phrases import expand


@dataclass(frozen=True, slots=True)
class CatalogueEntry:
    code: str
    severity: Severity
    key: str
    template: str


@cache
def _entries() -> dict[str, CatalogueEntry]:
    entries: dict[str, CatalogueEntry] = {}
    keys: set[str] = set()
    folder = resources.files(__package__)
    for source in sorted(folder.iterdir(), key=lambda item: item.name):
        if not source.name.endswith(".csv"):
            continue
        for row in csv.DictReader(source.read_text(encoding="utf-8").splitlines()):
            code, key = row["code"], row["key"]
            if code in entries or key in keys:
                raise ValueError(f"{source.name}: code {code} or key {key} is already catalogued")
            entries[code] = CatalogueEntry(code, Severity(row["severity"]), key, row["message"])
            keys.add(key)
    return entries


def entry(code: str) -> CatalogueEntry:
    """The catalogue entry of ``code``; an unknown code is a programming error (KeyError)."""
    return _entries()[code]


def all_entries() -> list[CatalogueEntry]:
    return list(_entries().values())


def render(code: str, span: Span | None = None, **params: Any) -> Diagnostic:
    """A diagnostic for ``code`` with its English message filled in from ``params``; phrase
    parameters are expanded (see :mod:`nasaq.diagnostics.phrases`)."""
    found = entry(code)
    params = expand(params)
    return Diagnostic(
        code=found.code,
        severity=found.severity,
        key=found.key,
        message=found.template.format(**params),
        params=params,
        span=span,
    )

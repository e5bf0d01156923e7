"""Diagnostics snapshots of erroneous Graph sources: each file under ``fixtures/bad`` is one
mistake a student makes (a few hold several), parsed and checked; the problems found (code,
line, element, parameters) must equal the committed snapshot ``fixtures/bad_snapshot.json``.

After an intended change, regenerate the snapshot and review its diff:

    NASAQ_UPDATE_SNAPSHOTS=1 .venv/bin/pytest -q \
        tests/backend/lang/graph/test_graph_check_snapshots.py
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import pytest

from nasaq.diagnostics.catalogue import all_entries
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.text import parse_graph

HERE = Path(__file__).parent
BAD = HERE / "fixtures" / "bad"
SNAPSHOT = HERE / "fixtures" / "bad_snapshot.json"
SOURCES = sorted(BAD.glob("*.graph"))
# Checker codes a .graph text cannot produce (the parser refuses the text first, or the FB
# would need hundreds of steps): test_graph_check_*.py build them from model objects.
NOT_FROM_TEXT = {"GRA208", "GRA209", "GRA210", "GRA211", "GRA214", "GRA247", "GRA280", "GRA286"}


def _problems(path: Path) -> list[dict[str, Any]]:
    parsed = parse_graph(path.read_text(encoding="utf-8"), path.name)
    found = list(parsed.diagnostics)
    for index in range(len(parsed.blocks)):
        found += check_block(parsed, index)
    return [
        {
            "code": problem.code,
            "line": problem.span.line if problem.span else None,
            "element": problem.span.element if problem.span else None,
            "params": problem.params,
        }
        for problem in found
    ]


def _snapshot() -> dict[str, list[dict[str, Any]]]:
    if os.environ.get("NASAQ_UPDATE_SNAPSHOTS"):
        taken = {path.stem: _problems(path) for path in SOURCES}
        SNAPSHOT.write_text(json.dumps(taken, indent=1, ensure_ascii=False) + "\n", "utf-8")
    loaded: dict[str, list[dict[str, Any]]] = json.loads(SNAPSHOT.read_text("utf-8"))
    return loaded


def test_at_least_40_erroneous_sources_all_in_the_snapshot() -> None:
    assert len(SOURCES) >= 40
    assert sorted(_snapshot()) == [path.stem for path in SOURCES]


@pytest.mark.parametrize("path", SOURCES, ids=[path.stem for path in SOURCES])
def test_diagnostics_match_the_snapshot(path: Path) -> None:
    found = _problems(path)
    assert found == _snapshot()[path.stem]
    # Each source is erroneous: at least one error or warning, each placed on a real line.
    lines = path.read_text(encoding="utf-8").count("\n") + 1
    assert any(problem["code"] != "GRA244" for problem in found), path.name
    assert all(1 <= problem["line"] <= lines for problem in found), path.name


def test_every_checker_code_readable_from_text_has_a_source() -> None:
    checker = {found.code for found in all_entries() if found.code.startswith("GRA2")}
    shown = {problem["code"] for problems in _snapshot().values() for problem in problems}
    assert checker - NOT_FROM_TEXT - shown == set()

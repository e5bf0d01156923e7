"""Shared fixtures: every test gets its own data folder, database and (fake) built front end."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from nasaq.api.app import create_app
from nasaq.settings import Settings

# Test helper modules live beside the tests that use them; this file is loaded however pytest is
# started (with or without backend/pyproject.toml as its config), so it puts them on the path.
_HERE = Path(__file__).resolve().parent
for _folder in ("cpu", "lang", "lang/stl", "lang/scl", "lang/lad", "workbench", "plants"):
    if str(_HERE / _folder) not in sys.path:
        sys.path.insert(0, str(_HERE / _folder))


@pytest.fixture
def dist(tmp_path: Path) -> Path:
    """A minimal built front end, shaped like Vite's output."""
    root = tmp_path / "dist"
    (root / "assets").mkdir(parents=True)
    (root / "index.html").write_text(
        '<!doctype html><html><head><script type="module" src="/assets/app-1a2b.js"></script>'
        '</head><body><div id="root"></div></body></html>',
        encoding="utf-8",
    )
    (root / "assets" / "app-1a2b.js").write_text("console.log('nasaq');\n" * 200, encoding="utf-8")
    (root / "favicon.svg").write_text("<svg xmlns='http://www.w3.org/2000/svg'/>", encoding="utf-8")
    return root


@pytest.fixture
def settings(tmp_path: Path, dist: Path) -> Settings:
    # No example projects: a test starts from an empty database unless it asks for them. One
    # simulation worker, not one per core: each app a test makes starts its workers, and a
    # worker's start (a Python process importing the CPU and the compilers) costs a second.
    return Settings(
        data_dir=tmp_path / "data",
        frontend_dist=dist,
        examples_dir=tmp_path / "no-examples",
        session_workers=1,
    )


@pytest.fixture
def client(settings: Settings) -> Iterator[TestClient]:
    with TestClient(create_app(settings)) as test_client:
        yield test_client

"""The example projects: correct programs whose scenarios pass, imported once on the first start."""

from __future__ import annotations

from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from sqlalchemy import select

from nasaq.api.app import create_app
from nasaq.scenarios.report import scenario_files
from nasaq.scenarios.runner import run_scenario
from nasaq.settings import Settings
from nasaq.storage.models import AppState
from nasaq.workbench.examples import MARKER, example_folders, seed_examples
from nasaq.workbench.names import is_valid_name
from nasaq.workbench.tree import build

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "projects"
FOLDERS = example_folders(EXAMPLES)


def _sources(folder: Path) -> list[tuple[str, str]]:
    return [
        (p.name, p.read_text("utf-8")) for p in sorted(folder.iterdir()) if is_valid_name(p.name)
    ]


def test_there_are_examples_in_stl_and_scl() -> None:
    assert [folder.name for folder in FOLDERS] == [
        "motor-start-stop",
        "tank-level",
        "traffic-light",
    ]
    languages = {b.language for folder in FOLDERS for b in build(_sources(folder)).blocks}
    assert languages == {"stl", "scl"}


@pytest.mark.parametrize("folder", FOLDERS, ids=lambda folder: folder.name)
def test_example_compiles_cleanly_and_its_scenarios_pass(folder: Path) -> None:
    found = build(_sources(folder))
    assert found.diagnostics == []
    assert any(block.kind == "OB" and block.number == 1 for block in found.blocks)
    scenarios = scenario_files([folder])
    assert scenarios, f"{folder.name} has no scenario"
    for path in scenarios:
        result = run_scenario(path)
        failures = [failure.describe() for failure in result.failures]
        assert result.passed, (result.error, result.diagnostics, failures)


def _names(client: TestClient) -> list[str]:
    return [project["name"] for project in client.get("/api/projects").json()]


def test_examples_are_imported_on_the_first_start_only(settings: Settings) -> None:
    settings = settings.model_copy(update={"examples_dir": EXAMPLES})
    with TestClient(create_app(settings)) as client:
        assert _names(client) == ["motor-start-stop", "tank-level", "traffic-light"]
        tank = next(p for p in client.get("/api/projects").json() if p["name"] == "tank-level")
        files = client.get(f"/api/projects/{tank['id']}/files").json()
        assert {f["name"] for f in files} == {name for name, _ in _sources(EXAMPLES / "tank-level")}
        assert client.get(f"/api/projects/{tank['id']}/blocks").json()["diagnostics"] == []
        client.delete(f"/api/projects/{tank['id']}")
    with TestClient(create_app(settings)) as client:
        assert _names(client) == ["motor-start-stop", "traffic-light"]  # deleting is final
        for project in client.get("/api/projects").json():
            client.delete(f"/api/projects/{project['id']}")
    with TestClient(create_app(settings)) as client:
        assert _names(client) == []  # an empty database is not a first start any more


def test_a_database_with_projects_is_marked_not_seeded(settings: Settings) -> None:
    with TestClient(create_app(settings)) as client:  # no examples folder: nothing, no mark
        client.post("/api/projects", json={"name": "Mine"})
        factory = client.app.state.sessions  # type: ignore[attr-defined]
        with factory() as session:
            assert session.scalar(select(AppState)) is None
    settings = settings.model_copy(update={"examples_dir": EXAMPLES})
    with TestClient(create_app(settings)) as client:
        assert _names(client) == ["Mine"]
        factory = client.app.state.sessions  # type: ignore[attr-defined]
        assert seed_examples(factory, EXAMPLES) == []
        with factory() as session:
            marker = session.get(AppState, MARKER)
        assert marker is not None
        assert marker.value.endswith("(none)")

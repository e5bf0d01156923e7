"""A project's CPU family (``profile = S7-1500`` in cpu.properties) reaches everything that
compiles it: the live check of the project's blocks, a session made from the project, and a
session the client asks for with ``profile``."""

from __future__ import annotations

from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

SOURCE = """\
DATA_BLOCK "Data"
STRUCT
  x : LREAL;
  n : UINT;
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK Main
BEGIN
  "Data".x := "Data".x + 0.5;
  "Data".n := "Data".n + 1;
END_ORGANIZATION_BLOCK
"""


def _codes(client: TestClient, project_id: int) -> list[str]:
    found = client.get(f"/api/projects/{project_id}/blocks")
    assert found.status_code == 200, found.text
    return [d["code"] for d in found.json()["diagnostics"]]


def test_the_live_check_compiles_for_the_projects_profile(client: TestClient) -> None:
    project_id = make_project(client, "Classic", {"Main.scl": SOURCE})
    assert _codes(client, project_id) == ["SCL500", "SCL500"]  # LREAL and UINT
    saved = client.put(
        f"/api/projects/{project_id}/files/cpu.properties",
        json={"text": "profile = S7-1500\n"},
    )
    assert saved.status_code in (200, 201), saved.text
    assert _codes(client, project_id) == []


def test_sessions_run_the_s7_1500_profile(client: TestClient) -> None:
    project_id = make_project(
        client, "Modern", {"Main.scl": SOURCE, "cpu.properties": "profile = S7-1500\n"}
    )
    made = client.post(f"/api/projects/{project_id}/sessions")
    assert made.status_code == 201, made.text
    try:
        assert made.json()["profile"] == "S7-1500"
    finally:
        client.delete(f"/api/sessions/{made.json()['id']}")
    sources = [{"name": "Main.scl", "text": SOURCE}]
    asked = client.post("/api/sessions", json={"sources": sources, "profile": "S7-1500"})
    assert asked.status_code == 201, asked.text
    client.delete(f"/api/sessions/{asked.json()['id']}")
    classic = client.post("/api/sessions", json={"sources": sources})
    assert classic.status_code == 422
    assert error_of(classic)["code"] == "MON611"

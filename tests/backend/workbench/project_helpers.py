"""Helpers the workbench tests share: a project with files, made through the API."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient


def make_project(client: TestClient, name: str, files: dict[str, str]) -> int:
    response = client.post("/api/projects", json={"name": name})
    assert response.status_code == 201, response.text
    project_id: int = response.json()["id"]
    for file_name, text in files.items():
        saved = client.put(f"/api/projects/{project_id}/files/{file_name}", json={"text": text})
        assert saved.status_code == 201, saved.text
    return project_id


def error_of(response: Any) -> dict[str, Any]:
    """The catalogue problem of an API error answer."""
    body = response.json()
    assert set(body) == {"error"}, body
    problem: dict[str, Any] = body["error"]
    return problem

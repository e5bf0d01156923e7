from datetime import datetime

import pytest
from fastapi.testclient import TestClient

from nasaq.api.app import create_app
from nasaq.settings import Settings


def _create(client: TestClient, name: str, description: str = "") -> dict[str, object]:
    response = client.post("/api/projects", json={"name": name, "description": description})
    assert response.status_code == 201, response.text
    body: dict[str, object] = response.json()
    return body


def test_a_new_database_has_no_projects(client: TestClient) -> None:
    assert client.get("/api/projects").json() == []


def test_create_returns_the_project_with_location_and_utc_timestamps(client: TestClient) -> None:
    response = client.post("/api/projects", json={"name": "  Tank filling ", "description": "L1"})
    assert response.status_code == 201
    project = response.json()
    assert project["name"] == "Tank filling"
    assert project["description"] == "L1"
    assert response.headers["location"] == f"/api/projects/{project['id']}"
    fetched = client.get(f"/api/projects/{project['id']}").json()
    assert fetched == project
    assert datetime.fromisoformat(fetched["created_at"]).utcoffset() is not None


def test_list_is_sorted_by_name_ignoring_case(client: TestClient) -> None:
    for name in ("conveyor", "Bottle line", "آموزش ۱", "Đèn giao thông"):
        _create(client, name)
    names = [p["name"] for p in client.get("/api/projects").json()]
    assert names == ["Bottle line", "conveyor", "Đèn giao thông", "آموزش ۱"]


def test_names_are_unique_regardless_of_case(client: TestClient) -> None:
    _create(client, "Mixer")
    response = client.post("/api/projects", json={"name": "mixer"})
    assert response.status_code == 409
    error = response.json()["error"]
    assert error["code"] == "API105"
    assert error["key"] == "project_name_taken"
    assert error["params"] == {"name": "mixer"}
    assert error["location"] == ["body", "name"]


@pytest.mark.parametrize(
    ("payload", "field"),
    [
        ({"name": ""}, "name"),
        ({"name": "   "}, "name"),
        ({"name": "a/b"}, "name"),
        ({"name": "x" * 65}, "name"),
        ({}, "name"),
        ({"name": "ok", "description": 5}, "description"),
    ],
)
def test_invalid_payloads_get_api103_with_the_field(
    client: TestClient, payload: dict[str, object], field: str
) -> None:
    response = client.post("/api/projects", json=payload)
    assert response.status_code == 422
    error = response.json()["error"]
    assert error["code"] == "API103"
    assert error["params"]["field"] == field
    assert error["location"][-1] == field


def test_malformed_json_is_a_clear_422(client: TestClient) -> None:
    response = client.post(
        "/api/projects", content=b"{not json", headers={"content-type": "application/json"}
    )
    assert response.status_code == 422
    assert response.json()["error"]["code"] == "API103"


def test_rename_and_describe(client: TestClient) -> None:
    project = _create(client, "Drill")
    response = client.patch(f"/api/projects/{project['id']}", json={"name": "Drill press"})
    assert response.status_code == 200
    assert response.json()["name"] == "Drill press"
    response = client.patch(f"/api/projects/{project['id']}", json={"description": "Lesson 4"})
    assert response.json()["description"] == "Lesson 4"
    assert response.json()["name"] == "Drill press"


def test_rename_to_a_taken_name_is_refused(client: TestClient) -> None:
    _create(client, "Heater")
    other = _create(client, "Silo")
    response = client.patch(f"/api/projects/{other['id']}", json={"name": "HEATER"})
    assert response.status_code == 409
    assert client.get(f"/api/projects/{other['id']}").json()["name"] == "Silo"


def test_delete_then_missing_gives_api104(client: TestClient) -> None:
    project = _create(client, "Garage door")
    assert client.delete(f"/api/projects/{project['id']}").status_code == 204
    response = client.get(f"/api/projects/{project['id']}")
    assert response.status_code == 404
    assert response.json()["error"]["code"] == "API104"
    assert response.json()["error"]["message"] == f"Project {project['id']} does not exist."
    assert client.delete(f"/api/projects/{project['id']}").status_code == 404


def test_projects_survive_a_server_restart(settings: Settings) -> None:
    with TestClient(create_app(settings)) as first:
        _create(first, "Traffic light")
    with TestClient(create_app(settings)) as second:
        assert [p["name"] for p in second.get("/api/projects").json()] == ["Traffic light"]

"""``/api/projects/{id}/files``: autosave, stale saves, rename, duplicate, delete, errors."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient
from project_helpers import error_of, make_project
from sqlalchemy import func, select

from nasaq.api import files as files_api
from nasaq.storage.models import ProjectFile
from nasaq.workbench.names import MAX_TEXT_CHARS

OB1 = "ORGANIZATION_BLOCK OB 1\nBEGIN\n  A I 0.0;\n  = Q 4.0;\nEND_ORGANIZATION_BLOCK\n"


def _files(client: TestClient, project_id: int) -> list[dict[str, Any]]:
    response = client.get(f"/api/projects/{project_id}/files")
    assert response.status_code == 200
    found: list[dict[str, Any]] = response.json()
    return found


def test_put_creates_then_lists_and_reads_the_file(client: TestClient) -> None:
    project_id = make_project(client, "Conveyor", {})
    response = client.put(f"/api/projects/{project_id}/files/OB1.awl", json={"text": OB1})
    assert response.status_code == 201
    assert response.headers["location"] == f"/api/projects/{project_id}/files/OB1.awl"
    saved = response.json()
    assert (saved["name"], saved["language"], saved["size"], saved["version"]) == (
        "OB1.awl",
        "stl",
        len(OB1),
        1,
    )
    assert "text" not in saved  # an autosave does not echo megabytes back
    client.put(f"/api/projects/{project_id}/files/Motor.scl", json={"text": "// later\n"})
    client.put(f"/api/projects/{project_id}/files/symbols.sdf", json={"text": ""})
    listed = _files(client, project_id)
    assert [(f["name"], f["language"]) for f in listed] == [
        ("Motor.scl", "scl"),
        ("OB1.awl", "stl"),
        ("symbols.sdf", "symbols"),
    ]
    one = client.get(f"/api/projects/{project_id}/files/OB1.awl").json()
    assert one["text"] == OB1
    assert one["version"] == 1


def test_autosave_replaces_and_counts_versions(client: TestClient) -> None:
    project_id = make_project(client, "Mixer", {"OB1.awl": OB1})
    before = client.get(f"/api/projects/{project_id}").json()["updated_at"]
    url = f"/api/projects/{project_id}/files/OB1.awl"
    response = client.put(url, json={"text": OB1 + "// v2\n", "base_version": 1})
    assert response.status_code == 200
    assert response.json()["version"] == 2
    assert client.get(url).json()["text"].endswith("// v2\n")
    assert client.get(f"/api/projects/{project_id}").json()["updated_at"] > before
    # The same text again changes nothing, not even the version.
    again = client.put(url, json={"text": OB1 + "// v2\n", "base_version": 2})
    assert again.json()["version"] == 2


def test_a_stale_tab_cannot_overwrite_a_newer_save(client: TestClient) -> None:
    project_id = make_project(client, "Silo", {"OB1.awl": OB1})
    url = f"/api/projects/{project_id}/files/OB1.awl"
    assert client.put(url, json={"text": "// tab A\n", "base_version": 1}).status_code == 200
    response = client.put(url, json={"text": "// tab B\n", "base_version": 1})
    assert response.status_code == 409
    error = error_of(response)
    assert error["code"] == "API111"
    assert error["key"] == "file_changed"
    assert error["params"] == {"name": "OB1.awl", "current_version": 2}
    assert client.get(url).json()["text"] == "// tab A\n"
    # A save without base_version is unconditional (e.g. "overwrite anyway").
    assert client.put(url, json={"text": "// tab B\n"}).json()["version"] == 3


def test_a_save_to_a_file_deleted_or_renamed_elsewhere_is_stale(client: TestClient) -> None:
    project_id = make_project(client, "Press", {"OB1.awl": OB1})
    url = f"/api/projects/{project_id}/files/OB1.awl"
    client.patch(url, json={"name": "Main.awl"})
    response = client.put(url, json={"text": OB1, "base_version": 1})
    assert response.status_code == 409
    assert error_of(response)["params"] == {"name": "OB1.awl", "current_version": None}
    assert [f["name"] for f in _files(client, project_id)] == ["Main.awl"]


def test_rename_keeps_the_text_and_refuses_a_taken_name(client: TestClient) -> None:
    project_id = make_project(client, "Lift", {"OB1.awl": OB1, "FC1.awl": "// fc\n"})
    base = f"/api/projects/{project_id}/files"
    response = client.patch(f"{base}/FC1.awl", json={"name": "Door.awl"})
    assert response.status_code == 200
    assert response.json()["name"] == "Door.awl"
    assert client.get(f"{base}/Door.awl").json()["text"] == "// fc\n"
    assert error_of(client.get(f"{base}/FC1.awl"))["code"] == "API107"
    taken = client.patch(f"{base}/Door.awl", json={"name": "ob1.AWL"})
    assert taken.status_code == 409
    error = error_of(taken)
    assert (error["code"], error["params"], error["location"]) == (
        "API108",
        {"name": "ob1.AWL"},
        ["body", "name"],
    )
    # Changing only the letter case of its own name is allowed.
    assert client.patch(f"{base}/OB1.awl", json={"name": "ob1.awl"}).status_code == 200


def test_a_new_file_may_not_differ_from_another_only_by_case(client: TestClient) -> None:
    project_id = make_project(client, "Boiler", {"OB1.awl": OB1})
    response = client.put(f"/api/projects/{project_id}/files/ob1.awl", json={"text": ""})
    assert response.status_code == 409
    assert error_of(response)["code"] == "API108"


def test_duplicate_copies_under_a_new_name(client: TestClient) -> None:
    project_id = make_project(client, "Crane", {"OB1.awl": OB1})
    base = f"/api/projects/{project_id}/files"
    response = client.post(f"{base}/OB1.awl/duplicate", json={"name": "OB1 copy.awl"})
    assert response.status_code == 201
    assert response.json()["version"] == 1
    assert response.headers["location"] == f"{base}/OB1%20copy.awl"
    assert client.get(f"{base}/OB1 copy.awl").json()["text"] == OB1
    again = client.post(f"{base}/OB1.awl/duplicate", json={"name": "OB1 copy.awl"})
    assert again.status_code == 409
    assert error_of(again)["code"] == "API108"


def test_delete_then_the_file_is_gone(client: TestClient) -> None:
    project_id = make_project(client, "Fan", {"OB1.awl": OB1})
    url = f"/api/projects/{project_id}/files/OB1.awl"
    assert client.delete(url).status_code == 204
    assert error_of(client.get(url))["code"] == "API107"
    assert client.delete(url).status_code == 404
    assert _files(client, project_id) == []


def test_unknown_project_or_file(client: TestClient) -> None:
    for response in (
        client.get("/api/projects/999/files"),
        client.get("/api/projects/999/files/OB1.awl"),
        client.put("/api/projects/999/files/OB1.awl", json={"text": ""}),
        client.delete("/api/projects/999/files/OB1.awl"),
    ):
        assert response.status_code == 404
        assert error_of(response)["code"] == "API104"
    project_id = make_project(client, "Pump", {})
    response = client.get(f"/api/projects/{project_id}/files/OB9.awl")
    assert response.status_code == 404
    error = error_of(response)
    assert error["code"] == "API107"
    assert error["message"] == f"Project {project_id} has no file 'OB9.awl'."
    for response in (
        client.patch(f"/api/projects/{project_id}/files/OB9.awl", json={"name": "X.awl"}),
        client.post(f"/api/projects/{project_id}/files/OB9.awl/duplicate", json={"name": "X.awl"}),
    ):
        assert error_of(response)["code"] == "API107"


@pytest.mark.parametrize(
    "name",
    [
        "OB1.txt",
        "OB1",
        ".awl",
        ".hidden.awl",
        " OB1.awl",
        "OB1.awl ",
        "a/b.awl",
        "a\\b.awl",
        "a:b.awl",
        'say"hi".scl',
        "CON.awl",
        "x" * 125 + ".awl",
        "",
    ],
)
def test_bad_names_are_refused_with_api109(client: TestClient, name: str) -> None:
    project_id = make_project(client, "Kiln", {"OB1.awl": OB1})
    response = client.patch(f"/api/projects/{project_id}/files/OB1.awl", json={"name": name})
    assert response.status_code == 422
    error = error_of(response)
    assert (error["code"], error["key"], error["location"]) == (
        "API109",
        "file_name_invalid",
        ["body", "name"],
    )
    assert error["params"] == {"name": name, "limit": 128}


def test_bad_name_in_the_path_and_names_at_the_limit(client: TestClient) -> None:
    project_id = make_project(client, "Dryer", {})
    base = f"/api/projects/{project_id}/files"
    response = client.put(f"{base}/notes.txt", json={"text": ""})
    assert error_of(response)["code"] == "API109"
    assert error_of(response)["location"] == ["path", "name"]
    longest = "x" * 124 + ".scl"
    for name in (longest, "Đèn giao thông.awl", "موتور.scl", "SYMBOLS.SEQ", "plc.STL"):
        response = client.put(f"{base}/{name}", json={"text": ""})
        assert response.status_code == 201, name
        assert client.get(response.headers["location"]).json()["name"] == name


def test_too_large_a_text_is_413(client: TestClient) -> None:
    project_id = make_project(client, "Hopper", {})
    url = f"/api/projects/{project_id}/files/Big.awl"
    response = client.put(url, json={"text": "x" * (MAX_TEXT_CHARS + 1)})
    assert response.status_code == 413
    error = error_of(response)
    assert error["code"] == "API110"
    assert error["params"] == {"name": "Big.awl", "size_kb": 4096, "limit_kb": 4096}
    assert client.put(url, json={"text": "x" * MAX_TEXT_CHARS}).status_code == 201


def test_the_number_of_files_is_limited(
    client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(files_api, "MAX_FILES", 2)
    project_id = make_project(client, "Oven", {"A.awl": "", "B.awl": ""})
    base = f"/api/projects/{project_id}/files"
    for response in (
        client.put(f"{base}/C.awl", json={"text": ""}),
        client.post(f"{base}/A.awl/duplicate", json={"name": "C.awl"}),
    ):
        assert response.status_code == 422
        assert error_of(response)["params"] == {"limit": 2}
    assert client.put(f"{base}/A.awl", json={"text": "// still saved"}).status_code == 200


def test_deleting_a_project_deletes_its_files(client: TestClient) -> None:
    project_id = make_project(client, "Chiller", {"OB1.awl": OB1, "symbols.sdf": ""})
    assert client.delete(f"/api/projects/{project_id}").status_code == 204
    factory = client.app.state.sessions  # type: ignore[attr-defined]
    with factory() as session:
        count = session.scalar(select(func.count()).select_from(ProjectFile))
    assert count == 0

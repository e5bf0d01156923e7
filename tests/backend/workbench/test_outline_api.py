"""``GET /api/projects/{id}/outline``."""

from __future__ import annotations

from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

SYMBOLS = '"Settings","DB 4","DB 4","limits"\n"Lamp","Q 4.0","BOOL","the lamp"\n'
SETTINGS = """\
DATA_BLOCK "Settings"
  STRUCT
   Limit : INT := 5;  // upper limit
  END_STRUCT ;
BEGIN
END_DATA_BLOCK
"""


def test_outline_of_a_project(client: TestClient) -> None:
    project = make_project(client, "outline", {"symbols.sdf": SYMBOLS, "Settings.awl": SETTINGS})
    response = client.get(f"/api/projects/{project}/outline")
    assert response.status_code == 200, response.text
    body = response.json()
    assert [(s["name"], s["address"], s["line"]) for s in body["symbols"]] == [
        ("Settings", "DB 4", 1),
        ("Lamp", "Q 4.0", 2),
    ]
    [block] = body["blocks"]
    assert (block["kind"], block["number"], block["name"], block["file"], block["line"]) == (
        "DB",
        4,
        "Settings",
        "Settings.awl",
        1,
    )
    [member] = block["members"]
    assert (
        member["path"],
        member["type"],
        member["section"],
        member["comment"],
        member["line"],
    ) == (
        "Limit",
        "INT",
        "DATA",
        "upper limit",
        3,
    )


def test_outline_follows_a_saved_file(client: TestClient) -> None:
    project = make_project(client, "outline2", {"Settings.awl": SETTINGS})
    assert client.get(f"/api/projects/{project}/outline").json()["symbols"] == []
    client.put(f"/api/projects/{project}/files/symbols.sdf", json={"text": SYMBOLS})
    assert len(client.get(f"/api/projects/{project}/outline").json()["symbols"]) == 2


def test_outline_of_an_unknown_project(client: TestClient) -> None:
    response = client.get("/api/projects/999/outline")
    assert response.status_code == 404
    assert error_of(response)["code"] == "API104"

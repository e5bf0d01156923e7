"""``POST /api/projects/{id}/files/{name}/convert``: an STL source of code blocks becomes a LAD or
FBD source in one step; what would lose something is refused and leaves the project as it was."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

from nasaq.lang.lad.convert import convert

MOTOR = """\
FUNCTION FC 5 : VOID
TITLE = Motor
VAR_INPUT
  Go : BOOL;
END_VAR
BEGIN
NETWORK
TITLE = Self-holding
      A(
      O     #Go
      O     Q 4.0
      )
      AN    I 0.1
      =     Q 4.0
NETWORK
TITLE = Exclusive OR
      A     I 0.3
      X     I 0.4
      =     Q 4.2
END_FUNCTION

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      CALL  FC 5 (Go := I 0.2)
END_ORGANIZATION_BLOCK
"""

SYMBOLS = '"Lamp","Q 4.0","BOOL","the lamp"\n'
DB = "DATA_BLOCK DB 1\n  STRUCT\n    x : INT;\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"


def _names(client: TestClient, project_id: int) -> list[str]:
    return [f["name"] for f in client.get(f"/api/projects/{project_id}/files").json()]


def _convert(client: TestClient, project_id: int, name: str, to: Any) -> Any:
    return client.post(f"/api/projects/{project_id}/files/{name}/convert", json={"to": to})


@pytest.mark.parametrize(("to", "language"), [("lad", "LAD"), ("fbd", "FBD")])
def test_an_stl_source_becomes_a_lad_or_fbd_source(
    client: TestClient, to: str, language: str
) -> None:
    project_id = make_project(client, f"Motor {to}", {"Motor.awl": MOTOR, "symbols.sdf": SYMBOLS})
    response = _convert(client, project_id, "Motor.awl", to)
    assert response.status_code == 201, response.text
    info = response.json()
    assert (info["name"], info["language"], info["version"]) == (f"Motor.{to}", to, 1)
    assert response.headers["location"] == f"/api/projects/{project_id}/files/Motor.{to}"
    assert _names(client, project_id) == [f"Motor.{to}", "symbols.sdf"]
    text = client.get(response.headers["location"]).json()["text"]
    assert text == convert("Motor.awl", MOTOR, to).text
    assert info["size"] == len(text)
    assert ("LANGUAGE FBD" in text) is (language == "FBD")
    assert "STL REASON LAD305" in text  # the XOR network stays STL inside the block
    # The project still compiles, now from the LAD source.
    build = client.get(f"/api/projects/{project_id}/blocks").json()
    assert build["diagnostics"] == []
    assert {(b["kind"], b["language"]) for b in build["blocks"]} == {("FC", to), ("OB", to)}


def test_an_stl_suffix_in_capitals_and_the_stl_suffix(client: TestClient) -> None:
    project_id = make_project(client, "Suffixes", {"A.STL": MOTOR})
    response = _convert(client, project_id, "A.STL", "lad")
    assert response.status_code == 201, response.text
    assert _names(client, project_id) == ["A.lad"]


@pytest.mark.parametrize(
    ("files", "name", "code", "params"),
    [
        ({"Motor.scl": "FUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION\n"}, "Motor.scl", "API130", {}),
        ({"Motor.lad": "FUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION\n"}, "Motor.lad", "API130", {}),
        ({"Motor.awl": MOTOR + DB}, "Motor.awl", "API131", {"block": "DATA_BLOCK DB 1"}),
        (
            {"Motor.awl": "TYPE UDT 1\n  STRUCT\n    x : INT;\n  END_STRUCT;\nEND_TYPE\n" + MOTOR},
            "Motor.awl",
            "API131",
            {"block": "TYPE UDT 1"},
        ),
        (
            {"Motor.awl": MOTOR.replace("AN    I 0.1", "AN    I 0.1 +")},
            "Motor.awl",
            "API132",
            {"line": 13, "problem": "STL101"},
        ),
    ],
)
def test_what_would_lose_something_is_refused(
    client: TestClient, files: dict[str, str], name: str, code: str, params: dict[str, Any]
) -> None:
    project_id = make_project(client, f"Refused {code} {name}", files)
    response = _convert(client, project_id, name, "lad")
    assert response.status_code == 422, response.text
    error = error_of(response)
    assert error["code"] == code
    assert error["location"] == ["path", "name"]
    assert error["params"]["name"] == name
    assert params.items() <= error["params"].items()
    assert _names(client, project_id) == sorted(files)  # nothing changed


def test_a_taken_name_is_409_and_nothing_changes(client: TestClient) -> None:
    files = {"Motor.awl": MOTOR, "motor.LAD": "// mine\n"}
    project_id = make_project(client, "Taken", files)
    response = _convert(client, project_id, "Motor.awl", "lad")
    assert response.status_code == 409
    assert error_of(response)["code"] == "API108"
    assert error_of(response)["params"] == {"name": "Motor.lad"}
    assert sorted(_names(client, project_id)) == sorted(files)
    assert client.get(f"/api/projects/{project_id}/files/motor.LAD").json()["text"] == "// mine\n"
    assert _convert(client, project_id, "Motor.awl", "fbd").status_code == 201


def test_no_such_project_or_file_and_bad_requests(client: TestClient) -> None:
    assert error_of(_convert(client, 999, "Motor.awl", "lad"))["code"] == "API104"
    project_id = make_project(client, "Missing", {"Motor.awl": MOTOR})
    missing = _convert(client, project_id, "Pump.awl", "lad")
    assert missing.status_code == 404
    assert error_of(missing)["code"] == "API107"
    for to in ("stl", "ladder", None, 5):
        response = _convert(client, project_id, "Motor.awl", to)
        assert response.status_code == 422, to
        assert error_of(response)["code"] == "API103"
    assert _names(client, project_id) == ["Motor.awl"]

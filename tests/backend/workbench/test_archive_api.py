"""Export a project as a zip of sources and import one: the round trip, and every refusal."""

from __future__ import annotations

import io
import zipfile
from typing import Any

import pytest
from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

from nasaq.api import archive as archive_api
from nasaq.workbench import archive

OB1 = "ORGANIZATION_BLOCK OB 1\nBEGIN\n  A I 0.0;\n  = Q 4.0;\nEND_ORGANIZATION_BLOCK\n"
SCL = "FUNCTION FC 2 : INT\nBEGIN\n  FC2 := 7; // ضریب\nEND_FUNCTION\n"


def _zip(entries: dict[str, bytes | str]) -> bytes:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as packed:
        for name, data in entries.items():
            packed.writestr(name, data)
    return buffer.getvalue()


def _import(client: TestClient, data: bytes, name: str | None = None) -> Any:
    params = {"name": name} if name is not None else {}
    headers = {"content-type": "application/zip"}
    return client.post("/api/projects/import", content=data, params=params, headers=headers)


def _texts(client: TestClient, project_id: int) -> dict[str, str]:
    names = [f["name"] for f in client.get(f"/api/projects/{project_id}/files").json()]
    return {n: client.get(f"/api/projects/{project_id}/files/{n}").json()["text"] for n in names}


def test_export_is_one_folder_named_after_the_project(client: TestClient) -> None:
    project_id = make_project(client, "Bottle line", {"OB1.awl": OB1, "Filler.scl": SCL})
    response = client.get(f"/api/projects/{project_id}/export.zip")
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/zip"
    assert 'filename="Bottle line.zip"' in response.headers["content-disposition"]
    with zipfile.ZipFile(io.BytesIO(response.content)) as packed:
        assert sorted(packed.namelist()) == ["Bottle line/Filler.scl", "Bottle line/OB1.awl"]
        assert packed.read("Bottle line/Filler.scl").decode("utf-8") == SCL


def test_export_of_a_non_latin_name_and_of_an_unknown_project(client: TestClient) -> None:
    project_id = make_project(client, "خط تعبئة", {"OB1.awl": OB1})
    response = client.get(f"/api/projects/{project_id}/export.zip")
    disposition = response.headers["content-disposition"]
    assert "filename*=UTF-8''%D8%AE%D8%B7%20" in disposition
    with zipfile.ZipFile(io.BytesIO(response.content)) as packed:
        assert packed.namelist() == ["خط تعبئة/OB1.awl"]
    assert error_of(client.get("/api/projects/999/export.zip"))["code"] == "API104"


def test_export_then_import_gives_the_same_files(client: TestClient) -> None:
    files = {"OB1.awl": OB1, "Filler.scl": SCL, "symbols.sdf": '"Start","I 0.0","BOOL",""\n'}
    project_id = make_project(client, "Drill", files)
    exported = client.get(f"/api/projects/{project_id}/export.zip").content
    response = _import(client, exported, name="Drill 2")
    assert response.status_code == 201, response.text
    body = response.json()
    assert body["project"]["name"] == "Drill 2"
    assert response.headers["location"] == f"/api/projects/{body['project']['id']}"
    assert sorted(body["files"]) == sorted(files)
    assert body["skipped"] == []
    assert _texts(client, body["project"]["id"]) == files
    assert client.get(f"/api/projects/{body['project']['id']}/blocks").json()["diagnostics"] == []


def test_the_name_comes_from_the_top_folder_and_must_be_free(client: TestClient) -> None:
    data = _zip({"Heater/OB1.awl": OB1, "Heater/README.md": "# notes", "Heater/": ""})
    response = _import(client, data)
    assert response.status_code == 201
    assert response.json()["project"]["name"] == "Heater"
    assert response.json()["skipped"] == ["Heater/README.md"]
    again = _import(client, data)
    assert again.status_code == 409
    assert (error_of(again)["code"], error_of(again)["params"]) == ("API105", {"name": "Heater"})


def test_without_one_top_folder_a_name_is_needed(client: TestClient) -> None:
    data = _zip({"OB1.awl": OB1, "lib/FC2.scl": SCL})
    response = _import(client, data)
    assert (response.status_code, error_of(response)["code"]) == (422, "API115")
    named = _import(client, data, name="Loose")
    assert named.status_code == 201
    assert sorted(named.json()["files"]) == ["FC2.scl", "OB1.awl"]  # sub-folders flattened
    invalid = _import(client, data, name="a/b")
    assert error_of(invalid)["code"] == "API103"


def test_macos_junk_does_not_hide_the_top_folder(client: TestClient) -> None:
    data = _zip({"Kiln/OB1.awl": OB1, "__MACOSX/Kiln/._OB1.awl": b"\x00\x05", "Kiln/.DS_Store": ""})
    response = _import(client, data)
    assert response.status_code == 201
    assert (response.json()["project"]["name"], response.json()["skipped"]) == ("Kiln", [])


def test_windows_1252_sources_and_byte_order_marks_are_decoded(client: TestClient) -> None:
    data = _zip(
        {
            "P/OB1.awl": "// Türöffner\n".encode("cp1252") + OB1.encode(),
            "P/FC2.scl": b"\xef\xbb\xbf" + SCL.encode("utf-8"),
        }
    )
    project_id = _import(client, data).json()["project"]["id"]
    texts = _texts(client, project_id)
    assert texts["OB1.awl"].startswith("// Türöffner\n")
    assert texts["FC2.scl"] == SCL


@pytest.mark.parametrize(
    ("data", "status", "code"),
    [
        (b"this is not a zip", 422, "API112"),
        (b"PK\x03\x04" + b"\x00" * 40, 422, "API112"),
        (_zip({"P/../../etc/OB1.awl": OB1}), 422, "API113"),
        (_zip({"/abs/OB1.awl": OB1}), 422, "API113"),
        (_zip({"..\\OB1.awl": OB1}), 422, "API113"),
        (_zip({"C:/OB1.awl": OB1}), 422, "API113"),
        (_zip({"P/README.md": "hello", "P/test.yaml": "steps: []"}), 422, "API116"),
        (_zip({"P/OB1.awl": OB1, "P/sub/ob1.AWL": OB1}), 409, "API108"),
        (b"", 422, "API112"),
    ],
)
def test_bad_archives_are_refused(client: TestClient, data: bytes, status: int, code: str) -> None:
    response = _import(client, data, name="Refused")
    assert response.status_code == status, response.text
    assert error_of(response)["code"] == code
    assert client.get("/api/projects").json() == []


def test_a_corrupt_member_is_refused(client: TestClient) -> None:
    data = bytearray(_zip({"P/OB1.awl": OB1 * 50}))
    start = data.index(b"OB1.awl") + len("OB1.awl")  # the compressed data follows the name
    data[start + 5 : start + 40] = b"\xff" * 35
    response = _import(client, bytes(data))
    assert (response.status_code, error_of(response)["code"]) == (422, "API112")


def test_zip_bombs_stop_at_the_limits(client: TestClient, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(archive, "MAX_UNPACKED_BYTES", 1024 * 1024)
    bomb = _zip({"P/OB1.awl": b" " * (2 * 1024 * 1024)})  # 2 MB of spaces pack into 2 KB
    assert len(bomb) < 10_000
    response = _import(client, bomb)
    assert (response.status_code, error_of(response)["code"]) == (413, "API114")
    assert error_of(response)["params"]["limit_mb"] == 1
    monkeypatch.setattr(archive, "MAX_ENTRIES", 3)
    many = _zip({f"P/FC{n}.awl": OB1 for n in range(4)})
    assert error_of(_import(client, many))["code"] == "API114"


def test_the_unpacked_size_is_counted_while_reading(monkeypatch: pytest.MonkeyPatch) -> None:
    """Headers may lie: what is read is counted too, across files."""
    monkeypatch.setattr(archive, "MAX_UNPACKED_BYTES", 3000)
    data = _zip({"P/A.awl": "x" * 2000, "P/B.awl": "y" * 2000})
    reader = archive._Reader(zipfile.ZipFile(io.BytesIO(data)))
    first, second = reader.archive.infolist()
    reader.read(first)
    with pytest.raises(archive.ArchiveError) as caught:
        reader.read(second)
    assert caught.value.code == "API114"


def test_too_large_uploads_and_sources(client: TestClient, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(archive, "MAX_TEXT_CHARS", 100)
    response = _import(client, _zip({"P/OB1.awl": OB1 * 3}))
    assert (response.status_code, error_of(response)["code"]) == (413, "API110")
    monkeypatch.setattr(archive_api, "MAX_UPLOAD_BYTES", 100)
    response = _import(client, _zip({"P/OB1.awl": OB1}) + b"\x00" * 200)
    assert (response.status_code, error_of(response)["code"]) == (413, "API114")


def test_too_many_sources(client: TestClient, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(archive, "MAX_FILES", 2)
    response = _import(client, _zip({f"P/FC{n}.awl": OB1 for n in range(3)}))
    assert (response.status_code, error_of(response)["params"]) == (422, {"limit": 2})

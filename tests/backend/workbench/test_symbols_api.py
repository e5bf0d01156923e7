"""``/symbols/{file}`` (rows, save, export, import) and ``/blocks/{block}/members``."""

from __future__ import annotations

from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

SDF = '"Start","I 0.0","BOOL","start button"\n"Tank","DB 1","DB 1","settings"\n'
DB1 = """DATA_BLOCK "Tank"
  STRUCT
   Low : REAL := 2.000000e+01;  // start below
   Count : INT;
  END_STRUCT ;
BEGIN
   Count := 3;
END_DATA_BLOCK
"""


def _project(client: TestClient) -> int:
    return make_project(client, "Symbols", {"symbols.sdf": SDF, "Tank.awl": DB1})


def test_get_returns_rows_problems_and_version(client: TestClient) -> None:
    project_id = _project(client)
    body = client.get(f"/api/projects/{project_id}/symbols/symbols.sdf").json()
    assert body["format"] == "sdf"
    assert body["version"] == 1
    assert body["rows"][0] == {
        "name": "Start",
        "address": "I 0.0",
        "type": "BOOL",
        "comment": "start button",
    }
    assert body["problems"] == []


def test_put_writes_the_file_in_its_format_and_checks_the_version(client: TestClient) -> None:
    project_id = _project(client)
    url = f"/api/projects/{project_id}/symbols/symbols.sdf"
    rows = [
        {"name": "Start", "address": "I 0.0", "type": "BOOL", "comment": ""},
        {"name": "start", "address": "X 1", "type": "BOOL", "comment": ""},
    ]
    saved = client.put(url, json={"rows": rows, "base_version": 1})
    assert saved.status_code == 200
    assert saved.json()["version"] == 2
    codes = [(p["row"], p["field"], p["problem"]["code"]) for p in saved.json()["problems"]]
    assert codes == [(1, "address", "API120"), (1, "name", "API121")]
    text = client.get(f"/api/projects/{project_id}/files/symbols.sdf").json()["text"]
    assert text.startswith('"Start                   ","I 0.0       ","BOOL      "')
    stale = client.put(url, json={"rows": rows, "base_version": 1})
    assert stale.status_code == 409
    assert error_of(stale)["code"] == "API111"


def test_put_refuses_what_an_asc_cannot_hold(client: TestClient) -> None:
    project_id = make_project(client, "Asc", {"s.asc": "126,A                       I 0.0\n"})
    rows = [{"name": "N" * 30, "address": "I 0.0", "type": "BOOL", "comment": ""}]
    refused = client.put(f"/api/projects/{project_id}/symbols/s.asc", json={"rows": rows})
    assert refused.status_code == 422
    assert error_of(refused)["code"] == "API124"


def test_not_a_symbol_table_or_missing(client: TestClient) -> None:
    project_id = _project(client)
    assert error_of(client.get(f"/api/projects/{project_id}/symbols/Tank.awl"))["code"] == "API127"
    missing = client.get(f"/api/projects/{project_id}/symbols/other.sdf")
    assert missing.status_code == 404
    assert error_of(missing)["code"] == "API107"


def test_export_downloads_step7_bytes(client: TestClient) -> None:
    project_id = _project(client)
    url = f"/api/projects/{project_id}/symbols/symbols.sdf/export"
    response = client.get(url, params={"format": "asc"})
    assert response.status_code == 200
    assert response.headers["content-type"] == "text/plain; charset=windows-1252"
    assert 'filename="symbols.asc"' in response.headers["content-disposition"]
    lines = response.content.split(b"\r\n")
    assert lines[0].startswith(b"126,Start" + b" " * 19 + b"I 0.0")
    assert lines[-1] == b""
    csv = client.get(url, params={"format": "csv"})
    assert csv.headers["content-type"].startswith("text/csv")
    assert csv.content.startswith(b"name,address,type,comment\r\nStart,I 0.0,BOOL,start button")
    assert client.get(url, params={"format": "xls"}).status_code == 422


def test_export_refuses_characters_windows_1252_lacks(client: TestClient) -> None:
    project_id = make_project(client, "Arabic", {"s.csv": "مضخة,Q 4.0,BOOL,\n"})
    url = f"/api/projects/{project_id}/symbols/s.csv/export"
    refused = client.get(url, params={"format": "sdf"})
    assert refused.status_code == 422
    assert error_of(refused)["code"] == "API125"
    assert error_of(refused)["params"]["char"] == "م"


def test_import_replaces_or_merges(client: TestClient) -> None:
    project_id = _project(client)
    url = f"/api/projects/{project_id}/symbols/symbols.sdf/import"
    upload = "126,Stop                    I 0.1       BOOL      stop\r\n".encode("cp1252")
    merged = client.post(url, params={"name": "up.asc", "mode": "merge"}, content=upload)
    assert merged.status_code == 200
    assert [row["name"] for row in merged.json()["rows"]] == ["Start", "Tank", "Stop"]
    seq = b"126\tStart\tI 1.0\tBOOL\tmoved\n"
    replaced = client.post(url, params={"name": "up.seq", "base_version": 2}, content=seq)
    assert replaced.status_code == 200
    assert replaced.json()["rows"] == [
        {"name": "Start", "address": "I 1.0", "type": "BOOL", "comment": "moved"}
    ]
    assert replaced.json()["version"] == 3
    wrong = client.post(url, params={"name": "up.txt"}, content=b"x")
    assert error_of(wrong)["code"] == "API127"
    empty = client.post(url, params={"name": "up.csv"}, content=b"\n\n")
    assert error_of(empty)["code"] == "API126"
    binary = client.post(url, params={"name": "up.csv"}, content=b"\x00\x01")
    assert error_of(binary)["code"] == "API126"


def test_db_members_by_number_or_symbol(client: TestClient) -> None:
    project_id = _project(client)
    for block in ("DB1", "DB 1", "Tank", '"Tank"'):
        response = client.get(f"/api/projects/{project_id}/blocks/{block}/members")
        assert response.status_code == 200, block
        body = response.json()
        assert (body["kind"], body["number"], body["name"]) == ("DB", 1, "Tank")
        assert (body["file"], body["line"], body["instance_of"]) == ("Tank.awl", 1, None)
        count = body["members"][1]
        assert (count["path"], count["offset"], count["actual"], count["line"]) == (
            "Count",
            "4.0",
            "3",
            4,
        )
    missing = client.get(f"/api/projects/{project_id}/blocks/DB7/members")
    assert missing.status_code == 404
    assert error_of(missing)["code"] == "API128"
    assert error_of(client.get(f"/api/projects/{project_id}/blocks/Start/members"))["code"] == (
        "API128"
    )

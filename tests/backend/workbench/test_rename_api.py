"""Rename through the API (preview, apply, undo) and the cross-reference API, on the examples:
every file changes together, refusals change nothing, undo never overwrites newer work."""

from __future__ import annotations

from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

from nasaq.scenarios.runner import run_scenario
from nasaq.workbench.names import language_of
from nasaq.workbench.rename import plan_rename

ROOT = Path(__file__).resolve().parents[3]
MOTOR = ROOT / "examples" / "projects" / "motor-start-stop"
TANK = ROOT / "examples" / "projects" / "tank-level"
LAD = ROOT / "examples" / "lad"
WATCH = '// watch table\n"Motor"   BOOL\n"Start"  BOOL  // "Motor" in a comment stays\n'


def folder_files(folder: Path, *names: str) -> dict[str, str]:
    chosen = names or tuple(
        p.name for p in folder.iterdir() if p.is_file() and language_of(p.name) is not None
    )
    return {name: (folder / name).read_text("utf-8") for name in chosen}


def texts(client: TestClient, project: int) -> dict[str, str]:
    listed = client.get(f"/api/projects/{project}/files").json()
    return {
        item["name"]: client.get(f"/api/projects/{project}/files/{item['name']}").json()["text"]
        for item in listed
    }


def test_rename_motor_to_pump_everywhere_then_undo(client: TestClient, tmp_path: Path) -> None:
    files = folder_files(MOTOR)
    project = make_project(client, "motor", files)
    preview = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": '"Motor"', "new_name": "Pump"},
    )
    assert preview.status_code == 200, preview.text
    body = preview.json()
    assert (body["kind"], body["old_name"], body["new_name"]) == (
        "symbol",
        "Motor",
        "Pump",
    )
    assert [(c["file"], c["line"]) for c in body["changes"]] == [
        ("OB1.awl", 15),
        ("OB1.awl", 19),
        ("OB1.awl", 22),
        ("symbols.sdf", 4),
    ]
    assert texts(client, project) == files  # a preview writes nothing

    applied = client.post(
        f"/api/projects/{project}/rename",
        json={"target": '"Motor"', "new_name": "Pump", "files": body["files"]},
    )
    assert applied.status_code == 200, applied.text
    after = texts(client, project)
    assert '"Motor"' not in after["OB1.awl"]
    assert after["OB1.awl"].count('"Pump"') == 3
    assert after["symbols.sdf"].splitlines()[3].startswith('"Pump","Q 4.0"')
    # The renamed program still passes the example's scenario.
    for name, text in after.items():
        (tmp_path / name).write_text(text, "utf-8")
    (tmp_path / "motor.yaml").write_text((MOTOR / "motor.yaml").read_text("utf-8"), "utf-8")
    assert run_scenario(tmp_path / "motor.yaml").passed
    xref = client.get(f"/api/projects/{project}/xref", params={"target": '"Pump"'}).json()
    assert [e["line"] for e in xref["entries"]] == [15, 19, 22]

    undone = client.post(
        f"/api/projects/{project}/rename/undo", json={"files": applied.json()["undo"]}
    )
    assert undone.status_code == 200, undone.text
    assert texts(client, project) == files


def test_refusals_change_nothing(client: TestClient) -> None:
    files = folder_files(MOTOR)
    project = make_project(client, "motor", files)
    for new_name, code in [
        ("Start", "XRF705"),
        ("start", "XRF705"),
        ('A"B', "XRF704"),
        ("x" * 25, "XRF704"),
        (" Pump", "XRF704"),
        ("", "XRF704"),
        ("Motor", "XRF712"),
    ]:
        for path in ("rename/preview", "rename"):
            response = client.post(
                f"/api/projects/{project}/{path}",
                json={"target": '"Motor"', "new_name": new_name, "files": []},
            )
            assert response.status_code == 422, (new_name, response.text)
            assert error_of(response)["code"] == code
    unknown = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": '"Nobody"', "new_name": "X"},
    )
    assert (unknown.status_code, error_of(unknown)["code"]) == (404, "XRF701")
    no_symbol = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": "M 0.0", "new_name": "X"},
    )
    assert error_of(no_symbol)["code"] == "XRF708"
    assert texts(client, project) == files


def test_a_file_changed_after_the_preview_stops_the_apply(client: TestClient) -> None:
    project = make_project(client, "motor", folder_files(MOTOR))
    request = {"target": '"Motor"', "new_name": "Pump"}
    preview = client.post(f"/api/projects/{project}/rename/preview", json=request).json()
    edited = texts(client, project)["OB1.awl"] + "\n"
    client.put(f"/api/projects/{project}/files/OB1.awl", json={"text": edited})
    before = texts(client, project)
    stale = client.post(
        f"/api/projects/{project}/rename", json={**request, "files": preview["files"]}
    )
    assert (stale.status_code, error_of(stale)["code"]) == (409, "XRF709")
    assert texts(client, project) == before


def test_undo_refuses_to_overwrite_a_later_change(client: TestClient) -> None:
    project = make_project(client, "motor", folder_files(MOTOR))
    request = {
        "target": "Q 4.0",
        "new_name": "Pump",
    }  # an address with a symbol renames it
    preview = client.post(f"/api/projects/{project}/rename/preview", json=request).json()
    applied = client.post(
        f"/api/projects/{project}/rename", json={**request, "files": preview["files"]}
    )
    assert applied.status_code == 200, applied.text
    later = texts(client, project)["OB1.awl"] + "// mine\n"
    client.put(f"/api/projects/{project}/files/OB1.awl", json={"text": later})
    refused = client.post(
        f"/api/projects/{project}/rename/undo", json={"files": applied.json()["undo"]}
    )
    assert (refused.status_code, error_of(refused)["code"]) == (409, "XRF713")
    assert texts(client, project)["OB1.awl"] == later
    assert '"Pump"' in texts(client, project)["symbols.sdf"]


def test_rename_a_db_member_and_a_block_in_stl_and_scl(client: TestClient) -> None:
    project = make_project(client, "tank", folder_files(TANK))
    member = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": '"TankSettings".HighLevel', "new_name": "UpperLimit"},
    )
    assert member.status_code == 200, member.text
    assert [(c["file"], c["line"]) for c in member.json()["changes"]] == [
        ("OB1.awl", 24),
        ("TankSettings.awl", 11),
    ]
    assert member.json()["changes"][1]["after"].strip().startswith("UpperLimit : REAL")
    assert '"TankSettings".UpperLimit' in member.json()["changes"][0]["after"]
    for new_name, code in [
        ("LowLevel", "XRF707"),
        ("1st", "XRF706"),
        ("a__b", "XRF706"),
    ]:
        refused = client.post(
            f"/api/projects/{project}/rename/preview",
            json={"target": '"TankSettings".HighLevel', "new_name": new_name},
        )
        assert error_of(refused)["code"] == code
    instance = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": '"LevelData".Pump', "new_name": "Feed"},
    )
    assert error_of(instance)["code"] == "XRF711"
    block = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": "FB 10", "new_name": "TwoPoint"},
    ).json()
    assert block["kind"] == "block"
    assert sorted({c["file"] for c in block["changes"]}) == [
        "LevelControl.scl",
        "LevelData.awl",
        "OB1.awl",
        "symbols.sdf",
    ]


def test_rename_in_a_lad_example(client: TestClient) -> None:
    files = folder_files(LAD, "vi_e06_motor_start_stop.lad", "vi_e06_motor_start_stop.sdf")
    project = make_project(client, "lad", files)
    preview = client.post(
        f"/api/projects/{project}/rename/preview",
        json={"target": '"Coil MC"', "new_name": "Contactor"},
    ).json()
    assert [(c["file"], c["after"].strip()) for c in preview["changes"]] == [
        ("vi_e06_motor_start_stop.lad", 'BRANCH Contact("Contactor") END_BRANCH'),
        ("vi_e06_motor_start_stop.lad", 'Coil("Contactor")'),
        (
            "vi_e06_motor_start_stop.sdf",
            '"Contactor","Q 0.0","BOOL","contactor coil of the three-phase motor"',
        ),
    ]


@pytest.mark.parametrize("target", ['"Motor"', "Q 4.0", "q4.0"])
def test_cross_references_and_assignment_list_api(client: TestClient, target: str) -> None:
    project = make_project(client, "motor", folder_files(MOTOR))
    found = client.get(f"/api/projects/{project}/xref", params={"target": target})
    assert found.status_code == 200, found.text
    assert [(e["line"], e["access"], e["symbol"]) for e in found.json()["entries"]] == [
        (15, "read", "Motor"),
        (19, "write", "Motor"),
        (22, "read", "Motor"),
    ]
    listed = client.get(f"/api/projects/{project}/assignments").json()
    assert [(b["area"], b["byte"]) for b in listed["bytes"]] == [("I", 0), ("Q", 4)]
    unknown = client.get(f"/api/projects/{project}/xref", params={"target": '"Nope"'})
    assert (unknown.status_code, error_of(unknown)["code"]) == (404, "XRF701")


def test_watch_tables_rename_quoted_symbols_but_not_comments() -> None:
    sources = [*folder_files(MOTOR).items(), ("motor.vat", WATCH)]
    plan = plan_rename(sources, '"Motor"', "Pump")
    assert plan.texts["motor.vat"] == WATCH.replace('"Motor"   BOOL', '"Pump"   BOOL')
    # Comments and titles keep their words: only operands are renamed.
    assert "// ... or the contactor already on" in plan.texts["OB1.awl"]

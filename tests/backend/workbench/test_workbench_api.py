"""``/blocks``, ``/check`` and ``/sessions`` of a project: what its files compile to and run as."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient
from project_helpers import error_of, make_project

SYMBOLS = '"Main","OB 1","OB 1",""\n"Level","FB 10","FB 10",""\n"LevelData","DB 10","FB 10",""\n'
OB1 = """\
ORGANIZATION_BLOCK "Main"
TITLE = Calls the SCL block
BEGIN
NETWORK
TITLE = call
      CALL "Level" , "LevelData" (
           In                       := IW 2);
      CALL FC 3;
END_ORGANIZATION_BLOCK
"""
FC3 = """\
// a comment that mentions FUNCTION FC 3 does not count

FUNCTION FC 3 : VOID
BEGIN
NETWORK
      L     5;
      T     MW 10;
END_FUNCTION
"""
LEVEL = """\
FUNCTION_BLOCK "Level"
VAR_INPUT
  In : INT;
END_VAR
VAR
  Last : INT;
END_VAR
BEGIN
  Last := In;
END_FUNCTION_BLOCK

DATA_BLOCK "LevelData" "Level"
BEGIN
END_DATA_BLOCK

TYPE UDT 5
  STRUCT
    a : INT;
  END_STRUCT
END_TYPE
"""
MOTOR = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     I 0.0;
      O     Q 4.0;
      AN    I 0.1;
      =     Q 4.0;
END_ORGANIZATION_BLOCK
"""


def _blocks(client: TestClient, project_id: int) -> dict[str, Any]:
    response = client.get(f"/api/projects/{project_id}/blocks")
    assert response.status_code == 200, response.text
    found: dict[str, Any] = response.json()
    return found


def _start_shows_the_motor_on(client: TestClient, session: dict[str, Any]) -> bool:
    """Over the session's socket: I0.0 on, watch Q4.0, RUN; whether a frame shows Q4.0 on."""
    with client.websocket_connect(session["websocket"]) as socket:
        assert socket.receive_json()["type"] == "hello"
        commands: list[dict[str, Any]] = [
            {"type": "set_input", "address": "I0.0", "value": 1},
            {"type": "watch", "entries": ["Q4.0"]},
            {"type": "run"},
        ]
        for ref, command in enumerate(commands):
            socket.send_json({**command, "ref": ref})
        for _ in range(100):
            message = socket.receive_json()
            assert message["type"] != "error", message
            watched = message.get("watch") if message["type"] == "frame" else None
            if watched and watched["Q4.0"]["value"] is True:
                return True
    return False


def test_blocks_of_stl_scl_and_symbols_in_tree_order(client: TestClient) -> None:
    files = {"OB1.awl": OB1, "FC3.awl": FC3, "Level.scl": LEVEL, "symbols.sdf": SYMBOLS}
    project_id = make_project(client, "Tank", files)
    build = _blocks(client, project_id)
    assert build["diagnostics"] == []
    rows = [
        (b["kind"], b["number"], b["name"], b["language"], b["file"], b["line"], b["instance_of"])
        for b in build["blocks"]
    ]
    assert rows == [
        ("OB", 1, "Main", "stl", "OB1.awl", 1, None),
        ("FB", 10, "Level", "scl", "Level.scl", 1, None),
        ("FC", 3, "", "stl", "FC3.awl", 3, None),
        ("DB", 10, "LevelData", "scl", "Level.scl", 12, "FB 10"),
        ("UDT", 5, "", "scl", "Level.scl", 16, None),
    ]
    assert build["blocks"][0]["title"] == "Calls the SCL block"


def test_an_instance_db_the_compiler_creates_has_no_line(client: TestClient) -> None:
    files = {
        "OB1.awl": OB1.replace('"LevelData"', "DB 20"),
        "FC3.awl": FC3,
        "Level.scl": LEVEL[: LEVEL.index("DATA_BLOCK")],
        "symbols.sdf": SYMBOLS,
    }
    build = _blocks(client, make_project(client, "Auto DB", files))
    (note,) = build["diagnostics"]  # "DB 20 is created as the instance data block of FB 10."
    assert note["severity"] != "error"
    blocks = {(b["kind"], b["number"]): b for b in build["blocks"]}
    assert (blocks[("DB", 20)]["line"], blocks[("DB", 20)]["instance_of"]) == (None, "FB 10")


def test_a_project_with_an_error_reports_file_line_and_column(client: TestClient) -> None:
    broken = MOTOR.replace("AN    I 0.1;", "AN    I 0.1;\n      XYZ   M 1.0;")
    project_id = make_project(client, "Broken", {"OB1.awl": broken})
    build = _blocks(client, project_id)
    assert [b["kind"] for b in build["blocks"]] == ["OB"]
    (problem,) = build["diagnostics"]
    assert (problem["code"], problem["severity"], problem["key"]) == (
        "STL201",
        "error",
        "stl_unknown_instruction",
    )
    span = problem["span"]
    assert (span["file"], span["line"], span["column"]) == ("OB1.awl", 7, 7)


def test_check_compiles_an_unsaved_text_in_place_of_the_stored_file(client: TestClient) -> None:
    project_id = make_project(client, "Typing", {"OB1.awl": MOTOR})
    url = f"/api/projects/{project_id}/check"
    typing = MOTOR.replace("=     Q 4.0;", '=     "Lamp";')
    response = client.post(url, json={"name": "OB1.awl", "text": typing})
    assert response.status_code == 200
    (problem,) = response.json()["diagnostics"]
    assert problem["code"] == "STL205"
    assert problem["span"]["line"] == 7
    # Nothing was saved; a new, unsaved symbol table joins the compilation.
    assert client.get(f"/api/projects/{project_id}/files/OB1.awl").json()["text"] == MOTOR
    table = {"name": "new.sdf", "text": '"Lamp","Q 4.1","BOOL",""\n'}
    assert client.post(url, json=table).json()["diagnostics"] == []
    assert client.post(url).json() == _blocks(client, project_id)


def test_check_refuses_bad_names_too_large_texts_and_unknown_projects(client: TestClient) -> None:
    project_id = make_project(client, "Checks", {})
    url = f"/api/projects/{project_id}/check"
    response = client.post(url, json={"name": "a/b.awl", "text": ""})
    assert error_of(response)["code"] == "API109"
    response = client.post(url, json={"name": "big.awl", "text": "x" * (4 * 1024 * 1024 + 1)})
    assert (response.status_code, error_of(response)["code"]) == (413, "API110")
    for response in (
        client.post("/api/projects/999/check"),
        client.get("/api/projects/999/blocks"),
    ):
        assert (response.status_code, error_of(response)["code"]) == (404, "API104")


def test_a_session_from_the_project_runs_its_program(client: TestClient) -> None:
    project_id = make_project(client, "Latch", {"OB1.awl": MOTOR})
    response = client.post(f"/api/projects/{project_id}/sessions", json={"cycle_ms": 20})
    assert response.status_code == 201, response.text
    session = response.json()
    assert session["blocks"] == ["OB1"]
    assert session["cpu"]["mode"] == "STOP"
    assert session["cpu"]["cycle_ms"] == 20
    try:
        assert _start_shows_the_motor_on(client, session)
        info = client.get(f"/api/sessions/{session['id']}").json()
        assert info["cpu"]["mode"] == "RUN"
        assert info["cpu"]["scans"] >= 1
    finally:
        client.delete(f"/api/sessions/{session['id']}")


def test_a_project_that_does_not_compile_gets_no_session(client: TestClient) -> None:
    project_id = make_project(client, "No run", {"OB1.awl": MOTOR.replace("A     I 0.0", "A ??")})
    response = client.post(f"/api/projects/{project_id}/sessions")
    assert response.status_code == 422
    error = error_of(response)
    assert error["code"] == "MON611"
    assert "OB1.awl:4:" in error["params"]["first"]
    assert error_of(client.post("/api/projects/999/sessions"))["code"] == "API104"


LATCH_LAD = """\
// the motor latch of MOTOR, drawn as a rung
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = Self-holding
RUNG
  PARALLEL
    BRANCH Contact(I 0.0) END_BRANCH
    BRANCH Contact(Q 4.0) END_BRANCH
  END_PARALLEL
  ContactNC(I 0.1)
  Coil(Q 4.0)
END_RUNG
END_ORGANIZATION_BLOCK
"""


def test_lad_and_fbd_files_are_sources_of_the_project(client: TestClient) -> None:
    fc3 = LATCH_LAD.replace("ORGANIZATION_BLOCK OB 1", "FUNCTION FC 3 : VOID").replace(
        "END_ORGANIZATION_BLOCK", "END_FUNCTION"
    )
    files = {"OB1.lad": LATCH_LAD, "FC3.fbd": fc3}
    build = _blocks(client, make_project(client, "Ladder", files))
    assert build["diagnostics"] == []
    rows = [(b["kind"], b["number"], b["language"], b["file"], b["line"]) for b in build["blocks"]]
    assert rows == [("OB", 1, "lad", "OB1.lad", 2), ("FC", 3, "fbd", "FC3.fbd", 2)]
    project = client.get(f"/api/projects/{make_project(client, 'Listed', files)}/files").json()
    assert sorted((f["name"], f["language"]) for f in project) == [
        ("FC3.fbd", "fbd"),
        ("OB1.lad", "lad"),
    ]


def test_check_places_a_lad_problem_on_its_line_and_network(client: TestClient) -> None:
    project_id = make_project(client, "Ladder typing", {"OB1.lad": LATCH_LAD})
    url = f"/api/projects/{project_id}/check"
    typing = LATCH_LAD.replace("Coil(Q 4.0)", 'Coil("Lamp")')
    (problem,) = client.post(url, json={"name": "OB1.lad", "text": typing}).json()["diagnostics"]
    assert problem["code"] == "STL205"  # the unknown symbol, found in the generated STL
    assert (problem["span"]["file"], problem["span"]["line"]) == ("OB1.lad", 4)
    assert (problem["span"]["network"], problem["span"]["element"]) == (1, "e5")
    word = LATCH_LAD.replace("ContactNC(I 0.1)", "ContactNC(MW 10)")
    (problem,) = client.post(url, json={"name": "OB1.lad", "text": word}).json()["diagnostics"]
    assert problem["code"] == "STL204"  # a word on a contact: on that contact
    assert (problem["span"]["network"], problem["span"]["element"]) == (1, "e4")
    unfilled = LATCH_LAD.replace("ContactNC(I 0.1)", "ContactNC(<??.?>)")
    (problem,) = client.post(url, json={"name": "OB1.lad", "text": unfilled}).json()["diagnostics"]
    assert problem["code"] == "LAD212"  # the lowering's own problems name their element too
    assert (problem["span"]["network"], problem["span"]["element"]) == (1, "e4")
    broken = LATCH_LAD.replace("ContactNC(I 0.1)", "ContactNC(I 0.1")
    (problem,) = client.post(url, json={"name": "OB1.lad", "text": broken}).json()["diagnostics"]
    assert problem["code"] == "LAD111"  # "',' or ')' expected, found 'Coil'": the text's own
    assert (problem["span"]["file"], problem["span"]["line"]) == ("OB1.lad", 12)


def test_a_session_runs_a_lad_program(client: TestClient) -> None:
    project_id = make_project(client, "Ladder latch", {"OB1.lad": LATCH_LAD})
    response = client.post(f"/api/projects/{project_id}/sessions")
    assert response.status_code == 201, response.text
    session = response.json()
    assert session["blocks"] == ["OB1"]
    try:
        assert _start_shows_the_motor_on(client, session)
    finally:
        client.delete(f"/api/sessions/{session['id']}")

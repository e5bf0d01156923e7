"""``/api/lessons``: the course, a lesson without its answers, the learner's project, Check,
hints, giving up and the solution only once earned."""

import json
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from nasaq.settings import Settings

COURSE = Path(__file__).parent / "fixtures" / "course"


@pytest.fixture
def settings(tmp_path: Path, dist: Path) -> Settings:
    return Settings(
        data_dir=tmp_path / "data",
        frontend_dist=dist,
        examples_dir=tmp_path / "no-examples",
        lessons_dir=COURSE,
        session_workers=1,  # as the shared fixture: a worker's start costs a second
    )


def _open(client: TestClient, lesson_id: str, reset: bool = False) -> dict[str, Any]:
    response = client.post(f"/api/lessons/{lesson_id}/open", json={"reset": reset})
    assert response.status_code in (200, 201), response.text
    body: dict[str, Any] = response.json()
    return body


def _put(client: TestClient, project_id: int, name: str, text: str) -> None:
    response = client.put(f"/api/projects/{project_id}/files/{name}", json={"text": text})
    assert response.status_code in (200, 201), response.text


def _solution(lesson_id: str, name: str) -> str:
    return (COURSE / "fa9" / lesson_id / "solution" / name).read_text("utf-8")


def test_the_course_lists_units_lessons_and_the_malformed_folder(
    client: TestClient,
) -> None:
    body = client.get("/api/lessons?lang=fa").json()
    [unit] = body["units"]
    assert (unit["id"], unit["language"], unit["title"]["fa"]) == (
        "fa9",
        "fa",
        "واحد آزمایشی",
    )
    first = unit["lessons"][0]
    assert first == {
        "id": "fa9-01",
        "order": 1,
        "title": {"fa": "پرکردن مخزن", "en": "Filling the tank"},
        "summary": first["summary"],
        "languages": ["fa", "en"],
        "works_in": "STL",
        "form": "program",
        "plant": "tank",
        "prerequisites": [],
        "progress": None,
    }
    assert [p["code"] for p in body["problems"]] == ["LSN202"]
    assert body["problems"][0]["file"] == "fa9/fa9-99/lesson.yaml"
    assert body["problems"][0]["line"] == 6


def test_a_lesson_is_served_without_answers_or_solution(client: TestClient) -> None:
    response = client.get("/api/lessons/fa9-02")
    assert response.status_code == 200
    body = response.json()
    assert set(body["text"]) == {"fa", "en"}
    assert body["hints_total"] == 0
    assert body["works_in"] == "none"
    assert [q["id"] for q in body["quiz"]] == ["q1", "q2", "q3", "q4", "q5"]
    served = json.dumps(body)
    assert '"answer"' not in served
    assert "W#16#0250" not in served
    assert "explain" not in served
    # A predict question shows the program the learner predicts from (given, not a solution);
    # the other questions carry none.
    programs = {q["id"]: q["program"] for q in body["quiz"]}
    predict = (COURSE / "fa9" / "fa9-02" / "predict" / "OB1.awl").read_text("utf-8")
    assert programs == {"q1": None, "q2": None, "q3": None, "q4": None, "q5": predict}
    tank = client.get("/api/lessons/fa9-01").json()
    assert tank["plant"]["kind"] == "tank"
    assert tank["figures"] == ["tank.svg"]
    assert tank["checks"] == [{"kind": "scenario", "name": "checks/fill.yaml"}]
    assert "Q4.0" not in json.dumps(tank["checks"])
    assert "AN    I 0.2" not in json.dumps(tank)


def test_unknown_lesson_and_figure_are_404_with_codes(client: TestClient) -> None:
    missing = client.get("/api/lessons/xx-01")
    assert missing.status_code == 404
    assert missing.json()["error"]["code"] == "LSN101"
    figure = client.get("/api/lessons/fa9-01/figures/tank.svg")
    assert figure.status_code == 200
    assert figure.headers["content-type"] == "image/svg+xml"
    assert figure.text.startswith("<svg")
    for name in ("nope.svg", "..%2Flesson.yaml"):
        response = client.get(f"/api/lessons/fa9-01/figures/{name}")
        assert response.status_code == 404


def test_open_makes_the_project_with_the_plant_file_once(client: TestClient) -> None:
    response = client.post("/api/lessons/fa9-01/open", json={"reset": False})
    assert response.status_code == 201
    opened = response.json()
    assert opened["open"] == "OB1.awl"
    assert opened["progress"]["status"] == "not_started"
    files = client.get(f"/api/projects/{opened['project_id']}/files").json()
    assert sorted(f["name"] for f in files) == ["OB1.awl", "tank.plant"]
    plant = client.get(f"/api/projects/{opened['project_id']}/files/tank.plant").json()["text"]
    assert "kind: tank" in plant
    assert "pump_pb: I0.0" in plant
    again = client.post("/api/lessons/fa9-01/open", json={})
    assert again.status_code == 200
    assert again.json()["project_id"] == opened["project_id"]
    listed = client.get("/api/lessons").json()["units"][0]["lessons"][0]
    assert listed["progress"]["status"] == "not_started"


def test_reset_puts_the_files_back_to_start(client: TestClient) -> None:
    project = _open(client, "fa9-01")["project_id"]
    _put(client, project, "OB1.awl", _solution("fa9-01", "OB1.awl"))
    _put(
        client,
        project,
        "extra.awl",
        _solution("fa9-01", "OB1.awl").replace("OB 1", "OB 35"),
    )
    _open(client, "fa9-01", reset=True)
    files = client.get(f"/api/projects/{project}/files").json()
    assert sorted(f["name"] for f in files) == ["OB1.awl", "tank.plant"]
    text = client.get(f"/api/projects/{project}/files/OB1.awl").json()["text"]
    assert "NOP" in text
    assert client.delete(f"/api/projects/{project}").status_code == 204
    response = client.post("/api/lessons/fa9-01/open", json={})
    assert response.status_code == 201  # a deleted project is made again from start/
    made = response.json()
    assert made["progress"]["attempts"] == 0
    files = client.get(f"/api/projects/{made['project_id']}/files").json()
    assert sorted(f["name"] for f in files) == ["OB1.awl", "tank.plant"]


def test_check_fails_then_passes_and_progress_is_kept(client: TestClient) -> None:
    project = _open(client, "fa9-01")["project_id"]
    failed = client.post("/api/lessons/fa9-01/check", json={"project_id": project}).json()
    assert failed["status"] == "failed"
    assert failed["progress"]["status"] == "tried"
    assert failed["progress"]["attempts"] == 1
    step = next(s for s in failed["checks"][0]["steps"] if not s["passed"])
    assert set(step["failures"][0]) == {
        "address",
        "expected",
        "actual",
        "at_ms",
        "where",
    }
    _put(client, project, "OB1.awl", _solution("fa9-01", "OB1.awl"))
    passed = client.post("/api/lessons/fa9-01/check", json={"project_id": project}).json()
    assert passed["status"] == "passed"
    assert passed["progress"]["status"] == "passed"
    assert passed["progress"]["passed_at"]
    assert passed["progress"]["attempts"] == 2
    listed = client.get("/api/lessons").json()["units"][0]["lessons"][0]
    assert listed["progress"]["status"] == "passed"


def test_check_answers_the_step_notes_in_the_interface_language(client: TestClient) -> None:
    project = _open(client, "fa9-01")["project_id"]
    notes = {}
    for lang in ("fa", "en", "vi"):
        body = {"project_id": project, "lang": lang}
        found = client.post("/api/lessons/fa9-01/check", json=body).json()
        notes[lang] = [step["note"] for step in found["checks"][0]["steps"]]
    assert notes["fa"][0] == "در حالت سکون"
    assert notes["en"][0] == "at rest"
    assert notes["vi"] == notes["en"]  # no Vietnamese note: English
    wrong = {"project_id": project, "lang": "xx"}
    assert client.post("/api/lessons/fa9-01/check", json=wrong).status_code == 422


def test_a_program_that_does_not_compile_is_a_compile_error(client: TestClient) -> None:
    project = _open(client, "fa9-01")["project_id"]
    _put(
        client,
        project,
        "OB1.awl",
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n  AX I 0.0\n",
    )
    body = client.post("/api/lessons/fa9-01/check", json={"project_id": project}).json()
    assert body["status"] == "compile_error"
    diagnostic = body["checks"][0]["diagnostics"][0]
    assert {"code", "severity", "message", "file", "line", "column"} <= set(diagnostic)
    assert diagnostic["file"] == "OB1.awl"


def test_a_failing_lad_rung_is_pointed_at(client: TestClient) -> None:
    project = _open(client, "fa9-03")["project_id"]
    body = client.post("/api/lessons/fa9-03/check", json={"project_id": project}).json()
    assert body["status"] == "failed"
    failure = body["checks"][0]["steps"][0]["failures"][0]
    assert failure["where"]["file"] == "OB1.lad"
    assert failure["where"]["network"] == 1
    assert failure["where"]["element"]


def test_quiz_answers_are_checked_and_the_truth_shown_only_once_passed(
    client: TestClient,
) -> None:
    project = _open(client, "fa9-02")["project_id"]
    wrong = client.post(
        "/api/lessons/fa9-02/check",
        json={"project_id": project, "answers": {"q1": "a"}},
    ).json()
    assert wrong["status"] == "failed"
    assert wrong["quiz"][0] == {
        "id": "q1",
        "correct": False,
        "expected_shown": None,
        "explain": {"fa": "A یعنی AND.", "en": "A stands for AND."},
    }
    answers = {
        "q1": "b",
        "q2": "۲٫۵",
        "q3": "16#0250",
        "q4": ["a", "c"],
        "q5": {"Q4.0": 1, "MW10": -7},
    }
    right = client.post(
        "/api/lessons/fa9-02/check", json={"project_id": project, "answers": answers}
    ).json()
    assert right["status"] == "passed"
    assert right["quiz"][4]["expected_shown"] == "Q4.0 = 1, MW10 = -7"


def test_hints_come_one_at_a_time(client: TestClient) -> None:
    project = _open(client, "fa9-01")["project_id"]
    first = client.post("/api/lessons/fa9-01/hint", json={"project_id": project}).json()
    assert (first["index"], first["total"], len(first["hints"])) == (1, 2, 1)
    second = client.post("/api/lessons/fa9-01/hint", json={"project_id": project}).json()
    third = client.post("/api/lessons/fa9-01/hint", json={"project_id": project}).json()
    assert second["index"] == third["index"] == 2
    assert len(third["hints"]) == 2
    detail = client.get("/api/lessons/fa9-01").json()
    assert detail["progress"]["hints_revealed"] == 2
    assert detail["hints"] == third["hints"]


def test_the_solution_is_locked_until_given_up(client: TestClient) -> None:
    project = _open(client, "fa9-01")["project_id"]
    locked = client.get(f"/api/lessons/fa9-01/solution?project_id={project}")
    assert locked.status_code == 403
    assert locked.json()["error"]["code"] == "LSN102"
    given = client.post("/api/lessons/fa9-01/give-up", json={"project_id": project}).json()
    assert given["gave_up"] is True
    body = client.get(f"/api/lessons/fa9-01/solution?project_id={project}").json()
    assert body == {"files": [{"name": "OB1.awl", "text": _solution("fa9-01", "OB1.awl")}]}


def test_a_project_that_is_not_the_lessons_is_refused(client: TestClient) -> None:
    other = client.post("/api/projects", json={"name": "mine"}).json()["id"]
    _open(client, "fa9-01")
    response = client.post("/api/lessons/fa9-01/check", json={"project_id": other})
    assert response.status_code == 409
    assert response.json()["error"]["code"] == "LSN103"
    response = client.get(f"/api/lessons/fa9-01/solution?project_id={other}")
    assert response.status_code == 409
    missing = client.post("/api/lessons/fa9-01/hint", json={"project_id": 999})
    assert missing.status_code == 404
    assert missing.json()["error"]["code"] == "API104"

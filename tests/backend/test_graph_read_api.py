"""``POST /api/graph/read``: a ``.graph`` file as the sequencer model the chart draws, with the
reader's problems, the checker's findings on a text that reads, and where each part is written;
any text gets an answer, never a 500."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from fastapi.testclient import TestClient

from nasaq.workbench.names import MAX_TEXT_CHARS

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios" / "graph"


def _read(client: TestClient, text: str, name: str = "seq.graph") -> dict[str, Any]:
    response = client.post("/api/graph/read", json={"name": name, "text": text})
    assert response.status_code == 200, response.text
    body: dict[str, Any] = response.json()
    return body


def test_a_course_source_reads_with_its_steps_places_and_no_problems(client: TestClient) -> None:
    body = _read(client, (SCENARIOS / "g17_conveyors.graph").read_text(encoding="utf-8"))
    assert body["diagnostics"] == []
    assert not [d for d in body["problems"] if d["severity"] == "error"]
    (block,) = body["blocks"]
    steps = block["sequencers"][0]["steps"]
    assert steps[0]["initial"] is True
    places = body["places"][0]
    for step in steps:
        assert places[f"S{step['number']}"] >= places["BLOCK"]
    assert all(action["id"] for step in steps for action in step["actions"])


def test_a_syntax_error_is_a_diagnostic_with_a_line_and_no_check_runs(client: TestClient) -> None:
    body = _read(client, "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER S\nSTEP x (\nEND_FUNCTION_BLOCK\n")
    assert body["diagnostics"]
    assert body["problems"] == []
    assert all(d["code"].startswith("GRA1") and d["span"]["line"] >= 1 for d in body["diagnostics"])


def test_a_checker_finding_comes_with_the_place_of_its_step(client: TestClient) -> None:
    text = (
        "FUNCTION_BLOCK FB 1\nBEGIN\nSEQUENCER Main\n"
        "INITIAL_STEP One (1)\nACTIONS\n  S1 CU Q 0.0;\nEND_ACTIONS\nEND_STEP\n"
        "TRANSITION T1 (1) FROM One TO One\nEND_TRANSITION\nEND_SEQUENCER\nEND_FUNCTION_BLOCK\n"
    )
    body = _read(client, text)
    assert body["diagnostics"] == []
    codes = {d["code"] for d in body["problems"]}
    assert any(code.startswith("GRA2") for code in codes), body["problems"]


def test_a_text_too_large_is_refused_with_its_code(client: TestClient) -> None:
    text = "x" * (MAX_TEXT_CHARS + 1)
    response = client.post("/api/graph/read", json={"name": "big.graph", "text": text})
    assert response.status_code == 413
    assert response.json()["error"]["code"] == "API110"

"""``POST /api/lad/read``: a LAD/FBD file as the network model, each block in its own language,
with the reader's problems only; any text gets an answer, never a 500."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nasaq.workbench.names import MAX_TEXT_CHARS

TWO_BLOCKS = """\
FUNCTION FC 2 : VOID
LANGUAGE FBD
BEGIN
NETWORK
RUNG Contact(I 0.0) Coil(Q 0.0) END_RUNG
END_FUNCTION

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = draft
RUNG
END_RUNG
NETWORK
RUNG Contact(I 0.1) Box(FC 2) END_RUNG
END_ORGANIZATION_BLOCK
"""


def _read(client: TestClient, name: str, text: str) -> dict[str, Any]:
    response = client.post("/api/lad/read", json={"name": name, "text": text})
    assert response.status_code == 200, response.text
    body: dict[str, Any] = response.json()
    return body


def test_each_block_comes_in_its_own_language(client: TestClient) -> None:
    body = _read(client, "main.lad", TWO_BLOCKS)
    assert body["diagnostics"] == []
    fc, ob = body["blocks"]
    assert (fc["name"], fc["language"]) == ("FC 2", "FBD")
    assert (ob["name"], ob["language"]) == ("OB 1", "LAD")
    assert ob["networks"][0] == {
        "title": "draft",
        "comment": "",
        "label": None,
        "logic": {"elements": []},
        "outputs": [],
        "stl": None,
        "stl_reason": None,
    }
    assert ob["networks"][1]["outputs"][0]["target"]["id"] == "e2"
    as_fbd = _read(client, "main.fbd", TWO_BLOCKS.replace("LANGUAGE FBD\n", ""))
    assert [block["language"] for block in as_fbd["blocks"]] == ["FBD", "FBD"]


def test_syntax_errors_come_with_their_place_and_what_still_reads(client: TestClient) -> None:
    broken = TWO_BLOCKS.replace("Contact(I 0.1)", "Contact(I 0.1")
    body = _read(client, "main.lad", broken)
    [problem] = body["diagnostics"]
    assert problem["code"] == "LAD111"
    assert (problem["span"]["file"], problem["span"]["line"]) == ("main.lad", 15)
    assert problem["span"]["network"] == 2
    assert [block["name"] for block in body["blocks"]] == ["FC 2", "OB 1"]


def test_only_syntax_is_checked(client: TestClient) -> None:
    """What the compiler finds (an unknown box, an unfinished rung) is not the reader's."""
    text = TWO_BLOCKS.replace("Box(FC 2)", "Box(NOSUCH, IN := <???>)")
    text = text.replace("Coil(Q 0.0)", "")
    assert _read(client, "main.lad", text)["diagnostics"] == []


def test_too_large_or_malformed_requests(client: TestClient) -> None:
    big = client.post("/api/lad/read", json={"name": "big.lad", "text": "x" * (MAX_TEXT_CHARS + 1)})
    assert big.status_code == 413
    assert big.json()["error"]["code"] == "API110"
    for body in ({"name": "a.lad"}, {"text": ""}, {"name": "x" * 129 + ".lad", "text": ""}, []):
        response = client.post("/api/lad/read", json=body)
        assert response.status_code == 422, body
        assert response.json()["error"]["code"] == "API103"


PIECES = [
    "FUNCTION FC 1 : VOID\n", "ORGANIZATION_BLOCK OB 1\n", "BEGIN\n", "END_FUNCTION\n",
    "END_ORGANIZATION_BLOCK\n", "NETWORK\n", "RUNG ", "END_RUNG\n", "OUTPUTS ", "END_OUTPUTS ",
    "PARALLEL ", "END_PARALLEL ", "BRANCH ", "END_BRANCH ", "Contact(I 0.0) ", "Coil(Q 0.0) ",
    "Box(MOVE, IN := ", "STL\n", "END_STL\n", "LANGUAGE FBD\n", "(*", '"', "@", "<??.?>", "\x00",
    "\u0645\u0648\u062a\u0648\u0631", "\ud7ff", "(", ")", ",", "\n",
]  # fmt: skip


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(st.lists(st.sampled_from(PIECES), max_size=30), st.sampled_from(["a.lad", "a.fbd", "a"]))
def test_any_text_gets_an_answer(client: TestClient, pieces: list[str], name: str) -> None:
    body = _read(client, name, "".join(pieces))
    assert all(p["code"].startswith("LAD1") for p in body["diagnostics"])

"""STL ↔ LAD ↔ FBD conversion: the module, ``nasaq convert``, ``POST /api/convert``, and LAD
files compiled with the rest of a program."""

from __future__ import annotations

from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from lad_to_stl_run import get, put, scan

from nasaq.cli import main
from nasaq.cpu import Cpu
from nasaq.lang.lad.convert import convert
from nasaq.lang.lad.model import Series
from nasaq.lang.lad.text import parse_lad, print_lad
from nasaq.lang.stl import SourceFile, compile_sources

MIXED_STL = """\
FUNCTION FC 5 : VOID
TITLE = Mixed
VAR_INPUT
  Go : BOOL;
END_VAR
BEGIN
NETWORK
TITLE = Self-holding
      A(
      O     I 0.0
      O     Q 4.0
      )
      AN    I 0.1
      =     Q 4.0
NETWORK
TITLE = A value moved
      L     MW 10
      T     MW 12
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

LAD = """\
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
NETWORK
RUNG
  Contact("Missing")
  Coil(Q 4.1)
END_RUNG
END_ORGANIZATION_BLOCK
"""


def test_stl_becomes_lad_network_by_network_and_keeps_the_rest_as_stl() -> None:
    result = convert("mixed.awl", MIXED_STL, "lad")
    assert (result.converted, result.kept) == (3, 1)
    [reason] = result.diagnostics
    assert reason.code.startswith("LAD3")
    assert reason.span is not None
    assert reason.span.line == MIXED_STL.split("\n").index("      X     I 0.4") + 1
    blocks, problems = parse_lad(result.text, "mixed.lad")
    assert problems == []
    fc = blocks[0]
    assert fc.return_type == "VOID"
    assert "Go : BOOL;" in fc.declarations
    assert fc.networks[1].outputs[0].target.kind == "box"  # L/T is a MOVE box
    kept = fc.networks[2]
    assert kept.title == "Exclusive OR"
    assert kept.stl_reason == reason.code == "LAD305"
    assert kept.stl == "      A     I 0.3\n      X     I 0.4\n      =     Q 4.2"


def test_the_converted_program_runs_as_the_stl_did() -> None:
    lad = convert("mixed.awl", MIXED_STL, "lad").text
    for sources in ([SourceFile("mixed.awl", MIXED_STL)], [SourceFile("mixed.lad", lad)]):
        result = compile_sources(sources)
        assert [d.code for d in result.diagnostics if d.severity == "error"] == []
        cpu = Cpu(result.program)
        cpu.start()
        put(cpu, MW10=1234, I0_0=1)
        scan(cpu)
        put(cpu, I0_0=0)
        scan(cpu)
        assert get(cpu, "Q 4.0") == 1  # held by its own contact
        assert get(cpu, "MW 12") == 1234
        assert get(cpu, "Q 4.2") == 0
        put(cpu, I0_3=1)
        scan(cpu)
        assert get(cpu, "Q 4.2") == 1  # the network kept as STL runs as before
        put(cpu, I0_1=1)
        scan(cpu)
        assert get(cpu, "Q 4.0") == 0


def test_lad_and_fbd_are_views_of_the_same_blocks() -> None:
    fbd = convert("motor.lad", LAD, "fbd")
    assert "LANGUAGE FBD" in fbd.text
    back = convert("motor.fbd", fbd.text, "lad")
    assert parse_lad(back.text, "x.lad")[0] == parse_lad(LAD, "x.lad")[0]
    stl = convert("motor.lad", LAD, "stl")
    assert "      AN    I 0.1" in stl.text
    assert "=     Q 4.0" in stl.text


def test_a_lad_file_compiles_with_problems_placed_on_its_network() -> None:
    result = compile_sources([SourceFile("motor.lad", LAD)])
    [problem] = [d for d in result.diagnostics if d.severity == "error"]
    assert problem.span is not None
    assert (problem.span.file, problem.span.network) == ("motor.lad", 2)
    assert problem.span.line == LAD.split("\n").index("NETWORK", 10) + 1


def test_an_unknown_source_kind_is_refused() -> None:
    result = convert("plant.scl", "FUNCTION FC 1 : VOID BEGIN END_FUNCTION", "lad")
    assert [d.code for d in result.diagnostics] == ["LAD501"]
    assert result.text == ""


def test_nasaq_convert(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "mixed.awl"
    source.write_text(MIXED_STL, encoding="utf-8")
    out = tmp_path / "mixed.fbd"
    assert main(["convert", str(source), "--to", "fbd", "--out", str(out)]) == 0
    assert "LANGUAGE FBD" in out.read_text(encoding="utf-8")
    assert "3 network(s) converted, 1 kept as STL" in capsys.readouterr().err
    assert main(["convert", str(out), "--to", "stl"]) == 0
    assert "CALL  FC 5" in capsys.readouterr().out
    assert main(["convert", str(tmp_path / "none.awl"), "--to", "lad"]) == 2


def test_post_convert(client: TestClient) -> None:
    response = client.post("/api/convert", json={"name": "m.awl", "text": MIXED_STL, "to": "lad"})
    assert response.status_code == 200, response.text
    body = response.json()
    assert (body["converted"], body["kept"]) == (3, 1)
    assert body["diagnostics"][0]["severity"] == "info"
    fc = body["blocks"][0]
    assert fc["networks"][2]["stl_reason"] == "LAD305"
    assert fc["networks"][0]["outputs"][0]["target"] == {
        "id": "e5",
        "kind": "coil",
        "coil": "=",
        "operand": "Q 4.0",
        "value": None,
    }
    refused = client.post("/api/convert", json={"name": "m.awl", "text": "", "to": "ladder"})
    assert refused.status_code == 422


def test_post_convert_gives_what_the_editors_draw(client: TestClient) -> None:
    """To LAD every network comes with its grid, to FBD with its boxes, wires and layers; a
    network kept as STL has nothing to draw; to STL there is nothing to draw at all."""
    lad = client.post("/api/convert", json={"name": "m.awl", "text": MIXED_STL, "to": "lad"})
    drawings = lad.json()["drawings"]
    blocks = lad.json()["blocks"]
    assert [len(block) for block in drawings] == [len(block["networks"]) for block in blocks]
    first = drawings[0][0]
    assert (first["fbd"], first["fbd_layout"]) == (None, None)
    placed = {cell["id"] for cell in first["lad"]["cells"]}
    assert {"e2", "e5"} <= placed  # a contact and the coil (e1 is the parallel around e2)
    assert drawings[0][2]["lad"]["cells"] == []  # the XOR network stays STL

    fbd = client.post("/api/convert", json={"name": "m.awl", "text": MIXED_STL, "to": "fbd"})
    first = fbd.json()["drawings"][0][0]
    assert first["lad"] is None
    assert first["fbd"]["outputs"][0]["id"] == "e5"
    nodes = {node["id"] for node in first["fbd_layout"]["nodes"]}
    assert "e5" in nodes
    edges = first["fbd_layout"]["edges"]
    assert all(edge["source"] in nodes and edge["target"] in nodes for edge in edges)

    stl = client.post(
        "/api/convert", json={"name": "m.lad", "text": fbd.json()["text"], "to": "stl"}
    )
    assert stl.json()["drawings"] is None


# ---- LAD → STL → LAD gives the block back -------------------------------------------------------

EXAMPLES = Path(__file__).resolve().parents[4] / "examples" / "lad"


def _canonical(text: str, name: str) -> str:
    """The text as the printer writes its model: comments outside blocks go (the model has
    none), and a single output's conditions are logic (``to_stl`` lowers them as one chain, so
    that is the shape STL lifts to)."""
    blocks, problems = parse_lad(text, name)
    assert problems == []
    shaped = []
    for block in blocks:
        networks = []
        for network in block.networks:
            if len(network.outputs) == 1 and network.outputs[0].conditions.elements:
                only = network.outputs[0]
                logic = [*network.logic.elements, *only.conditions.elements]
                network = network.model_copy(
                    update={
                        "logic": network.logic.model_copy(update={"elements": logic}),
                        "outputs": [only.model_copy(update={"conditions": Series()})],
                    }
                )
            networks.append(network)
        shaped.append(block.model_copy(update={"networks": networks}))
    return print_lad(shaped)


@pytest.mark.parametrize(
    "path",
    sorted([*EXAMPLES.glob("*.lad"), *EXAMPLES.glob("*.fbd")]),
    ids=lambda path: path.name,
)
def test_every_example_comes_back_from_its_stl(path: Path) -> None:
    text = path.read_text("utf-8")
    to = "fbd" if path.suffix == ".fbd" else "lad"
    stl = convert(path.name, text, "stl")
    back = convert(path.with_suffix(".awl").name, stl.text, to)
    assert back.kept == 0, back.diagnostics  # every network of the examples lifts
    assert back.text == _canonical(text, path.name)


TEMPS = """\
FUNCTION_BLOCK FB 3
VAR_INPUT
  go : BOOL;
END_VAR
BEGIN
NETWORK
TITLE = several outputs: the common logic in a temporary
RUNG
  Contact(#go)
  OUTPUTS
    BRANCH Contact(I 0.1) Coil(Q 0.0) END_BRANCH
    BRANCH Coil(Q 0.1) END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
TITLE = a parallel acting on the flow
RUNG
  Contact(I 0.0)
  PARALLEL
    BRANCH Contact(I 0.2) Not END_BRANCH
    BRANCH Contact(I 0.3) END_BRANCH
  END_PARALLEL
  Coil(Q 0.2)
END_RUNG
END_FUNCTION_BLOCK
"""


@pytest.mark.parametrize(
    ("declarations", "prefix"),
    [
        ("VAR_INPUT\n  go : BOOL;\nEND_VAR", "_lad_t"),
        ("VAR_INPUT\n  go : BOOL;\nEND_VAR\nVAR_TEMP\n  _lad_t7 : INT;\nEND_VAR", "_lad2_t"),
    ],
)
def test_the_lowerings_temporaries_are_dropped_on_the_way_back(
    declarations: str, prefix: str
) -> None:
    text = TEMPS.replace("VAR_INPUT\n  go : BOOL;\nEND_VAR", declarations)
    stl = convert("fb3.lad", text, "stl").text
    assert f"VAR_TEMP\n  {prefix}0 : BOOL;\nEND_VAR\nBEGIN" in stl  # each network counts from 0
    back = convert("fb3.awl", stl, "lad")
    assert back.kept == 0
    assert back.text == text
    assert convert("fb3.lad", back.text, "stl").text == stl


SECTION = "VAR_TEMP\n  _lad_t0 : BOOL;\nEND_VAR"


@pytest.mark.parametrize(
    ("change", "section"),
    [
        # A network that stays STL still reads the temporary.
        (
            (
                "END_FUNCTION_BLOCK",
                "NETWORK\n      L     MW 0\n      A     #_lad_t0\nEND_FUNCTION_BLOCK",
            ),
            SECTION,
        ),
        # Not numbered from 0: not what the lowering writes.
        (
            ("_lad_t0 : BOOL;\nEND_VAR\nBEGIN", "_lad_t1 : BOOL;\nEND_VAR\nBEGIN"),
            SECTION.replace("0", "1"),
        ),
        # The declarations before it use _lad_t: the lowering would have named it _lad2_t.
        (("END_VAR\nVAR_TEMP", "END_VAR\nVAR\n  _lad_t9 : INT;\nEND_VAR\nVAR_TEMP"), SECTION),
    ],
)
def test_a_section_that_is_not_the_lowerings_stays(change: tuple[str, str], section: str) -> None:
    stl = convert("fb3.lad", TEMPS, "stl").text
    assert change[0] in stl
    blocks = convert("fb3.awl", stl.replace(*change), "lad").blocks
    assert blocks is not None
    assert blocks[0].declarations.endswith(section)


def test_post_convert_draws_empty_and_unfinished_rungs(client: TestClient) -> None:
    """An empty STL network lifts to an empty rung, and a rung still being drawn converts
    between LAD and FBD: both come with what the editors draw."""
    stl = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nTITLE = new\nNETWORK\nM001: NOP 0\n"
    stl += "END_ORGANIZATION_BLOCK\n"
    for to in ("lad", "fbd"):
        response = client.post("/api/convert", json={"name": "e.awl", "text": stl, "to": to})
        assert response.status_code == 200, response.text
        body = response.json()
        assert (body["converted"], body["kept"]) == (2, 0)
        assert [n["label"] for n in body["blocks"][0]["networks"]] == [None, "M001"]
        assert len(body["drawings"][0]) == 2
    draft = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG\n  Contact(I 0.0)\n"
    draft += "  ContactNC(<??.?>)\nEND_RUNG\nEND_ORGANIZATION_BLOCK\n"
    response = client.post("/api/convert", json={"name": "d.lad", "text": draft, "to": "fbd"})
    assert response.status_code == 200, response.text
    [network] = response.json()["blocks"][0]["networks"]
    assert (len(network["logic"]["elements"]), network["outputs"]) == (2, [])
    back = client.post(
        "/api/convert", json={"name": "d.fbd", "text": response.json()["text"], "to": "lad"}
    )
    assert back.json()["text"] == draft
    lowered = client.post("/api/convert", json={"name": "d.lad", "text": draft, "to": "stl"})
    assert [d["code"] for d in lowered.json()["diagnostics"]] == ["LAD212", "LAD211"]

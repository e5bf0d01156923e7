"""An S7-Graph file in a project: a source of language ``graph``, its FB in the block tree with
its instance DB, its sequencers, steps and transitions in the outline with their lines, the
operands of its actions and conditions in the cross-references on the line they are written on,
and a symbol renamed in it."""

from __future__ import annotations

from fastapi.testclient import TestClient

from nasaq.workbench.names import is_valid_name, language_of
from nasaq.workbench.outline import outline
from nasaq.workbench.rename import plan_rename
from nasaq.workbench.tree import build
from nasaq.workbench.xref import assignment_list, references

FILLER = """\
FUNCTION_BLOCK "Filler"
TITLE = Fill and drain
BEGIN
SEQUENCER Tank
INITIAL_STEP Idle (1)
ACTIONS
  N "Ready";  // (* not a comment *) "Ready" lamp
END_ACTIONS
END_STEP

TRANSITION Go (1) FROM Idle TO Fill
CONDITION Contact("Start") ContactNC(I 0.1) END_CONDITION
END_TRANSITION

STEP Fill (2)
ACTIONS
  N Q 4.0;
  S1 S M 10.0;
END_ACTIONS
END_STEP

TRANSITION Full (2) FROM Fill JUMP Idle
CONDITION Contact(I 0.2) END_CONDITION
END_TRANSITION
END_SEQUENCER

SEQUENCER Alarm
INITIAL_STEP Quiet (10)
ACTIONS
  N Q 5.0;
END_ACTIONS
END_STEP

TRANSITION Ring (10) FROM Quiet JUMP Quiet
CONDITION Contact(I 0.3) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""
OB1 = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE =
      CALL "Filler" , "FillerData";
END_ORGANIZATION_BLOCK

DATA_BLOCK "FillerData"
"Filler"
BEGIN
END_DATA_BLOCK
"""
SYMBOLS = """\
"Filler","FB 3","FB 3","the sequencer"
"FillerData","DB 3","FB 3","its instance"
"Start","I 0.0","BOOL","start button"
"Ready","Q 4.7","BOOL","ready lamp"
"""


def _sources() -> list[tuple[str, str]]:
    return [("filler.graph", FILLER), ("OB1.awl", OB1), ("symbols.sdf", SYMBOLS)]


def test_a_graph_file_is_a_source_of_language_graph() -> None:
    assert language_of("Filler.GRAPH") == "graph"
    assert is_valid_name("Filler.graph")


def test_the_tree_shows_the_graph_fb_and_its_instance_db() -> None:
    built = build(_sources())
    assert [d for d in built.diagnostics if d.severity == "error"] == []
    shown = {(b.kind, b.number): b for b in built.blocks}
    fb = shown[("FB", 3)]
    assert (fb.name, fb.language, fb.file, fb.line, fb.title) == (
        "Filler",
        "graph",
        "filler.graph",
        1,
        "Fill and drain",
    )
    assert shown[("DB", 3)].instance_of == "FB 3"


def test_the_outline_lists_sequencers_steps_and_transitions_with_their_lines() -> None:
    lines = FILLER.split("\n")

    def line_of(text: str) -> int:
        return lines.index(text) + 1

    blocks = {(b.kind, b.number): b for b in outline(_sources()).blocks}
    fb = blocks[("FB", 3)]
    assert fb.language == "graph"
    assert fb.sequencers is not None
    tank, alarm = fb.sequencers
    assert (tank.name, tank.line, alarm.name, alarm.line) == (
        "Tank",
        line_of("SEQUENCER Tank"),
        "Alarm",
        line_of("SEQUENCER Alarm"),
    )
    assert [(s.number, s.name, s.initial, s.line) for s in tank.steps] == [
        (1, "Idle", True, line_of("INITIAL_STEP Idle (1)")),
        (2, "Fill", False, line_of("STEP Fill (2)")),
    ]
    assert [(t.number, t.name, t.source, t.target, t.line) for t in tank.transitions] == [
        (1, "Go", ["Idle"], ["Fill"], line_of("TRANSITION Go (1) FROM Idle TO Fill")),
        (
            2,
            "Full",
            ["Fill"],
            ["Idle"],
            line_of("TRANSITION Full (2) FROM Fill JUMP Idle"),
        ),
    ]
    assert [s.number for s in alarm.steps] == [10]
    # The instance DB's members are the FB's: the steps are there by name.
    names = {member.path for member in blocks[("DB", 3)].members}
    assert {"Idle.X", "Fill.T", "Go.TT", "G7_CMD"} <= names
    assert blocks[("OB", 1)].sequencers is None


def test_cross_references_point_at_the_graph_lines() -> None:
    lines = FILLER.split("\n")
    sources = _sources()
    start = references(sources, '"Start"').entries
    graph = [e for e in start if e.file == "filler.graph"]
    # A condition's operand: on its transition's line, with the contact's element id.
    transition = lines.index("TRANSITION Go (1) FROM Idle TO Fill") + 1
    assert [(e.language, e.block, e.line, e.network, e.access, e.element) for e in graph] == [
        ("graph", "FB 3", transition, None, "read", "T1/e1")
    ]
    written = [e for e in references(sources, "Q 4.0").entries if e.exact]
    # Written by its N row, and reset by the step's own code when the step is left.
    assert {(e.file, e.line, e.element) for e in written if e.access != "read"} == {
        ("filler.graph", lines.index("  N Q 4.0;") + 1, "S2/A1"),
        ("filler.graph", lines.index("STEP Fill (2)") + 1, "S2"),
    }
    marker = [e for e in references(sources, "M 10.0").entries if e.exact]
    assert {(e.line, e.element) for e in marker} == {(lines.index("  S1 S M 10.0;") + 1, "S2/A2")}
    assigned = assignment_list(sources)
    written_bits = {
        (byte.area, byte.byte, bit.bit) for byte in assigned.bytes for bit in byte.bits if bit.write
    }
    assert {("Q", 4, 0), ("Q", 4, 7), ("Q", 5, 0), ("M", 10, 0)} <= written_bits


def test_a_symbol_is_renamed_in_the_graph_source_too() -> None:
    result = plan_rename(_sources(), '"Ready"', "Lamp_ready")
    changed = {(c.file, c.before.strip(), c.after.strip()) for c in result.changes}
    assert (
        "filler.graph",
        'N "Ready";  // (* not a comment *) "Ready" lamp',
        'N "Lamp_ready";  // (* not a comment *) "Ready" lamp',
    ) in changed


def test_post_convert_gives_a_graph_fb_as_stl_and_refuses_a_diagram(client: TestClient) -> None:
    stl = client.post("/api/convert", json={"name": "filler.graph", "text": FILLER, "to": "stl"})
    assert stl.status_code == 200
    assert stl.json()["text"].startswith('FUNCTION_BLOCK "Filler"\n')
    lad = client.post("/api/convert", json={"name": "filler.graph", "text": FILLER, "to": "lad"})
    assert lad.status_code == 200
    body = lad.json()
    assert (body["text"], [d["code"] for d in body["diagnostics"]]) == ("", ["LAD502"])
    assert body["diagnostics"][0]["params"]["to"] == "LAD"


def test_a_graph_file_is_saved_and_listed_as_graph(client: TestClient) -> None:
    project = client.post("/api/projects", json={"name": "Graph project"}).json()["id"]
    saved = client.put(f"/api/projects/{project}/files/filler.graph", json={"text": FILLER})
    assert saved.status_code in (200, 201)
    assert saved.json()["language"] == "graph"
    client.put(f"/api/projects/{project}/files/OB1.awl", json={"text": OB1})
    client.put(f"/api/projects/{project}/files/symbols.sdf", json={"text": SYMBOLS})
    blocks = client.get(f"/api/projects/{project}/blocks").json()["blocks"]
    assert {(b["kind"], b["number"], b["language"]) for b in blocks} >= {("FB", 3, "graph")}

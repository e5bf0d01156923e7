"""Where generated code comes from (SEMANTICS.md §5): the instructions carry the chart element
they were lowered from, and a problem found in the generated STL, or by the lowering, is
reported on the graph line of its step, action row or transition."""

from __future__ import annotations

from graph_lower_support import compiled

from nasaq.ir import BlockKind
from nasaq.lang.graph.compile import lower_file

SOURCE = """FUNCTION_BLOCK FB 1
VAR
  level : REAL;
END_VAR
BEGIN
PERMANENT_PRE
NETWORK
TITLE = Lamp test
RUNG Contact(I 1.0) Coil(Q 1.0) END_RUNG
END_PERMANENT_PRE
SEQUENCER Main
INITIAL_STEP Idle (1)
ACTIONS
  N Q 0.0;
END_ACTIONS
END_STEP
TRANSITION Go (2) FROM Idle TO Fill
CONDITION Contact(I 0.0) ContactNC(I 0.1) END_CONDITION
END_TRANSITION
STEP Fill (3)
INTERLOCK Contact(I 0.2) END_INTERLOCK
ACTIONS
  N Q 0.1;
  S1 N #level := SIN(#level);
  {extra}
END_ACTIONS
END_STEP
TRANSITION Back (4) FROM Fill TO Idle
CONDITION Contact(I 0.3) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""


def line_of(text: str, needle: str) -> int:
    return next(k for k, line in enumerate(text.split("\n"), start=1) if needle in line)


def test_instructions_carry_their_chart_element() -> None:
    result = compiled(SOURCE.format(extra=""))
    block = result.program.get(BlockKind.FB, 1)
    assert block is not None
    elements = {i.origin.element for i in block.code if i.origin is not None}
    for wanted in ("G7", "S1", "S3", "S1/A1", "S3/A1", "S3/A2", "S3/C", "T2", "T4"):
        assert wanted in elements, sorted(e for e in elements if e)
    assert {"T2/e1", "T2/e2", "T4/e1", "PRE1/e1", "PRE1/e2"} <= elements
    by_element = {}
    for instruction in block.code:
        if instruction.origin is not None:
            by_element.setdefault(instruction.origin.element, []).append(instruction)
    assert [i.op for i in by_element["S3/A2"]][-2:] == ["SIN", "T"]
    assert by_element["T2/e2"][0].op == "AN"
    # an instruction's line is the generated STL line, which the file's line map takes back
    # to the graph line of its element (as for LAD)
    text = SOURCE.format(extra="")
    lowered = lower_file("seq.graph", text)
    sin = by_element["S3/A2"][0].origin
    contact = by_element["T2/e1"][0].origin
    assert sin is not None
    assert contact is not None
    assert lowered.place(sin.line)[0] == line_of(text, "SIN(")
    assert lowered.place(contact.line)[0] == line_of(text, "TRANSITION Go")


def test_the_line_map_of_the_generated_stl() -> None:
    text = SOURCE.format(extra="")
    lowered = lower_file("seq.graph", text)
    stl = lowered.stl.split("\n")
    assert len(lowered.origins) == len(lowered.elements) == len(stl) - 1
    fill = stl.index("TITLE = S3 Fill")
    assert lowered.place(fill + 1) == (line_of(text, "STEP Fill"), None)
    assert lowered.element(fill + 1) == "S3"


def test_an_unknown_symbol_in_an_action_is_reported_on_its_row() -> None:
    text = SOURCE.format(extra='S "Valve";')
    result = compiled(text)
    problems = [d for d in result.diagnostics if d.severity == "error"]
    assert problems, result.diagnostics
    assert all(d.span is not None and d.span.file == "seq.graph" for d in problems)
    assert {d.span.line for d in problems if d.span} == {line_of(text, '"Valve"')}
    assert {d.span.element for d in problems if d.span} == {"S3/A3"}


def test_an_arithmetic_action_of_unknown_type_is_gra303_on_its_row() -> None:
    text = SOURCE.format(extra='N "Total" := "Total" + 1;')
    lowered = lower_file("seq.graph", text)
    found = [d for d in lowered.diagnostics if d.code == "GRA303"]
    assert len(found) == 1
    assert found[0].span is not None
    assert found[0].span.line == line_of(text, '"Total"')
    assert found[0].span.element == "S3/A3"
    assert '"Total"' in found[0].message


def test_a_block_with_a_checker_error_is_not_lowered() -> None:
    text = SOURCE.format(extra="").replace("TO Idle", "TO Nowhere")
    lowered = lower_file("seq.graph", text)
    assert any(d.severity == "error" and d.code.startswith("GRA2") for d in lowered.diagnostics)
    assert lowered.stl == ""


def test_an_operand_not_filled_in_yet_is_lad212_on_its_transition_not_a_syntax_error() -> None:
    """The LAD editor draws a new compare box as ``<???>`` pins while the student types."""
    text = SOURCE.format(extra="").replace(
        "CONDITION Contact(I 0.3) END_CONDITION",
        "CONDITION Contact(I 0.3) Box(CMP>=D, IN1 := <???>, IN2 := MD 4) END_CONDITION",
    )
    result = compiled(text)
    errors = [d for d in result.diagnostics if d.severity == "error"]
    assert [d.code for d in errors] == ["LAD212"]
    assert errors[0].span is not None
    assert errors[0].span.line == line_of(text, "TRANSITION Back")

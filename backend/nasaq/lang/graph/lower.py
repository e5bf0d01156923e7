"""Graph → STL: a Graph FB becomes an STL FUNCTION_BLOCK the STL compiler compiles with the
project's other sources, so it runs on the CPU as any FB (no interpreter FC as in S7-Graph V5).

The instance DB and what one call does are ``SEMANTICS.md``; the parts are written by
``lower_interface`` (VAR sections), ``lower_inputs`` (phase 0), ``lower_machinery`` (phases
1–4), ``lower_actions`` (phase 5), ``lower_outputs`` (phase 6), ``lower_conditions`` (LAD
logic) and ``lower_arith`` (arithmetic actions); ``lower_syntax`` gives the STL compiler the
syntax tree of the result without parsing it. The code
is straight-line with one NETWORK per step and per transition, titled with its name: it is also
the "Graph → STL" view (``nasaq compile --emit stl``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic, Span
from nasaq.lang.graph.lower_actions import Actions
from nasaq.lang.graph.lower_arith import Arithmetic
from nasaq.lang.graph.lower_chart import Chart
from nasaq.lang.graph.lower_conditions import Conditions
from nasaq.lang.graph.lower_emit import Emitter, GraphLabels
from nasaq.lang.graph.lower_inputs import StartOfCall
from nasaq.lang.graph.lower_interface import declared_types, interface_lines
from nasaq.lang.graph.lower_machinery import Machinery
from nasaq.lang.graph.lower_outputs import Outputs
from nasaq.lang.graph.model import GraphBlock
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.lad.model import Network
from nasaq.lang.lad.to_stl import temp_prefix

_STL_LABEL = re.compile(r"^[ \t]*([A-Za-z_]\w*)[ \t]*:(?!=)", re.MULTILINE)


@dataclass(slots=True)
class LoweredGraph:
    """The STL source of one Graph FB, per line of it the graph source line and the origin
    element (``SEMANTICS.md`` §5; None: the block's frame), and the problems found."""

    text: str
    lines: list[int] = field(default_factory=list)
    elements: list[str | None] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    own_from: int = 0  # the index of the line where the lowering's own STAT section starts


def _labels_taken(block: GraphBlock) -> list[str]:
    taken: list[str] = []
    for network in [*block.pre, *block.post]:
        if network.label:
            taken.append(network.label)
        if network.stl:
            taken += _STL_LABEL.findall(network.stl)
    return taken


def place_key(element: str | None, places: dict[str, int]) -> str:
    """The ``ParsedGraph.places`` key of an origin element: itself (``S2/A1``), else its
    part before the element id (``S2/C`` of ``S2/C/e1``, ``T3`` of ``T3/e4``), else the block."""
    if element is None:
        return "BLOCK"
    while True:
        if element in places:
            return element
        if "/" not in element:
            return "BLOCK"
        element = element.rsplit("/", 1)[0]


def _networks(out: Emitter, conditions: Conditions, networks: list[Network], kind: str) -> None:
    for number, network in enumerate(networks, start=1):
        origin = f"{kind}{number}"
        what = "Permanent pre-instruction" if kind == "PRE" else "Permanent post-instruction"
        out.network(network.title or f"{what} {number}", origin)
        for line in network.comment.splitlines():
            out.raw(f"//{line}", origin)
        out.labels.network = number
        conditions.network(network, origin)


def lower_block(block: GraphBlock, parsed: ParsedGraph, index: int) -> LoweredGraph:
    """The STL source of ``block`` (block ``index`` of ``parsed``, for the source lines)."""
    chart = Chart.of(block)
    labels = GraphLabels(_labels_taken(block), temp_prefix(block.declarations))
    out = Emitter(labels)
    conditions = Conditions(chart, out)
    machinery = Machinery(chart, out, conditions)
    actions = Actions(chart, out, conditions, Arithmetic(chart, declared_types(block.declarations)))
    StartOfCall(chart, out).start_of_call()
    _networks(out, conditions, block.pre, "PRE")
    machinery.initialisation()
    machinery.times()
    machinery.supervision()
    machinery.transitions()
    for step in chart.steps:
        actions.step(step)
    Outputs(chart, out).outputs()
    _networks(out, conditions, block.post, "POST")
    out.flush()

    head = Emitter(labels)
    head.raw(f"FUNCTION_BLOCK {block.name}")
    if block.title:
        head.raw(f"TITLE = {block.title}")
    for line in block.comment.splitlines():
        head.raw(f"//{line}")
    lad_temps = [f"{labels.temp_prefix}{k}" for k in range(labels.temps_needed)]
    lad_temps += machinery.temps
    for line in interface_lines(chart, lad_temps):
        for part in line.split("\n"):
            head.raw(part)
    head.raw("BEGIN")
    lines = head.lines + out.lines + ["END_FUNCTION_BLOCK"]
    elements = head.elements + out.elements + [None]
    places = parsed.places[index] if 0 <= index < len(parsed.places) else {}
    source_lines = [parsed.line(index, place_key(element, places)) for element in elements]
    diagnostics = []
    for problem in out.diagnostics:
        element = problem.span.element if problem.span is not None else None
        at = parsed.line(index, place_key(element, places))
        span = Span(file=parsed.file, line=at, column=1, end_line=at, element=element)
        diagnostics.append(problem.model_copy(update={"span": span}))
    own_from = head.lines.index("  G7_MODE : INT := 1;") - 1
    return LoweredGraph("\n".join(lines) + "\n", source_lines, elements, diagnostics, own_from)

"""A ``.graph`` file as the STL compiler reads it: parse → check → lower each block to STL.

As a LAD/FBD file (``nasaq.lang.lad.compile``), the file becomes the STL text of its blocks with
a per-line map back to the graph source line and the chart element (``S2/A1``, ``T3/e4`` …), so
the STL compiler's problems land on the graph line and monitoring finds each element's code.
A block with a syntax or checker error is not lowered: its problems are the messages the user
gets, not the STL compiler's complaints about what the mistake would lower to.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.diagnostics import Diagnostic, Severity
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.lower import lower_block
from nasaq.lang.graph.lower_syntax import tree
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.graph.text_limits import refuse_oversized
from nasaq.lang.lad.compile import LoweredFile
from nasaq.lang.stl.parse import ParseResult


@dataclass(slots=True)
class LoweredGraphFile(LoweredFile):
    """A lowered ``.graph`` file with the syntax tree of its STL, built without the STL
    parser (``lower_syntax``), which the STL compiler takes instead of parsing ``stl``."""

    parsed: ParseResult | None = None


def _errors_by_block(parsed: ParsedGraph) -> set[int]:
    """The blocks a syntax error was found in (by the lines the blocks start at)."""
    starts = [places.get("BLOCK", 1) for places in parsed.places]
    found: set[int] = set()
    for problem in parsed.diagnostics:
        if problem.severity is not Severity.ERROR:
            continue
        line = problem.span.line if problem.span is not None else None
        if line is None:
            continue
        for index in range(len(starts) - 1, -1, -1):
            if starts[index] <= line:
                found.add(index)
                break
    return found


def lower_parsed(parsed: ParsedGraph) -> LoweredGraphFile:
    """The STL of every block of ``parsed`` without an error, and all problems found."""
    diagnostics: list[Diagnostic] = list(parsed.diagnostics)
    broken = _errors_by_block(parsed)
    out: list[str] = []
    origins: list[tuple[int, int | None]] = []
    elements: list[str | None] = []
    blocks: list[tuple[list[str], int, int]] = []
    for index, block in enumerate(parsed.blocks):
        checked = check_block(parsed, index)
        diagnostics += checked
        if index in broken or any(d.severity is Severity.ERROR for d in checked):
            continue
        lowered = lower_block(block, parsed, index)
        diagnostics += lowered.diagnostics
        text = lowered.text.rstrip("\n").split("\n")
        blocks.append((text, lowered.own_from, len(out)))
        out += text
        origins += [(line, None) for line in lowered.lines]
        elements += lowered.elements
    stl = "\n".join(out) + "\n" if out else ""
    syntax = tree(parsed.file, blocks)
    return LoweredGraphFile(stl, diagnostics, origins, elements, syntax)


def lower_file(name: str, text: str) -> LoweredGraphFile:
    """Parses a ``.graph`` file and lowers every block that has no error."""
    # A block far over the 256-step limit is refused before it is read (``text_limits``).
    text, refused = refuse_oversized(name, text)
    lowered = lower_parsed(parse_graph(text, name))
    lowered.diagnostics += refused
    return lowered

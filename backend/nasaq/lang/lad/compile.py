"""A LAD/FBD file as the STL compiler reads it: the STL its blocks lower to, and where each
generated line came from.

The STL compiler takes a ``.lad``/``.fbd`` file like an STL source whose text is the lowering of
its blocks (``to_stl.lower_block``), so LAD blocks call and are called by STL and SCL blocks,
share the symbol table and run on the CPU unchanged. A problem the STL compiler finds in that
text (an unknown symbol, a wrong operand type) is moved back to the LAD file: to the line of the
network it belongs to, with the network number and the element id, since the generated line
means nothing to the user. The same element ids go on the instructions (``ir.Origin.element``)
for monitoring.
"""

from __future__ import annotations

import re
from bisect import bisect_right
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic, Span
from nasaq.lang.lad.text import parse_lad
from nasaq.lang.lad.to_stl import lower_block

_NETWORK = re.compile(r"^[ \t]*NETWORK\b", re.IGNORECASE | re.MULTILINE)
_BLOCK_START = re.compile(
    r"^[ \t]*(?:ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)\b", re.IGNORECASE | re.MULTILINE
)


@dataclass(slots=True)
class LoweredFile:
    """The STL text of a LAD file's blocks, its diagnostics so far, and the line map."""

    stl: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    # Generated line (1-based) -> (LAD line, network number or None).
    origins: list[tuple[int, int | None]] = field(default_factory=list)
    # Generated line (1-based) -> the element id in its network, or None; aligned with origins.
    elements: list[str | None] = field(default_factory=list)

    def place(self, line: int) -> tuple[int, int | None]:
        """The LAD line and network of a generated STL line."""
        if 1 <= line <= len(self.origins):
            return self.origins[line - 1]
        return (1, None)

    def element(self, line: int) -> str | None:
        """The element a generated STL line belongs to."""
        return self.elements[line - 1] if 1 <= line <= len(self.elements) else None


def _starts(pattern: re.Pattern[str], text: str) -> list[int]:
    return [text.count("\n", 0, match.start()) + 1 for match in pattern.finditer(text)]


def lower_file(name: str, text: str) -> LoweredFile:
    """Parses a LAD/FBD file and lowers every block; a block that does not parse is left out
    (its problems are in the diagnostics)."""
    blocks, diagnostics = parse_lad(text, name)
    lad_blocks = _starts(_BLOCK_START, text)
    lad_networks = _starts(_NETWORK, text)
    out: list[str] = []
    origins: list[tuple[int, int | None]] = []
    elements: list[str | None] = []
    syntax_lines = sorted(
        d.span.line
        for d in diagnostics
        if d.severity == "error" and d.span is not None and d.span.line is not None
    )
    for number, block in enumerate(blocks):
        lowered = lower_block(block)
        stl, problems = lowered.text, lowered.diagnostics
        elements += lowered.elements
        block_line = lad_blocks[number] if number < len(lad_blocks) else 1
        # The LAD header lines of this block's networks, in order.
        ends = lad_blocks[number + 1] if number + 1 < len(lad_blocks) else len(text) + 1
        network_lines = [line for line in lad_networks if block_line <= line < ends]
        for problem in problems:
            placed = _on_network(problem, name, network_lines, ends, syntax_lines)
            if placed is not None:
                diagnostics.append(placed)
        lines = stl.rstrip("\n").split("\n")
        generated = [k for k, line in enumerate(lines) if _NETWORK.match(line)]
        for k in range(len(lines)):
            seen = bisect_right(generated, k)  # networks started at or before line k
            if seen == 0 or seen > len(network_lines):
                origins.append((block_line, None))
            else:
                origins.append((network_lines[seen - 1], seen))
        out += lines
    return LoweredFile("\n".join(out) + "\n", diagnostics, origins, elements)


def _on_network(
    problem: Diagnostic, name: str, network_lines: list[int], end: int, syntax_lines: list[int]
) -> Diagnostic | None:
    """A problem of the lowering, placed in the file on its network's line; None when that
    network has a syntax error, which is the one message its mistake gives (a coil dropped by
    the reader would otherwise also be "no output yet")."""
    span = problem.span
    update: dict[str, object] = {"file": name} if span is None or span.file is None else {}
    network = span.network if span is not None else None
    if network is not None and 1 <= network <= len(network_lines):
        first = network_lines[network - 1]
        last = network_lines[network] if network < len(network_lines) else end
        index = bisect_right(syntax_lines, first - 1)
        if index < len(syntax_lines) and syntax_lines[index] < last:
            return None
        if span is None or span.line is None:
            update["line"] = first
    if not update:
        return problem
    base = span if span is not None else Span()
    return problem.model_copy(update={"span": base.model_copy(update=update)})


def moved_to_lad(diagnostic: Diagnostic, lowered: LoweredFile) -> Diagnostic:
    """A diagnostic about the generated STL, placed on the LAD file's network and on the
    element the generated line belongs to instead."""
    span = diagnostic.span
    if span is None or span.line is None:
        return diagnostic
    line, network = lowered.place(span.line)
    update = {
        "line": line,
        "column": 1,
        "end_line": line,
        "end_column": None,
        "network": network,
        "element": lowered.element(span.line),
    }
    return diagnostic.model_copy(update={"span": span.model_copy(update=update)})

"""The generated STL of one Graph FB as it is being written: lines, where each came from, labels.

Every line carries its origin element (``SEMANTICS.md`` §5: ``S2``, ``S2/A1``, ``T3/e4``,
``PRE1/e2``, ``G7``) so monitoring and the STL compiler's problems find their way back to the
chart. Labels are four characters (``_`` + three base-36 digits, STEP 7's label length), unique
in the block, and skip the labels the user's permanent networks use.
"""

from __future__ import annotations

from collections.abc import Iterable

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.lang.lad.to_stl import LabelMaker, stl_line

_DIGITS = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"


class GraphLabels(LabelMaker):
    """LAD's label maker with 46,656 four-character labels (``_000`` … ``_ZZZ``) instead of
    999: a 200-step sequencer needs a few per step."""

    def label(self) -> str:
        while True:
            n = self.count
            self.count += 1
            label = "_" + _DIGITS[n // 1296 % 36] + _DIGITS[n // 36 % 36] + _DIGITS[n % 36]
            if label not in self.taken:
                self.taken.add(label)
                return label


class Emitter:
    """Appends STL lines with their origin element; ``at`` sets the element of the lines that
    follow, ``mark`` puts a label on the next line (a ``NOP 0`` when a network ends on it)."""

    def __init__(self, labels: GraphLabels) -> None:
        self.labels = labels
        self.lines: list[str] = []
        self.elements: list[str | None] = []
        self.element: str | None = None
        self.pending: list[str] = []
        self.diagnostics: list[Diagnostic] = []

    def at(self, element: str | None) -> None:
        self.element = element

    def raw(self, text: str, element: str | None = None) -> None:
        """A line outside the code (header, declarations), of ``element`` (None: the block)."""
        self.flush()
        self.lines.append(text)
        self.elements.append(element)

    def emit(self, op: str, operand: str = "") -> None:
        label = None
        if self.pending:
            label = self.pending.pop(0)
            while self.pending:  # several labels on one place: each needs its own line
                self.lines.append(stl_line("NOP", "0", label))
                self.elements.append(self.element)
                label = self.pending.pop(0)
        self.lines.append(stl_line(op, operand, label))
        self.elements.append(self.element)

    def extend(self, lines: Iterable[str], elements: Iterable[str | None]) -> None:
        """Lines made elsewhere (the LAD lowering); a pending label goes on the first one."""
        for line, element in zip(lines, elements, strict=True):
            if self.pending and line.startswith(" "):
                parts = line.split(None, 1)
                self.element, saved = element, self.element
                self.emit(parts[0], parts[1] if len(parts) > 1 else "")
                self.element = saved
                continue
            self.flush()
            self.lines.append(line)
            self.elements.append(element)

    def label(self) -> str:
        return self.labels.label()

    def mark(self, label: str) -> None:
        self.pending.append(label)

    def flush(self) -> None:
        """Places pending labels on ``NOP 0`` lines (before a network or block ends)."""
        while self.pending:
            self.lines.append(stl_line("NOP", "0", self.pending.pop(0)))
            self.elements.append(self.element)

    def network(self, title: str, element: str | None) -> None:
        """A new network; a label still pending goes on its first instruction (labels are
        the block's, so a jump may end in the next network)."""
        self.at(element)
        self.lines += ["NETWORK", f"TITLE = {title}".rstrip()]
        self.elements += [element, element]

    def report(self, code: str, element: str | None, **params: object) -> None:
        self.diagnostics.append(render(code, Span(element=element), **params))

"""Writes LAD/FBD blocks in the text format ``text_parse`` reads (``grammars/lad.lark``).

The layout aims at small diffs: one element per line in a rung, a PARALLEL over several lines
with each branch on one line while it fits, a box on one line while it fits (else one pin per
line). Ids equal to their reading-order number are left out; the reader numbers them again.
"""

from __future__ import annotations

from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    LadBlock,
    Midline,
    Network,
    OpenDb,
    Parallel,
    Return,
    Series,
    StatusContact,
)
from nasaq.lang.lad.text_ids import default_id

WIDTH = 100
INDENT = "  "
_OPENERS = {"OB": "ORGANIZATION_BLOCK", "FB": "FUNCTION_BLOCK", "FC": "FUNCTION"}
_COILS = {"=": "Coil", "S": "SetCoil", "R": "ResetCoil"}


class _Printer:
    def __init__(self) -> None:
        self.count = 0
        self.out: list[str] = []

    def tag(self, element_id: str) -> str:
        """`` @id`` unless the id is the one the reader gives this position."""
        self.count += 1
        return f" @{element_id}" if element_id and element_id != default_id(self.count) else ""

    # ---- one line -------------------------------------------------------------------------
    def inline(self, node: Element | Final) -> str:
        if isinstance(node, Parallel):
            tag = self.tag(node.id)
            branches = " ".join(f"BRANCH {self.series_inline(b)}END_BRANCH" for b in node.branches)
            return f"PARALLEL{tag} {branches} END_PARALLEL"
        if isinstance(node, Box):
            tag = self.tag(node.id)
            return f"Box({', '.join(self.box_items(node))}){tag}"
        return self.simple(node) + self.tag(node.id)

    def series_inline(self, series: Series) -> str:
        return "".join(self.inline(element) + " " for element in series.elements)

    def box_items(self, box: Box) -> list[str]:
        items = [box.name]
        if box.instance is not None:
            items.append(f"INSTANCE {box.instance}")
        for pin, value in box.inputs.items():
            if isinstance(value, Series):
                items.append(f"{pin} := RUNG {self.series_inline(value)}END_RUNG")
            else:
                items.append(f"{pin} := {value}")
        items.extend(f"{pin} => {value}" for pin, value in box.outputs.items())
        return items

    @staticmethod
    def simple(node: Element | Final) -> str:
        """An element without nested elements, without its id."""
        if isinstance(node, Contact):
            return f"{'ContactNC' if node.negated else 'Contact'}({node.operand})"
        if isinstance(node, StatusContact):
            return f"{'StatusNC' if node.negated else 'Status'}({node.bit})"
        if isinstance(node, Invert):
            return "Not"
        if isinstance(node, EdgeContact):
            return f"Edge({node.edge}, {node.memory})"
        if isinstance(node, Midline):
            return f"Midline({node.operand})"
        if isinstance(node, Coil):
            if node.coil == "SAVE":
                return "Save"
            name = _COILS.get(node.coil, node.coil)
            value = "" if node.value is None else f", {node.value}"
            return f"{name}({node.operand}{value})"
        if isinstance(node, Jump):
            return f"{'JumpN' if node.negated else 'Jump'}({node.label})"
        if isinstance(node, Return):
            return "Return"
        assert isinstance(node, OpenDb)
        return f"Open({node.block})"

    # ---- lines ----------------------------------------------------------------------------
    def emit(self, depth: int, text: str) -> None:
        self.out.append(INDENT * depth + text)

    def element(self, node: Element | Final, depth: int) -> None:
        if isinstance(node, Parallel):
            self.emit(depth, "PARALLEL" + self.tag(node.id))
            for branch in node.branches:
                self.branch(branch, None, depth + 1)
            self.emit(depth, "END_PARALLEL")
            return
        start = self.count
        line = self.inline(node)
        if not isinstance(node, Box) or len(INDENT * depth + line) <= WIDTH:
            self.emit(depth, line)
            return
        self.count = start
        self.box_lines(node, depth)

    def box_lines(self, box: Box, depth: int) -> None:
        """A box too wide for one line: one pin a line, logic in a pin over several lines
        when it does not fit or holds a PARALLEL."""
        tag = self.tag(box.id)
        pins: list[tuple[str, str | Series]] = []
        if box.instance is not None:
            pins.append(("INSTANCE ", box.instance))
        pins += [(f"{pin} := ", value) for pin, value in box.inputs.items()]
        pins += [(f"{pin} => ", value) for pin, value in box.outputs.items()]
        self.emit(depth, f"Box({box.name},")
        for number, (head, value) in enumerate(pins, start=1):
            end = f"){tag}" if number == len(pins) else ","
            if not isinstance(value, Series):
                self.emit(depth + 2, head + value + end)
                continue
            start = self.count
            line = f"{head}RUNG {self.series_inline(value)}END_RUNG{end}"
            nested = any(isinstance(element, Parallel) for element in value.elements)
            if not nested and len(INDENT * (depth + 2) + line) <= WIDTH:
                self.emit(depth + 2, line)
                continue
            self.count = start
            self.emit(depth + 2, head + "RUNG")
            for element in value.elements:
                self.element(element, depth + 3)
            self.emit(depth + 2, "END_RUNG" + end)

    def branch(self, series: Series, final: Final | None, depth: int) -> None:
        """``BRANCH ... END_BRANCH`` on one line when it fits and holds no PARALLEL."""
        nodes: list[Element | Final] = [*series.elements, *([final] if final else [])]
        start = self.count
        if not any(isinstance(node, Parallel) for node in nodes):
            line = "BRANCH " + "".join(self.inline(node) + " " for node in nodes) + "END_BRANCH"
            if len(INDENT * depth + line) <= WIDTH:
                self.emit(depth, line)
                return
        self.count = start
        self.emit(depth, "BRANCH")
        for node in nodes:
            self.element(node, depth + 1)
        self.emit(depth, "END_BRANCH")

    def network(self, network: Network) -> None:
        self.count = 0
        self.emit(0, "NETWORK")
        if network.title:
            self.emit(0, f"TITLE = {_one_line(network.title)}")
        if network.comment:
            for line in network.comment.split("\n"):
                self.emit(0, f"COMMENT = {line}".rstrip())
        if network.label is not None:
            self.emit(0, f"LABEL {network.label}")
        if network.stl is not None:
            reason = f" REASON {network.stl_reason}" if network.stl_reason else ""
            self.emit(0, f"STL{reason}")
            self.out.extend(network.stl.split("\n") if network.stl else [])
            self.emit(0, "END_STL")
            return
        self.emit(0, "RUNG")
        for element in network.logic.elements:
            self.element(element, 1)
        outputs = network.outputs
        logic = network.logic.elements
        if not outputs and logic and isinstance(logic[-1], Box):
            # A rung being drawn that ends in a box: without the empty OUTPUTS the reader
            # would take the box for the rung's final element.
            self.emit(1, "OUTPUTS")
            self.emit(1, "END_OUTPUTS")
        elif len(outputs) == 1 and not outputs[0].conditions.elements:
            self.element(outputs[0].target, 1)
        elif outputs:
            self.emit(1, "OUTPUTS")
            for output in outputs:
                self.branch(output.conditions, output.target, 2)
            self.emit(1, "END_OUTPUTS")
        self.emit(0, "END_RUNG")

    def block(self, block: LadBlock) -> None:
        opener = _OPENERS[block.kind]
        head = f"{opener} {block.name}"
        if block.return_type is not None:
            head += f" : {block.return_type}"
        self.emit(0, head)
        if block.title:
            self.emit(0, f"TITLE = {_one_line(block.title)}")
        if block.language == "FBD":
            self.emit(0, "LANGUAGE FBD")
        if block.declarations.strip():
            self.out.append(block.declarations.rstrip())
        self.emit(0, "BEGIN")
        for network in block.networks:
            self.network(network)
        self.emit(0, f"END_{opener}")


def _one_line(text: str) -> str:
    return " ".join(text.split("\n")).strip()


def print_blocks(blocks: list[LadBlock]) -> str:
    """The text of ``blocks``, one blank line between blocks, ending with a newline."""
    parts = []
    for block in blocks:
        printer = _Printer()
        printer.block(block)
        parts.append("\n".join(printer.out) + "\n")
    return "\n".join(parts)


def network_lines(network: Network) -> list[str]:
    """The lines of one network (the Graph format's permanent instructions are LAD networks)."""
    printer = _Printer()
    printer.network(network)
    return printer.out


def series_lines(series: Series, depth: int) -> list[str]:
    """The elements of ``series`` one per line at ``depth``, ids numbered from ``e1`` as in a
    rung without its final element (the Graph format's conditions)."""
    printer = _Printer()
    for element in series.elements:
        printer.element(element, depth)
    return printer.out

"""A layered description of an FBD network, ready for elkjs (``elk.layered``) or direct drawing.

As in STEP 7 FBD, operands are not boxes: an operand (or status bit) is the label of the pin it
feeds, with ``negated`` for the negation circle. The boxes are nodes with ports (``WEST`` inputs,
``EAST`` outputs, numbered from the top); wires are edges from an output port to an input port.
The common logic feeds every output through its own edge (the T-branch); the ``flow`` of an
OR box (the AND box of the power flow into a LAD parallel) feeds the first pin of each of its
branches through its own edge too.

Layers come from the longest path to an output: final boxes (``=``, ``S``, JMP, boxes ending
the rung) are in the last layer, a box feeding them one layer to the left, and so on; a box used
by two outputs sits left of both. A network being drawn may have no outputs yet: its common
logic's node is then the last layer (a lone operand or status bit is a node without a box, its
text and negation circle on its one output port), and an empty rung, whose logic is the rail
alone, has no nodes: an empty FBD network. Within a layer, nodes are ordered by first visit,
walking the outputs top-down and each box's inputs top-down, so the same network always gives
the same layout. A node is two cells wide and as tall as its larger side's port count (at least
one).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict

from nasaq.lang.lad.boxes import box_spec
from nasaq.lang.lad.fbd import (
    FbdAssign,
    FbdBox,
    FbdBranch,
    FbdEdge,
    FbdFinal,
    FbdJump,
    FbdLogic,
    FbdMidline,
    FbdNetwork,
    FbdNode,
    FbdOpenDb,
    FbdOperand,
    FbdReturn,
    FbdStatus,
    flow_pins,
)


class _Frozen(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class FbdPort(_Frozen):
    """A pin: ``id`` is ``<node>.<side>.<index>``; ``label`` the operand written at it,
    ``negated`` its negation circle; ``element`` the LAD element that operand is (the contact or
    status bit, so the editor selects it and shows its status there), None for a box's own
    operand or a wire; ``open``: a pin of a catalogued box nothing is connected to."""

    id: str
    name: str
    side: Literal["WEST", "EAST"]
    index: int
    label: str | None = None
    negated: bool = False
    element: str | None = None
    open: bool = False


class FbdLayoutNode(_Frozen):
    """A box: ``title`` is what is written in it (``&``, ``>=1``, ``S_ODT``, ``=`` ...),
    ``operand`` what is written above it (the coil's bit, the edge memory, the jump label)."""

    id: str
    kind: str
    title: str
    operand: str | None = None
    layer: int
    order: int
    width: int
    height: int
    ports: list[FbdPort]


class FbdLayoutEdge(_Frozen):
    id: str
    source: str
    source_port: str
    target: str
    target_port: str


class FbdLayout(_Frozen):
    layers: int
    nodes: list[FbdLayoutNode]
    edges: list[FbdLayoutEdge]


_Box = FbdNode | FbdFinal
_TITLES = {"AND": "&", "OR": ">=1", "XOR": "XOR"}


def _inputs(node: _Box) -> list[tuple[str, str | FbdNode | None]]:
    """The node's input pins in drawing order, each with its operand text or feeding node
    (None: a pin of a catalogued box nothing is connected to; a catalogued box shows all its
    pins in the catalogue's order, as in LAD)."""
    if isinstance(node, FbdLogic):
        return [(f"IN{index + 1}", item) for index, item in enumerate(node.inputs)]
    if isinstance(node, FbdBox):
        flow_in = flow_pins(node.name)[0] or "EN"
        spec = box_spec(node.name)
        names = [] if spec is None else [p.name for p in spec.inputs if p.name != flow_in]
        names += [name for name in node.inputs if name not in names]
        pins: list[tuple[str, str | FbdNode | None]] = [(n, node.inputs.get(n)) for n in names]
        return pins if node.en is None else [(flow_in, node.en), *pins]
    if isinstance(node, FbdOperand | FbdStatus | FbdBranch):
        return []
    return [("IN", node.input)]


def _outputs(node: _Box) -> list[tuple[str, str | None]]:
    if isinstance(node, FbdOperand):  # only the lone logic of a network without outputs
        return [("OUT", node.operand)]
    if isinstance(node, FbdStatus):
        return [("OUT", node.bit)]
    if isinstance(node, FbdBox):
        flow_out = flow_pins(node.name)[1] or "OUT"
        spec = box_spec(node.name)
        names = [] if spec is None else [p.name for p in spec.outputs if p.name != flow_out]
        names += [name for name in node.outputs if name != flow_out and name not in names]
        return [(flow_out, node.outputs.get(flow_out)), *((n, node.outputs.get(n)) for n in names)]
    if isinstance(node, FbdAssign | FbdJump | FbdReturn | FbdOpenDb):
        return []
    return [("OUT", None)]


def _title(node: _Box) -> str:
    if isinstance(node, FbdOperand | FbdStatus):
        return ""  # no box: the operand is written at its output
    if isinstance(node, FbdLogic):
        return _TITLES[node.op]
    if isinstance(node, FbdBox):
        return node.name if node.instance is None else f"{node.instance} {node.name}"
    if isinstance(node, FbdAssign):
        return node.coil
    if isinstance(node, FbdJump):
        return "JMPN" if node.negated else "JMP"
    if isinstance(node, FbdMidline):
        return "#"
    if isinstance(node, FbdEdge):
        return node.edge
    return {"not": "NOT", "ret": "RET", "opn": "OPN"}.get(node.kind, node.kind)


def _operand(node: _Box) -> str | None:
    """The operand written above the box (the coil's bit, the midline's, the edge memory ...)."""
    if isinstance(node, FbdAssign | FbdMidline):
        return node.operand
    if isinstance(node, FbdEdge):
        return node.memory
    if isinstance(node, FbdJump):
        return node.label
    if isinstance(node, FbdOpenDb):
        return node.block
    return None


class _Layering:
    def __init__(self, fbd: FbdNetwork) -> None:
        self.logic: FbdNode = fbd.logic
        self.depth: dict[int, int] = {}
        self.first: list[_Box] = []
        self.ids: dict[int, str] = {}
        self.in_logic: set[int] = set()
        self.ands: dict[str, FbdLogic] = {}
        self.path: set[int] = set()
        self.loops: set[tuple[int, int]] = set()
        self._mark(fbd.logic, self.in_logic)
        for final in fbd.outputs:
            self._mark(final, set())

    def _mark(self, node: _Box, seen: set[int]) -> None:
        seen.add(id(node))
        if isinstance(node, FbdLogic):
            if node.op == "AND" and node.id:
                self.ands.setdefault(node.id, node)
            if node.flow is not None:
                self._mark(node.flow, seen)
        for _, value in _inputs(node):
            if value is not None and not isinstance(value, str):
                self._mark(value, seen)

    def resolve(self, node: str | FbdNode, owner: _Box) -> str | FbdNode:
        """The node behind a wire: the common logic behind a T-branch, the AND box behind a
        tap of its wire (a T-branch inside the common logic itself, or a tap of a box that is
        not there, which LAD refuses, stays an open pin)."""
        if isinstance(node, FbdBranch):
            if node.source:
                return self.ands.get(node.source, node)
            if id(owner) not in self.in_logic:
                return self.logic
        return node

    def visit(self, node: _Box, depth: int) -> None:
        key = id(node)
        if key not in self.depth:
            self.first.append(node)
            self.ids[key] = self._name(node)
        elif self.depth[key] >= depth:
            return
        self.depth[key] = depth
        self.path.add(key)
        for _, value in _inputs(node):
            if value is None:
                continue
            fed = self.resolve(value, node)
            if isinstance(fed, str | FbdOperand | FbdStatus | FbdBranch):
                continue
            if id(fed) in self.path:  # a box tapping its own wire (no LAD): an open pin
                self.loops.add((key, id(value)))
                continue
            self.visit(fed, depth + 1)
        self.path.discard(key)

    def _name(self, node: _Box) -> str:
        taken = set(self.ids.values())
        if node.id and node.id not in taken:
            return node.id
        count = len(taken)
        while f"n{count}" in taken:
            count += 1
        return f"n{count}"


def _lone_operand(node: _Box) -> tuple[bool, str | None]:
    """The negation circle and the element at the output of a node that is an operand (the
    lone logic of a network without outputs); none for a box."""
    if isinstance(node, FbdOperand | FbdStatus):
        return node.negated, node.id or None
    return False, None


def _is_rail(node: FbdNode) -> bool:
    """Whether ``node`` is the empty series: an AND without inputs, always true."""
    return isinstance(node, FbdLogic) and node.op == "AND" and not node.inputs and node.flow is None


def _west(walk: _Layering, node: _Box, name: str) -> tuple[list[FbdPort], list[FbdLayoutEdge]]:
    """The node's input ports, with the operand written at each, and the wires into them."""
    ports: list[FbdPort] = []
    edges: list[FbdLayoutEdge] = []
    for index, (pin, value) in enumerate(_inputs(node)):
        port = f"{name}.W.{index}"
        if value is None:
            ports.append(FbdPort(id=port, name=pin, side="WEST", index=index, open=True))
            continue
        fed = walk.resolve(value, node)
        if isinstance(fed, str):
            ports.append(FbdPort(id=port, name=pin, side="WEST", index=index, label=fed))
        elif isinstance(fed, FbdOperand | FbdStatus):
            text = fed.operand if isinstance(fed, FbdOperand) else fed.bit
            element = fed.id or None
            ports.append(
                FbdPort(
                    id=port,
                    name=pin,
                    side="WEST",
                    index=index,
                    label=text,
                    negated=fed.negated,
                    element=element,
                )
            )
        else:
            ports.append(FbdPort(id=port, name=pin, side="WEST", index=index))
            if isinstance(fed, FbdBranch) or (id(node), id(value)) in walk.loops:
                continue  # an open pin: a T-branch LAD refuses
            source = walk.ids[id(fed)]
            edges.append(
                FbdLayoutEdge(
                    id=f"{source}->{port}",
                    source=source,
                    source_port=f"{source}.E.0",
                    target=name,
                    target_port=port,
                )
            )
    return ports, edges


def _east(node: _Box, name: str) -> list[FbdPort]:
    """The node's output ports, with the operand written at each."""
    negated, element = _lone_operand(node)
    return [
        FbdPort(
            id=f"{name}.E.{index}",
            name=pin,
            side="EAST",
            index=index,
            label=label,
            negated=negated,
            element=element,
            open=isinstance(node, FbdBox) and index > 0 and label is None,
        )
        for index, (pin, label) in enumerate(_outputs(node))
    ]


def fbd_layout(fbd: FbdNetwork) -> FbdLayout:
    """The layered graph of one FBD network (see the module docstring for the rules); none for
    a network kept as STL or an empty one."""
    if fbd.stl is not None:
        return FbdLayout(layers=0, nodes=[], edges=[])
    walk = _Layering(fbd)
    for final in fbd.outputs:
        walk.visit(final, 0)
    if not fbd.outputs and not _is_rail(fbd.logic):  # a network being drawn ends at its logic
        walk.visit(fbd.logic, 0)
    if not walk.depth:
        return FbdLayout(layers=0, nodes=[], edges=[])
    deepest = max(walk.depth.values())
    orders: dict[int, int] = {}
    nodes: list[FbdLayoutNode] = []
    edges: list[FbdLayoutEdge] = []
    for node in walk.first:
        name = walk.ids[id(node)]
        layer = deepest - walk.depth[id(node)]
        order = orders.get(layer, 0)
        orders[layer] = order + 1
        ports, into = _west(walk, node, name)
        east = _east(node, name)
        edges.extend(into)
        nodes.append(
            FbdLayoutNode(
                id=name,
                kind=node.kind,
                title=_title(node),
                operand=_operand(node),
                layer=layer,
                order=order,
                width=2,
                height=max(1, len(ports), len(east)),
                ports=[*ports, *east],
            )
        )
    return FbdLayout(layers=deepest + 1, nodes=nodes, edges=edges)

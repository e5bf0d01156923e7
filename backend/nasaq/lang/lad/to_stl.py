"""LAD/FBD → STL: every network lowers to the STL STEP 7 Classic generates for it.

The shapes are listed in ``STL_PATTERNS.md`` beside this module (the STL → LAD direction
recognises them). Lowering always yields STL: an element that cannot be lowered (an unknown box,
a wrong pin, an element where it cannot sit) is reported with its network and element id and
left out, and the rest of the network still lowers.

Where STEP 7 keeps a power flow in an absolute local bit (``= L 20.0``) we use BOOL temporaries
``#_lad_t0`` … declared in an extra ``VAR_TEMP`` section, so that the block's own temporaries
keep their addresses.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from nasaq.diagnostics import Diagnostic, Span, render
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
    Output,
    Parallel,
    Return,
    Series,
    StatusContact,
)
from nasaq.lang.lad.to_stl_boxes import lower_box, needs_whole_flow
from nasaq.lang.lad.to_stl_unfilled import without_unfilled

_TIMER_COILS = ("SP", "SE", "SD", "SS", "SF")
_ENDS = {"OB": "ORGANIZATION_BLOCK", "FB": "FUNCTION_BLOCK", "FC": "FUNCTION"}


def stl_line(op: str, operand: str = "", label: str | None = None) -> str:
    """One STL line in STEP 7's columns: a label (or 6 spaces), the mnemonic in 6, the operand."""
    head = f"{label + ':':<5} " if label else " " * 6
    return f"{head}{op:<6}{operand}".rstrip() if operand else f"{head}{op}".rstrip()


class LabelMaker:
    """The naming state of one block's lowering: jump labels ``_001`` … (skipping the user's
    labels), the temporaries' prefix, how many temporaries the largest network needs, the
    network being lowered and the problems found so far."""

    def __init__(self, taken: Iterable[str] = (), temp_prefix: str = "_lad_t") -> None:
        self.taken = {label.upper() for label in taken}
        self.count = 0
        self.temp_prefix = temp_prefix
        self.temps_needed = 0
        self.network = 1
        self.diagnostics: list[Diagnostic] = []

    def label(self) -> str:
        while True:
            self.count += 1
            label = f"_{self.count:03d}"
            if label not in self.taken:
                self.taken.add(label)
                return label

    def temp(self, index: int) -> str:
        self.temps_needed = max(self.temps_needed, index + 1)
        return f"#{self.temp_prefix}{index}"

    def report(self, code: str, element: str | None, **params: object) -> None:
        """A problem of the network being lowered; ``element`` None: of the whole network."""
        span = Span(network=self.network, element=element or None)
        if element is not None:
            params["element"] = element or "?"
        self.diagnostics.append(render(code, span, network=self.network, **params))


class NetworkLowering:
    """The STL of one network; the chain helpers return whether a chain has started (an RLO is
    being built), which decides ``A`` vs. brackets, ``JNB`` vs. nothing, ``JC`` vs. ``JU``.

    ``elements`` names, per line, the element the line belongs to (its ``owner`` when it was
    emitted): monitoring reads an element's status from its lines, and a problem the STL
    compiler finds on a line is placed on its element. Lines the lowering adds for the network
    as a whole (the temporary that carries the common logic to several outputs) have None."""

    def __init__(self, labels: LabelMaker) -> None:
        self.labels = labels
        self.lines: list[str] = []
        self.elements: list[str | None] = []
        self.owner: str | None = None
        self.temps = 0

    # -- primitives used by the box lowering ------------------------------------------------------

    def emit(self, op: str, operand: str = "", label: str | None = None) -> None:
        self.lines.append(stl_line(op, operand, label))
        self.elements.append(self.owner)

    def own(self, element_id: str) -> str | None:
        """Makes the element the owner of the lines emitted next and returns the owner to
        restore; an element without an id (a temporary the lowering reads as a contact) keeps
        the owner it stands in."""
        previous = self.owner
        if element_id:
            self.owner = element_id
        return previous

    def temp(self) -> str:
        name = self.labels.temp(self.temps)
        self.temps += 1
        return name

    def report(self, code: str, element: str | None, **params: object) -> None:
        self.labels.report(code, element, **params)

    def bool_input(self, value: str | Series, started: bool) -> bool:
        """A Boolean pin fed by an operand (``A x``) or by logic, ANDed onto the chain."""
        if isinstance(value, str):
            self.emit("A", value)
            return True
        return self.chain(value.elements, started)

    # -- logic --------------------------------------------------------------------------------

    def chain(self, elements: Sequence[Element], started: bool) -> bool:
        if not started and len(elements) == 1 and isinstance(elements[0], Parallel):
            previous = self.own(elements[0].id)
            self.parallel(elements[0], None)
            self.owner = previous
            return True
        for element in elements:
            started = self.element(element, started)
        return started

    def element(self, element: Element, started: bool) -> bool:
        previous = self.own(element.id)
        started = self.lower_element(element, started)
        self.owner = previous
        return started

    def lower_element(self, element: Element, started: bool) -> bool:
        if isinstance(element, Contact | StatusContact):
            operand = element.operand if isinstance(element, Contact) else element.bit
            self.emit("AN" if element.negated else "A", operand)
            return True
        if isinstance(element, Parallel):
            prefix = None
            if started and needs_whole_flow(element):  # each branch starts from the flow so far
                prefix = Contact(operand=self.temp())
                self.emit("=", prefix.operand)
            self.emit("A(")
            self.parallel(element, prefix)
            self.emit(")")
            return True
        if isinstance(element, Box):
            return lower_box(self, element, started, in_chain=True)
        if not started:
            what = "NOT" if isinstance(element, Invert) else element.kind  # a problemWords key
            self.report("LAD205", element.id, what=what)
            return started
        if isinstance(element, Invert):
            self.emit("NOT")
        elif isinstance(element, EdgeContact):
            self.emit("FP" if element.edge == "P" else "FN", element.memory)
        elif isinstance(element, Midline):
            self.emit("=", element.operand)
            self.emit("A", element.operand)
        return True

    def parallel(self, parallel: Parallel, prefix: Contact | None) -> bool:
        """The OR of the branches as the start of a chain (no bracket around it)."""
        for index, branch in enumerate(parallel.branches):
            elements: list[Element] = [*([prefix] if prefix else []), *branch.elements]
            if not elements:
                self.report("LAD206", parallel.id)
                continue
            if len(elements) == 1 and isinstance(elements[0], Contact | StatusContact):
                self.element_or(elements[0])
            elif len(elements) > 1 and all(_in_and_group(item) for item in elements):
                if index > 0:
                    self.emit("O")
                self.chain(elements, False)
            else:
                self.emit("O(")
                self.chain(elements, False)
                self.emit(")")
        return True

    def element_or(self, element: Element) -> None:
        assert isinstance(element, Contact | StatusContact)
        operand = element.operand if isinstance(element, Contact) else element.bit
        previous = self.own(element.id)
        self.emit("ON" if element.negated else "O", operand)
        self.owner = previous

    # -- outputs ------------------------------------------------------------------------------

    def outputs(self, logic: Series, outputs: Sequence[Output]) -> None:
        if len(outputs) == 1:
            only = outputs[0]
            if isinstance(only.target, OpenDb):
                self.open_db(only.target, [*logic.elements, *only.conditions.elements])
                return
            started = self.chain([*logic.elements, *only.conditions.elements], False)
            self.target(only.target, started)
            return
        simple = all(not out.conditions.elements for out in outputs) and all(
            isinstance(out.target, Coil | OpenDb) for out in outputs[:-1]
        )
        opens = [out for out in outputs if isinstance(out.target, OpenDb)]
        for out in opens:
            assert isinstance(out.target, OpenDb)
            self.open_db(out.target, [*logic.elements, *out.conditions.elements])
        rest = [out for out in outputs if not isinstance(out.target, OpenDb)]
        if not rest:
            return
        started = self.chain(logic.elements, False)
        if simple:
            for out in rest:
                started = self.target(out.target, started) or started
            return
        if not started:
            self.emit("SET")
        kept = self.temp()
        self.emit("=", kept)
        for out in rest:
            started = self.chain([Contact(operand=kept), *out.conditions.elements], False)
            self.target(out.target, started)

    def open_db(self, target: OpenDb, flow: Sequence[Element]) -> None:
        if flow:
            self.report("LAD207", target.id)
        previous = self.own(target.id)
        self.emit("OPN", target.block)
        self.owner = previous

    def target(self, target: Final, started: bool) -> bool:
        """Emits a rung's end; returns whether the RLO is still the chain's (a coil keeps it)."""
        previous = self.own(target.id)
        started = self.lower_target(target, started)
        self.owner = previous
        return started

    def lower_target(self, target: Final, started: bool) -> bool:
        if isinstance(target, Box):
            lower_box(self, target, started, in_chain=False)
            return False
        if isinstance(target, Jump):
            if started:
                self.emit("JCN" if target.negated else "JC", target.label)
            elif target.negated:
                self.emit("SET")
                self.emit("JCN", target.label)
            else:
                self.emit("JU", target.label)
            return False
        if isinstance(target, Return):
            self.emit("BEC" if started else "BEU")
            return False
        if isinstance(target, OpenDb):
            self.open_db(target, [])
            return started
        return self.coil(target, started)

    def coil(self, coil: Coil, started: bool) -> bool:
        kind = coil.coil
        if kind != "SAVE" and not coil.operand:
            self.report("LAD210", coil.id, coil=kind, what="operand")
            return started
        needs_value = kind in _TIMER_COILS or kind == "SC"
        if needs_value and not coil.value:
            self.report("LAD210", coil.id, coil=kind, what="value")
            return started
        if not started:
            self.emit("SET")
        if needs_value:
            self.emit("L", coil.value or "")
        if kind == "SAVE":
            self.emit("SAVE")
        else:
            self.emit("S" if kind == "SC" else kind, coil.operand)
        return True

    def network(self, network: Network) -> list[str]:
        """The network's lines: an empty rung has none (as in STEP 7), a rung still waiting
        for its output none either (LAD211), its label aside."""
        rung = without_unfilled(network, self.report)
        if not network.outputs and network.logic.elements:
            self.report("LAD211", None)
        if rung.outputs:
            self.outputs(rung.logic, rung.outputs)
        if network.label:
            first = self.lines[0].lstrip() if self.lines else "NOP   0"
            self.lines[:1] = [f"{network.label + ':':<5} {first}"]
            self.elements[:1] = self.elements[:1] or [None]
        return self.lines


def _in_and_group(element: Element) -> bool:
    """Whether an element can stand in an AND group of an OR (after ``O`` with no operand):
    checks and brackets keep the pending OR; NOT, assignments, compares and boxes would not."""
    if isinstance(element, Parallel):
        return not needs_whole_flow(element)
    return isinstance(element, Contact | StatusContact)


def network_to_stl(network: Network, labels: LabelMaker) -> tuple[list[str], list[str | None]]:
    """The STL lines of one network (without the ``NETWORK``/``TITLE`` header) and the element
    each line belongs to. Problems go to ``labels.diagnostics``; ``labels.network`` is the
    network's number for them. A network that stayed STL (``Network.stl``) is its own lines,
    of no element."""
    if network.stl is not None:
        lines = network.stl.split("\n") if network.stl else []
        return lines, [None] * len(lines)
    lowering = NetworkLowering(labels)
    return lowering.network(network), lowering.elements


_STL_LABEL = re.compile(r"^[ \t]*([A-Za-z_]\w*)[ \t]*:(?!=)", re.MULTILINE)


def _labels_taken(block: LadBlock) -> list[str]:
    """The jump labels the user wrote: of LAD networks, and inside networks kept as STL."""
    taken = [net.label for net in block.networks if net.label]
    for net in block.networks:
        if net.stl:
            taken += _STL_LABEL.findall(net.stl)
    return taken


def temp_prefix(declarations: str) -> str:
    """The name of the lowering's temporaries (``_lad_t`` unless the declarations use it)."""
    lowered = declarations.lower()
    prefix, attempt = "_lad_t", 1
    while prefix in lowered:
        attempt += 1
        prefix = f"_lad{attempt}_t"
    return prefix


def _header(block: LadBlock) -> str:
    if block.kind == "FC":
        return f"FUNCTION {block.name} : {block.return_type or 'VOID'}"
    return f"{_ENDS[block.kind]} {block.name}"


@dataclass(slots=True)
class LoweredBlock:
    """A block's STL source, the problems found while lowering it, and per line of ``text``
    the LAD/FBD element it belongs to (None: the block's frame, headers, kept STL)."""

    text: str
    diagnostics: list[Diagnostic]
    elements: list[str | None]


class _Source:
    """Lines of the generated source with the element of each (text may hold several lines)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.elements: list[str | None] = []

    def add(self, text: str) -> None:
        parts = text.split("\n")
        self.lines += parts
        self.elements += [None] * len(parts)


def lower_block(block: LadBlock) -> LoweredBlock:
    """A complete STL source of the block (header, the declarations as they are, temporaries,
    networks) for ``compile_sources``, the problems found while lowering, and the element of
    each line."""
    labels = LabelMaker(_labels_taken(block), temp_prefix(block.declarations))
    body = _Source()
    for number, network in enumerate(block.networks, start=1):
        labels.network = number
        body.add("NETWORK")
        body.add(f"TITLE = {network.title}".rstrip())
        for line in network.comment.splitlines():
            body.add(f"//{line}")
        lines, elements = network_to_stl(network, labels)
        body.lines += lines
        body.elements += elements
    out = _Source()
    out.add(_header(block))
    if block.title:
        out.add(f"TITLE = {block.title}")
    if block.declarations.strip():
        out.add(block.declarations.rstrip("\n"))
    if labels.temps_needed:
        out.add("VAR_TEMP")
        for index in range(labels.temps_needed):
            out.add(f"  {labels.temp_prefix}{index} : BOOL;")
        out.add("END_VAR")
    out.add("BEGIN")
    out.lines += body.lines
    out.elements += body.elements
    out.add(f"END_{_ENDS[block.kind]}")
    return LoweredBlock("\n".join(out.lines) + "\n", labels.diagnostics, out.elements)


def block_to_stl(block: LadBlock) -> tuple[str, list[Diagnostic]]:
    """The block's STL source and the problems found while lowering it (``lower_block``)."""
    lowered = lower_block(block)
    return lowered.text, lowered.diagnostics

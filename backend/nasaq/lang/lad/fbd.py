"""The FBD view of the network model: the rung drawn as boxes and wires.

STEP 7 shows one network in LAD or FBD without losing anything, because both draw the same
series/parallel tree (``nasaq.lang.lad.model``). Here the tree is turned into boxes:

* a series is an ``AND`` box, a parallel an ``OR`` box; a series of one element needs no box, and
  the empty series (the rail itself) is an ``AND`` without inputs (always true);
* a contact is an operand on a pin, a normally closed contact the same operand with a negation
  circle (``negated``); status bits likewise;
* an element that takes *the power flow so far* (``--|NOT|--``, ``(P)``/``(N)``, the midline
  ``(#)``, boxes with EN or a timer's S ...) is a box whose flow input is everything left of it;
  what follows it in the series is ANDed to its output. A box without a flow pin (comparators,
  POS/NEG, see ``boxes``) is one input of the AND, like a contact, as STEP 7 draws it;
* the rung's common part (``Network.logic``) is :attr:`FbdNetwork.logic`; each output is a final
  box (``=``/``S``/``R``/timer/counter coils, JMP/JMPN, RET, OPN or a box) whose input starts
  from that common wire, :class:`FbdBranch` (the T-branch of STEP 7 FBD). A rung being drawn
  without outputs yet is its logic and no final boxes (an empty rung: the AND without inputs),
  and ``from_fbd`` reads such a network back as the rung without outputs;
* a parallel after other elements whose branches hold an element acting on the flow (NOT, an
  edge, a midline, a box with EN ...): every branch starts from the power flow *into* the
  parallel and the parallel passes the OR of its branches, as in IEC 61131-3 ladder (a
  parallel is a wired OR of branches fed from one left link) and as ``to_stl`` lowers it
  (``= #_lad_tN``, then ``A(`` with each branch from ``#_lad_tN``). The flow so far becomes an
  AND box ``&k``, the OR's ``flow``, and each branch starts from a T-branch of its wire
  (``FbdBranch(source="&k")``). A parallel of checks only stays ``AND(x, OR(...))``: for it
  the two readings give the same.

``to_fbd`` always succeeds. ``from_fbd`` refuses, with a catalogued reason (``LAD401``..), what
LAD cannot draw: XOR, a box/NOT/edge/midline output entering an AND anywhere but first, a network
that is not one rung. Normal forms, so that LAD -> FBD -> LAD gives the same tree back (element
ids aside) and FBD -> LAD -> FBD settles after one pass:

* an ``AND`` inside an ``AND`` is spliced into it (LAD has no series inside a series);
* an ``AND``/``OR`` with one input is that input;
* an ``OR`` inside an ``OR`` stays nested (LAD draws it as a branch holding a parallel);
* a negated box output is written as a :class:`FbdNot` box (the front end may draw it as a
  circle); only operands carry ``negated``, so ``AN x`` and ``A x`` + ``NOT`` stay apart.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.lang.lad.boxes import box_spec
from nasaq.lang.lad.model import (
    Box,
    Coil,
    CoilKind,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    Midline,
    Network,
    OpenDb,
    Output,
    Parallel,
    Return,
    Series,
    StatusBit,
    StatusContact,
)
from nasaq.lang.lad.to_stl_boxes import needs_whole_flow


class _Node(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    id: str = Field(default="", description="The LAD element's id; AND boxes get '&1', '&2' ...")


class FbdOperand(_Node):
    """An operand on a Boolean pin; ``negated`` draws the negation circle (LAD: NC contact)."""

    kind: Literal["operand"] = "operand"
    operand: str
    negated: bool = False


class FbdStatus(_Node):
    """A status bit on a Boolean pin (``OV``, ``==0`` ...), optionally negated."""

    kind: Literal["status"] = "status"
    bit: StatusBit
    negated: bool = False


class FbdLogic(_Node):
    """``AND``, ``OR`` or ``XOR`` (FBD only) of its inputs. An ``OR`` drawing a LAD parallel
    whose branches act on the flow has ``flow``: the AND box of the power flow into the
    parallel, which every branch starts from through a T-branch of its wire
    (``FbdBranch(source=flow.id)``); it is evaluated before the inputs."""

    kind: Literal["logic"] = "logic"
    op: Literal["AND", "OR", "XOR"]
    inputs: list[FbdNode] = Field(default_factory=list)
    flow: FbdNode | None = None


class FbdNot(_Node):
    """Negates its input (LAD ``--|NOT|--``)."""

    kind: Literal["not"] = "not"
    input: FbdNode


class FbdEdge(_Node):
    """``P``/``N`` edge of its input, remembered in ``memory`` (STL ``FP``/``FN``)."""

    kind: Literal["edge"] = "edge"
    edge: Literal["P", "N"]
    memory: str
    input: FbdNode


class FbdMidline(_Node):
    """The ``#`` box: writes its input to ``operand`` and passes it on."""

    kind: Literal["midline"] = "midline"
    operand: str
    input: FbdNode


class FbdBox(_Node):
    """Every element with named pins (``nasaq.lang.lad.model.Box``, one to one); ``en`` is the
    flow into its flow pin (EN, or a timer's S ...), its output the ENO (or Q). A box without a
    flow pin (comparators, POS/NEG: ``en`` None) is one more input of an AND, like a contact, as
    STEP 7 draws it. A Boolean pin fed by logic holds a node."""

    kind: Literal["box"] = "box"
    name: str
    instance: str | None = None
    en: FbdNode | None = None
    inputs: dict[str, str | FbdNode] = Field(default_factory=dict)
    outputs: dict[str, str] = Field(default_factory=dict)


class FbdBranch(_Node):
    """A T-branch: the wire of the network's common logic (:attr:`FbdNetwork.logic`) where an
    output branches off it, or (``source`` set) the wire of the AND box ``source`` that is the
    ``flow`` of an OR, at the start of each of that OR's branches."""

    kind: Literal["branch"] = "branch"
    source: str = Field(default="", description="The tapped AND box; empty: the common logic")


FbdNode = Annotated[
    FbdOperand | FbdStatus | FbdLogic | FbdNot | FbdEdge | FbdMidline | FbdBox | FbdBranch,
    Field(discriminator="kind"),
]


class FbdAssign(_Node):
    """The assignment box ``=``, ``S``, ``R``, a timer/counter coil box or ``SAVE``."""

    kind: Literal["assign"] = "assign"
    coil: CoilKind
    operand: str = ""
    value: str | None = None
    input: FbdNode


class FbdJump(_Node):
    kind: Literal["jump"] = "jump"
    negated: bool = False
    label: str
    input: FbdNode


class FbdReturn(_Node):
    kind: Literal["ret"] = "ret"
    input: FbdNode


class FbdOpenDb(_Node):
    kind: Literal["opn"] = "opn"
    block: str
    input: FbdNode


FbdFinal = Annotated[
    FbdAssign | FbdJump | FbdReturn | FbdOpenDb | FbdBox, Field(discriminator="kind")
]


class FbdNetwork(BaseModel):
    """One network in FBD: the common logic and the final boxes fed from it (none yet while
    the network is being drawn)."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    title: str = ""
    comment: str = ""
    label: str | None = None
    logic: FbdNode = Field(default_factory=lambda: FbdLogic(op="AND"))
    outputs: list[FbdFinal] = Field(default_factory=list)
    stl: str | None = Field(
        default=None, description="A network that stays STL (no LAD/FBD shape): its lines"
    )
    stl_reason: str | None = None


class FbdNotLad(BaseModel):
    """Why an FBD network cannot be shown in LAD; ``element`` is the node to highlight."""

    model_config = ConfigDict(frozen=True)

    element: str
    diagnostic: Diagnostic


for _model in (FbdLogic, FbdNot, FbdEdge, FbdMidline, FbdBox, FbdAssign, FbdJump, FbdReturn):
    _model.model_rebuild()
FbdOpenDb.model_rebuild()
FbdNetwork.model_rebuild()


def flow_pins(name: str) -> tuple[str | None, str | None]:
    """The pins the power flow enters and leaves box ``name`` by: ``EN``/``ENO`` for boxes with
    EN/ENO and calls, ``S``/``Q`` for a timer ..., ``(None, None)`` for a comparator."""
    spec = box_spec(name)
    if spec is None:
        return "EN", "ENO"
    return spec.flow_pin, spec.flow_out


def takes_flow(name: str) -> bool:
    """Whether box ``name`` takes the power flow so far (EN, S ...) rather than being ANDed."""
    return flow_pins(name)[0] is not None


# --- LAD -> FBD ------------------------------------------------------------------------------


class _ToFbd:
    """Numbers the AND boxes it creates, in reading order, so the output is deterministic."""

    def __init__(self) -> None:
        self._ands = 0

    def network(self, network: Network) -> FbdNetwork:
        if network.stl is not None:
            return FbdNetwork(
                title=network.title,
                comment=network.comment,
                label=network.label,
                stl=network.stl,
                stl_reason=network.stl_reason,
            )
        logic = self.series(network.logic)
        outputs = [self.final(out) for out in network.outputs]
        return FbdNetwork(
            title=network.title,
            comment=network.comment,
            label=network.label,
            logic=logic,
            outputs=outputs,
        )

    def final(self, output: Output) -> FbdFinal:
        flow = self.series(output.conditions, FbdBranch())
        target: Final = output.target
        if isinstance(target, Coil):
            return FbdAssign(
                id=target.id,
                coil=target.coil,
                operand=target.operand,
                value=target.value,
                input=flow,
            )
        if isinstance(target, Jump):
            return FbdJump(id=target.id, negated=target.negated, label=target.label, input=flow)
        if isinstance(target, Return):
            return FbdReturn(id=target.id, input=flow)
        if isinstance(target, OpenDb):
            return FbdOpenDb(id=target.id, block=target.block, input=flow)
        return self.box(target, flow)

    def series(self, series: Series, head: FbdNode | None = None) -> FbdNode:
        """AND of the series' terms; an element taking the flow so far closes the AND."""
        terms: list[FbdNode] = [] if head is None else [head]
        for element in series.elements:
            if isinstance(element, Contact):
                terms.append(
                    FbdOperand(id=element.id, operand=element.operand, negated=element.negated)
                )
            elif isinstance(element, StatusContact):
                terms.append(FbdStatus(id=element.id, bit=element.bit, negated=element.negated))
            elif isinstance(element, Parallel):
                terms = self.parallel(element, terms)
            elif isinstance(element, Box) and not takes_flow(element.name):
                terms.append(self.box(element, None))
            else:
                terms = [self.flow_element(element, self.conjunction(terms))]
        return self.conjunction(terms)

    def parallel(self, parallel: Parallel, terms: list[FbdNode]) -> list[FbdNode]:
        """The terms with the OR box of ``parallel`` added; when its branches act on the flow
        and something comes before it, the OR replaces the terms: they become its ``flow``."""
        if not terms or not needs_whole_flow(parallel):
            branches = [self.series(branch) for branch in parallel.branches]
            return [*terms, FbdLogic(id=parallel.id, op="OR", inputs=branches)]
        self._ands += 1
        flow = FbdLogic(id=f"&{self._ands}", op="AND", inputs=terms)
        branches = [self.series(branch, FbdBranch(source=flow.id)) for branch in parallel.branches]
        return [FbdLogic(id=parallel.id, op="OR", inputs=branches, flow=flow)]

    def flow_element(self, element: Element, flow: FbdNode) -> FbdNode:
        if isinstance(element, Invert):
            return FbdNot(id=element.id, input=flow)
        if isinstance(element, EdgeContact):
            return FbdEdge(id=element.id, edge=element.edge, memory=element.memory, input=flow)
        if isinstance(element, Midline):
            return FbdMidline(id=element.id, operand=element.operand, input=flow)
        assert isinstance(element, Box)
        return self.box(element, flow)

    def box(self, box: Box, flow: FbdNode | None) -> FbdBox:
        inputs: dict[str, str | FbdNode] = {
            pin: value if isinstance(value, str) else self.series(value)
            for pin, value in box.inputs.items()
        }
        return FbdBox(
            id=box.id,
            name=box.name,
            instance=box.instance,
            en=flow,
            inputs=inputs,
            outputs=dict(box.outputs),
        )

    def conjunction(self, terms: list[FbdNode]) -> FbdNode:
        if len(terms) == 1:
            return terms[0]
        self._ands += 1
        return FbdLogic(id=f"&{self._ands}", op="AND", inputs=terms)


def to_fbd(network: Network) -> FbdNetwork:
    """The FBD view of a LAD network; every network has one."""
    return _ToFbd().network(network)


# --- FBD -> LAD ------------------------------------------------------------------------------


class _NotLadError(Exception):
    def __init__(self, code: str, element: str, **params: str) -> None:
        super().__init__(code)
        self.code = code
        self.element = element
        self.params = params


def _takes_flow(element: Element) -> bool:
    if isinstance(element, Box):
        return takes_flow(element.name)
    return isinstance(element, Invert | EdgeContact | Midline)


_COMMON = ""  # the wire of the network's common logic, as FbdBranch.source names it
_NO_WIRE: frozenset[str] = frozenset()


class _FromFbd:
    """Reads a node as a LAD series. ``wires`` are the T-branches that may start the chain:
    the common wire (``_COMMON``) at the start of an output, the wire of an OR's ``flow`` box at
    the start of each of that OR's branches."""

    def __init__(self) -> None:
        self._seen: set[str] = set()
        self._final = "?"  # the output being read, named when its common wire is misplaced

    def network(self, fbd: FbdNetwork) -> Network:
        if fbd.stl is not None:
            return Network(
                title=fbd.title,
                comment=fbd.comment,
                label=fbd.label,
                stl=fbd.stl,
                stl_reason=fbd.stl_reason,
            )
        self._final = fbd.logic.id or "logic"
        _, logic = self.chain(fbd.logic, _NO_WIRE)
        rail = not logic and isinstance(fbd.logic, FbdLogic)
        outputs = []
        for final in fbd.outputs:
            self.claim(final.id)
            self._final = final.id or "?"
            starts, conditions = self.chain(self.flow_of(final), frozenset({_COMMON}))
            if starts is None and not rail:
                raise _NotLadError("LAD403", self._final)
            outputs.append(
                Output(conditions=Series(elements=conditions), target=self.target(final))
            )
        return Network(
            title=fbd.title,
            comment=fbd.comment,
            label=fbd.label,
            logic=Series(elements=logic),
            outputs=outputs,
        )

    def claim(self, ident: str) -> None:
        if ident and ident in self._seen:
            raise _NotLadError("LAD406", ident)
        self._seen.add(ident)

    @staticmethod
    def flow_of(final: FbdFinal) -> FbdNode:
        if isinstance(final, FbdBox):
            return FbdBranch() if final.en is None else final.en
        return final.input

    def target(self, final: FbdFinal) -> Final:
        if isinstance(final, FbdAssign):
            return Coil(id=final.id, coil=final.coil, operand=final.operand, value=final.value)
        if isinstance(final, FbdJump):
            return Jump(id=final.id, negated=final.negated, label=final.label)
        if isinstance(final, FbdReturn):
            return Return(id=final.id)
        if isinstance(final, FbdOpenDb):
            return OpenDb(id=final.id, block=final.block)
        return self.box(final)

    def chain(self, node: FbdNode, wires: frozenset[str]) -> tuple[str | None, list[Element]]:
        """The series ``node`` stands for, and the T-branch it starts from (None: none)."""
        if isinstance(node, FbdBranch):
            if node.source not in wires:
                if node.source == _COMMON:
                    raise _NotLadError("LAD402", node.id or self._final)
                raise _NotLadError("LAD407", node.source, where=node.id or self._final)
            return node.source, []
        self.claim(node.id)
        if isinstance(node, FbdOperand):
            return None, [Contact(id=node.id, operand=node.operand, negated=node.negated)]
        if isinstance(node, FbdStatus):
            return None, [StatusContact(id=node.id, bit=node.bit, negated=node.negated)]
        if isinstance(node, FbdLogic):
            return self.logic(node, wires)
        if isinstance(node, FbdBox):
            if node.en is None:
                return None, [self.box(node)]
            starts, elements = self.chain(node.en, wires)
            return starts, [*elements, self.box(node)]
        starts, elements = self.chain(node.input, wires)
        if isinstance(node, FbdNot):
            return starts, [*elements, Invert(id=node.id)]
        if isinstance(node, FbdEdge):
            return starts, [*elements, EdgeContact(id=node.id, edge=node.edge, memory=node.memory)]
        return starts, [*elements, Midline(id=node.id, operand=node.operand)]

    def logic(self, node: FbdLogic, wires: frozenset[str]) -> tuple[str | None, list[Element]]:
        if node.op == "XOR":
            raise _NotLadError("LAD401", node.id or "?")
        if node.op == "OR":
            return self.either(node, wires)
        starts: str | None = None
        elements: list[Element] = []
        for index, item in enumerate(node.inputs):
            item_starts, more = self.chain(item, wires if index == 0 else _NO_WIRE)
            if index == 0:
                starts = item_starts
            elif isinstance(item, FbdLogic) and item.flow is not None:
                raise _NotLadError("LAD405", item.id or "?", box=node.id or "?")
            else:
                for element in more:
                    if _takes_flow(element):
                        raise _NotLadError("LAD405", element.id or "?", box=node.id or "?")
            elements.extend(more)
        return starts, elements

    def either(self, node: FbdLogic, wires: frozenset[str]) -> tuple[str | None, list[Element]]:
        """An OR box: a LAD parallel. With a ``flow``, that flow is the series before the
        parallel and every branch starts from its wire; without, no branch starts from a wire."""
        if not node.inputs:
            raise _NotLadError("LAD404", node.id or "?")
        starts: str | None = None
        before: list[Element] = []
        taps = _NO_WIRE
        if node.flow is not None:
            flow = node.flow
            if not isinstance(flow, FbdLogic) or flow.op != "AND" or not flow.id:
                raise _NotLadError("LAD407", flow.id or "?", where=node.id or "?")
            starts, before = self.chain(flow, wires)
            taps = frozenset({flow.id})
        elif len(node.inputs) == 1:
            return self.chain(node.inputs[0], wires)
        read = [self.chain(item, taps) for item in node.inputs]
        if taps and any(item_starts is None for item_starts, _ in read):
            raise _NotLadError("LAD407", next(iter(taps), "?"), where=node.id or "?")
        branches = [Series(elements=elements) for _, elements in read]
        if len(branches) == 1:  # a parallel of one branch is that branch
            return starts, [*before, *branches[0].elements]
        return starts, [*before, Parallel(id=node.id, branches=branches)]

    def box(self, node: FbdBox) -> Box:
        inputs: dict[str, str | Series] = {}
        for pin, value in node.inputs.items():
            if isinstance(value, str):
                inputs[pin] = value
            else:
                inputs[pin] = Series(elements=self.chain(value, _NO_WIRE)[1])
        return Box(
            id=node.id,
            name=node.name,
            instance=node.instance,
            inputs=inputs,
            outputs=dict(node.outputs),
        )


def from_fbd(fbd: FbdNetwork, network: int | None = None) -> Network | FbdNotLad:
    """The LAD rung an FBD network draws, or why LAD cannot draw it (``network``: its number,
    for the diagnostic's span)."""
    try:
        return _FromFbd().network(fbd)
    except _NotLadError as refusal:
        span = Span(network=network) if network is not None else None
        diagnostic = render(refusal.code, span=span, element=refusal.element, **refusal.params)
        return FbdNotLad(element=refusal.element, diagnostic=diagnostic)

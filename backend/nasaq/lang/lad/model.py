"""The network model LAD and FBD share: a rung is a series/parallel tree of elements.

A LAD network is a *rung*: the power flows from the left rail through ``logic`` (a
:class:`Series` of elements, where a :class:`Parallel` holds branches that are series again) and
then into its :class:`Output` branches (none yet while the rung is being drawn), each with its
own optional conditions and one final element (a coil, a jump, a box that ends the rung). FBD
draws the same tree as boxes: a series is an AND box, a parallel an OR box, a negated contact a
negated input; see ``nasaq.lang.lad.fbd`` for the FBD view and the one element LAD lacks (XOR).

The model holds structure only: no coordinates (layout is computed, ``layout.py``), operands as
the user wrote them (``"Start"``, ``I 0.0``, ``#count``, ``DB5.DBX 2.1``), which the STL compiler
resolves once the network has been lowered to STL. Every element carries an ``id`` unique in its
network (``e1``, ``e2`` ... by default, numbered in reading order) so that diagnostics, the
monitor's element status and the editors can point at it.

Boxes (``Box``) are every element with named pins: comparisons, MOVE, arithmetic, conversions,
word logic, shifts, timers, counters, flip-flops, edge boxes, and calls of FC/FB/SFC/SFB. Their
pins are described by ``nasaq.lang.lad.boxes``. In a rung a box sits in series: the power flow
into it is its EN (or its first Boolean input), the flow out of it its ENO (or its Q).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

StatusBit = Literal["OV", "OS", "BR", "UO", "==0", "<>0", ">0", "<0", ">=0", "<=0"]
CoilKind = Literal[
    "=",  # output coil
    "S",  # set coil
    "R",  # reset coil
    "SP",  # S5 timer coils: pulse, extended pulse, on delay, retentive on delay, off delay
    "SE",
    "SD",
    "SS",
    "SF",
    "CU",  # counter coils: count up, count down, set counter value
    "CD",
    "SC",
    "SAVE",  # ---(SAVE): the RLO into BR
]


class _Element(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    id: str = Field(default="", description="Unique in the network; empty: numbered on load")


class Contact(_Element):
    """A normally open (``negated`` False, STL ``A``) or normally closed (``AN``) contact."""

    kind: Literal["contact"] = "contact"
    operand: str
    negated: bool = False


class StatusContact(_Element):
    """A contact on a status bit or a result of the last math instruction (STL ``A OV``,
    ``A ==0`` ...); ``negated`` is the normally closed form."""

    kind: Literal["status"] = "status"
    bit: StatusBit
    negated: bool = False


class Invert(_Element):
    """``--|NOT|--``: inverts the power flow (STL ``NOT``)."""

    kind: Literal["not"] = "not"


class EdgeContact(_Element):
    """``--(P)--`` / ``--(N)--`` in the rung: the power flow for one scan at a rising/falling
    edge of the flow before it; ``memory`` keeps its previous state (STL ``FP``/``FN``). The
    address edge boxes (POS/NEG, with an M_BIT pin) are boxes."""

    kind: Literal["edge"] = "edge"
    edge: Literal["P", "N"]
    memory: str


class Midline(_Element):
    """``--(#)--``: the power flow so far is written to ``operand`` and flows on (STL ``=`` in
    the middle of a chain, reloaded with ``A``)."""

    kind: Literal["midline"] = "midline"
    operand: str


class Box(_Element):
    """An element with named pins (see ``nasaq.lang.lad.boxes``): ``name`` is the box
    (``CMP>=I``, ``MOVE``, ``ADD_I``, ``S_ODT``, ``SR``, ``FC 10``, ``"Motor"``, ``SFB 4``);
    ``instance`` the instance DB of an FB/SFB call (``DB 10``, or ``#inst`` for a
    multi-instance). ``inputs``/``outputs`` map a pin to its operand; a Boolean input fed by
    logic rather than an operand holds a :class:`Series` (in LAD: a branch drawn into the pin)."""

    kind: Literal["box"] = "box"
    name: str
    instance: str | None = None
    inputs: dict[str, str | Series] = Field(default_factory=dict)
    outputs: dict[str, str] = Field(default_factory=dict)


class Parallel(_Element):
    """Branches side by side (OR): every branch starts from the power flow into the parallel,
    and the flow passes when it passes any branch (a wired OR, as in IEC 61131-3 ladder). An
    element in a branch sees the flow at its position: a NOT after ``a`` in a branch gives
    NOT(flow into the parallel AND a)."""

    kind: Literal["parallel"] = "parallel"
    branches: list[Series] = Field(min_length=2)


Element = Annotated[
    Contact | StatusContact | Invert | EdgeContact | Midline | Box | Parallel,
    Field(discriminator="kind"),
]


class Series(BaseModel):
    """Elements one after the other (AND). Empty: the rail itself (always powered)."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    elements: list[Element] = Field(default_factory=list)


class Coil(_Element):
    """A rung's end: ``=``/``S``/``R`` on a bit, a timer coil with its time value (``value``:
    ``S5T#5S`` or an operand), a counter coil (``SC`` with its preset value), or ``SAVE``."""

    kind: Literal["coil"] = "coil"
    coil: CoilKind
    operand: str = ""
    value: str | None = None


class Jump(_Element):
    """``--(JMP)--`` to ``label`` when powered, ``--(JMPN)--`` when not (STL ``JC``/``JCN``; a
    jump straight from the rail is ``JU``)."""

    kind: Literal["jump"] = "jump"
    negated: bool = False
    label: str


class Return(_Element):
    """``--(RET)--``: ends the block when powered (STL ``BEC``)."""

    kind: Literal["ret"] = "ret"


class OpenDb(_Element):
    """``--(OPN)--``: opens a data block (STL ``OPN DB n``); it needs no power flow."""

    kind: Literal["opn"] = "opn"
    block: str


Final = Annotated[Coil | Jump | Return | OpenDb | Box, Field(discriminator="kind")]


class Output(BaseModel):
    """One branch at the rung's end: optional conditions of its own, then its final element."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    conditions: Series = Field(default_factory=Series)
    target: Final


class Network(BaseModel):
    """One network: a rung (LAD; FBD shows the same tree), an optional jump label at its
    start (``LABEL``), its title and comment.

    A rung being drawn may have no outputs yet: an empty rung (a new network; it lowers to an
    empty network, or to the label's ``NOP 0``) or logic still waiting for its coil, which the
    lowering reports (LAD211) as TIA Portal reports an unfinished network at compile time.

    A network without LAD shape stays STL, as in STEP 7's LAD view of an STL block: ``stl``
    holds its instructions as written (label included) and ``stl_reason`` the code of the
    reason it does not convert (``LAD3xx``); it then has no logic and no outputs."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    title: str = ""
    comment: str = ""
    label: str | None = None
    logic: Series = Field(default_factory=Series)
    outputs: list[Output] = Field(default_factory=list)
    stl: str | None = None
    stl_reason: str | None = None

    @model_validator(mode="after")
    def _rung_or_stl(self) -> Network:
        if self.stl is not None and (self.outputs or self.logic.elements):
            raise ValueError("an STL network has no rung")
        return self


class LadBlock(BaseModel):
    """A code block written in LAD or FBD: its header as in an STL source (kind, number or
    name, title, the interface declaration text) and its networks."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    language: Literal["LAD", "FBD"] = "LAD"
    kind: Literal["OB", "FB", "FC"]
    name: str = Field(description="'FC 10', '\"Motor\"', 'OB 1' as an STL source names it")
    return_type: str | None = Field(default=None, description="FC only: VOID, INT, ...")
    title: str = ""
    declarations: str = Field(
        default="", description="The VAR sections as STL/SCL source text, copied as they are"
    )
    networks: list[Network] = Field(default_factory=list)


Series.model_rebuild()
Box.model_rebuild()
Parallel.model_rebuild()

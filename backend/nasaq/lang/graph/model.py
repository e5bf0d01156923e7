"""The S7-Graph model: an FB of one or more sequencers, structure only (no coordinates).

The shape follows S7-Graph (and the textual SFC of IEC 61131-3 that S7-Graph sources use): a
sequencer is a list of steps and a list of transitions, each transition going FROM one step (or
several: a simultaneous convergence) TO one step (or several: a simultaneous divergence), or to
nothing (a sequence end). Several transitions from one step are an alternative divergence; their
order in ``Sequencer.transitions`` is their priority (the leftmost branch first, as S7-Graph
draws and evaluates them). Several transitions to one step are an alternative convergence. A
transition whose target is drawn as an arrow rather than a line is a jump (``jump``): the same
structure, a different drawing, kept so the chart looks the way the user built it.

Conditions (transition, interlock, supervision) are LAD/FBD logic from ``nasaq.lang.lad.model``
(a :class:`~nasaq.lang.lad.model.Series` of contacts, parallels and comparator boxes), so the
Graph editor reuses the LAD/FBD views; permanent instructions are whole LAD/FBD networks (coils
``=``/``S``/``R`` and block calls). ``None`` is "not programmed" (an empty transition passes at
once; a step without interlock is never disturbed).

Operands are kept as the user wrote them; step and transition variables (``Step3.T``,
``S3.X``, ``Trans2.TT``) are resolved by the lowering (``nasaq.lang.graph.lower``).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from nasaq.lang.lad.model import Network, Series

Event = Literal["S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1"]
Qualifier = Literal[
    "N", "S", "R", "D", "L", "CALL", "ON", "OFF", "CS", "CU", "CD", "CR", "TL", "TD", "TR"
]
ParameterSet = Literal["MINIMUM", "STANDARD", "MAXIMUM", "USER_DEFINED"]


class _Frozen(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Action(_Frozen):
    """One row of a step's action table: ``[event] qualifier[C] operand [, time]``.

    ``operand`` is the address or symbol (``Q 0.0``, ``"Belt_A"``, ``#count``), the block of a
    CALL (``FC 1``, ``FB 2, DB 2``, ``"Motor"``), the step of ON/OFF (``S3`` or a step name, or
    ``S_ALL``), the timer/counter (``T 0``, ``C 1``), or for an arithmetic action (qualifier N)
    the whole assignment (``#A := #A + 1``, ``#E := SIN(MD 0)``). ``time`` is the D/L time
    (``T#5S`` or an operand), the CS preset (``C#26`` or an operand) or the TL/TD time
    (``S5T#8S`` or an operand)."""

    id: str = Field(default="", description="Unique in its step: a1, a2 ... (numbered on load)")
    event: Event | None = None
    qualifier: Qualifier
    interlock: bool = Field(default=False, description="The C suffix: only while interlock OK")
    operand: str
    time: str | None = None
    comment: str = ""


class Step(_Frozen):
    """A step: its number (unique in the FB, what S_SEL/S_NO and ON/OFF ``S<n>`` use), its
    name (unique in the FB, the member of the instance DB), whether it is an initial step, its
    interlock (marker C), supervision (marker V; true = error) and actions in execution order."""

    number: int = Field(ge=1)
    name: str
    initial: bool = False
    comment: str = ""
    interlock: Series | None = None
    supervision: Series | None = None
    actions: list[Action] = Field(default_factory=list)


class Transition(_Frozen):
    """A transition from ``source`` (one step, or several: simultaneous convergence, all must be
    active) to ``target`` (one step, several: simultaneous divergence, or none: sequence end,
    S7-Graph's branch stop). ``condition`` None passes at once (a compile warning)."""

    number: int = Field(ge=1)
    name: str
    comment: str = ""
    source: list[str] = Field(min_length=1, description="Step names")
    target: list[str] = Field(default_factory=list, description="Step names; [] = sequence end")
    jump: bool = Field(default=False, description="Drawn as a jump arrow to target[0]")
    condition: Series | None = None


class Sequencer(_Frozen):
    """One sequencer of the FB: steps and transitions in chart order (top to bottom, left to
    right). Transitions sharing a source step are evaluated in this order (priority)."""

    name: str
    comment: str = ""
    steps: list[Step] = Field(default_factory=list)
    transitions: list[Transition] = Field(default_factory=list)


class Settings(_Frozen):
    """Options > Block Settings of S7-Graph that change the compiled FB."""

    parameters: ParameterSet = Field(default="STANDARD", description="The FB parameter set")
    skip_steps: bool = Field(
        default=False,
        description="A step whose incoming and outgoing transitions are true at once is passed",
    )
    acknowledge_required: bool = Field(
        default=True, description="A supervision error stays until acknowledged (ACK_EF)"
    )
    interlock_blocks: bool = Field(
        default=False, description="An interlock error also blocks the step's transitions"
    )


class GraphBlock(_Frozen):
    """A function block written in S7-Graph."""

    name: str = Field(description="'FB 1' or '\"Seq_drill\"' as an STL source names it")
    title: str = ""
    comment: str = ""
    settings: Settings = Field(default_factory=Settings)
    declarations: str = Field(
        default="", description="The user's VAR sections as STL source text, copied as they are"
    )
    pre: list[Network] = Field(default_factory=list, description="Permanent pre-instructions")
    sequencers: list[Sequencer] = Field(default_factory=list)
    post: list[Network] = Field(default_factory=list, description="Permanent post-instructions")

"""What the lowering asks about a Graph FB: its steps and transitions over all sequencers, the
FB parameters of its parameter set, and how a name in a condition or an action is read.

Step and transition variables (``SEMANTICS.md`` §1) are rewritten to the instance DB members:
``Fill.T``, ``#Fill.T``, ``S3.T`` (when no step is named ``S3``) → ``#Fill.T``; ``Trans2.TT``,
``T2.TT`` → ``#Trans2.TT``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from nasaq.lang.graph.model import GraphBlock, Step, Transition


def _names(text: str) -> tuple[str, ...]:
    return tuple(text.split())


INPUTS: dict[str, tuple[str, ...]] = {
    "MINIMUM": ("INIT_SQ",),
    "STANDARD": _names(
        "OFF_SQ INIT_SQ ACK_EF S_PREV S_NEXT SW_AUTO SW_TAP SW_MAN S_SEL S_ON S_OFF T_PUSH"
    ),
    "MAXIMUM": _names(
        "OFF_SQ INIT_SQ ACK_EF HALT_SQ HALT_TM ZERO_OP EN_IL EN_SV S_PREV S_NEXT SW_AUTO SW_TAP"
        " SW_MAN S_SEL S_ON S_OFF T_PUSH"
    ),
}
INPUTS["USER_DEFINED"] = (*INPUTS["MAXIMUM"], "EN_ACKREQ", "EN_SSKIP", "SW_TOP")
OUTPUTS: dict[str, tuple[str, ...]] = {
    "MINIMUM": (),
    "STANDARD": _names("S_NO S_MORE S_ACTIVE ERR_FLT AUTO_ON TAP_ON MAN_ON"),
    "MAXIMUM": _names(
        "S_NO S_MORE S_ACTIVE ERR_FLT SQ_HALTED TM_HALTED OP_ZEROED IL_ENABLED SV_ENABLED"
        " AUTO_ON TAP_ON MAN_ON"
    ),
}
OUTPUTS["USER_DEFINED"] = (*OUTPUTS["MAXIMUM"], "ERROR", "FAULT", "SQ_ISOFF", "TOP_ON")
INT_PARAMETERS = ("S_SEL", "S_NO")
# The inputs that act on their rising edge, in the order of their edge memories G7_M_<name>.
EDGE_INPUTS = _names("SW_AUTO SW_MAN SW_TAP SW_TOP ACK_EF T_PUSH S_ON S_OFF S_NEXT S_PREV")
STEP_EVENTS = ("S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1")

_VARIABLE = re.compile(r"^#?\s*([A-Za-z_][A-Za-z_0-9]*)\s*\.\s*(X|T|U|TT)$", re.IGNORECASE)
_IN_TEXT = re.compile(r'(?<![\w."#])#?([A-Za-z_][A-Za-z_0-9]*)\.(X|T|U|TT)(?![\w.])', re.IGNORECASE)


@dataclass(slots=True)
class Chart:
    """The block's steps (in step order over all sequencers) and transitions, by name and
    number, and the parameter set's inputs and outputs."""

    block: GraphBlock
    steps: list[Step] = field(default_factory=list)
    transitions: list[Transition] = field(default_factory=list)
    step_names: dict[str, Step] = field(default_factory=dict)  # upper-case name
    step_numbers: dict[int, Step] = field(default_factory=dict)
    transition_names: dict[str, Transition] = field(default_factory=dict)
    transition_numbers: dict[int, Transition] = field(default_factory=dict)
    inputs: tuple[str, ...] = ()
    outputs: tuple[str, ...] = ()

    @classmethod
    def of(cls, block: GraphBlock) -> Chart:
        chart = cls(block)
        for sequencer in block.sequencers:
            chart.steps += sequencer.steps
            chart.transitions += sequencer.transitions
        for step in chart.steps:
            chart.step_names.setdefault(step.name.upper(), step)
            chart.step_numbers.setdefault(step.number, step)
        for transition in chart.transitions:
            chart.transition_names.setdefault(transition.name.upper(), transition)
            chart.transition_numbers.setdefault(transition.number, transition)
        chart.inputs = INPUTS[block.settings.parameters]
        chart.outputs = OUTPUTS[block.settings.parameters]
        return chart

    def has(self, parameter: str) -> bool:
        return parameter in self.inputs or parameter in self.outputs

    def step(self, name: str) -> Step | None:
        """A step by its name or as ``S<number>`` (the name wins)."""
        found = self.step_names.get(name.strip().upper())
        if found is None and re.fullmatch(r"S\d+", name.strip(), re.IGNORECASE):
            found = self.step_numbers.get(int(name.strip()[1:]))
        return found

    def transition(self, name: str) -> Transition | None:
        found = self.transition_names.get(name.upper())
        if found is None and re.fullmatch(r"T\d+", name, re.IGNORECASE):
            found = self.transition_numbers.get(int(name[1:]))
        return found

    def variable(self, operand: str) -> str | None:
        """The instance DB member a step/transition variable names, or None."""
        match = _VARIABLE.match(operand.strip())
        if match is None:
            return None
        return self._member(match.group(1), match.group(2))

    def _member(self, name: str, member: str) -> str | None:
        member = member.upper()
        if member == "TT":
            transition = self.transition(name)
            return f"#{transition.name}.TT" if transition is not None else None
        step = self.step(name)
        return f"#{step.name}.{member}" if step is not None else None

    def operand(self, operand: str) -> str:
        """``operand`` with a step/transition variable rewritten to its member."""
        return self.variable(operand) or operand

    def in_text(self, text: str) -> str:
        """Every step/transition variable in an expression rewritten to its member."""

        def replace(match: re.Match[str]) -> str:
            return self._member(match.group(1), match.group(2)) or match.group(0)

        return _IN_TEXT.sub(replace, text)

    def sources_with(self, step: Step) -> list[Transition]:
        """The transitions leaving ``step`` alone (source = [step]), in priority order."""
        return [t for t in self.transitions if [s.upper() for s in t.source] == [step.name.upper()]]

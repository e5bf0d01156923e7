"""Where an S7-Graph FB switches a step on: the instructions a step breakpoint and a single step
by transition hold before.

The lowering (``nasaq/lang/graph/lower_machinery.py``) switches a step on with ``S #<step>.X``
wherever it happens (an initial step at the first call or INIT_SQ, a transition firing, a
skipped step's successor, MAN's S_ON, an ON action), and only there; it always reaches that
instruction with RLO 1, so holding before it is holding at the step's activation. The
instructions are found from the instance layout (``graph_sequencer.graph_layout``: the offset of
each step's ``X``), never from code patterns, so they stay right when the lowering changes.

A transition whose targets are a simultaneous branch switches several steps on in a row: those
activations are one *firing* (``firing``), so a single step by transition from one of them goes
on to the next firing instead of stopping at each target.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.cpu.codegen.jumps import JUMPS
from nasaq.ir import Area, Block, RegisterIndirect
from nasaq.monitor.graph_sequencer import graph_layout


@dataclass(frozen=True, slots=True)
class Activations:
    """The step activations of one Graph FB's code."""

    steps: dict[int, str]  # step number -> name, in step order
    at: dict[int, int]  # instruction index -> the number of the step it switches on
    firing: dict[int, tuple[int, int]]  # instruction index -> first and last index of its firing

    def of_step(self, number: int) -> list[int]:
        return [index for index, step in self.at.items() if step == number]


def activations(fb: Block) -> Activations | None:
    """The activations of ``fb``; None when it is not an S7-Graph FB."""
    layout = graph_layout(fb)
    if layout is None:
        return None
    numbers = _step_numbers(fb)
    by_offset: dict[int, int] = {}
    steps: dict[int, str] = {}
    for step in layout.steps:
        number = numbers.get(step.name.upper())
        if number is not None:
            by_offset[step.x.at] = number
            steps[number] = step.name
    at: dict[int, int] = {}
    for index, instruction in enumerate(fb.code):
        operand = instruction.operand
        if (
            instruction.op == "S"
            and isinstance(operand, RegisterIndirect)
            and operand.register == 2
            and operand.area is Area.DI
            and operand.offset_bits in by_offset
        ):
            at[index] = by_offset[operand.offset_bits]
    return Activations(dict(sorted(steps.items())), at, _firings(fb, sorted(at)))


def _step_numbers(fb: Block) -> dict[str, int]:
    """Each step's number: the initial value of its ``SNO`` (``SEMANTICS.md`` §1)."""
    found: dict[str, int] = {}
    for variable in fb.interface:
        if variable.section != "STAT":
            continue
        for member in variable.members:
            if member.name.upper() == "SNO":
                number = _number(member.initial)
                if number is not None:
                    found[variable.name.upper()] = number
    return found


def _number(initial: object) -> int | None:
    """An INT's initial value as the compiler keeps it (the literal nodes of its source)."""
    if isinstance(initial, list) and len(initial) == 1:
        initial = getattr(initial[0], "text", None)
    try:
        return int(str(initial))
    except ValueError:
        return None


def _firings(fb: Block, indices: list[int]) -> dict[int, tuple[int, int]]:
    """Groups activations that follow each other with no label or jump between them, from the
    same chart element (one transition's targets): they happen together or not at all."""
    code = fb.code
    groups: list[list[int]] = []
    for index in indices:
        if groups:
            last = groups[-1][-1]
            same = _element(fb, last) == _element(fb, index)
            between = code[last + 1 : index + 1]
            if same and not any(i.label is not None or i.op in JUMPS for i in between):
                groups[-1].append(index)
                continue
        groups.append([index])
    return {index: (group[0], group[-1]) for group in groups for index in group}


def _element(fb: Block, index: int) -> str | None:
    origin = fb.code[index].origin
    return None if origin is None else origin.element

"""What every rule family of the Graph checker needs to know about one block, built once.

The indexes (steps and transitions by name and by number, the sequencer of each) are dicts
filled in one pass, so every rule looks a name up in constant time and the whole check stays
linear in the size of the block (a 10,000-step source is checked in a fraction of a second).

Names are compared without regard to case, as STEP 7 compares the names of an instance DB's
members (``Fill`` and ``FILL`` are the same variable).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.lang.graph.model import GraphBlock, Step, Transition
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.stl.parse import parse_source

_STEP_BY_NUMBER = re.compile(r"S(\d+)", re.IGNORECASE)
_TRANSITION_BY_NUMBER = re.compile(r"T(\d+)", re.IGNORECASE)


def step_key(step: Step) -> str:
    """The places/origin key of a step (``S3``)."""
    return f"S{step.number}"


def transition_key(transition: Transition) -> str:
    """The places/origin key of a transition (``T4``)."""
    return f"T{transition.number}"


def names_list(names: list[str], limit: int = 8) -> str:
    """A short, language-neutral list of names for a message parameter."""
    shown = ", ".join(names[:limit])
    return shown + (", …" if len(names) > limit else "") if names else "—"


@dataclass(slots=True)
class Declared:
    """A variable the user declared before BEGIN: its name and section (``VAR_INPUT`` ...)."""

    name: str
    section: str


@dataclass
class BlockContext:
    """One block of a parsed file, with the lookups the rules share."""

    parsed: ParsedGraph
    index: int
    block: GraphBlock = field(init=False)
    steps: list[tuple[int, Step]] = field(init=False, default_factory=list)
    transitions: list[tuple[int, Transition]] = field(init=False, default_factory=list)
    step_by_name: dict[str, Step] = field(init=False, default_factory=dict)
    step_by_number: dict[int, Step] = field(init=False, default_factory=dict)
    transition_by_name: dict[str, Transition] = field(init=False, default_factory=dict)
    transition_by_number: dict[int, Transition] = field(init=False, default_factory=dict)
    sequencer_of_step: dict[int, int] = field(init=False, default_factory=dict)  # id(step)

    def __post_init__(self) -> None:
        self.block = self.parsed.blocks[self.index]
        for position, sequencer in enumerate(self.block.sequencers):
            for step in sequencer.steps:
                self.steps.append((position, step))
                self.sequencer_of_step[id(step)] = position
                self.step_by_name.setdefault(step.name.upper(), step)
                self.step_by_number.setdefault(step.number, step)
            for transition in sequencer.transitions:
                self.transitions.append((position, transition))
                self.transition_by_name.setdefault(transition.name.upper(), transition)
                self.transition_by_number.setdefault(transition.number, transition)

    # ---- diagnostics -------------------------------------------------------------------------

    def problem(self, code: str, key: str, element: str | None = None, **params: Any) -> Diagnostic:
        """A diagnostic placed on the line of part ``key`` (``S3/A2``, ``T4``, ``BLOCK`` ...);
        ``element`` names a finer place inside it (``T4/e3``), by default the part itself."""
        line = self.parsed.line(self.index, key)
        span = Span(file=self.parsed.file, line=max(line, 1), element=element or key)
        return render(code, span, **params)

    # ---- lookups -----------------------------------------------------------------------------

    def step(self, name: str) -> Step | None:
        """The step named ``name`` (as a transition's FROM/TO names it)."""
        return self.step_by_name.get(name.strip().upper())

    def step_reference(self, text: str) -> Step | None:
        """The step an ON/OFF action or a step variable names: a step of that name first,
        else ``S<number>`` (SEMANTICS.md §1: ``S<number>`` when no step is named so)."""
        found = self.step(text)
        if found is not None:
            return found
        number = _STEP_BY_NUMBER.fullmatch(text.strip())
        return self.step_by_number.get(int(number.group(1))) if number else None

    def transition_reference(self, text: str) -> Transition | None:
        """The transition a ``.TT`` variable names: by name first, else ``T<number>``."""
        found = self.transition_by_name.get(text.strip().upper())
        if found is not None:
            return found
        number = _TRANSITION_BY_NUMBER.fullmatch(text.strip())
        return self.transition_by_number.get(int(number.group(1))) if number else None

    def sequencer_name(self, position: int) -> str:
        return self.block.sequencers[position].name

    @cached_property
    def links(self) -> list[tuple[list[Step | None], list[Step | None]]]:
        """Per transition (aligned with ``transitions``): its source and target steps, None
        where a name names no step."""
        return [
            (
                [self.step(name) for name in transition.source],
                [self.step(name) for name in transition.target],
            )
            for _, transition in self.transitions
        ]

    @cached_property
    def declared(self) -> list[Declared]:
        """The variables of the user's declarations (top level only: members of a STRUCT are
        not members of the instance DB). Read with the STL parser; declarations it cannot
        read give no names here (the STL compiler reports them when the FB is compiled)."""
        if not self.block.declarations.strip():
            return []
        text = f"FUNCTION_BLOCK FB 1\n{self.block.declarations}\nBEGIN\nEND_FUNCTION_BLOCK\n"
        result = parse_source(self.parsed.file, text)
        found: list[Declared] = []
        for source_block in result.source.blocks[:1]:
            for item in source_block.head:
                decls = getattr(item, "decls", None)
                kind = getattr(item, "kind", "")
                if decls is not None:
                    found.extend(Declared(decl.name, kind) for decl in decls)
        return found

    @cached_property
    def declared_names(self) -> set[str]:
        return {declared.name.upper() for declared in self.declared}

"""The chart of each S7-Graph FB for the project outline: its sequencers, steps and transitions
with the line each is written on, so the text editor lists them and jumps to them.

Read from the ``.graph`` text itself (``nasaq.lang.graph.text.parse_graph``), not from the
compiled program: the program has the STL the FB lowers to, whose structure is the sequencer
machinery, not the chart. A block the parser could not read is absent (its problems are in the
project's diagnostics).
"""

from __future__ import annotations

from collections.abc import Callable

from pydantic import BaseModel, Field

from nasaq.lang.graph.model import GraphBlock


class OutlineStep(BaseModel):
    number: int
    name: str
    initial: bool
    line: int


class OutlineTransition(BaseModel):
    number: int
    name: str
    source: list[str] = Field(description="Step names")
    target: list[str] = Field(description="Step names; [] = sequence end")
    line: int


class OutlineSequencer(BaseModel):
    name: str
    line: int
    steps: list[OutlineStep]
    transitions: list[OutlineTransition]


def block_key(name: str) -> str:
    """How a Graph block's name (``FB 1``, ``"Seq"``) matches the tree's: ``FB1`` or the
    casefolded symbol."""
    text = name.strip()
    if text.startswith('"'):
        return text.strip('"').casefold()
    return text.replace(" ", "").upper()


def graph_charts(file: str, text: str) -> dict[str, list[OutlineSequencer]]:
    """Each FB of a ``.graph`` file (by :func:`block_key`) -> its sequencers, placed."""
    from nasaq.lang.graph.text import parse_graph  # only a project with Graph files needs it

    parsed = parse_graph(text, file)
    charts: dict[str, list[OutlineSequencer]] = {}
    for index, block in enumerate(parsed.blocks):
        charts.setdefault(block_key(block.name), _sequencers(block, parsed.line, index))
    return charts


def _sequencers(
    block: GraphBlock, at: Callable[[int, str], int], index: int
) -> list[OutlineSequencer]:
    """``at`` is ``ParsedGraph.line``: the line of a part of block ``index``."""
    return [
        OutlineSequencer(
            name=sequencer.name,
            line=at(index, f"SEQ:{sequencer.name}"),
            steps=[
                OutlineStep(
                    number=step.number,
                    name=step.name,
                    initial=step.initial,
                    line=at(index, f"S{step.number}"),
                )
                for step in sequencer.steps
            ],
            transitions=[
                OutlineTransition(
                    number=transition.number,
                    name=transition.name,
                    source=list(transition.source),
                    target=list(transition.target),
                    line=at(index, f"T{transition.number}"),
                )
                for transition in sequencer.transitions
            ],
        )
        for sequencer in block.sequencers
    ]

"""The ``.graph`` text format: S7-Graph function blocks as IEC 61131-3 textual SFC, structure
only (no coordinates), git-friendly. ``grammars/graph.lark`` is its reference grammar.

``parse_graph`` never raises: every problem is a ``GRA1xx`` diagnostic (or, inside a condition
or a permanent network, the LAD reader's ``LAD1xx``) with its position, and reading goes on
with the next action row, step, transition, sequencer or block. Action ids (``a1`` ...) and
the element ids of conditions (``e1`` ..., per condition) are numbered on reading, as LAD
numbers its networks; ``print_graph`` leaves out the ids that equal their number, so
``parse_graph(print_graph(blocks))`` gives back ``blocks`` once they are numbered
(``number_block``).
"""

from __future__ import annotations

import gc

from nasaq.lang.graph.model import GraphBlock, Sequencer, Step, Transition
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text_parse import GraphReader
from nasaq.lang.graph.text_print import print_blocks
from nasaq.lang.lad.model import Network, Series
from nasaq.lang.lad.text_ids import number_elements

SUFFIXES = (".graph",)


def parse_graph(text: str, file: str) -> ParsedGraph:
    """The blocks of a ``.graph`` file, the problems found and where each part was written
    (``file`` names the file in diagnostics)."""
    gc_was_enabled = gc.isenabled()
    gc.disable()  # reading makes many small objects and frees few: collection passes would
    try:  # scan them again and again (quadratic on a long file), as in the STL parser
        return GraphReader(text, file).read()
    finally:
        if gc_was_enabled:
            gc.enable()


def print_graph(blocks: list[GraphBlock]) -> str:
    """The canonical text of ``blocks``; ``parse_graph`` reads it back to the same blocks
    once their ids are numbered (``number_block``)."""
    return print_blocks(blocks)


def _series(series: Series | None) -> Series | None:
    return None if series is None else number_elements(Network(logic=series))[0].logic


def _step(step: Step) -> Step:
    actions = [
        action if action.id else action.model_copy(update={"id": f"a{number}"})
        for number, action in enumerate(step.actions, start=1)
    ]
    update = {
        "interlock": _series(step.interlock),
        "supervision": _series(step.supervision),
        "actions": actions,
    }
    return step.model_copy(update=update)


def _transition(transition: Transition) -> Transition:
    return transition.model_copy(update={"condition": _series(transition.condition)})


def _sequencer(sequencer: Sequencer) -> Sequencer:
    steps = [_step(step) for step in sequencer.steps]
    transitions = [_transition(transition) for transition in sequencer.transitions]
    return sequencer.model_copy(update={"steps": steps, "transitions": transitions})


def number_block(block: GraphBlock) -> GraphBlock:
    """``block`` with its unnamed action rows and condition/network elements numbered as
    ``parse_graph`` numbers them (given ids kept)."""
    return block.model_copy(
        update={
            "pre": [number_elements(network)[0] for network in block.pre],
            "post": [number_elements(network)[0] for network in block.post],
            "sequencers": [_sequencer(sequencer) for sequencer in block.sequencers],
        }
    )

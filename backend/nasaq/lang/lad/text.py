"""The LAD/FBD text format: git-friendly files of LAD and FBD blocks, structure only.

``.lad`` and ``.fbd`` files share one syntax (``grammars/lad.lark`` is its reference): the
block header and VAR sections exactly as in an STL source, then ``BEGIN``, networks of
``RUNG ... END_RUNG`` and the block's ``END_...``. A block is FBD when it says
``LANGUAGE FBD`` after its header, or, without a LANGUAGE line, when the file name ends in
``.fbd``; the printer writes ``LANGUAGE FBD`` for FBD blocks and nothing for LAD blocks.

``parse_lad`` never raises: every problem is a ``LAD1xx`` diagnostic with its position, and
reading goes on with the next element, network or block.
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.lad.model import LadBlock, Network
from nasaq.lang.lad.text_ids import number_elements
from nasaq.lang.lad.text_parse import LadReader
from nasaq.lang.lad.text_print import print_blocks

SUFFIXES = (".lad", ".fbd")


def parse_lad(text: str, file: str) -> tuple[list[LadBlock], list[Diagnostic]]:
    """The blocks of a ``.lad``/``.fbd`` file and the problems found (``file`` names the
    file in diagnostics and decides the default language)."""
    reader = LadReader(text, file)
    blocks = reader.read()
    return blocks, reader.scan.diagnostics


def print_lad(blocks: list[LadBlock]) -> str:
    """The text of ``blocks``; ``parse_lad`` reads it back to the same blocks once their
    elements are numbered (``number_network``)."""
    return print_blocks(blocks)


def number_network(network: Network) -> Network:
    """``network`` with its unnamed elements numbered ``e1``, ``e2`` ... in reading order, as
    ``parse_lad`` numbers them."""
    return number_elements(network)[0]

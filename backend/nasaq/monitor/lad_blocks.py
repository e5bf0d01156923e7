"""The network model each LAD/FBD code block of a download was drawn as.

The CPU runs the STL a ``.lad``/``.fbd`` file lowers to; its element status needs the rungs
themselves (which element is a contact, a coil, a box of which family). They are read once per
download from the sources the session keeps, and looked up by block when a client opens one.
"""

from __future__ import annotations

from nasaq.ir import BlockKind, Program
from nasaq.lang.lad.model import LadBlock
from nasaq.lang.lad.text import SUFFIXES, parse_lad
from nasaq.lang.stl import SourceFile
from nasaq.lang.stl.compiler import decode
from nasaq.monitor.block_info import parse_block_name
from nasaq.monitor.errors import MonitorError

Key = tuple[BlockKind, int]


def lad_blocks(sources: list[SourceFile], program: Program) -> dict[Key, LadBlock]:
    """Each code block of ``program`` compiled from a LAD/FBD source, as that source draws it
    (its elements numbered as the compiler numbered them)."""
    found: dict[Key, LadBlock] = {}
    for source in sources:
        if not source.name.lower().endswith(SUFFIXES):
            continue
        blocks, _ = parse_lad(decode(source.text), source.name)
        for block in blocks:
            try:
                key = parse_block_name(block.name, program)
            except MonitorError:
                continue  # not in the program (it did not compile)
            compiled = program.get(*key)
            if compiled is not None and compiled.file == source.name:
                found[key] = block
    return found

"""SCL → STL: every SCL block becomes an STL syntax tree (``nasaq.lang.stl.ast``) whose
instructions carry their SCL line and column, and the STL compiler turns those into the IR the
CPU runs (so SCL and STL blocks call each other, share one symbol table and one layout).

Parts, each one job: ``emitter`` (instructions, labels, temporaries), ``literals`` (constants
for a type), ``places`` (variables as operands), ``expressions`` (values and conditions),
``calls`` (FC/FB/SFC calls, S5 timers and counters), ``functions`` (built-in functions),
``statements``, ``blocks`` (headers, interfaces, DBs, prologue/epilogue).
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.scl.bind import SclIndex
from nasaq.lang.scl.lower.blocks import lower_block
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.stl import ast as stl


def lower_index(
    index: SclIndex, contexts: dict[tuple[BlockKind, int], Context] | None = None
) -> tuple[list[tuple[str, stl.BlockNode]], list[Diagnostic]]:
    """(file, STL block) for every block of ``index`` that could be lowered, and the problems.
    ``contexts`` are the checker's, by block: expression types are then not computed again."""
    found_contexts = contexts or {}
    blocks: list[tuple[str, stl.BlockNode]] = []
    diagnostics: list[Diagnostic] = []
    for block in index:
        if block.external:
            continue
        lowered, found = lower_block(index, block, found_contexts.get((block.kind, block.number)))
        diagnostics += found
        if lowered is not None:
            blocks.append((block.file, lowered))
    return blocks, diagnostics


__all__ = ["lower_block", "lower_index"]

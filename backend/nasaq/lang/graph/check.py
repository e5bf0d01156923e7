"""The semantic check of a Graph FB, after parsing and before lowering (codes GRA200–GRA299).

    parsed = parse_graph(text, file)
    problems = [*parsed.diagnostics, *check_block(parsed, 0)]

One module per rule family: ``check_structure`` (numbers, links, reachability, limits, loops
without conditions), ``check_branches`` (simultaneous branches opened and closed alike),
``check_actions`` (the event × qualifier × C table, operands, values), ``check_conditions``
(only contacts, branches and comparators; 32 elements; permanent networks), ``check_names``
(identifiers, clashes, step variables). Each module's docstring lists the decisions it makes
where S7-Graph's editor would not let the mistake happen.

Every diagnostic is placed on the line of the part it is about (``ParsedGraph.line``) and
names that part as its element (``S3``, ``S3/A2``, ``S3/C``, ``T4``, ``T4/e2``, ``PRE1``,
``SEQ:<name>``, ``BLOCK``), the keys the lowering's origins use. The check never raises on a
model the parser produced and is linear in the size of the block.
"""

from __future__ import annotations

import gc

from nasaq.diagnostics import Diagnostic, Span
from nasaq.lang.graph.check_actions import check_actions
from nasaq.lang.graph.check_branches import check_branches
from nasaq.lang.graph.check_conditions import check_conditions
from nasaq.lang.graph.check_context import BlockContext
from nasaq.lang.graph.check_names import check_names
from nasaq.lang.graph.check_structure import check_structure
from nasaq.lang.graph.source import ParsedGraph

_SEVERITY_ORDER = {"error": 0, "warning": 1, "info": 2}


def check_block(parsed: ParsedGraph, index: int) -> list[Diagnostic]:
    """The problems of block ``index`` of ``parsed``, sorted by line, then errors first."""
    gc_was_enabled = gc.isenabled()
    gc.disable()  # the indexes allocate many small objects; collection passes cost more than
    try:  # the check itself on a large block (as in the STL parser)
        ctx = BlockContext(parsed, index)
        found = [
            *check_structure(ctx),
            *check_branches(ctx),
            *check_actions(ctx),
            *check_conditions(ctx),
            *check_names(ctx),
        ]
    finally:
        if gc_was_enabled:
            gc.enable()
    return sorted(found, key=_order)


def has_errors(diagnostics: list[Diagnostic]) -> bool:
    """Whether any of ``diagnostics`` stops the FB from being compiled."""
    return any(diagnostic.severity == "error" for diagnostic in diagnostics)


def _order(diagnostic: Diagnostic) -> tuple[int, int, str]:
    span = diagnostic.span or Span()
    return (span.line or 0, _SEVERITY_ORDER[diagnostic.severity.value], diagnostic.code)

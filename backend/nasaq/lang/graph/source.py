"""A ``.graph`` file as read: its blocks, the problems found, and where each part was written.

The model has no positions (it is what the editors hold); the checker and the lowering place
their diagnostics through ``places``: per block, the 1-based line of each part, keyed as the
generated code's origins are (``SEMANTICS.md`` §5): ``BLOCK``, ``SEQ:<sequencer name>``,
``S<number>``, ``S<number>/A<k>``, ``S<number>/C``, ``S<number>/V``, ``T<number>``, ``PRE<n>``,
``POST<n>``, ``SETTINGS``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.model import GraphBlock


@dataclass(slots=True)
class ParsedGraph:
    file: str
    blocks: list[GraphBlock] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    places: list[dict[str, int]] = field(default_factory=list)  # aligned with blocks

    def line(self, block: int, key: str) -> int:
        """The line of a part of block ``block``; the block's own line when unknown."""
        found = self.places[block] if 0 <= block < len(self.places) else {}
        return found.get(key, found.get("BLOCK", 1))

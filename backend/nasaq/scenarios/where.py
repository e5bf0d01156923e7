"""Where a failing expectation points: the instruction that last writes the address.

A learner whose check fails wants the rung or the line to look at, as TIA Portal's
cross-reference "goes to" the assignment of an output. The uses come from the cross-reference
walk (``nasaq.workbench.xref.project_uses``), so STL lines, SCL statements and LAD/FBD networks
with their element are found alike. "Last" is the last write in program order (blocks in the
compiled program's order, code in block order): for an output assigned twice, the assignment that
wins at the end of the scan. An address nobody writes (an input, a forgotten coil) has no place.
Computed only when a failure needs it, never in the scan loop.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.headless.addresses import AddressError, TimerAddress, parse_address
from nasaq.ir import Direct, Program
from nasaq.workbench.xref import Operated, project_uses

_WRITES = frozenset({"write", "set", "reset", "read_write", "start", "count"})


@dataclass(frozen=True, slots=True)
class Where:
    file: str
    line: int
    network: int | None
    element: str | None

    def as_dict(self) -> dict[str, object]:
        return {
            "file": self.file,
            "line": self.line,
            "network": self.network,
            "element": self.element,
        }


def _place(key: str) -> Operated | None:
    try:
        address = parse_address(key)
    except AddressError:
        return None
    if isinstance(address, Direct):
        start = address.byte * 8 + (address.bit or 0)
        return Operated("memory", address.area, address.db, start, int(address.width))
    kind = "timer" if isinstance(address, TimerAddress) else "counter"
    return Operated(kind, number=address.number)


class Writers:
    """The last writer of every address the program writes, looked up on demand."""

    def __init__(self, program: Program, texts: dict[str, str]) -> None:
        self._program = program
        self._texts = texts
        self._uses: list[tuple[Operated, Where]] | None = None

    def _all(self) -> list[tuple[Operated, Where]]:
        if self._uses is None:
            self._uses = [
                (use.place, Where(use.block.file, use.line, use.network, use.element))
                for use in project_uses(self._program, self._texts)
                if use.access in _WRITES
            ]
        return self._uses

    def of(self, key: str) -> Where | None:
        place = _place(key)
        if place is None:
            return None
        found: Where | None = None
        for used, where in self._all():
            if used.overlaps(place):
                found = where
        return found

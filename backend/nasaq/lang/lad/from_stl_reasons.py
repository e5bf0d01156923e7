"""Why an STL network stays STL: the reason codes of the STL → LAD/FBD lifter.

STEP 7 Classic shows a network in LAD or FBD only when it is one RLO chain ending in
assignments or boxes; otherwise the network stays STL and the editor says why. Each reason is a
catalogue code (``LAD302``..``LAD327`` in ``diagnostics/lad.csv``) whose message names the
instruction and its line. :data:`REASONS` explains each one in a line, for the README table
"which STL constructs convert to LAD/FBD".
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.diagnostics.catalogue import entry

REASONS: dict[str, str] = {
    "LAD302": "The network has a syntax error; it is shown as it was typed.",
    "LAD303": "L or T inside the logic chain: a load between bit checks has no LAD element.",
    "LAD304": "A jump label in the middle of the network (a jump into the middle of a rung).",
    "LAD305": "X / XN / X( (exclusive OR) has no LAD contact.",
    "LAD306": "Several chains in one network: a new chain starts after an output.",
    "LAD307": "=, S and R on the same operand mixed in one network.",
    "LAD308": "An accumulator value used across the network boundary (T or an operation "
    "without its loads).",
    "LAD309": "The RLO of the previous network is used (the network starts with =, S, R, "
    "NOT, a jump ...).",
    "LAD310": "An instruction with no LAD element (TAK, LOOP, JL, CLR, jumps on status bits ...).",
    "LAD311": "Brackets that do not match: ) without ( or ( without ).",
    "LAD312": "The logic chain ends without an output (assignment, jump, box).",
    "LAD313": "An assignment inside brackets that is not a midline (= x then A x).",
    "LAD314": "Instructions after a conditional jump or BEC: the rung ends there.",
    "LAD315": "JU after logic: only a jump straight from the rail is a LAD jump.",
    "LAD316": "Indirect addressing (I [MD 2], [AR1, P#0.0]) cannot stand on a LAD element.",
    "LAD317": "An operand that no contact or coil takes (a constant, a missing operand).",
    "LAD318": "Accumulator instructions that form no box (compare, MOVE, math, conversion, "
    "word logic, shift).",
    "LAD319": "A negated bracket (AN( / ON() after other checks: LAD can only invert the "
    "whole flow so far.",
    "LAD320": "NOT, an edge or a midline after O (AND before OR): the parked AND group "
    "cannot be drawn.",
    "LAD321": "A block call that is not in the EN/ENO box pattern (a CALL after logic "
    "without JNB).",
    "LAD322": "A value is left in the accumulator for the next network.",
    "LAD323": "A timer or set-counter instruction without its value loaded just before it.",
    "LAD324": "Empty brackets: A( ) without a check inside.",
    "LAD325": "A box pattern (timer, counter, SR/RS, EN/ENO) that is incomplete or out of order.",
    "LAD326": "OPN in a rung: OPN stands only straight from the rail, alone in its network.",
    "LAD327": "A( … ) holding NOT, an edge, a midline or a box after other checks: in LAD it "
    "would act on the whole flow so far.",
    "LAD151": "Brackets nested deeper than the converter follows (40 levels; STEP 7 allows 7).",
}

_INSTRUCTION_WIDTH = 60


@dataclass(frozen=True, slots=True)
class NotConvertible:
    """A network that stays STL: the reason's code and key, its parameters, the English
    message, and the instruction (text and line) it names."""

    code: str
    key: str
    params: dict[str, str | int] = field(hash=False)
    message: str
    line: int
    instruction: str

    def diagnostic(self, file: str | None = None, network: int | None = None) -> Diagnostic:
        """The reason as a catalogue diagnostic at the instruction's line."""
        span = Span(file=file, line=max(1, self.line), network=network)
        return render(self.code, span, **self.params)


def not_convertible(code: str, line: int, instruction: str) -> NotConvertible:
    """The reason ``code`` for ``instruction`` (its STL text) at ``line``."""
    text = " ".join(instruction.split())
    if len(text) > _INSTRUCTION_WIDTH:
        text = text[: _INSTRUCTION_WIDTH - 3] + "..."
    params: dict[str, str | int] = {"instruction": text, "line": line}
    found = entry(code)
    return NotConvertible(
        code=code,
        key=found.key,
        params=params,
        message=found.template.format(**params),
        line=line,
        instruction=text,
    )


class RefusalError(Exception):
    """Raised inside the lifter to stop at the first reason; ``lift_network`` catches it, so it
    never leaves the package."""

    def __init__(self, reason: NotConvertible) -> None:
        super().__init__(reason.message)
        self.reason = reason

"""Refuses, before it is read, an FB far over S7-Graph's limit of 256 steps and 256 transitions.

The checker reports the limit (GRA208/GRA209) after a full parse and check; for a block with
thousands of steps (a generated file, a paste gone wrong) that costs seconds and the answer is
the same. ``refuse_oversized`` counts the lines that start with ``STEP``/``INITIAL_STEP`` and
``TRANSITION`` per ``FUNCTION_BLOCK`` with one regular expression; a block with more than
``FAR_OVER`` of either gets the checker's diagnostics (same codes, same line: the first step or
transition over the limit) and its text is replaced by empty lines (the line numbers of the other
blocks stay), so the compiler reads the rest of the file as usual. A block just over the limit
takes the normal way, with all its other problems reported. The count is of lines, so a step
inside a ``(* *)`` comment counts: it only decides between two ways of reporting the same limit.
"""

from __future__ import annotations

import re

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.lang.graph.check_structure import MAX_STEPS, MAX_TRANSITIONS

FAR_OVER = 4 * MAX_STEPS  # more steps (or transitions) than this: refused without reading
_PARTS = re.compile(
    r"^[ \t]*(END_FUNCTION_BLOCK|FUNCTION_BLOCK|INITIAL_STEP|STEP|TRANSITION)(?!\w)"
    r"(?:[ \t]+[A-Za-z_]\w*[ \t]*\([ \t]*(\d+)[ \t]*\))?",
    re.IGNORECASE | re.MULTILINE,
)


class _Block:
    """What the scan found of one FUNCTION_BLOCK."""

    def __init__(self, start: int) -> None:
        self.start = start  # offset of the FUNCTION_BLOCK line
        self.steps = 0
        self.transitions = 0
        self.over_step: tuple[int, str | None] | None = None  # (offset, number) of step 257
        self.over_transition: tuple[int, str | None] | None = None

    def far_over(self) -> bool:
        return self.steps > FAR_OVER or self.transitions > FAR_OVER


def refuse_oversized(file: str, text: str) -> tuple[str, list[Diagnostic]]:
    """``text`` with every block far over the limit blanked out, and their limit diagnostics
    (the text itself when no block is)."""
    if text.count("\n") < FAR_OVER:  # too few lines to hold that many steps
        return text, []
    refused: list[tuple[_Block, int]] = []  # each with the offset its text ends at
    block: _Block | None = None
    for found in _PARTS.finditer(text):
        word = found.group(1).upper()
        if word == "FUNCTION_BLOCK":
            if block is not None and block.far_over():
                refused.append((block, found.start()))
            block = _Block(found.start())
        elif block is None:
            continue
        elif word == "END_FUNCTION_BLOCK":
            if block.far_over():
                refused.append((block, found.end()))
            block = None
        elif word == "TRANSITION":
            block.transitions += 1
            if block.transitions == MAX_TRANSITIONS + 1:
                block.over_transition = (found.start(), found.group(2))
        else:
            block.steps += 1
            if block.steps == MAX_STEPS + 1:
                block.over_step = (found.start(), found.group(2))
    if block is not None and block.far_over():
        refused.append((block, len(text)))
    if not refused:
        return text, []
    diagnostics: list[Diagnostic] = []
    kept: list[str] = []
    done = 0
    for over, end in refused:
        if over.over_step is not None:
            diagnostics.append(
                _problem(file, text, over.over_step, "S", "GRA208", over.steps, MAX_STEPS)
            )
        if over.over_transition is not None:
            diagnostics.append(
                _problem(
                    file,
                    text,
                    over.over_transition,
                    "T",
                    "GRA209",
                    over.transitions,
                    MAX_TRANSITIONS,
                )
            )
        kept += [text[done : over.start], "\n" * text.count("\n", over.start, end)]
        done = end
    kept.append(text[done:])
    return "".join(kept), diagnostics


def _problem(
    file: str,
    text: str,
    where: tuple[int, str | None],
    prefix: str,
    code: str,
    count: int,
    limit: int,
) -> Diagnostic:
    """The checker's limit diagnostic on the line of the first part over the limit."""
    offset, number = where
    element = f"{prefix}{int(number)}" if number is not None else None
    span = Span(file=file, line=text.count("\n", 0, offset) + 1, element=element)
    return render(code, span, count=count, limit=limit)

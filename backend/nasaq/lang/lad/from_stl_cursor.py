"""A cursor over one network's steps, and what each instruction is (``StepCursor``).

The lifter reads forwards and backtracks when a box pattern does not match; every refusal is a
``RefusalError`` carrying the catalogued reason at the instruction it names.
"""

from __future__ import annotations

import re
from typing import NoReturn

from nasaq.lang.lad.from_stl_boxes import BINARY, COMPARES, SHIFTS, TIMERS, UNARY
from nasaq.lang.lad.from_stl_reasons import RefusalError, not_convertible
from nasaq.lang.lad.from_stl_steps import Step

STATUS_BITS = frozenset({"OV", "OS", "BR", "UO"})
CHECKS = frozenset({"A", "AN", "O", "ON", "A(", "AN(", "O(", "ON(", "X", "XN", "X(", "XN("})
ACCU_OPS = frozenset(
    {"L", "T", "LC", "TAK", "PUSH", "POP", "ENT", "LEAVE", "INC", "DEC", "+", "CAW", "CAD"}
    | COMPARES
    | set(BINARY)
    | set(SHIFTS)
    | set(UNARY)
)
# Instructions that use the RLO left by what came before them.
RLO_USERS = frozenset(
    {"=", "S", "R", "NOT", "FP", "FN", ")", "JC", "JCN", "JNB", "JCB", "BEC", "SAVE", "CU", "CD"}
    | set(TIMERS)
)
COUNTER = re.compile(r"[CZ]\s*\d+", re.IGNORECASE)


class StepCursor:
    """The steps of one network and the reading position."""

    def __init__(self, steps: list[Step]) -> None:
        self.steps = steps
        self.i = 0

    def peek(self, ahead: int = 0) -> Step | None:
        at = self.i + ahead
        return self.steps[at] if at < len(self.steps) else None

    def take(self) -> Step:
        step = self.steps[self.i]
        self.i += 1
        return step

    def refuse(self, code: str, step: Step | None = None) -> NoReturn:
        if step is None:
            step = self.peek() or self.steps[-1]
        raise RefusalError(not_convertible(code, step.line, step.text))

    def no_label(self, step: Step) -> None:
        if step.labels and self.i > 0:
            raise RefusalError(not_convertible("LAD304", step.line, step.labels[0]))

    def is_nop(self, step: Step | None) -> bool:
        return step is not None and step.op == "NOP" and step.operand == "0"

    def classify(self, step: Step) -> str:
        op = step.op
        if step.labels and self.i > 0:
            raise RefusalError(not_convertible("LAD304", step.line, step.labels[0]))
        if op in ("X", "XN", "X(", "XN("):
            return "LAD305"
        if op in CHECKS or op in ("NOT", "FP", "FN"):
            return "LAD306"
        if op == "JU":
            return "LAD315"
        if op == "OPN":
            return "LAD326"
        if op == "CALL":
            return "LAD321"
        if op in ("L", "T", "LC"):
            return "LAD303"
        if op in ACCU_OPS:
            return "LAD318"
        if op in TIMERS:
            return "LAD323"
        return "LAD310"

    def coil_operand(self, step: Step) -> None:
        if step.kind == "indirect":
            self.refuse("LAD316", step)
        if step.operand is None or step.kind in ("literal", "status", "none"):
            self.refuse("LAD317", step)

    def value(self, step: Step) -> str:
        if step.kind == "indirect":
            self.refuse("LAD316", step)
        if step.operand is None:
            self.refuse("LAD317", step)
        return step.operand

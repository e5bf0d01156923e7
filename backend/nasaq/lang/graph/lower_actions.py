"""Phase 5 of a call (``SEMANTICS.md`` §2): one network per step with its interlock and its
action rows, in row order.

After ``A #Step.X`` / ``JCN`` the RLO is 1, so an ``N``/``S``/``R`` row is one ``=``/``S``/``R``
line; the lowering tracks whether the RLO is still 1 and writes ``SET`` only when a row before
left it otherwise. An event row is guarded by its event bit (``A #Step.S1`` / ``JCN``).
S5 timers and counters act on a rising RLO, so their rows give them one: ``CLR`` then ``SET``
(each event row runs once per event, so each acts exactly once).
"""

from __future__ import annotations

import re

from nasaq.lang.graph.lower_arith import Arithmetic, ArithmeticProblem
from nasaq.lang.graph.lower_chart import Chart
from nasaq.lang.graph.lower_conditions import Conditions
from nasaq.lang.graph.lower_emit import Emitter
from nasaq.lang.graph.lower_machinery import activate, m
from nasaq.lang.graph.model import Action, Step

_TIMER = re.compile(r"^T\s*\d+$", re.IGNORECASE)
_COUNTER = re.compile(r"^[CZ]\s*\d+$", re.IGNORECASE)
_COUNTER_OPS = {"CU": "CU", "CD": "CD"}
_TIMER_OPS = {"TL": "SE", "TD": "SS"}


def is_arithmetic(action: Action) -> bool:
    return action.qualifier == "N" and ":=" in action.operand


def _output_bit(action: Action) -> bool:
    """An N, D or L row on a bit (reset when the step is left), S0 N excepted."""
    if action.qualifier in ("D", "L"):
        return True
    return action.qualifier == "N" and not is_arithmetic(action) and action.event != "S0"


class Actions:
    """Emits each step's network of phase 5."""

    def __init__(
        self, chart: Chart, out: Emitter, conditions: Conditions, arithmetic: Arithmetic
    ) -> None:
        self.chart = chart
        self.out = out
        self.conditions = conditions
        self.arithmetic = arithmetic
        self.rlo_one = False  # the RLO is 1 and the first-check bit 0

    def need_one(self) -> None:
        if not self.rlo_one:
            self.out.emit("SET")
            self.rlo_one = True

    def step(self, step: Step) -> None:
        out = self.out
        origin = f"S{step.number}"
        title = f"S{step.number} {step.name}" + (f": {step.comment}" if step.comment else "")
        out.network(title.split("\n")[0], origin)
        bits = self._bits(step)
        leaving = bits or any(action.event == "S0" for action in step.actions)
        left, done = out.label(), out.label()
        out.emit("A", m(step, "X"))
        out.emit("JCN", left if leaving else done)
        self.rlo_one = True
        checked = self.interlock(step)
        for k, action in enumerate(step.actions, start=1):
            out.at(f"{origin}/A{k}")  # S0 rows too: a step left and entered again (a jump
            self.row(step, action, checked, True)  # to itself) runs them in row order
        out.at(origin)
        if bits and self.chart.has("ZERO_OP"):
            out.emit("A", "#ZERO_OP")
            out.emit("JCN", done)
            out.emit("CLR")
            for bit in bits:
                out.emit("=", bit)
        if leaving:  # the step left in this call: its S0 rows, its N/D/L bits to 0
            out.emit("JU", done)
            out.mark(left)
            out.emit("A", m(step, "S0"))
            out.emit("JCN", done)
            self.rlo_one = True
            for k, action in enumerate(step.actions, start=1):
                if action.event == "S0":
                    out.at(f"{origin}/A{k}")
                    self.row(step, action, False, False)
            out.at(origin)
            if bits:
                out.emit("CLR")
                for bit in bits:
                    out.emit("=", bit)
        out.mark(done)

    def _bits(self, step: Step) -> list[str]:
        found: list[str] = []
        for action in step.actions:
            if _output_bit(action) and action.operand.strip() not in found:
                found.append(action.operand.strip())
        return [self.chart.operand(bit) for bit in found]

    def interlock(self, step: Step) -> bool:
        """The interlock's L1/L0 events and ``#G7_OK``; False when the step has no interlock
        (its C rows run as plain rows)."""
        if step.interlock is None or not step.interlock.elements:
            return False
        out = self.out
        out.at(f"S{step.number}/C")
        self.conditions.chain(step.interlock, f"S{step.number}/C")
        out.emit("ON", "#G7_ILEN")
        out.emit("=", "#G7_OK")
        out.emit("AN", "#G7_OK")
        out.emit("AN", m(step, "LA"))
        out.emit("S", m(step, "LA"))
        out.emit("S", m(step, "L1"))
        out.emit("A", "#G7_OK")
        out.emit("A", m(step, "LA"))
        out.emit("R", m(step, "LA"))
        out.emit("S", m(step, "L0"))
        self.rlo_one = False
        return True

    def row(self, step: Step, action: Action, checked: bool, active: bool) -> None:
        """One row; ``checked``: the step has an interlock, so a C row depends on #G7_OK;
        ``active``: in the active step's code (an S0 row is guarded there too)."""
        out = self.out
        guarded = checked and action.interlock
        operand = self.chart.operand(action.operand.strip())
        bit_row = action.qualifier in ("N", "S", "R") and not is_arithmetic(action)
        if bit_row and action.event is None and guarded:  # NC: the bit follows the interlock
            out.emit("A", "#G7_OK")
            out.emit("=" if action.qualifier == "N" else action.qualifier, operand)
            self.rlo_one = False
            return
        if bit_row and action.event is not None and (active or action.event != "S0"):
            # an event row on a bit needs no jump: the event bit is the RLO of S/R
            out.emit("A", m(step, action.event))
            if guarded:
                out.emit("A", "#G7_OK")
            out.emit("R" if action.qualifier == "R" else "S", operand)
            self.rlo_one = False
            return
        skip = None
        if action.event is not None and (active or action.event != "S0"):
            skip = out.label()
            out.emit("A", m(step, action.event))
            if guarded:
                out.emit("A", "#G7_OK")
            out.emit("JCN", skip)
            self.rlo_one = True
        elif guarded:
            skip = out.label()
            out.emit("A", "#G7_OK")
            out.emit("JCN", skip)
            self.rlo_one = True
        self.body(step, action)
        if skip is not None:
            out.mark(skip)
            self.rlo_one = False

    def body(self, step: Step, action: Action) -> None:
        out = self.out
        operand = self.chart.operand(action.operand.strip())
        qualifier = action.qualifier
        if qualifier == "N" and is_arithmetic(action):
            lines = self.arithmetic.lower(action.operand)
            if isinstance(lines, ArithmeticProblem):
                out.report(lines.code, out.element, **lines.params)
                return
            for op, value in lines:
                out.emit(op, value)
            self.rlo_one = False
        elif qualifier in ("N", "S", "R"):
            self.need_one()
            out.emit("=" if qualifier == "N" else qualifier, operand)
        elif qualifier in ("D", "L"):
            if not self._has_time(action, "T#5S"):
                return
            out.emit("L", m(step, "T"))
            out.emit("L", self.chart.operand(action.time or ""))
            out.emit(">=D" if qualifier == "D" else "<D")
            out.emit("=", operand)
            self.rlo_one = False
        elif qualifier == "CALL":
            self.call(operand)
        elif qualifier in ("ON", "OFF"):
            self.step_control(step, action)
        elif qualifier in ("CS", "CU", "CD", "CR"):
            self.counter(action, operand)
        else:
            self.timer(action, operand)

    def _has_time(self, action: Action, example: str) -> bool:
        if action.time is not None and action.time.strip():
            return True
        self.out.report("GRA305", self.out.element, qualifier=action.qualifier, example=example)
        return False

    def call(self, operand: str) -> None:
        out = self.out
        skip = None
        if self.chart.has("ZERO_OP"):
            skip = out.label()
            out.emit("A", "#ZERO_OP")
            out.emit("JC", skip)
        out.emit("CALL", operand)
        if skip is not None:
            out.mark(skip)
        self.rlo_one = False

    def step_control(self, step: Step, action: Action) -> None:
        out, chart = self.out, self.chart
        name = action.operand.strip()
        if action.qualifier == "OFF" and name.upper() == "S_ALL":
            targets = [other for other in chart.steps if other is not step]
        else:
            found = chart.step(name)
            if found is None:
                out.report("GRA306", out.element, step=name)
                return
            targets = [found]
        for target in targets:
            if action.qualifier == "ON":
                skip = out.label()
                out.emit("AN", m(target, "X"))
                out.emit("JCN", skip)
                activate(out, target, "PS1")
                out.mark(skip)
            else:
                out.emit("A", m(target, "X"))
                out.emit("R", m(target, "X"))
                out.emit("S", m(target, "PS0"))
                if target.interlock is not None:
                    out.emit("R", m(target, "LA"))
                if target.supervision is not None:
                    out.emit("R", m(target, "VA"))
        self.rlo_one = False

    def counter(self, action: Action, operand: str) -> None:
        out = self.out
        if not _COUNTER.match(operand) and not operand.startswith('"'):
            out.report("GRA307", out.element, operand=operand, what="C")
            return
        if action.qualifier == "CR":
            self.need_one()
            out.emit("R", operand)
            return
        if action.qualifier == "CS" and not self._has_time(action, "C#10"):
            return
        out.emit("CLR")  # the edge memory of the instruction to 0, then the rising RLO
        out.emit("S" if action.qualifier == "CS" else _COUNTER_OPS[action.qualifier], operand)
        out.emit("SET")
        if action.qualifier == "CS":
            out.emit("L", self.chart.operand(action.time or ""))
            out.emit("S", operand)
        else:
            out.emit(_COUNTER_OPS[action.qualifier], operand)
        self.rlo_one = True

    def timer(self, action: Action, operand: str) -> None:
        out = self.out
        if not _TIMER.match(operand) and not operand.startswith('"'):
            out.report("GRA307", out.element, operand=operand, what="T")
            return
        if action.qualifier == "TR":
            self.need_one()
            out.emit("R", operand)
            return
        if not self._has_time(action, "S5T#5S"):
            return
        op = _TIMER_OPS[action.qualifier]
        out.emit("CLR")
        out.emit(op, operand)
        out.emit("SET")
        out.emit("L", self.chart.operand(action.time or ""))
        out.emit(op, operand)
        self.rlo_one = True

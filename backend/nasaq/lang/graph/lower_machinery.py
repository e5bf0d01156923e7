"""The sequencer machinery of one call (``SEMANTICS.md`` §2, phases 1–4) as straight-line
STL: an inactive step or transition costs one ``A``/``JCN`` pair per phase, the rare paths
(initialisation, a Control Sequencer command, MAN mode) are jumped over.

The parameters a set lacks are not read: their fixed value is built in (``EN_IL`` as 1 …).
"""

from __future__ import annotations

from nasaq.lang.graph.lower_chart import Chart
from nasaq.lang.graph.lower_conditions import Conditions
from nasaq.lang.graph.lower_emit import Emitter
from nasaq.lang.graph.model import Step, Transition

G7 = "G7"


def m(step: Step | Transition, member: str) -> str:
    """A member of a step's or transition's STRUCT."""
    return f"#{step.name}.{member}"


def activate(out: Emitter, step: Step, event: str = "S1") -> None:
    """With RLO 1 (after the caller's check that ``step`` is inactive): switches it on,
    raising ``event`` (``S1`` now, or ``PS1`` for the next call), its times starting at 0."""
    out.emit("S", m(step, "X"))
    out.emit("S", m(step, event))
    out.emit("L", "L#0")
    out.emit("T", m(step, "T"))
    out.emit("T", m(step, "U"))


def has_interlock(step: Step) -> bool:
    return step.interlock is not None


def has_supervision(step: Step) -> bool:
    return step.supervision is not None


class Machinery:
    """Emits the phases around the actions."""

    def __init__(self, chart: Chart, out: Emitter, conditions: Conditions) -> None:
        self.chart = chart
        self.out = out
        self.conditions = conditions
        self.temps: list[str] = []  # VAR_TEMP bits beyond lower_interface.TEMPS

    # -- phase 1 --------------------------------------------------------------------------------

    def initialisation(self) -> None:
        out, chart = self.out, self.chart
        out.network("Sequencer: initialisation (INIT_SQ, OFF_SQ)", G7)
        off, done = out.label(), out.label()
        out.emit("A", "#G7_OFF")
        out.emit("JC", off)
        out.emit("AN", "#G7_STARTED")
        out.emit("O", "#G7_INIT")
        out.emit("=", "#G7_NOSW")
        out.emit("JCN", done)
        for step in chart.steps:
            if not step.initial:
                self._leave_if_active(step, "S0")
        for step in chart.steps:
            if step.initial:
                kept = out.label()
                out.emit("AN", m(step, "X"))
                out.emit("JCN", kept)
                activate(out, step)
                out.mark(kept)
        self._clear_errors()
        out.emit("SET")
        out.emit("=", "#G7_STARTED")
        out.emit("JU", done)
        out.mark(off)
        for step in chart.steps:
            self._leave_if_active(step, "S0")
        self._clear_errors()
        out.emit("SET")
        out.emit("=", "#G7_NOSW")
        out.mark(done)
        # Switching (phase 4) this call: P1 lets a true condition fire, P2 fires without one.
        out.emit("AN", "#G7_NOSW")
        if chart.has("HALT_SQ"):
            out.emit("AN", "#HALT_SQ")
        out.emit("AN", "#G7_MAN")
        out.emit("=", "#G7_SW")
        out.emit("A(")
        out.emit("A", "#G7_TAP")
        out.emit("A", "#G7_E_T_PUSH")
        out.emit("O", "#G7_AUTO")
        out.emit("O", "#G7_TOP")
        out.emit(")")
        out.emit("A", "#G7_SW")
        out.emit("=", "#G7_P1")
        out.emit("A", "#G7_SW")
        out.emit("A", "#G7_TOP")
        out.emit("A", "#G7_E_T_PUSH")
        out.emit("=", "#G7_P2")
        entered = sorted({step.number for step, _ in self._leaving()})
        if entered:  # which of the steps that can be passed a transition enters this call
            out.emit("CLR")
            for number in entered:
                self.temps.append(f"G7_J{number}")
                out.emit("=", f"#G7_J{number}")

    def _leaving(self) -> list[tuple[Step, Transition]]:
        """With Skip Step possible: the steps that can be passed and their leaving transitions."""
        chart = self.chart
        if not chart.block.settings.skip_steps and not chart.has("EN_SSKIP"):
            return []
        return [(s, t) for s in chart.steps for t in chart.sources_with(s)]

    def _leave_if_active(self, step: Step, event: str) -> None:
        self.out.emit("A", m(step, "X"))
        self.out.emit("R", m(step, "X"))
        self.out.emit("S", m(step, event))

    def clear_errors(self, step: Step) -> None:
        """A step being left (the RLO says whether): its disturbance goes, without events."""
        if has_interlock(step):
            self.out.emit("R", m(step, "LA"))
        if has_supervision(step):
            self.out.emit("R", m(step, "VA"))

    def _clear_errors(self) -> None:
        self.out.emit("CLR")
        for step in self.chart.steps:
            if has_interlock(step):
                self.out.emit("=", m(step, "LA"))
            if has_supervision(step):
                self.out.emit("=", m(step, "VA"))

    # -- phases 2 and 3 --------------------------------------------------------------------------

    def times(self) -> None:
        out = self.out
        out.network("Sequencer: step times T and U", G7)
        for step in self.chart.steps:
            skip = out.label()
            out.emit("A", m(step, "X"))
            out.emit("AN", m(step, "S1"))
            out.emit("JCN", skip)
            out.emit("L", m(step, "T"))
            out.emit("L", "#G7_DT")
            out.emit("+D")
            out.emit("T", m(step, "T"))
            if not has_interlock(step) and not has_supervision(step):
                out.emit("T", m(step, "U"))  # never disturbed: U is T
                out.mark(skip)
                continue
            out.emit("A", m(step, "LA"))
            out.emit("O", m(step, "VA"))
            out.emit("JC", skip)
            out.emit("L", m(step, "U"))
            out.emit("L", "#G7_DT")
            out.emit("+D")
            out.emit("T", m(step, "U"))
            out.mark(skip)

    def supervision(self) -> None:
        out, chart = self.out, self.chart
        supervised = [step for step in chart.steps if has_supervision(step)]
        if not supervised:
            return
        for step in supervised:
            origin = f"S{step.number}/V"
            out.network(f"S{step.number} {step.name}: supervision", origin)
            skip = out.label()
            out.emit("A", m(step, "X"))
            out.emit("AN", m(step, "S1"))
            out.emit("JCN", skip)
            self.conditions.chain(step.supervision, origin)
            out.emit("A", "#G7_SVEN")
            out.emit("=", "#G7_ERR")
            out.emit("A", "#G7_ERR")
            out.emit("AN", m(step, "VA"))
            out.emit("S", m(step, "VA"))
            out.emit("S", m(step, "V1"))
            settings = chart.block.settings
            if chart.has("EN_ACKREQ") or not settings.acknowledge_required:
                out.emit("AN", "#G7_ERR")
                out.emit("A", m(step, "VA"))
                if chart.has("EN_ACKREQ"):
                    out.emit("AN", "#EN_ACKREQ")
                out.emit("R", m(step, "VA"))
                out.emit("S", m(step, "V0"))
            out.mark(skip)
        out.network("Sequencer: acknowledgement (ACK_EF)", G7)
        skip = out.label()
        out.emit("A", "#G7_E_ACK_EF")
        out.emit("JCN", skip)
        for step in supervised:
            out.emit("A", m(step, "VA"))
            out.emit("R", m(step, "VA"))
            out.emit("S", m(step, "V0"))
            out.emit("S", m(step, "A1"))
        out.mark(skip)

    # -- phase 4 --------------------------------------------------------------------------------

    def transitions(self) -> None:
        for transition in self.chart.transitions:
            self.transition(transition)
        self.skip_steps()
        self.manual()

    def skip_steps(self) -> None:
        """Skip Step (``skip_steps`` or EN_SSKIP): a step activated in this call whose leaving
        transition is already true is left again at once, without S1 or S0, and that
        transition's targets are activated instead; repeated until nothing more is skipped,
        each step at most once (``#G7_K<n>``)."""
        out, chart = self.out, self.chart
        if not chart.block.settings.skip_steps and not chart.has("EN_SSKIP"):
            return
        leaving = self._leaving()
        if not leaving:
            return
        out.network("Sequencer: skip steps", G7)
        done, again = out.label(), out.label()
        if chart.has("EN_SSKIP"):
            out.emit("A", "#EN_SSKIP")
            out.emit("A", "#G7_SW")
        else:
            out.emit("A", "#G7_SW")
        out.emit("JCN", done)
        out.emit("CLR")
        flags: dict[int, str] = {}
        for step, _ in leaving:
            if step.number not in flags:
                flags[step.number] = f"#G7_K{step.number}"
                self.temps.append(f"G7_K{step.number}")
                out.emit("=", flags[step.number])
        out.mark(again)
        out.emit("CLR")
        out.emit("=", "#G7_SKIP")
        for step, transition in leaving:
            origin = f"T{transition.number}"
            out.at(origin)
            other = out.label()
            out.emit("A", m(step, "X"))
            out.emit("A", f"#G7_J{step.number}")
            out.emit("AN", flags[step.number])
            out.emit("JCN", other)
            if self.conditions.chain(transition.condition, origin):
                out.at(origin)
                out.emit("JCN", other)
            out.emit("SET")
            out.emit("=", flags[step.number])
            out.emit("=", "#G7_SKIP")
            out.emit("R", m(step, "X"))
            out.emit("R", m(step, "S1"))
            targets = [s for s in (chart.step(n) for n in transition.target) if s is not None]
            self.fire([], targets)
            out.mark(other)
        out.at(G7)
        out.emit("A", "#G7_SKIP")
        out.emit("JC", again)
        out.mark(done)

    def transition(self, transition: Transition) -> None:
        out, chart = self.out, self.chart
        origin = f"T{transition.number}"
        target = ", ".join(transition.target) or "end"
        source = ", ".join(transition.source)
        out.network(f"T{transition.number} {transition.name}: {source} -> {target}", origin)
        done = out.label()
        out.emit("CLR")
        out.emit("=", m(transition, "TT"))
        sources = [s for s in (chart.step(name) for name in transition.source) if s is not None]
        targets = [s for s in (chart.step(name) for name in transition.target) if s is not None]
        for step in sources:
            out.emit("A", m(step, "X"))
            out.emit("AN", m(step, "S1"))
        out.emit("JCN", done)
        self.conditions.chain(transition.condition, origin)
        out.at(origin)
        out.emit("=", m(transition, "TT"))
        out.emit("A", m(transition, "TT"))
        out.emit("A", "#G7_P1")
        out.emit("O", "#G7_P2")
        out.emit("JCN", done)
        blocking = self._blocking(sources)
        if blocking:
            for k, (step, bit) in enumerate(blocking):
                out.emit("A" if k == 0 else "O", m(step, bit))
            out.emit("JC", done)
        self.fire(sources, targets)
        out.mark(done)

    def _blocking(self, sources: list[Step]) -> list[tuple[Step, str]]:
        """The error bits that keep a transition from firing."""
        found: list[tuple[Step, str]] = []
        for step in sources:
            if has_supervision(step):
                found.append((step, "VA"))
            if has_interlock(step) and self.chart.block.settings.interlock_blocks:
                found.append((step, "LA"))
        return found

    def fire(self, sources: list[Step], targets: list[Step]) -> None:
        """With RLO 1: leaves the sources, activates the targets."""
        out = self.out
        for step in sources:
            out.emit("R", m(step, "X"))
            out.emit("S", m(step, "S0"))
            self.clear_errors(step)
        for step in targets:
            out.emit("S", m(step, "X"))
            out.emit("S", m(step, "S1"))
            if f"G7_J{step.number}" in self.temps:
                out.emit("S", f"#G7_J{step.number}")
            if has_interlock(step):
                out.emit("R", m(step, "LA"))
            if has_supervision(step):
                out.emit("R", m(step, "VA"))
        if targets:
            out.emit("L", "L#0")
            for step in targets:
                out.emit("T", m(step, "T"))
                out.emit("T", m(step, "U"))

    def manual(self) -> None:
        """MAN mode: S_ON/S_OFF (or the Control Sequencer) switch the step S_SEL."""
        out, chart = self.out, self.chart
        out.network("Sequencer: MAN mode (S_ON, S_OFF on step S_SEL)", G7)
        done, off = out.label(), out.label()
        out.emit("A", "#G7_MAN")  # phase 4: not while initialising, off or halted
        out.emit("AN", "#G7_NOSW")
        if chart.has("HALT_SQ"):
            out.emit("AN", "#HALT_SQ")
        out.emit("A(")
        out.emit("O", "#G7_E_S_ON")
        out.emit("O", "#G7_E_S_OFF")
        out.emit(")")
        out.emit("JCN", done)
        out.emit("A", "#G7_E_S_ON")
        out.emit("JCN", off)
        for step in chart.steps:
            other = out.label()
            out.emit("L", "#G7_SEL")
            out.emit("L", str(step.number))
            out.emit("==I")
            out.emit("AN", m(step, "X"))  # only an inactive step is switched on
            out.emit("JCN", other)
            activate(out, step)
            out.mark(other)
        out.mark(off)
        out.emit("A", "#G7_E_S_OFF")
        out.emit("JCN", done)
        for step in chart.steps:
            out.emit("L", "#G7_SEL")
            out.emit("L", str(step.number))
            out.emit("==I")
            out.emit("A", m(step, "X"))
            out.emit("R", m(step, "X"))
            out.emit("S", m(step, "S0"))
            self.clear_errors(step)
        out.mark(done)

"""Phase 6 of a call (``SEMANTICS.md`` §2): the FB's outputs of its parameter set: the error
summaries, the mode and enable echoes, and the step display (S_NO, S_ACTIVE, S_MORE) moved
through the active steps by S_NEXT/S_PREV.
"""

from __future__ import annotations

from nasaq.lang.graph.lower_chart import Chart
from nasaq.lang.graph.lower_emit import Emitter
from nasaq.lang.graph.lower_machinery import G7, has_interlock, has_supervision, m


class Outputs:
    """Emits the outputs network."""

    def __init__(self, chart: Chart, out: Emitter) -> None:
        self.chart = chart
        self.out = out

    def outputs(self) -> None:
        out, chart = self.out, self.chart
        if not chart.outputs:
            return
        out.network("Sequencer: outputs", G7)
        interlocked = [s for s in chart.steps if has_interlock(s)]
        supervised = [s for s in chart.steps if has_supervision(s)]
        for name, bits in (
            ("ERR_FLT", [(s, "LA") for s in interlocked] + [(s, "VA") for s in supervised]),
            ("ERROR", [(s, "LA") for s in interlocked]),
            ("FAULT", [(s, "VA") for s in supervised]),
        ):
            if not chart.has(name):
                continue
            if bits:
                for step, bit in bits:
                    out.emit("O", m(step, bit))
            else:
                out.emit("CLR")
            out.emit("=", f"#{name}")
        if chart.has("SQ_ISOFF"):
            for step in chart.steps:
                out.emit("O", m(step, "X"))
            if not chart.steps:
                out.emit("CLR")
            out.emit("NOT")
            out.emit("=", "#SQ_ISOFF")
        for name, temp in (
            ("AUTO_ON", "#G7_AUTO"),
            ("MAN_ON", "#G7_MAN"),
            ("TAP_ON", "#G7_TAP"),
            ("TOP_ON", "#G7_TOP"),
            ("IL_ENABLED", "#EN_IL"),
            ("SV_ENABLED", "#EN_SV"),
            ("SQ_HALTED", "#HALT_SQ"),
            ("TM_HALTED", "#HALT_TM"),
            ("OP_ZEROED", "#ZERO_OP"),
        ):
            if chart.has(name):
                out.emit("A", temp)
                out.emit("=", f"#{name}")
        if chart.has("S_NO"):
            self.display()

    def display(self) -> None:
        """S_NO, S_ACTIVE, S_MORE: the displayed active step, moved by S_NEXT/S_PREV (one pass
        over the steps, a second one when the displayed step moved)."""
        out, chart = self.out, self.chart
        again, found, redo = out.label(), out.label(), out.label()
        out.emit("CLR")
        out.emit("=", "#G7_ERR")  # the second pass is running
        out.mark(again)
        self._find_displayed()
        out.emit("A", "#G7_ERR")
        out.emit("JC", found)
        out.emit("L", "#G7_N")
        out.emit("L", "1")
        out.emit(">I")
        out.emit("=", "#S_MORE")
        out.emit("A", "#G7_MAN")
        out.emit("JC", found)
        out.emit("L", "#G7_N")  # no active step: nothing to show, G7_DISP kept
        out.emit("L", "0")
        out.emit("==I")
        out.emit("JC", found)
        for edge, op in (("#G7_E_S_NEXT", "+I"), ("#G7_E_S_PREV", "-I")):
            kept = out.label()
            out.emit("A", edge)
            out.emit("JCN", kept)
            out.emit("L", "#G7_DISP")
            out.emit("L", "1")
            out.emit(op)
            out.emit("T", "#G7_DISP")
            out.mark(kept)
        inside = out.label()  # G7_DISP := G7_DISP modulo G7_N, 0 .. G7_N - 1
        out.emit("L", "#G7_DISP")
        out.emit("ITD")
        out.emit("L", "#G7_N")
        out.emit("ITD")
        out.emit("MOD")
        out.emit("T", "#G7_DISP")
        out.emit("L", "#G7_DISP")
        out.emit("L", "0")
        out.emit("<I")
        out.emit("JCN", inside)
        out.emit("L", "#G7_DISP")
        out.emit("L", "#G7_N")
        out.emit("+I")
        out.emit("T", "#G7_DISP")
        out.mark(inside)
        out.emit("A", "#G7_E_S_NEXT")
        out.emit("O", "#G7_E_S_PREV")
        out.emit("JC", redo)
        out.emit("L", "#G7_SNO")
        out.emit("L", "0")
        out.emit("==I")
        out.emit("JCN", found)
        out.mark(redo)
        out.emit("SET")
        out.emit("=", "#G7_ERR")
        out.emit("JU", again)
        out.mark(found)
        manual, done = out.label(), out.label()
        out.emit("A", "#G7_MAN")
        out.emit("JC", manual)
        out.emit("L", "#G7_SNO")
        out.emit("T", "#S_NO")
        out.emit("L", "#G7_SNO")
        out.emit("L", "0")
        out.emit("<>I")
        out.emit("=", "#S_ACTIVE")
        out.emit("JU", done)
        out.mark(manual)
        out.emit("L", "#S_SEL")
        out.emit("T", "#S_NO")
        out.emit("CLR")
        out.emit("=", "#S_ACTIVE")
        for step in chart.steps:
            out.emit("L", "#S_SEL")
            out.emit("L", str(step.number))
            out.emit("==I")
            out.emit("A", m(step, "X"))
            out.emit("S", "#S_ACTIVE")
        out.mark(done)

    def _find_displayed(self) -> None:
        """G7_N := the number of active steps, G7_SNO := the number of the G7_DISP-th (or 0):
        a step's count is compared after it was counted, so one label per step does."""
        out = self.out
        out.emit("L", "0")
        out.emit("T", "#G7_N")
        out.emit("T", "#G7_SNO")
        out.emit("L", "#G7_DISP")
        out.emit("L", "1")
        out.emit("+I")
        out.emit("T", "#G7_D1")
        for step in self.chart.steps:
            skip = out.label()
            out.emit("A", m(step, "X"))
            out.emit("JCN", skip)
            out.emit("L", "#G7_N")
            out.emit("L", "1")
            out.emit("+I")
            out.emit("T", "#G7_N")
            out.emit("L", "#G7_D1")
            out.emit("==I")
            out.emit("JCN", skip)
            out.emit("L", str(step.number))
            out.emit("T", "#G7_SNO")
            out.mark(skip)

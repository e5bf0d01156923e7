"""Phase 0 of a call (``SEMANTICS.md`` §2): the time since the last call (TIME_TCK, SFC 64,
once per call), last call's events cleared, the inputs' edges and the Control Sequencer's
command (§4) merged into this call's temporaries, the mode.

Only the event bits something can set are cleared (the S1/S0 of every step, PS1/PS0 of the
steps an ON/OFF row names, V1 V0 A1 of supervised and L1 L0 of interlocked steps): an idle
step costs two lines here.
"""

from __future__ import annotations

from nasaq.lang.graph.lower_chart import EDGE_INPUTS, Chart
from nasaq.lang.graph.lower_emit import Emitter
from nasaq.lang.graph.lower_machinery import G7, has_interlock, has_supervision, m

# Control Sequencer commands (§4) that act as an input edge.
_COMMAND_EDGES = {1: "SW_AUTO", 2: "SW_MAN", 3: "SW_TAP", 4: "SW_TOP", 5: "ACK_EF", 8: "T_PUSH"}
_COMMAND_BITS = {9: ("S", "#G7_INIT"), 10: ("S", "#G7_OFF"), 11: ("R", "#G7_IL_OFF")}
_COMMAND_BITS |= {12: ("S", "#G7_IL_OFF"), 13: ("R", "#G7_SV_OFF"), 14: ("S", "#G7_SV_OFF")}
_MODES = (("SW_AUTO", 1), ("SW_TAP", 3), ("SW_TOP", 4), ("SW_MAN", 2))


class StartOfCall:
    """Emits the first network of the FB."""

    def __init__(self, chart: Chart, out: Emitter) -> None:
        self.chart = chart
        self.out = out

    def start_of_call(self) -> None:
        out, chart = self.out, self.chart
        out.network("Sequencer: start of call (time, events, inputs, mode)", G7)
        out.emit("CALL", "SFC 64 (RET_VAL := #G7_NOW)")
        out.emit("L", "L#0")
        out.emit("T", "#G7_DT")
        first = out.label()
        out.emit("A", "#G7_STARTED")
        out.emit("JCN", first)
        out.emit("L", "#G7_NOW")
        out.emit("L", "#G7_TICK")
        out.emit("-D")
        out.emit("L", "DW#16#7FFFFFFF")
        out.emit("AD")
        out.emit("T", "#G7_DT")
        out.mark(first)
        out.emit("L", "#G7_NOW")
        out.emit("T", "#G7_TICK")
        if chart.has("HALT_TM"):
            running = out.label()
            out.emit("A", "#HALT_TM")
            out.emit("JCN", running)
            out.emit("L", "L#0")
            out.emit("T", "#G7_DT")
            out.mark(running)
        # Last call's events go; an ON/OFF of last call raises S1/S0 now. Only the bits
        # something can set are written: PS1/PS0 of the steps an ON/OFF row names, V1 V0 A1
        # of supervised steps, L1 L0 of interlocked ones.
        switched_on, switched_off = self._switched()
        pending = [s for s in chart.steps if s.name in switched_on or s.name in switched_off]
        for step in pending:
            out.emit("A", m(step, "PS1"))
            out.emit("=", m(step, "S1"))
            out.emit("A", m(step, "PS0"))
            out.emit("=", m(step, "S0"))
        out.emit("CLR")
        for step in chart.steps:
            bits = ["PS1", "PS0"] if step in pending else ["S1", "S0"]
            if has_supervision(step):
                bits += ["V1", "V0", "A1"]
            if has_interlock(step):
                bits += ["L1", "L0"]
            for bit in bits:
                out.emit("=", m(step, bit))
        self.edges()
        self.mode()

    def _switched(self) -> tuple[set[str], set[str]]:
        """The names of the steps an ON row / an OFF row can switch."""
        on: set[str] = set()
        off: set[str] = set()
        for step in self.chart.steps:
            for action in step.actions:
                if action.qualifier not in ("ON", "OFF"):
                    continue
                if action.operand.strip().upper() == "S_ALL":
                    (on if action.qualifier == "ON" else off).update(
                        s.name for s in self.chart.steps
                    )
                    continue
                found = self.chart.step(action.operand)
                if found is not None:
                    (on if action.qualifier == "ON" else off).add(found.name)
        return on, off

    def edges(self) -> None:
        """This call's edges of the inputs (and the Control Sequencer's command), level inputs
        copied to temporaries so the command can add to them."""
        out, chart = self.out, self.chart
        missing = []
        for name in EDGE_INPUTS:
            if name in chart.inputs:
                out.emit("A", f"#{name}")
                out.emit("FP", f"#G7_M_{name}")
                out.emit("=", f"#G7_E_{name}")
            else:
                missing.append(name)
        out.emit("A", "#INIT_SQ")
        out.emit("=", "#G7_INIT")
        if chart.has("OFF_SQ"):
            out.emit("A", "#OFF_SQ")
            out.emit("=", "#G7_OFF")
            out.emit("CLR")
        else:
            out.emit("CLR")
            out.emit("=", "#G7_OFF")
        for name in missing:
            out.emit("=", f"#G7_E_{name}")
        out.emit("L", "#S_SEL" if chart.has("S_SEL") else "0")
        out.emit("T", "#G7_SEL")
        done = out.label()
        out.emit("L", "#G7_CMD")
        out.emit("L", "0")
        out.emit("==I")
        out.emit("JC", done)
        for number, name in _COMMAND_EDGES.items():
            self._command(number)
            out.emit("S", f"#G7_E_{name}")
        for number, name in ((6, "S_ON"), (7, "S_OFF")):
            other = out.label()
            self._command(number)
            out.emit("JCN", other)
            out.emit("S", f"#G7_E_{name}")
            out.emit("L", "#G7_CMD_STEP")
            out.emit("T", "#G7_SEL")
            out.mark(other)
        for number, (op, bit) in _COMMAND_BITS.items():
            self._command(number)
            out.emit(op, bit)
        out.emit("L", "0")
        out.emit("T", "#G7_CMD")
        out.mark(done)

    def _command(self, number: int) -> None:
        self.out.emit("L", "#G7_CMD")
        self.out.emit("L", str(number))
        self.out.emit("==I")

    def mode(self) -> None:
        out = self.out
        for name, mode in _MODES:
            kept = out.label()
            out.emit("A", f"#G7_E_{name}")
            out.emit("JCN", kept)
            out.emit("L", str(mode))
            out.emit("T", "#G7_MODE")
            out.mark(kept)
        for temp, mode in (("#G7_AUTO", 1), ("#G7_MAN", 2), ("#G7_TAP", 3), ("#G7_TOP", 4)):
            out.emit("L", "#G7_MODE")
            out.emit("L", str(mode))
            out.emit("==I")
            out.emit("=", temp)
        self._enabled("EN_IL", "#G7_IL_OFF", "#G7_ILEN")
        self._enabled("EN_SV", "#G7_SV_OFF", "#G7_SVEN")

    def _enabled(self, parameter: str, box: str, temp: str) -> None:
        out = self.out
        if self.chart.has(parameter):
            out.emit("A", f"#{parameter}")
            out.emit("AN", box)
        else:
            out.emit("AN", box)
        out.emit("=", temp)

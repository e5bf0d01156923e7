"""A direct Python model of one call of a Graph FB (``nasaq/lang/graph/SEMANTICS.md`` §2).

The oracle the rule and property tests compare the compiled FB on the CPU with. It reads the
model objects (``GraphBlock``), never the lowering, and follows the phases of SEMANTICS §2 in
their order, one function per phase. Memory is a dict of bits and words keyed by the operand
as written without spaces (``Q0.0``, ``MW10``, ``#count``); S5 timers and counters are kept as
plain numbers. It models what the tests use: contacts, parallels and comparator boxes in
conditions; ``=``/``S``/``R`` coils in permanent networks; ``A := B [op C]`` arithmetic with
``+ - *`` on INT/DINT; CALLs as Python callables given by the test.

Where SEMANTICS.md leaves room, the reference reads it as follows (noted for the lead in
/work/briefs/h4-to-h3.md): TT is computed in every call, only firing is gated (as in MAN);
MAN's S_ON/S_OFF belong to phase 4, so phase 1 and HALT_SQ stop them too, and S_OFF raises S0
only on an active step; Skip Step evaluates the leaving transition as the step would be just
activated (T = 0); ZERO_OP zeroes the N/D/L bits of the active steps (a left step's S0 N still
writes 1).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from nasaq.lang.graph.model import Action, GraphBlock, Step, Transition
from nasaq.lang.lad.model import Box, Coil, Contact, Element, Network, Parallel, Series

STANDARD_IN = [
    "OFF_SQ",
    "INIT_SQ",
    "ACK_EF",
    "S_PREV",
    "S_NEXT",
    "SW_AUTO",
    "SW_TAP",
    "SW_MAN",
    "S_SEL",
    "S_ON",
    "S_OFF",
    "T_PUSH",
]
MAXIMUM_IN = [
    "OFF_SQ",
    "INIT_SQ",
    "ACK_EF",
    "HALT_SQ",
    "HALT_TM",
    "ZERO_OP",
    "EN_IL",
    "EN_SV",
    "S_PREV",
    "S_NEXT",
    "SW_AUTO",
    "SW_TAP",
    "SW_MAN",
    "S_SEL",
    "S_ON",
    "S_OFF",
    "T_PUSH",
]
PARAMETERS_IN: dict[str, list[str]] = {
    "MINIMUM": ["INIT_SQ"],
    "STANDARD": STANDARD_IN,
    "MAXIMUM": MAXIMUM_IN,
    "USER_DEFINED": [*MAXIMUM_IN, "EN_ACKREQ", "EN_SSKIP", "SW_TOP"],
}
EDGE_INPUTS = [
    "SW_AUTO",
    "SW_MAN",
    "SW_TAP",
    "SW_TOP",
    "ACK_EF",
    "T_PUSH",
    "S_ON",
    "S_OFF",
    "S_NEXT",
    "S_PREV",
]
EVENTS = ("S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1")
# The Control Sequencer mailbox (§4): command -> the input it pulses.
MAILBOX_EDGES = {1: "SW_AUTO", 2: "SW_MAN", 3: "SW_TAP", 4: "SW_TOP", 5: "ACK_EF"}
MAILBOX_EDGES |= {6: "S_ON", 7: "S_OFF", 8: "T_PUSH"}

Call = Callable[["Memory"], None]


@dataclass(slots=True)
class StepState:
    step: Step
    sequencer: int
    X: int = 0
    LA: int = 0
    VA: int = 0
    PS1: int = 0
    PS0: int = 0
    T: int = 0
    U: int = 0
    events: dict[str, int] = field(default_factory=lambda: dict.fromkeys(EVENTS, 0))

    def member(self, name: str) -> int:
        if name in EVENTS:
            return self.events[name]
        if name == "SNO":
            return self.step.number
        value = getattr(self, name)
        assert isinstance(value, int)
        return value


@dataclass(slots=True)
class Timer:
    kind: str  # "SE" (TL) or "SS" (TD)
    start: int
    duration: int


@dataclass(slots=True)
class Memory:
    """Bits and words of the process image, markers and the FB's own variables; timers and
    counters. Words are kept as Python ints (signed)."""

    cells: dict[str, int] = field(default_factory=dict)
    timers: dict[int, Timer] = field(default_factory=dict)
    counters: dict[int, int] = field(default_factory=dict)
    now: int = 0

    def get(self, operand: str) -> int:
        return self.cells.get(key(operand), 0)

    def put(self, operand: str, value: int) -> None:
        self.cells[key(operand)] = int(value)

    def timer_q(self, number: int) -> int:
        timer = self.timers.get(number)
        if timer is None:
            return 0
        elapsed = self.now - timer.start >= timer.duration
        return int(elapsed) if timer.kind == "SS" else int(not elapsed)


def key(operand: str) -> str:
    """``Q 0.0`` -> ``Q0.0``, ``mw 10`` -> ``MW10``, ``#Count`` -> ``#count``."""
    text = operand.strip().replace(" ", "")
    return text if text.startswith("#") else text.upper()


_TIME_PART = re.compile(r"(\d+)(MS|D|H|M|S)", re.IGNORECASE)
_UNIT_MS = {"D": 86_400_000, "H": 3_600_000, "M": 60_000, "S": 1000, "MS": 1}


def time_ms(text: str) -> int:
    """``T#1M30S`` / ``S5T#8S`` / ``T#500MS`` in ms."""
    body = text.split("#", 1)[1].replace("_", "")
    return sum(int(n) * _UNIT_MS[u.upper()] for n, u in _TIME_PART.findall(body))


class Reference:
    """One instance of a Graph FB (its instance DB) and the memory it works on."""

    def __init__(self, block: GraphBlock, calls: Mapping[str, Call] | None = None) -> None:
        self.block = block
        self.calls = {key(name): call for name, call in (calls or {}).items()}
        self.settings = block.settings
        self.memory = Memory()
        self.steps: dict[str, StepState] = {}
        self.numbers: dict[int, StepState] = {}
        for index, sequencer in enumerate(block.sequencers):
            for step in sequencer.steps:
                state = StepState(step, index)
                self.steps[step.name] = state
                self.numbers[step.number] = state
        self.transitions: list[tuple[int, Transition]] = [
            (i, t) for i, sequencer in enumerate(block.sequencers) for t in sequencer.transitions
        ]
        self.tt: dict[str, int] = {t.name: 0 for _, t in self.transitions}
        self.numbered_transitions = {t.number: t.name for _, t in self.transitions}
        self.inputs = PARAMETERS_IN[self.settings.parameters]
        self.params: dict[str, int] = dict.fromkeys(self.inputs, 0)
        for name, value in (("EN_IL", 1), ("EN_SV", 1)):
            if name in self.params:
                self.params[name] = value
        if "EN_ACKREQ" in self.params:
            self.params["EN_ACKREQ"] = int(self.settings.acknowledge_required)
            self.params["EN_SSKIP"] = int(self.settings.skip_steps)
        self.outs: dict[str, int] = {}
        self.mode = 1
        self.started = 0
        self.tick = 0
        self.edge_memory: dict[str, int] = dict.fromkeys(EDGE_INPUTS, 0)
        self.disp = 0
        self.il_off = 0
        self.sv_off = 0
        self.cmd = 0
        self.cmd_step = 0

    # ---- the parameters a missing one behaves as ---------------------------------------------
    def param(self, name: str) -> int:
        if name in self.params:
            return self.params[name]
        defaults = {
            "EN_IL": 1,
            "EN_SV": 1,
            "EN_ACKREQ": int(self.settings.acknowledge_required),
            "EN_SSKIP": int(self.settings.skip_steps),
        }
        return defaults.get(name, 0)

    # ---- conditions ------------------------------------------------------------------------
    def value(self, operand: str) -> int:
        """A bit, word, step/transition variable or constant."""
        text = operand.strip()
        if "#" in text and not text.startswith("#"):
            if text.upper().startswith(("T#", "S5T#")):
                return time_ms(text)
            if text.upper().startswith("C#"):
                return int(text[2:])
            raise ValueError(f"constant {text!r}")
        if re.fullmatch(r"[+-]?\d+", text):
            return int(text)
        variable = self.step_variable(text)
        if variable is not None:
            return variable
        return self.memory.get(text)

    def step_variable(self, text: str) -> int | None:
        name, dot, member = text.lstrip("#").rpartition(".")
        if not dot or not name:
            return None
        member = member.upper()
        if name in self.steps and member in ("X", "T", "U"):
            return self.steps[name].member(member)
        if name in self.tt and member == "TT":
            return self.tt[name]
        match = re.fullmatch(r"([ST])(\d+)", name, re.IGNORECASE)
        if match is not None:
            number = int(match.group(2))
            if match.group(1).upper() == "S" and number in self.numbers:
                return self.numbers[number].member(member)
            if number in self.numbered_transitions:
                return self.tt[self.numbered_transitions[number]]
        return None

    def series(self, series: Series) -> bool:
        return all(self.element(e) for e in series.elements)

    def element(self, element: Element) -> bool:
        if isinstance(element, Contact):
            return bool(self.value(element.operand)) != element.negated
        if isinstance(element, Parallel):
            return any(self.series(branch) for branch in element.branches)
        if isinstance(element, Box) and element.name.upper().startswith("CMP"):
            a, b = (self.value(str(element.inputs[pin])) for pin in ("IN1", "IN2"))
            op = element.name[3:].rstrip("IDRidr")
            compare: dict[str, Callable[[int, int], bool]] = {
                "==": lambda x, y: x == y,
                "<>": lambda x, y: x != y,
                ">": lambda x, y: x > y,
                "<": lambda x, y: x < y,
                ">=": lambda x, y: x >= y,
                "<=": lambda x, y: x <= y,
            }
            return compare[op](a, b)
        raise NotImplementedError(f"the reference does not model {element!r}")

    def network(self, network: Network) -> None:
        flow = self.series(network.logic)
        for output in network.outputs:
            powered = flow and self.series(output.conditions)
            target = output.target
            if not isinstance(target, Coil) or target.coil not in ("=", "S", "R"):
                raise NotImplementedError(f"the reference does not model {target!r}")
            if target.coil == "=":
                self.memory.put(target.operand, int(powered))
            elif powered:
                self.memory.put(target.operand, int(target.coil == "S"))

    # ---- one call ----------------------------------------------------------------------------
    def call(self, inputs: Mapping[str, int], now_ms: int) -> None:
        """One call of the FB at TIME_TCK ``now_ms``; ``inputs`` sets FB parameters (by name)
        and process inputs (``I 0.0``); both keep their values until set again."""
        for name, value in inputs.items():
            if name.upper() in self.params or name.upper() in EDGE_INPUTS:
                self.params[name.upper()] = int(value)
            else:
                self.memory.put(name, int(value))
        self.memory.now = now_ms
        # 0. start of the call
        dt = (now_ms - self.tick) & 0x7FFFFFFF if self.started else 0
        self.tick = now_ms
        for state in self.steps.values():
            for event in EVENTS:
                state.events[event] = 0
            state.events["S1"], state.events["S0"] = state.PS1, state.PS0
            state.PS1 = state.PS0 = 0
        edges = {}
        for name in EDGE_INPUTS:
            level = self.param(name)
            edges[name] = int(level and not self.edge_memory[name])
            self.edge_memory[name] = level
        init_sq, off_sq = self.param("INIT_SQ"), self.param("OFF_SQ")
        selected = self.param("S_SEL")
        command, self.cmd = self.cmd, 0
        if command in MAILBOX_EDGES:
            edges[MAILBOX_EDGES[command]] = 1
            if command in (6, 7):
                selected = self.cmd_step
        init_sq |= command == 9
        off_sq |= command == 10
        if command in (11, 12):
            self.il_off = int(command == 12)
        if command in (13, 14):
            self.sv_off = int(command == 14)
        for name, mode in (("SW_AUTO", 1), ("SW_TAP", 3), ("SW_TOP", 4), ("SW_MAN", 2)):
            if edges[name]:
                self.mode = mode
        interlock_on = self.param("EN_IL") and not self.il_off
        supervision_on = self.param("EN_SV") and not self.sv_off
        for network in self.block.pre:
            self.network(network)
        # 1. initialisation
        switching = True
        if off_sq:
            for state in self.steps.values():
                if state.X:
                    state.X, state.events["S0"] = 0, 1
                state.LA = state.VA = 0
            switching = False
        elif not self.started or init_sq:
            for state in self.steps.values():
                if state.X and not state.step.initial:
                    state.X, state.events["S0"] = 0, 1
                elif state.step.initial and not state.X:
                    state.X, state.events["S1"] = 1, 1
                    state.T = state.U = 0
                state.LA = state.VA = 0
            self.started = 1
            switching = False
        # 2. times
        halted = self.param("HALT_SQ")
        if not self.param("HALT_TM"):
            for state in self.steps.values():
                if state.X and not state.events["S1"]:
                    state.T += dt
                    if not (state.LA or state.VA):
                        state.U += dt
        # 3. supervision and acknowledgement
        need_ack = self.param("EN_ACKREQ")
        for state in self.steps.values():
            if not state.X or state.events["S1"]:
                continue
            supervision = state.step.supervision
            error = bool(supervision_on and supervision is not None and self.series(supervision))
            if error and not state.VA:
                state.VA, state.events["V1"] = 1, 1
            elif not error and state.VA and not need_ack:
                state.VA, state.events["V0"] = 0, 1
        if edges["ACK_EF"]:
            for state in self.steps.values():
                if state.VA:
                    state.VA = 0
                    state.events["V0"] = state.events["A1"] = 1
        # 4. switching: TT is computed in every call (for display, as in MAN), transitions
        # fire only when phase 1, HALT_SQ and MAN do not stop them
        firing = switching and not halted and self.mode != 2
        self.switch(edges["T_PUSH"], firing)
        if switching and not halted and self.mode == 2:
            target = self.numbers.get(selected)
            if target is not None and edges["S_ON"]:
                target.X, target.events["S1"] = 1, 1
                target.T = target.U = 0
            if target is not None and edges["S_OFF"] and target.X:  # S0: it was active
                self.leave(target)
        # 5. actions
        zero = self.param("ZERO_OP")
        for state in self.steps.values():
            active = state.X
            if active:
                step = state.step
                ok = not interlock_on or step.interlock is None or self.series(step.interlock)
                if not ok and not state.LA:
                    state.LA, state.events["L1"] = 1, 1
                elif ok and state.LA:
                    state.LA, state.events["L0"] = 0, 1
                for action in step.actions:
                    if action.event is not None and not state.events[action.event]:
                        continue
                    if action.interlock and not ok:
                        if action.qualifier == "N" and ":=" not in action.operand:
                            self.memory.put(action.operand, 0)
                        continue
                    self.act(state, action, zero)
            elif state.events["S0"]:
                for action in state.step.actions:
                    if action.event == "S0":
                        self.act(state, action, zero)
                for action in state.step.actions:
                    output = action.qualifier in ("N", "D", "L") and ":=" not in action.operand
                    if output and action.event != "S0":
                        self.memory.put(action.operand, 0)
            if zero and active:  # the N/D/L bits of the active steps (as S7-Graph's ZERO_OP)
                for action in state.step.actions:
                    if action.qualifier in ("N", "D", "L") and ":=" not in action.operand:
                        self.memory.put(action.operand, 0)
        # 6. outputs
        self.outputs(edges)
        for network in self.block.post:
            self.network(network)

    def valid(self, transition: Transition) -> bool:
        sources = [self.steps[name] for name in transition.source]
        return all(s.X and not s.events["S1"] for s in sources)

    def condition(self, transition: Transition) -> bool:
        return transition.condition is None or self.series(transition.condition)

    def switch(self, push: int, firing: bool) -> None:
        skipped: set[str] = set()
        for _, transition in self.transitions:
            valid = self.valid(transition)
            condition = valid and self.condition(transition)
            self.tt[transition.name] = int(condition)
            if not (valid and firing):
                continue
            sources = [self.steps[name] for name in transition.source]
            blocked = any(s.VA for s in sources)
            if self.settings.interlock_blocks:
                blocked = blocked or any(s.LA for s in sources)
            mode_ok = {1: condition, 3: condition and push, 4: condition or push}[self.mode]
            if blocked or not mode_ok:
                continue
            self.fire(transition, skipped)

    def fire(self, transition: Transition, skipped: set[str]) -> None:
        for name in transition.source:
            self.leave(self.steps[name])
        for name in transition.target:
            self.activate(self.steps[name], skipped)

    @staticmethod
    def leave(state: StepState) -> None:
        """A step left: S0, and its disturbance is no longer shown (no L0/V0)."""
        state.X, state.events["S0"] = 0, 1
        state.LA = state.VA = 0

    def activate(self, state: StepState, skipped: set[str]) -> None:
        """Activates a target; with Skip Step, a step whose leaving transition is already true
        (evaluated as the step would be now, T = 0) is left again at once, without S1 or S0,
        and that transition's targets are activated instead (each step skipped once a call)."""
        state.X, state.events["S1"] = 1, 1
        state.T = state.U = 0
        state.LA = state.VA = 0
        name = state.step.name
        if not self.param("EN_SSKIP") or name in skipped:
            return
        for _, leaving in self.transitions:
            if leaving.source == [name] and self.condition(leaving):
                skipped.add(name)
                state.X, state.events["S1"] = 0, 0
                for target in leaving.target:
                    self.activate(self.steps[target], skipped)
                return

    # ---- actions -----------------------------------------------------------------------------
    def act(self, state: StepState, action: Action, zero: int) -> None:
        qualifier, operand, memory = action.qualifier, action.operand, self.memory
        if qualifier == "N" and ":=" in operand:
            self.assign(operand)
        elif qualifier == "N":
            memory.put(operand, 1)
        elif qualifier in ("S", "R"):
            memory.put(operand, int(qualifier == "S"))
        elif qualifier in ("D", "L"):
            assert action.time is not None
            reached = self.value(action.time) <= state.T
            memory.put(operand, int(reached == (qualifier == "D")))
        elif qualifier == "CALL":
            if not zero:
                self.calls[key(operand)](memory)
        elif qualifier in ("ON", "OFF"):
            self.step_control(state, qualifier, operand)
        elif qualifier in ("CS", "CU", "CD", "CR"):
            number = int(key(operand)[1:])
            count = memory.counters.get(number, 0)
            changed = {
                "CS": lambda: self.value(action.time or "0"),
                "CU": lambda: min(count + 1, 999),
                "CD": lambda: max(count - 1, 0),
                "CR": lambda: 0,
            }[qualifier]()
            memory.counters[number] = changed
        else:  # TL TD TR
            number = int(key(operand)[1:])
            if qualifier == "TR":
                memory.timers.pop(number, None)
            else:
                assert action.time is not None
                kind = "SE" if qualifier == "TL" else "SS"
                memory.timers[number] = Timer(kind, memory.now, self.value(action.time))

    def step_control(self, state: StepState, qualifier: str, operand: str) -> None:
        if operand.strip().upper() == "S_ALL":
            others = [s for s in self.steps.values() if s is not state]
        else:
            found = self.steps.get(operand.strip())
            if found is None:
                found = self.numbers[int(operand.strip()[1:])]
            others = [found]
        for other in others:
            if qualifier == "ON" and not other.X:
                other.X, other.PS1 = 1, 1
                other.T = other.U = 0
            elif qualifier == "OFF" and other.X:
                other.X, other.PS0 = 0, 1
                other.LA = other.VA = 0

    def assign(self, text: str) -> None:
        target, expression = (part.strip() for part in text.split(":=", 1))
        match = re.fullmatch(r"(.+?)\s*([-+*])\s*(.+)", expression)
        if match is None:
            result = self.value(expression)
        else:
            a, b = self.value(match.group(1)), self.value(match.group(3))
            result = {"+": a + b, "-": a - b, "*": a * b}[match.group(2)]
        self.memory.put(target, ((result + 0x8000) & 0xFFFF) - 0x8000)

    # ---- 6. outputs ------------------------------------------------------------------------
    def outputs(self, edges: Mapping[str, int]) -> None:
        states = list(self.steps.values())
        active = [s for s in states if s.X]
        out = {
            "ERR_FLT": int(any(s.LA or s.VA for s in states)),
            "ERROR": int(any(s.LA for s in states)),
            "FAULT": int(any(s.VA for s in states)),
            "SQ_ISOFF": int(not active),
            "AUTO_ON": int(self.mode == 1),
            "MAN_ON": int(self.mode == 2),
            "TAP_ON": int(self.mode == 3),
            "TOP_ON": int(self.mode == 4),
            "IL_ENABLED": self.param("EN_IL"),
            "SV_ENABLED": self.param("EN_SV"),
            "SQ_HALTED": self.param("HALT_SQ"),
            "TM_HALTED": self.param("HALT_TM"),
            "OP_ZEROED": self.param("ZERO_OP"),
            "S_MORE": int(len(active) > 1),
        }
        if self.mode == 2:
            out["S_NO"] = self.param("S_SEL")
            found = self.numbers.get(out["S_NO"])
            out["S_ACTIVE"] = found.X if found is not None else 0
        else:
            if active:
                self.disp += edges["S_NEXT"] - edges["S_PREV"]
                self.disp %= len(active)
            out["S_NO"] = active[self.disp].step.number if active else 0
            out["S_ACTIVE"] = int(out["S_NO"] != 0)
        self.outs = out

    # ---- a warm restart: what the CPU clears ---------------------------------------------------
    def warm_restart(self) -> None:
        """The instance DB stays; Q, the markers from MB 16 on, every timer and the counters
        from C 8 on are cleared (the CPU's default retentive ranges)."""
        memory = self.memory
        for name in list(memory.cells):
            if name.startswith("Q") or (name.startswith("M") and _byte(name) >= 16):
                del memory.cells[name]
        memory.timers.clear()
        memory.counters = {n: v for n, v in memory.counters.items() if n < 8}


def _byte(name: str) -> int:
    found = re.search(r"\d+", name)
    return int(found.group()) if found else 0

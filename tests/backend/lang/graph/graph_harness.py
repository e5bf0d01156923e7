"""Runs a Graph FB two ways behind one interface: the Python reference (``graph_reference``)
and the compiled FB on the CPU, so every rule test and the property test check both.

A test builds a ``GraphBlock`` with the terse helpers below, then drives an executor made by
``make(kind, block)``: ``call()`` is one FB call (one scan of an OB 1 that does
``CALL FB 1, DB 1``), after ``dt`` ms of virtual time; FB parameters are written into the
instance DB by name (an FB input the call does not assign keeps its instance value, as in
STEP 7) and process inputs into the process image; both keep their values until set again.
The compiled side prints the block as ``.graph`` text (the format of the issue's contract) and
compiles it with the STL compiler, as a project file would be.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Protocol

from graph_reference import Call, Reference, key

from nasaq.cpu import Cpu
from nasaq.headless.addresses import parse_address, signed
from nasaq.ir import Direct
from nasaq.lang.graph.model import (
    Action,
    GraphBlock,
    Sequencer,
    Settings,
    Step,
    Transition,
)
from nasaq.lang.lad.model import Box, Contact, Element, Network, Parallel, Series
from nasaq.lang.lad.text_print import _Printer
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.monitor.targets import resolve

KINDS = ("reference", "compiled")
_PROCESS = re.compile(r"^[IQM]\s*[BWD]?\s*\d", re.IGNORECASE)  # I 0.0, MW 10: not DB members

# ---- building blocks ----------------------------------------------------------------------


def c(operand: str) -> Contact:
    return Contact(operand=operand)


def nc(operand: str) -> Contact:
    return Contact(operand=operand, negated=True)


def cmp(op: str, in1: str, in2: str, kind: str = "D") -> Box:
    return Box(name=f"CMP{op}{kind}", inputs={"IN1": in1, "IN2": in2})


def anyof(*branches: Element | Series) -> Parallel:
    return Parallel(
        branches=[b if isinstance(b, Series) else Series(elements=[b]) for b in branches]
    )


def cond(*elements: Element) -> Series:
    return Series(elements=list(elements))


def act(text: str) -> Action:
    """``"S1 N C Q 0.0"``, ``"D Q 0.1, T#5S"``, ``"N MW 10 := MW 10 + 1"`` as an Action."""
    words = text.split()
    event = words.pop(0) if words[0] in ("S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1") else None
    qualifier = words.pop(0)
    interlock = words[0] == "C" and len(words) > 1 and not words[1][0].isdigit()  # C 1: counter
    if interlock:
        words.pop(0)
    rest = " ".join(words)
    operand, comma, time = rest.partition(",") if ":=" not in rest else (rest, "", "")
    return Action(
        event=event,  # type: ignore[arg-type]
        qualifier=qualifier,  # type: ignore[arg-type]
        interlock=interlock,
        operand=operand.strip(),
        time=time.strip() if comma else None,
    )


def step(
    name: str,
    number: int,
    *actions: str,
    initial: bool = False,
    interlock: Series | None = None,
    supervision: Series | None = None,
) -> Step:
    return Step(
        name=name,
        number=number,
        initial=initial,
        interlock=interlock,
        supervision=supervision,
        actions=[act(a) for a in actions],
    )


def trans(
    number: int,
    source: str | list[str],
    target: str | list[str] | None,
    *condition: Element,
) -> Transition:
    """A transition; ``condition`` empty means none (always true)."""
    return Transition(
        number=number,
        name=f"Trans{number}",
        source=[source] if isinstance(source, str) else source,
        target=[] if target is None else [target] if isinstance(target, str) else target,
        condition=Series(elements=list(condition)) if condition else None,
    )


def seq(name: str, steps: list[Step], transitions: list[Transition]) -> Sequencer:
    return Sequencer(name=name, steps=steps, transitions=transitions)


def fb(
    *sequencers: Sequencer,
    settings: Settings | None = None,
    declarations: str = "",
    pre: list[Network] | None = None,
    post: list[Network] | None = None,
) -> GraphBlock:
    return GraphBlock(
        name="FB 1",
        settings=settings or Settings(),
        declarations=declarations,
        sequencers=list(sequencers),
        pre=pre or [],
        post=post or [],
    )


# ---- the .graph text of a block (the DECIDED format of the contract) ------------------


def _series(series: Series) -> str:
    return _Printer().series_inline(series)


def _action(action: Action) -> str:
    words = [
        action.event or "",
        action.qualifier,
        "C" if action.interlock else "",
        action.operand,
    ]
    text = " ".join(w for w in words if w)
    return f"{text}, {action.time};" if action.time is not None else f"{text};"


def _steps(names: list[str]) -> str:
    return names[0] if len(names) == 1 else f"({', '.join(names)})"


def graph_text(block: GraphBlock) -> str:
    s = block.settings
    out = [f"FUNCTION_BLOCK {block.name}", "SETTINGS"]
    out += [
        f"  PARAMETERS := {s.parameters};",
        f"  SKIP_STEPS := {str(s.skip_steps).upper()};",
    ]
    out += [f"  ACKNOWLEDGE := {str(s.acknowledge_required).upper()};"]
    out += [f"  INTERLOCK_BLOCKS := {str(s.interlock_blocks).upper()};", "END_SETTINGS"]
    if block.declarations.strip():
        out.append(block.declarations.rstrip())
    out.append("BEGIN")
    for section, networks in (
        ("PERMANENT_PRE", block.pre),
        ("PERMANENT_POST", block.post),
    ):
        if section == "PERMANENT_POST":
            out += _sequencers(block)
        if networks:
            printer = _Printer()
            for network in networks:
                printer.network(network)
            out += [section, *printer.out, f"END_{section}"]
    out.append("END_FUNCTION_BLOCK")
    return "\n".join(out) + "\n"


def _sequencers(block: GraphBlock) -> list[str]:
    out: list[str] = []
    for sequencer in block.sequencers:
        out.append(f"SEQUENCER {sequencer.name}")
        for st in sequencer.steps:
            out.append(f"{'INITIAL_STEP' if st.initial else 'STEP'} {st.name} ({st.number})")
            if st.interlock is not None:
                out.append(f"INTERLOCK {_series(st.interlock)}END_INTERLOCK")
            if st.supervision is not None:
                out.append(f"SUPERVISION {_series(st.supervision)}END_SUPERVISION")
            if st.actions:
                out += [
                    "ACTIONS",
                    *(f"  {_action(a)}" for a in st.actions),
                    "END_ACTIONS",
                ]
            out.append("END_STEP")
        for t in sequencer.transitions:
            head = f"TRANSITION {t.name} ({t.number}) FROM {_steps(t.source)}"
            if not t.target:
                head += " STOP"
            else:
                head += f" {'JUMP' if t.jump else 'TO'} {_steps(t.target)}"
            out.append(head)
            if t.condition is not None:
                out.append(f"CONDITION {_series(t.condition)}END_CONDITION")
            out.append("END_TRANSITION")
        out.append("END_SEQUENCER")
    return out


# ---- the two executors ----------------------------------------------------------------------


class Executor(Protocol):
    def call(self, inputs: Mapping[str, int] | None = None, dt: int = 100) -> None: ...
    def step(self, name: str, member: str = "X") -> int: ...
    def tt(self, name: str) -> int: ...
    def out(self, name: str) -> int: ...
    def mode(self) -> int: ...
    def bit(self, operand: str) -> int: ...
    def word(self, operand: str) -> int: ...
    def var(self, name: str) -> int: ...
    def timer(self, number: int) -> int: ...
    def counter(self, number: int) -> int: ...
    def command(self, command: int, step: int = 0) -> None: ...
    def restart(self) -> None: ...


class Modelled:
    """The reference behind the common interface."""

    def __init__(self, block: GraphBlock, calls: Mapping[str, Call] | None = None) -> None:
        self.ref = Reference(block, calls)
        self.now = 0

    def call(self, inputs: Mapping[str, int] | None = None, dt: int = 100) -> None:
        self.now += dt
        self.ref.call(inputs or {}, self.now)

    def step(self, name: str, member: str = "X") -> int:
        return self.ref.steps[name].member(member)

    def tt(self, name: str) -> int:
        return self.ref.tt[name]

    def out(self, name: str) -> int:
        if name == "G7_CMD":
            return self.ref.cmd
        return self.ref.outs[name] if name in self.ref.outs else self.ref.param(name)

    def mode(self) -> int:
        return self.ref.mode

    def bit(self, operand: str) -> int:
        return self.ref.memory.get(operand)

    def word(self, operand: str) -> int:
        return self.ref.memory.get(operand)

    def var(self, name: str) -> int:
        return self.ref.memory.get(f"#{name}")

    def timer(self, number: int) -> int:
        return self.ref.memory.timer_q(number)

    def counter(self, number: int) -> int:
        return self.ref.memory.counters.get(number, 0)

    def command(self, command: int, step: int = 0) -> None:
        self.ref.cmd_step, self.ref.cmd = step, command

    def restart(self) -> None:
        self.ref.warm_restart()


OB1 = """\
DATA_BLOCK DB 1
  FB 1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = the sequencer
      CALL FB 1, DB 1
END_ORGANIZATION_BLOCK
"""


class Compiled:
    """The block compiled from its ``.graph`` text with an OB 1 calling it, on a CPU. Time is
    set before each scan and stands still during and after it (cycle 0 ms), so the S5 timers
    read after a call are read at the call's TIME_TCK, as the reference reads them."""

    def __init__(self, block: GraphBlock, extra: str = "") -> None:
        self.text = graph_text(block)
        sources = [SourceFile("seq.graph", self.text), SourceFile("ob1.awl", OB1)]
        if extra:
            sources.append(SourceFile("extra.awl", extra))
        result = compile_sources(sources)
        errors = [str(d) for d in result.diagnostics if d.severity == "error"]
        assert not errors, (errors, self.text)
        self.program = result.program
        self.cpu = Cpu(self.program, cycle_ms=0)
        self.cpu.start()
        assert self.cpu.mode == "RUN", self.cpu.stop_reason
        self.now = self.cpu.time_ms
        self.places: dict[str, tuple[Direct, bool]] = {}

    def place(self, name: str) -> tuple[Direct, bool]:
        """The address of ``DB1.<name>`` and whether it reads signed."""
        found = self.places.get(name)
        if found is None:
            target = resolve(f"DB1.{name}", self.program)
            assert target.direct is not None, name
            found = (target.direct, target.type in ("INT", "DINT", "TIME"))
            self.places[name] = found
        return found

    def db(self, name: str) -> int:
        direct, is_signed = self.place(name)
        raw = self.cpu.read(direct)
        return signed(raw, direct.width) if is_signed else raw

    def write_db(self, name: str, value: int) -> None:
        direct, _ = self.place(name)
        self.cpu.write(direct, value & ((1 << int(direct.width)) - 1))

    def call(self, inputs: Mapping[str, int] | None = None, dt: int = 100) -> None:
        for name, value in (inputs or {}).items():
            address = parse_address(name) if _PROCESS.match(name) else None
            if isinstance(address, Direct):
                if address.area.name == "I":
                    self.cpu.set_input(address, int(value))
                else:
                    self.cpu.write(address, int(value))
            else:
                self.write_db(name, int(value))
        self.now += dt
        self.cpu.engine.m.now = self.now
        self.cpu.scan()
        assert self.cpu.mode == "RUN", self.cpu.stop_reason

    def step(self, name: str, member: str = "X") -> int:
        return self.db(f"{name}.{member}")

    def tt(self, name: str) -> int:
        return self.db(f"{name}.TT")

    def out(self, name: str) -> int:
        return self.db(name)

    def mode(self) -> int:
        return self.db("G7_MODE")

    def _direct(self, operand: str) -> Direct:
        found = parse_address(operand)
        assert isinstance(found, Direct), operand
        return found

    def bit(self, operand: str) -> int:
        return self.cpu.read(self._direct(operand))

    def word(self, operand: str) -> int:
        direct = self._direct(operand)
        return signed(self.cpu.read(direct), direct.width)

    def var(self, name: str) -> int:
        return self.db(name)

    def timer(self, number: int) -> int:
        return int(self.cpu.timer(number)[0])

    def counter(self, number: int) -> int:
        return self.cpu.counter(number)[1]

    def command(self, command: int, step: int = 0) -> None:
        self.write_db("G7_CMD_STEP", step)
        self.write_db("G7_CMD", command)

    def restart(self) -> None:
        self.cpu.stop()
        self.cpu.start()
        assert self.cpu.mode == "RUN", self.cpu.stop_reason


def make(
    kind: str,
    block: GraphBlock,
    calls: Mapping[str, Call] | None = None,
    extra: str = "",
) -> Executor:
    """The executor ``kind`` ("reference" or "compiled") of ``block``; ``calls`` are the CALLed
    blocks as the reference runs them, ``extra`` the same blocks in STL for the CPU."""
    if kind == "reference":
        return Modelled(block, calls)
    return Compiled(block, extra)


def chain(
    *run_actions: str,
    idle_actions: tuple[str, ...] = (),
    settings: Settings | None = None,
    declarations: str = "",
    interlock: Series | None = None,
    supervision: Series | None = None,
) -> GraphBlock:
    """The two-step loop most rule tests use: ``Idle`` (1, initial) --Trans1: I 0.0--> ``Run``
    (2, with ``run_actions``, interlock and supervision) --Trans2: I 0.1--> jump to Idle."""
    return fb(
        seq(
            "Loop",
            [
                step("Idle", 1, *idle_actions, initial=True),
                step("Run", 2, *run_actions, interlock=interlock, supervision=supervision),
            ],
            [
                trans(1, "Idle", "Run", c("I 0.0")),
                trans(2, "Run", "Idle", c("I 0.1")).model_copy(update={"jump": True}),
            ],
        ),
        settings=settings,
        declarations=declarations,
    )


def enter_run(ex: Executor) -> None:
    """The first call (Idle activated), then one with I 0.0 (Trans1 fires: Run is activated
    in it, its actions run once); I 0.0 stays 1."""
    ex.call()
    ex.call({"I 0.0": 1})


__all__ = ["KINDS", "Compiled", "Executor", "Modelled", "key", "make"]

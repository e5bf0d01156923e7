"""Breakpoints, single steps and the hold: the CPU stopping in the middle of a scan.

While a session debugs (a breakpoint is set or a step is pending) every code block runs its
instrumented compilation, whose ``_B`` hook runs before each instruction; otherwise no block pays
for it. A breakpoint holds before its instruction, so a value changed at the hold is the value the
instruction reads. The hold runs in the CPU's thread: it waits there for commands (modify, step,
continue, stop) while the scan's Python frames, and with them the block's locals, stay alive.
The call stack is read from those frames: each instrumented block's code object maps its line
numbers back to instructions.

S7-Graph (``graph_activation``): a step breakpoint is a breakpoint on the instructions that
switch the step on; a single step by ``transition`` holds before the next instruction that
switches any Graph FB's step on, past the rest of the firing it was held in.
"""

from __future__ import annotations

import operator
import re
import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from nasaq.cpu.codegen.compiler import Compiled
from nasaq.cpu.errors import CpuStopError
from nasaq.diagnostics.phrases import phrase
from nasaq.ir import BlockKind
from nasaq.monitor import targets
from nasaq.monitor.block_info import BlockInfo, Slot, read_slot, write_slot
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.graph_activation import Activations, activations
from nasaq.monitor.protocol import HoldState, StackFrame, Variable
from nasaq.monitor.status import A1, A2, AR1, AR2, BR, CC0, CC1, DI, OS, OV, RLO, STA, status_word

if TYPE_CHECKING:
    from nasaq.monitor.session import Session

MAX_BREAKPOINTS = 64
Key = tuple[BlockKind, int]
_REGISTERS = {
    "RLO": RLO,
    "VKE": RLO,
    "STA": STA,
    "ACCU1": A1,
    "AKKU1": A1,
    "ACCU2": A2,
    "AKKU2": A2,
    "AR1": AR1,
    "AR2": AR2,
    "OV": OV,
    "OS": OS,
    "BR": BR,
    "BIE": BR,
    "CC0": CC0,
    "CC1": CC1,
}
_COMPARE: dict[str, Callable[[Any, Any], bool]] = {
    "==": operator.eq,
    "=": operator.eq,
    "<>": operator.ne,
    "<=": operator.le,
    ">=": operator.ge,
    "<": operator.lt,
    ">": operator.gt,
}
_CONDITION = re.compile(r"^\s*(.+?)\s*(==|<>|<=|>=|=|<|>)\s*(\S+)\s*$")


class OperatorStopError(CpuStopError):
    """Unwinds a held scan: the operator switched the CPU to STOP (or closed the session)."""


@dataclass(slots=True)
class Condition:
    text: str
    operand: str  # "reg:<index>", "local:<name>" or "target"
    target: targets.Target | None
    compare: Callable[[Any, Any], bool]
    value: float

    def holds(
        self,
        info: BlockInfo,
        frame: bytearray,
        params: list[Any],
        regs: tuple[Any, ...],
        session: Session,
    ) -> bool:
        kind, _, name = self.operand.partition(":")
        if kind == "reg":
            actual: Any = regs[int(name)]
        elif kind == "local":
            slot = info.by_name.get(name)
            if slot is None:
                return False
            actual = read_slot(slot, frame, regs[DI], regs[AR2], params)
        else:
            assert self.target is not None
            actual = targets.read(self.target, session.cpu)
        if isinstance(actual, bool):
            actual = int(actual)
        if not isinstance(actual, int | float):
            return False
        return self.compare(actual, self.value)


@dataclass(slots=True)
class Breakpoint:
    id: int
    key: Key
    indices: list[int]
    condition: Condition | None
    where: str


@dataclass(slots=True)
class StepRequest:
    kind: str  # "instruction", "statement", "network"
    into: bool
    depth: int
    key: Key | None
    line: int | None
    network: int | None
    skip: tuple[Key, int, int] | None = None  # transition: the firing held in (first, last)


@dataclass(slots=True)
class HoldContext:
    """The held instruction with everything alive at that point of the scan."""

    compiled: Compiled
    info: BlockInfo
    index: int
    frame: bytearray
    params: list[Any]
    regs: tuple[Any, ...]
    reason: str
    breakpoint: int | None
    depth: int
    graph_step: int | None = None  # the S7-Graph step this instruction switches on


def parse_condition(text: str, session: Session, info: BlockInfo) -> Condition:
    """Reads ``<operand> <op> <value>``; a name of the block's own variables (with or without
    ``#``) is that variable, else a register, an address or a symbol."""
    match = _CONDITION.match(text)
    if match is None:
        raise MonitorError("MON612", condition=text, reason=phrase("condition_form"))
    left, op, right = match.groups()
    try:
        value = float(right) if "." in right else float(int(right, 0))
    except ValueError:
        upper = right.upper()
        if upper not in ("TRUE", "FALSE"):
            raise MonitorError(
                "MON612", condition=text, reason=phrase("condition_not_number", value=right)
            ) from None
        value = 1.0 if upper == "TRUE" else 0.0
    name = left.strip()
    if name.upper() in _REGISTERS:
        return Condition(text, f"reg:{_REGISTERS[name.upper()]}", None, _COMPARE[op], value)
    own = name.lstrip("#").casefold()
    if own in info.by_name:
        return Condition(text, f"local:{own}", None, _COMPARE[op], value)
    if name.startswith("#"):
        raise MonitorError(
            "MON612",
            condition=text,
            reason=phrase("condition_no_variable", block=info.name, name=name),
        )
    try:
        target = targets.resolve(name, session.program)
    except targets.TargetError as error:
        raise MonitorError("MON612", condition=text, reason=error.params["reason"]) from None
    return Condition(text, "target", target, _COMPARE[op], value)


class Debugger:
    def __init__(self, session: Session) -> None:
        self.session = session
        self.breakpoints: dict[int, Breakpoint] = {}
        self.at: dict[Key, dict[int, list[Breakpoint]]] = {}
        self.step: StepRequest | None = None
        self._next_id = 1
        self._graph: dict[Key, Activations | None] = {}

    def activations(self, key: Key) -> Activations | None:
        """The step activations of block ``key`` (None: not an S7-Graph FB), worked out once."""
        if key not in self._graph:
            block = self.session.program.get(*key)
            self._graph[key] = None if block is None else activations(block)
        return self._graph[key]

    @property
    def active(self) -> bool:
        """Whether every block must run instrumented (breakpoints set or a step pending)."""
        return bool(self.breakpoints) or self.step is not None

    # -- breakpoints ----------------------------------------------------------------------------
    def add(self, key: Key, indices: list[int], condition: Condition | None, where: str) -> int:
        if len(self.breakpoints) >= MAX_BREAKPOINTS:
            raise MonitorError("MON615", limit=MAX_BREAKPOINTS)
        number = self._next_id
        self._next_id += 1
        found = Breakpoint(number, key, indices, condition, where)
        self.breakpoints[number] = found
        table = self.at.setdefault(key, {})
        for index in indices:
            table.setdefault(index, []).append(found)
        return number

    def remove(self, number: int | None) -> None:
        chosen = list(self.breakpoints) if number is None else [number]
        for k in chosen:
            found = self.breakpoints.pop(k, None)
            if found is None:
                raise MonitorError(
                    "MON607",
                    action=phrase("act_clear_breakpoint", id=k),
                    reason=phrase("no_such_breakpoint"),
                )
            table = self.at.get(found.key, {})
            for index in found.indices:
                remaining = [b for b in table.get(index, []) if b.id != k]
                if remaining:
                    table[index] = remaining
                else:
                    table.pop(index, None)

    # -- hooks ----------------------------------------------------------------------------------
    def before_hook(self, compiled: Compiled, info: BlockInfo) -> Callable[..., None]:
        key = (compiled.block.kind, compiled.block.number)
        table = self.at.setdefault(key, {})
        debugger = self

        def before(index: int, frame: bytearray, params: list[Any], *regs: Any) -> None:
            if debugger.step is not None or index in table:
                debugger.check(compiled, info, index, frame, params, regs)

        return before

    def check(
        self,
        compiled: Compiled,
        info: BlockInfo,
        index: int,
        frame: bytearray,
        params: list[Any],
        regs: tuple[Any, ...],
    ) -> None:
        session = self.session
        depth = session.engine.m.depth
        key = (compiled.block.kind, compiled.block.number)
        for found in self.at.get(key, {}).get(index, ()):
            condition = found.condition
            if condition is None or condition.holds(info, frame, params, regs, session):
                self.step = None
                session.hold(
                    HoldContext(
                        compiled,
                        info,
                        index,
                        frame,
                        params,
                        regs,
                        "breakpoint",
                        found.id,
                        depth,
                        self._activated(key, index),
                    )
                )
                return
        if self.step is not None and self._step_ends(key, info, index, depth):
            self.step = None
            session.hold(
                HoldContext(
                    compiled,
                    info,
                    index,
                    frame,
                    params,
                    regs,
                    "step",
                    None,
                    depth,
                    self._activated(key, index),
                )
            )

    def _activated(self, key: Key, index: int) -> int | None:
        found = self.activations(key)
        return None if found is None else found.at.get(index)

    def _step_ends(self, key: Key, info: BlockInfo, index: int, depth: int) -> bool:
        step = self.step
        assert step is not None
        if step.kind == "transition":
            return self._next_firing(step, key, index)
        if step.key is None or depth < step.depth:
            return True  # a break-in, or back in the caller
        if depth > step.depth:
            return step.into
        if step.kind == "instruction":
            return True
        if key != step.key:
            return True
        if step.kind == "network":
            return info.networks[index] != step.network
        return info.statement_start[index] and info.lines[index] != step.line

    def _next_firing(self, step: StepRequest, key: Key, index: int) -> bool:
        """Whether ``index`` switches a step on, outside the firing the step started in."""
        skip = step.skip
        if skip is not None:
            if key == skip[0] and skip[1] <= index <= skip[2]:
                return False
            step.skip = None  # the firing is over (a later call of it holds again)
        found = self.activations(key)
        return found is not None and index in found.at

    def request_step(self, kind: str, into: bool, held: HoldContext | None) -> None:
        if kind == "transition":
            skip = None
            if held is not None:
                key = (held.compiled.block.kind, held.compiled.block.number)
                found = self.activations(key)
                firing = None if found is None else found.firing.get(held.index)
                if firing is not None:
                    skip = (key, firing[0], firing[1])
            self.step = StepRequest(kind, True, 0, None, None, None, skip)
            return
        if held is None:  # a running CPU: hold at the next instruction anywhere
            self.step = StepRequest(kind, True, 0, None, None, None)
            return
        info = held.info
        self.step = StepRequest(
            kind,
            into,
            held.depth,
            (held.compiled.block.kind, held.compiled.block.number),
            info.lines[held.index],
            info.networks[held.index],
        )


# -- what a hold shows ---------------------------------------------------------------------------


def hold_state(held: HoldContext, call_stack: list[StackFrame]) -> HoldState:
    regs = held.regs
    registers = {
        "accu1": regs[A1] & 0xFFFFFFFF,
        "accu2": regs[A2] & 0xFFFFFFFF,
        "ar1": regs[AR1],
        "ar2": regs[AR2],
        "stw": status_word(regs),
        "rlo": regs[RLO],
        "sta": regs[STA],
    }
    return HoldState(
        reason="breakpoint" if held.reason == "breakpoint" else "step",
        breakpoint=held.breakpoint,
        location=call_stack[0],
        registers=registers,
        locals=locals_of(held),
        call_stack=call_stack,
        graph_step=held.graph_step,
        graph_block=None if held.graph_step is None else held.info.name,
    )


def locals_of(held: HoldContext) -> list[Variable]:
    regs = held.regs
    return [
        Variable(
            name=slot.name,
            type=slot.type,
            value=read_slot(slot, held.frame, regs[DI], regs[AR2], held.params),
        )
        for slot in held.info.slots
    ]


def local_slot(held: HoldContext, name: str) -> Slot:
    slot = held.info.by_name.get(name.lstrip("#").strip().casefold())
    if slot is None:
        known = ", ".join(s.name for s in held.info.slots[:12]) or "none"
        raise MonitorError(
            "MON603",
            target=name,
            reason=phrase("no_such_local", block=held.info.name, known=known),
        )
    return slot


def modify_local(held: HoldContext, name: str, value: Any) -> None:
    slot = local_slot(held, name)
    probe = targets.Target(text=name, type=slot.type, direct=None)
    pattern = targets.encode(probe, value)
    regs = held.regs
    write_slot(slot, pattern, held.frame, regs[DI], regs[AR2], held.params)


def call_stack(
    held: HoldContext, by_filename: dict[str, Compiled], infos: Callable[[Compiled], BlockInfo]
) -> list[StackFrame]:
    """The held block first, then every caller, read from the live Python frames."""
    stack = [_frame(held.info, held.index)]
    python_frame = sys._getframe()
    seen_held = False
    while python_frame is not None:
        compiled = by_filename.get(python_frame.f_code.co_filename)
        if compiled is not None:
            if not seen_held and compiled is held.compiled:
                seen_held = True
            elif seen_held:
                index = compiled.line_map.get(python_frame.f_lineno, 0)
                stack.append(_frame(infos(compiled), index))
        python_frame = python_frame.f_back  # type: ignore[assignment]
    return stack


def _frame(info: BlockInfo, index: int) -> StackFrame:
    return StackFrame(
        block=info.name,
        instruction=index,
        line=info.lines[index] if index < len(info.lines) else None,
        file=info.file,
        network=info.networks[index] if index < len(info.networks) else None,
    )

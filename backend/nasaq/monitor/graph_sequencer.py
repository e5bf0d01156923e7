"""An S7-Graph FB's sequencer as the monitor sees it: the block status of its steps and
transitions, and the Control Sequencer's commands.

Both work from the instance DB by member name, as ``nasaq/lang/graph/SEMANTICS.md`` §1 lays it
out, never from code offsets: one STRUCT per step, named as the step (``X``, ``LA``, ``VA``,
``SNO``, ``T``, ``U``), one per transition (``TT``, ``TNO``), ``G7_MODE`` and the mailbox
``G7_CMD_STEP``/``G7_CMD``. A Graph FB is recognised by that interface (the checker reserves the
``G7_`` names), so a DB is a Graph instance DB when its FB declares the mailbox.

Decisions (STEP 7's Control Sequencer, written down here):
- The block status reads the instance the sampled call used (the DI register at the FB's
  first instruction in its last call of the sampled scan, a multi-instance at its AR2 offset),
  at the end of that scan: what the chart shows online is the DB's state after the call.
- A command goes through the mailbox, which holds one: the session keeps a short queue per DB
  and writes the next command before a scan once the FB has taken the previous one (G7_CMD is
  0 again), so ``man`` then ``step_on`` sent at once both act, in order, in two calls.
- Commands need the CPU in RUN (MON622): in STOP the FB is not called, and a command taken up
  at some later start would surprise. ``step_on``/``step_off`` need MAN mode, the mode the DB
  will be in once the queued commands are carried out (MON621), as S7-Graph only switches
  steps by hand in MAN.
"""

from __future__ import annotations

import re
from collections import deque
from dataclasses import dataclass, field
from typing import Literal

from nasaq.ir import Block, BlockKind, Program, Variable
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import (
    GraphOp,
    GraphStatus,
    GraphStepStatus,
    GraphTransitionStatus,
)

MAX_QUEUED = 16  # commands waiting for one DB's FB to take them
MODES: dict[int, Literal["AUTO", "MAN", "TAP", "TOP"]] = {1: "AUTO", 2: "MAN", 3: "TAP", 4: "TOP"}
COMMANDS: dict[GraphOp, int] = {
    "auto": 1,
    "man": 2,
    "tap": 3,
    "top": 4,
    "ack": 5,
    "step_on": 6,
    "step_off": 7,
    "push": 8,
    "init": 9,
    "off": 10,
    "interlock_on": 11,
    "interlock_off": 12,
    "supervision_on": 13,
    "supervision_off": 14,
}
_DB = re.compile(r"^\s*DB\s*(\d+)\s*$", re.IGNORECASE)


@dataclass(frozen=True, slots=True)
class Place:
    """An elementary member: its bit offset from the instance's start, and its width."""

    at: int
    bits: int


@dataclass(frozen=True, slots=True)
class StepLayout:
    name: str
    x: Place
    la: Place | None
    va: Place | None
    sno: Place
    t: Place | None
    u: Place | None


@dataclass(frozen=True, slots=True)
class TransitionLayout:
    name: str
    tt: Place
    tno: Place


@dataclass(frozen=True, slots=True)
class GraphLayout:
    """Where a Graph FB keeps its sequencer in its instance."""

    mode: Place | None
    cmd: Place
    cmd_step: Place
    steps: tuple[StepLayout, ...]
    transitions: tuple[TransitionLayout, ...]


def _member(variable: Variable, name: str) -> Place | None:
    """A member of a step or transition STRUCT (the layout gives members' offsets from the
    instance's start, as their parent's)."""
    for member in variable.members:
        if member.name.upper() == name and not member.members:
            return Place(member.offset_bits, member.size_bits)
    return None


def graph_layout(fb: Block) -> GraphLayout | None:
    """The sequencer layout of ``fb``; None when it is not an S7-Graph FB."""
    if fb.kind is not BlockKind.FB:
        return None
    own: dict[str, Variable] = {}
    steps: list[StepLayout] = []
    transitions: list[TransitionLayout] = []
    for variable in fb.interface:
        if variable.section not in ("IN", "OUT", "IN_OUT", "STAT"):
            continue
        own[variable.name.upper()] = variable
        if variable.section != "STAT" or not variable.members:
            continue
        x, sno = _member(variable, "X"), _member(variable, "SNO")
        if x is not None and sno is not None:
            steps.append(
                StepLayout(
                    variable.name,
                    x,
                    _member(variable, "LA"),
                    _member(variable, "VA"),
                    sno,
                    _member(variable, "T"),
                    _member(variable, "U"),
                )
            )
            continue
        tt, tno = _member(variable, "TT"), _member(variable, "TNO")
        if tt is not None and tno is not None:
            transitions.append(TransitionLayout(variable.name, tt, tno))
    cmd, cmd_step = own.get("G7_CMD"), own.get("G7_CMD_STEP")
    if cmd is None or cmd_step is None or cmd.members or cmd_step.members:
        return None
    mode = own.get("G7_MODE")
    return GraphLayout(
        None if mode is None else Place(mode.offset_bits, mode.size_bits),
        Place(cmd.offset_bits, cmd.size_bits),
        Place(cmd_step.offset_bits, cmd_step.size_bits),
        tuple(steps),
        tuple(transitions),
    )


def read(buf: bytearray, base: int, where: Place) -> int:
    """The member's bit pattern (0 beyond the DB: a DB shorter than its FB reads as zeros)."""
    at = base * 8 + where.at
    byte = at >> 3
    if where.bits == 1:
        return (buf[byte] >> (at & 7)) & 1 if byte < len(buf) else 0
    size = where.bits // 8
    if byte + size > len(buf):
        return 0
    return int.from_bytes(buf[byte : byte + size], "big")


def write(buf: bytearray, base: int, where: Place, value: int) -> None:
    byte = (base * 8 + where.at) >> 3
    size = where.bits // 8
    if size and byte + size <= len(buf):
        buf[byte : byte + size] = (value & ((1 << where.bits) - 1)).to_bytes(size, "big")


def _signed(pattern: int, bits: int) -> int:
    return pattern - (1 << bits) if bits and pattern >> (bits - 1) & 1 else pattern


def graph_status(layout: GraphLayout, db: int, buf: bytearray, base: int) -> GraphStatus:
    """The sequencer state in instance data ``buf`` at byte ``base`` (0 for an instance DB)."""
    steps: list[GraphStepStatus] = []
    for step in layout.steps:
        active = bool(read(buf, base, step.x))
        la = step.la is not None and bool(read(buf, base, step.la))
        va = step.va is not None and bool(read(buf, base, step.va))
        state: Literal["inactive", "active", "disturbed"] = (
            "inactive" if not active else "disturbed" if la or va else "active"
        )
        steps.append(
            GraphStepStatus(
                number=_signed(read(buf, base, step.sno), step.sno.bits),
                name=step.name,
                state=state,
                t_ms=0 if step.t is None else _signed(read(buf, base, step.t), 32),
                u_ms=0 if step.u is None else _signed(read(buf, base, step.u), 32),
                interlock_error=la,
                supervision_error=va,
            )
        )
    transitions = [
        GraphTransitionStatus(
            number=_signed(read(buf, base, item.tno), item.tno.bits),
            name=item.name,
            tt=bool(read(buf, base, item.tt)),
        )
        for item in layout.transitions
    ]
    mode = None if layout.mode is None else MODES.get(read(buf, base, layout.mode))
    return GraphStatus(db=f"DB{db}", at=base, mode=mode, steps=steps, transitions=transitions)


def status_of_call(
    layout: GraphLayout, di: object, ar2: int, dbs: dict[int, bytearray]
) -> GraphStatus | None:
    """The status of the instance a call ran with: ``di`` the DI register (the instance DB's
    memory), ``ar2`` the multi-instance offset (an area-internal pointer)."""
    for number, memory in dbs.items():
        if memory is di:
            return graph_status(layout, number, memory, (ar2 & 0x7FFFF) >> 3)
    return None


@dataclass(slots=True)
class Mailbox:
    """The commands waiting for one instance DB's FB, oldest first: (command, step)."""

    db: int
    layout: GraphLayout
    waiting: deque[tuple[int, int]] = field(default_factory=deque)


class Controller:
    """The Control Sequencer of a session: validates commands and feeds each instance DB's
    mailbox one command per FB call (``before_scan``)."""

    def __init__(self) -> None:
        self.boxes: dict[int, Mailbox] = {}

    def clear(self) -> None:
        self.boxes.clear()

    def command(
        self,
        program: Program,
        dbs: dict[int, bytearray],
        running: bool,
        db_text: str,
        op: GraphOp,
        step: int | None,
    ) -> dict[str, object]:
        number = _db_number(program, db_text)
        block = program.get(BlockKind.DB, number) if number is not None else None
        if number is None or block is None:
            raise MonitorError("MON617", db=db_text.strip())
        fb = program.get(BlockKind.FB, block.instance_of) if block.instance_of else None
        layout = graph_layout(fb) if fb is not None else None
        if fb is None or layout is None:
            raise MonitorError("MON618", db=f"DB{number}")
        fb_name = f"FB{fb.number}"
        buf = dbs.get(number)
        if buf is None:
            raise MonitorError("MON617", db=f"DB{number}")
        if not running:
            raise MonitorError("MON622", db=f"DB{number}")
        box = self.boxes.get(number)
        if box is None or box.layout != layout:
            box = self.boxes[number] = Mailbox(number, layout)
        code = COMMANDS[op]
        target = 0
        if op in ("step_on", "step_off"):
            if step is None:
                raise MonitorError("MON620", op=op)
            numbers = sorted(_signed(read(buf, 0, s.sno), s.sno.bits) for s in layout.steps)
            if step not in numbers:
                shown = ", ".join(f"S{n}" for n in numbers[:24]) + (
                    ", ..." if len(numbers) > 24 else ""
                )
                raise MonitorError("MON619", fb=fb_name, step=step, steps=shown or "-")
            mode = _mode_after(box, buf, layout)
            if mode != 2:
                raise MonitorError("MON621", db=f"DB{number}", mode=MODES.get(mode, "?"))
            target = step
        if len(box.waiting) >= MAX_QUEUED:
            raise MonitorError("MON623", db=f"DB{number}", count=len(box.waiting), fb=fb_name)
        box.waiting.append((code, target))
        self._feed(box, buf)
        return {"db": f"DB{number}", "fb": fb_name, "command": code, "waiting": len(box.waiting)}

    def before_scan(self, dbs: dict[int, bytearray]) -> None:
        """Writes each DB's next command once its FB took the previous one."""
        for box in self.boxes.values():
            if box.waiting:
                buf = dbs.get(box.db)
                if buf is not None:
                    self._feed(box, buf)

    @staticmethod
    def _feed(box: Mailbox, buf: bytearray) -> None:
        if box.waiting and read(buf, 0, box.layout.cmd) == 0:
            code, step = box.waiting.popleft()
            write(buf, 0, box.layout.cmd_step, step)
            write(buf, 0, box.layout.cmd, code)


def _mode_after(box: Mailbox, buf: bytearray, layout: GraphLayout) -> int:
    """The mode once the commands in the mailbox and the queue are carried out."""
    mode = 1 if layout.mode is None else read(buf, 0, layout.mode)
    pending = read(buf, 0, layout.cmd)
    for code in [pending, *(code for code, _ in box.waiting)]:
        if 1 <= code <= 4:
            mode = code
    return mode


def _db_number(program: Program, text: str) -> int | None:
    match = _DB.match(text)
    if match:
        return int(match[1])
    wanted = text.strip().strip('"').casefold()
    for name, address in program.symbols.items():
        if name.casefold() == wanted:
            found = _DB.match(address)
            return int(found[1]) if found else None
    for block in program.blocks.values():
        if block.kind is BlockKind.DB and block.name and block.name.casefold() == wanted:
            return block.number
    return None

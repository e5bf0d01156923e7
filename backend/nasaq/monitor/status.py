"""Block status: the registers after every instruction of one sampled execution of a block.

Like STEP 7's "monitor block", the status is sampled, not streamed: in a scan chosen for sampling
(at most ~30 per second) the block runs its instrumented compilation and each instruction's hook
stores its registers and operand value; every other scan runs the fast compilation. An
instruction executed several times in that scan (a loop, several calls) shows its last execution.
SCL lines show the block's variables their code read or wrote, with the last value seen.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Literal

from nasaq.cpu.memory import Memory
from nasaq.cpu.timers import Timers
from nasaq.ir import Area, CounterRef, Direct, ParamRef, RegisterIndirect, TimerRef
from nasaq.monitor.block_info import BlockInfo, Slot, read_slot
from nasaq.monitor.protocol import (
    BlockStatus,
    GraphStatus,
    InstructionStatus,
    LineStatus,
    Value,
)

# Positions in the register tuple the hooks pass (codegen.compiler.HOOK_REGISTERS).
A1, A2, FC, RLO, STA, ORB, OS, OV, CC0, CC1, BR, AR1, AR2, DB, DI = range(15)
Reader = Callable[[bytearray, list[Any], tuple[Any, ...]], Any]

if TYPE_CHECKING:
    from nasaq.monitor.element_status import ElementStatusBuilder


def status_word(regs: tuple[Any, ...]) -> int:
    word: int = (
        regs[FC]
        | regs[RLO] << 1
        | regs[STA] << 2
        | regs[ORB] << 3
        | regs[OS] << 4
        | regs[OV] << 5
        | regs[CC0] << 6
        | regs[CC1] << 7
        | regs[BR] << 8
    )
    return word


class Recorder:
    """Collects one block's rows while recording: ``rows[index] = (registers, operand value)``,
    for the instructions of the selected networks only (``select``).

    Which instructions record is one list of flags, ``active``, that the hook reads by index:
    all False between sampled scans, the selected networks' mask during one. So the hook costs
    one check however many networks the block has, recording or not. ``extra`` holds what an
    element status needs beyond the registers (a timer's time, a call's parameters), read by
    readers ``attach`` adds to the instructions that need them."""

    def __init__(
        self,
        info: BlockInfo,
        memory: Memory,
        timers: Timers,
        counters: Any,
        elements: ElementStatusBuilder | None = None,
    ) -> None:
        self.info = info
        self.memory, self.timers, self.counters = memory, timers, counters
        self.rows: dict[int, tuple[tuple[Any, ...], Value]] = {}
        self.extra: dict[int, Any] = {}
        self.readers: list[Reader | None] = [
            reader_of(ins.operand, info, memory, timers, counters) for ins in info.block.code
        ]
        self.names: list[str | None] = [_name(ins.operand, info) for ins in info.block.code]
        size = len(info.block.code)
        self.mask = [True] * size
        self.selected: frozenset[int] | None = None
        self.entry_only = False  # instruction 0 records only to tell that the block ran
        self._off = [False] * size
        self.active = list(self._off)
        self.elements = elements
        if elements is not None:
            elements.attach(self)
        self.last: BlockStatus | None = None
        # An S7-Graph FB: its sequencer's state from the registers of its entry (the instance).
        self.graph: Callable[[tuple[Any, ...]], GraphStatus | None] | None = None

    def select(self, networks: frozenset[int] | None) -> None:
        """Records only the instructions of ``networks`` (None: all), from the next sample."""
        if networks == self.selected:
            return
        owner = self.info.networks
        self.mask = [networks is None or owner[k] in networks for k in range(len(owner))]
        # The block's first instruction always records: it says whether the block ran at all
        # (its row is dropped again when its network is not selected).
        self.entry_only = bool(self.mask) and not self.mask[0]
        if self.mask:
            self.mask[0] = True
        self.selected = networks

    def attach(self, index: int, extra: Reader) -> None:
        """Also reads ``extra`` after instruction ``index`` while recording (into ``extra``)."""
        base, store = self.readers[index], self.extra

        def both(frame: bytearray, params: list[Any], regs: tuple[Any, ...]) -> Value:
            store[index] = extra(frame, params, regs)
            return base(frame, params, regs) if base else None

        self.readers[index] = both

    def hook(self) -> Callable[..., None]:
        rows, readers, active = self.rows, self.readers, self.active

        def after(index: int, frame: bytearray, params: list[Any], *regs: Any) -> None:
            if active[index]:
                reader = readers[index]
                rows[index] = (regs, reader(frame, params, regs) if reader else None)

        return after

    def begin(self) -> None:
        self.rows.clear()
        self.extra.clear()
        self.active[:] = self.mask

    def finish(self, scan: int) -> BlockStatus | None:
        """The status of the sampled scan, or the previous one if the block did not run."""
        self.active[:] = self._off
        if not self.rows:
            return self.last  # the block did not run in this scan
        entry = self.rows.get(0)  # the last call's first instruction: its instance
        if self.entry_only:
            self.rows.pop(0, None)
        info = self.info
        instructions: list[InstructionStatus] = []
        lines: dict[int, dict[str, Value]] = {}
        for index in sorted(self.rows):
            regs, operand = self.rows[index]
            instructions.append(
                InstructionStatus(
                    index=index,
                    line=info.lines[index],
                    rlo=regs[RLO],
                    sta=regs[STA],
                    accu1=regs[A1] & 0xFFFFFFFF,
                    accu2=regs[A2] & 0xFFFFFFFF,
                    stw=status_word(regs),
                    ar1=regs[AR1],
                    ar2=regs[AR2],
                    operand=operand,
                )
            )
            name, line = self.names[index], info.lines[index]
            if name is not None and line is not None:
                lines.setdefault(line, {})[name] = operand
        elements = self.elements
        self.last = BlockStatus(
            block=info.name,
            language=_LANGUAGES.get(info.language, "stl"),
            scan=scan,
            instructions=instructions,
            lines=[LineStatus(line=k, values=v) for k, v in sorted(lines.items())],
            elements=[] if elements is None else elements.status(self.rows, self.extra),
            graph=None if self.graph is None or entry is None else self.graph(entry[0]),
        )
        return self.last

    def at_hold(
        self, frame: bytearray, params: list[Any], regs: tuple[Any, ...], scan: int
    ) -> BlockStatus:
        """The status of the held block at the hold: every line's variables as they are now in
        the held scan (read from the live frame as the Locals are, so both show the same
        values), not as the last sampled scan left them; the instruction rows stay the last
        sample's. TIA Portal also shows an SCL block's current values at a breakpoint. An
        S7-Graph FB's sequencer is read from the held call's instance as it is now (a step
        breakpoint: the source steps already left, the step not yet on)."""
        info, by_name = self.info, self.info.by_name
        lines: dict[int, dict[str, Value]] = {}
        for index, name in enumerate(self.names):
            line = info.lines[index]
            slot = None if name is None or line is None else by_name.get(name.casefold())
            if slot is not None and line is not None:
                value = read_slot(slot, frame, regs[DI], regs[AR2], params)
                lines.setdefault(line, {})[slot.name] = value
        last = self.last
        graph = None if self.graph is None else self.graph(regs)
        return BlockStatus(
            block=info.name,
            language=_LANGUAGES.get(info.language, "stl"),
            scan=scan,
            instructions=[] if last is None else last.instructions,
            lines=[LineStatus(line=k, values=v) for k, v in sorted(lines.items())],
            elements=[] if last is None else last.elements,
            graph=graph if graph is not None or last is None else last.graph,
        )


_LANGUAGES: dict[str, Literal["stl", "scl", "lad", "fbd", "graph"]] = {
    "stl": "stl",
    "scl": "scl",
    "lad": "lad",
    "fbd": "fbd",
    "graph": "graph",
}


def narrowed(status: BlockStatus, networks: frozenset[int], info: BlockInfo) -> BlockStatus:
    """``status`` with only the rows of ``networks``: what a client that opened those networks
    sees when another client of the session records more of the block."""
    owner = info.networks
    if all(owner[row.index] in networks for row in status.instructions):
        return status
    lines = {info.lines[k] for k in range(len(owner)) if owner[k] in networks and info.lines[k]}
    return status.model_copy(
        update={
            "instructions": [row for row in status.instructions if owner[row.index] in networks],
            "lines": [row for row in status.lines if row.line in lines],
            # an S7-Graph FB's elements (network 0) are keyed by chart element, not network
            "elements": [
                row for row in status.elements if row.network in networks or not row.network
            ],
        }
    )


def _name(operand: object, info: BlockInfo) -> str | None:
    """The variable name an SCL line shows for this operand (its own variables, parameters)."""
    if isinstance(operand, Direct):
        slot = info.slot_at(operand)
        return slot.name if slot is not None else None
    if isinstance(operand, ParamRef) and operand.bit_offset == 0:
        return operand.name
    instance = _instance_slot(operand)
    if instance is not None:
        slot = info.slot_at(instance)
        return slot.name if slot is not None else None
    return None


def _instance_slot(operand: object) -> Direct | None:
    """``DIW [AR2, P#4.0]``, an FB's access to its own instance data, as the DI address it is
    relative to the instance's start (what the block interface gives as offsets)."""
    if isinstance(operand, RegisterIndirect) and operand.register == 2 and operand.area is Area.DI:
        at = operand.offset_bits
        return Direct(Area.DI, operand.width, at >> 3, at & 7)
    return None


def reader_of(
    operand: object, info: BlockInfo, memory: Memory, timers: Timers, counters: Any
) -> Reader | None:
    """What an instruction's row shows of ``operand`` after it: a bit, a value by its type,
    a timer's or counter's state; None for operands that have no value (labels, constants)."""
    if isinstance(operand, TimerRef):
        number = operand.number
        return lambda frame, params, regs: timers.status(number)
    if isinstance(operand, CounterRef):
        number = operand.number
        return lambda frame, params, regs: counters.load(number)
    if isinstance(operand, ParamRef):
        found = info.by_name.get(operand.name.casefold())
        if found is None or found.home != "P" or operand.bit_offset:
            return None
        slot = found
        return lambda frame, params, regs: read_slot(slot, frame, bytearray(), 0, params)
    instance = _instance_slot(operand)
    if instance is not None:
        slot_of = info.slot_at(instance)
        if slot_of is not None and slot_of.bits == 64:  # read the whole 8-byte variable
            relative = Slot("", slot_of.type, "DI", slot_of.bit_offset, 64)
        else:
            kind = slot_of.type if slot_of is not None else _type_of_width(int(instance.width))
            relative = Slot("", kind, "DI", instance.byte * 8 + instance.bit, int(instance.width))
        return lambda frame, params, regs: read_slot(relative, frame, regs[DI], regs[AR2], params)
    if not isinstance(operand, Direct):
        return None
    own = info.slot_at(operand)
    if own is not None and own.bits == 64:  # either half of an 8-byte local: the whole value
        local = Slot("", own.type, "L", own.bit_offset, 64)
    else:
        type_name = own.type if own is not None else _type_of_width(int(operand.width))
        local = Slot("", type_name, "L", operand.byte * 8 + operand.bit, int(operand.width))
    area = operand.area
    if area is Area.L:
        return lambda frame, params, regs: read_slot(local, frame, frame, 0, params)
    if area is Area.DI:
        return lambda frame, params, regs: read_slot(local, regs[DI], regs[DI], 0, params)
    if area is Area.DB:
        db_number = operand.db
        if db_number is None:
            return lambda frame, params, regs: read_slot(local, regs[DB], regs[DB], 0, params)
        dbs = memory.dbs

        def from_db(frame: bytearray, params: list[Any], regs: tuple[Any, ...]) -> Value:
            buf = dbs.get(db_number)
            return None if buf is None else read_slot(local, buf, buf, 0, params)

        return from_db
    if area in (Area.V,):
        return None
    buf = memory.area(area)
    return lambda frame, params, regs: read_slot(local, buf, buf, 0, params)


def _type_of_width(bits: int) -> str:
    return {1: "BOOL", 8: "BYTE", 16: "INT", 32: "DINT"}.get(bits, "DWORD")

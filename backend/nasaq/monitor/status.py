"""Block status: the registers after every instruction of one sampled execution of a block.

Like STEP 7's "monitor block", the status is sampled, not streamed: in a scan chosen for sampling
(at most ~30 per second) the block runs its instrumented compilation and each instruction's hook
stores its registers and operand value; every other scan runs the fast compilation. An
instruction executed several times in that scan (a loop, several calls) shows its last execution.
SCL lines show the block's variables their code read or wrote, with the last value seen.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from nasaq.cpu.memory import Memory
from nasaq.cpu.timers import Timers
from nasaq.ir import Area, CounterRef, Direct, ParamRef, RegisterIndirect, TimerRef
from nasaq.monitor.block_info import BlockInfo, Slot, read_slot
from nasaq.monitor.protocol import BlockStatus, InstructionStatus, LineStatus, Value

# Positions in the register tuple the hooks pass (codegen.compiler.HOOK_REGISTERS).
A1, A2, FC, RLO, STA, ORB, OS, OV, CC0, CC1, BR, AR1, AR2, DB, DI = range(15)
Reader = Callable[[bytearray, list[Any], tuple[Any, ...]], Value]


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
    """Collects one block's rows while ``on``; ``rows[index] = (registers, operand value)``."""

    def __init__(self, info: BlockInfo, memory: Memory, timers: Timers, counters: Any) -> None:
        self.info = info
        self.on = False
        self.rows: dict[int, tuple[tuple[Any, ...], Value]] = {}
        self.readers: list[Reader | None] = [
            _reader(ins.operand, info, memory, timers, counters) for ins in info.block.code
        ]
        self.names: list[str | None] = [_name(ins.operand, info) for ins in info.block.code]
        self.last: BlockStatus | None = None

    def hook(self) -> Callable[..., None]:
        rows, readers = self.rows, self.readers
        recorder = self

        def after(index: int, frame: bytearray, params: list[Any], *regs: Any) -> None:
            if recorder.on:
                reader = readers[index]
                rows[index] = (regs, reader(frame, params, regs) if reader else None)

        return after

    def begin(self) -> None:
        self.rows.clear()
        self.on = True

    def finish(self, scan: int) -> BlockStatus | None:
        """The status of the sampled scan, or the previous one if the block did not run."""
        self.on = False
        if not self.rows:
            return self.last
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
        self.last = BlockStatus(
            block=info.name,
            language="scl" if info.language == "scl" else "stl",
            scan=scan,
            instructions=instructions,
            lines=[LineStatus(line=k, values=v) for k, v in sorted(lines.items())],
        )
        return self.last


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


def _reader(
    operand: object, info: BlockInfo, memory: Memory, timers: Timers, counters: Any
) -> Reader | None:
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
        kind = slot_of.type if slot_of is not None else _type_of_width(int(instance.width))
        relative = Slot("", kind, "DI", instance.byte * 8 + instance.bit, int(instance.width))
        return lambda frame, params, regs: read_slot(relative, frame, regs[DI], regs[AR2], params)
    if not isinstance(operand, Direct):
        return None
    own = info.slot_at(operand)
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

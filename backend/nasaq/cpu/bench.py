"""Speed benchmark: ``python -m nasaq.cpu.bench [seconds]``.

Builds two programs as IR and prints STL instructions per second for each:
1. OB1 with a LOOP over bit logic and INT arithmetic (the compiled fast path);
2. OB1 with a LOOP calling an FC with parameters and an FB with an instance DB.
"""

from __future__ import annotations

import sys
import time

from nasaq.cpu.api import Cpu
from nasaq.cpu.profile import Profile
from nasaq.ir import (
    Area,
    Block,
    BlockKind,
    BlockRef,
    CallArg,
    CallInfo,
    Constant,
    ConstType,
    Direct,
    Instruction,
    LabelRef,
    ParamRef,
    Program,
    RegisterIndirect,
    Variable,
    Width,
)

LOOPS_PER_SCAN = 5000


def _int(value: int) -> Constant:
    return Constant(ConstType.INT, value & 0xFFFFFFFF, value, str(value))


def _bit(area: Area, byte: int, bit: int) -> Direct:
    return Direct(area, Width.BIT, byte, bit)


def _word(area: Area, byte: int) -> Direct:
    return Direct(area, Width.WORD, byte)


def _loop(body: list[Instruction]) -> list[Instruction]:
    """``L n / NEXT: T MW 0 / body / L MW 0 / LOOP NEXT``."""
    return [
        Instruction("L", _int(LOOPS_PER_SCAN)),
        Instruction("T", _word(Area.M, 0), label="NEXT"),
        *body,
        Instruction("L", _word(Area.M, 0)),
        Instruction("LOOP", LabelRef("NEXT")),
    ]


def logic_program() -> Program:
    body = [
        Instruction("A", _bit(Area.I, 0, 0)),
        Instruction("AN", _bit(Area.I, 0, 1)),
        Instruction("O", _bit(Area.M, 1, 0)),
        Instruction("=", _bit(Area.Q, 0, 0)),
        Instruction("A", _bit(Area.M, 0, 1)),
        Instruction("S", _bit(Area.M, 2, 0)),
        Instruction("L", _word(Area.M, 2)),
        Instruction("L", _int(3)),
        Instruction("+I"),
        Instruction("T", _word(Area.M, 2)),
        Instruction("L", _word(Area.M, 4)),
        Instruction("L", _word(Area.M, 2)),
        Instruction("-I"),
        Instruction("T", _word(Area.M, 4)),
    ]
    program = Program()
    program.add(_with_labels(Block(BlockKind.OB, 1, code=_loop(body))))
    return program


def calls_program() -> Program:
    fc_code = [
        Instruction("L", ParamRef(0, "IN", Width.WORD)),
        Instruction("L", _int(2)),
        Instruction("*I"),
        Instruction("T", ParamRef(1, "OUT", Width.WORD)),
        Instruction("A", ParamRef(2, "EN", Width.BIT)),
        Instruction("=", _bit(Area.M, 3, 0)),
    ]
    fc = Block(
        BlockKind.FC,
        1,
        code=fc_code,
        interface=[
            Variable("IN", "INT", "IN", 0, 16),
            Variable("OUT", "INT", "OUT", 0, 16),
            Variable("EN", "BOOL", "IN", 0, 1),
        ],
    )
    stat = RegisterIndirect(Width.WORD, Area.DI, 2, 16)
    fb_code = [
        Instruction("A", RegisterIndirect(Width.BIT, Area.DI, 2, 0)),
        Instruction("JCN", LabelRef("SKIP")),
        Instruction("L", stat),
        Instruction("L", _int(1)),
        Instruction("+I"),
        Instruction("T", stat),
        Instruction("L", stat, label="SKIP"),
        Instruction("T", RegisterIndirect(Width.WORD, Area.DI, 2, 32)),
    ]
    fb = Block(
        BlockKind.FB,
        1,
        code=fb_code,
        interface=[
            Variable("RUN", "BOOL", "IN", 0, 1),
            Variable("COUNT", "INT", "STAT", 16, 16),
            Variable("OUT", "INT", "OUT", 32, 16),
        ],
    )
    call_fc = CallInfo(
        BlockRef(BlockKind.FC, 1),
        None,
        (
            CallArg("IN", _word(Area.M, 10)),
            CallArg("OUT", _word(Area.M, 12)),
            CallArg("EN", _bit(Area.I, 0, 0)),
        ),
    )
    call_fb = CallInfo(
        BlockRef(BlockKind.FB, 1),
        BlockRef(BlockKind.DB, 1),
        (CallArg("RUN", _bit(Area.M, 3, 1)), CallArg("OUT", _word(Area.M, 14))),
    )
    body = [
        Instruction("CALL", call=call_fc),
        Instruction("CALL", call=call_fb),
    ]
    program = Program()
    program.add(_with_labels(Block(BlockKind.OB, 1, code=_loop(body))))
    program.add(_with_labels(fc))
    program.add(_with_labels(fb))
    program.add(Block(BlockKind.DB, 1, instance_of=1, data=bytes(6)))
    return program


def _with_labels(block: Block) -> Block:
    block.labels = {ins.label: k for k, ins in enumerate(block.code) if ins.label}
    return block


def measure(program: Program, seconds: float) -> tuple[float, int]:
    """Instructions per second over about ``seconds`` of scanning, and the count."""
    cpu = Cpu(program, profile=Profile.S7_300, watchdog_ms=10_000)
    cpu.start()
    cpu.scan()  # compile and warm up
    before = cpu.instructions_executed
    started = time.perf_counter()
    elapsed = 0.0
    while elapsed < seconds:
        cpu.scan()
        elapsed = time.perf_counter() - started
    if cpu.mode != "RUN":
        raise RuntimeError(cpu.stop_reason)
    executed = cpu.instructions_executed - before
    return executed / elapsed, executed


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    seconds = float(args[0]) if args else 3.0
    for name, program in (
        ("bit logic + INT loop", logic_program()),
        ("FC/FB calls", calls_program()),
    ):
        rate, executed = measure(program, seconds)
        print(f"{name:22s} {rate / 1e6:7.2f} M STL instructions/s ({executed} executed)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

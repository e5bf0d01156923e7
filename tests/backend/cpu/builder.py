"""A tiny IR builder for CPU tests: blocks from lists of instructions, short operand helpers."""

from __future__ import annotations

import struct

from nasaq.cpu import Cpu, Profile
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
    Operand,
    Origin,
    Program,
    Register,
    Variable,
    Width,
)


def ins(
    op: str, operand: Operand | None = None, label: str | None = None, **kw: object
) -> Instruction:
    return Instruction(op, operand, label=label, **kw)  # type: ignore[arg-type]


def I(byte: int, bit: int = 0) -> Direct:  # noqa: E743, N802
    return Direct(Area.I, Width.BIT, byte, bit)


def Q(byte: int, bit: int = 0) -> Direct:  # noqa: N802
    return Direct(Area.Q, Width.BIT, byte, bit)


def M(byte: int, bit: int = 0) -> Direct:  # noqa: N802
    return Direct(Area.M, Width.BIT, byte, bit)


def MB(byte: int) -> Direct:  # noqa: N802
    return Direct(Area.M, Width.BYTE, byte)


def MW(byte: int) -> Direct:  # noqa: N802
    return Direct(Area.M, Width.WORD, byte)


def MD(byte: int) -> Direct:  # noqa: N802
    return Direct(Area.M, Width.DWORD, byte)


def QW(byte: int) -> Direct:  # noqa: N802
    return Direct(Area.Q, Width.WORD, byte)


def DBW(db: int | None, byte: int) -> Direct:  # noqa: N802
    return Direct(Area.DB, Width.WORD, byte, db=db)


def DBX(db: int | None, byte: int, bit: int) -> Direct:  # noqa: N802
    return Direct(Area.DB, Width.BIT, byte, bit, db=db)


def LW(byte: int) -> Direct:  # noqa: N802
    return Direct(Area.L, Width.WORD, byte)


def lbl(name: str) -> LabelRef:
    return LabelRef(name)


def INT(value: int) -> Constant:  # noqa: N802
    return Constant(ConstType.INT, value & 0xFFFFFFFF, value, str(value))


def DINT(value: int) -> Constant:  # noqa: N802
    return Constant(ConstType.DINT, value & 0xFFFFFFFF, value, f"L#{value}")


def WORD(value: int) -> Constant:  # noqa: N802
    return Constant(ConstType.WORD, value & 0xFFFF, value, f"W#16#{value:X}")


def DWORD(value: int) -> Constant:  # noqa: N802
    return Constant(ConstType.DWORD, value & 0xFFFFFFFF, value, f"DW#16#{value:X}")


def REAL(value: float) -> Constant:  # noqa: N802
    pattern = struct.unpack(">I", struct.pack(">f", value))[0]
    return Constant(ConstType.REAL, pattern, value, repr(value))


def S5T(ms: int) -> Constant:  # noqa: N802
    """S5TIME with the smallest time base that holds ``ms``."""
    for base_code, base in enumerate((10, 100, 1000, 10000)):
        units = ms // base
        if units <= 999:
            bcd = int(str(units), 16)
            return Constant(ConstType.S5TIME, bcd | base_code << 12, ms, f"S5T#{ms}MS")
    raise ValueError(ms)


def P(byte: int, bit: int = 0, area: Area | None = None) -> Constant:  # noqa: N802
    from nasaq.cpu.pointers import area_pointer, internal_pointer

    pattern = area_pointer(area, byte, bit) if area else internal_pointer(byte, bit)
    return Constant(ConstType.POINTER, pattern, pattern, f"P#{byte}.{bit}")


def sfc(number: int, **args: Operand) -> Instruction:
    """``CALL SFC number (NAME := operand, ...)``."""
    info = CallInfo(
        BlockRef(BlockKind.SFC, number), None, tuple(CallArg(k, v) for k, v in args.items())
    )
    return Instruction("CALL", call=info)


def reg(name: str) -> Register:
    return Register(name)


def real_of(bits: int) -> float:
    return float(struct.unpack(">f", struct.pack(">I", bits & 0xFFFFFFFF))[0])


def number_lines(code: list[Instruction]) -> list[Instruction]:
    for k, instruction in enumerate(code):
        if instruction.origin is None:
            instruction.origin = Origin("test.awl", k + 1, 1, network=1)
    return code


def block(kind: BlockKind, number: int, code: list[Instruction], **kw: object) -> Block:
    code = number_lines(code)
    labels = {i.label: k for k, i in enumerate(code) if i.label}
    return Block(kind, number, code=code, labels=labels, **kw)  # type: ignore[arg-type]


def program(*blocks: Block) -> Program:
    prog = Program()
    for b in blocks:
        prog.add(b)
    return prog


def ob1(*code: Instruction, extra: tuple[Block, ...] = (), temp_bytes: int = 0) -> Program:
    return program(block(BlockKind.OB, 1, list(code), temp_bytes=temp_bytes), *extra)


def run_ob1(
    *code: Instruction,
    extra: tuple[Block, ...] = (),
    scans: int = 1,
    profile: Profile = Profile.S7_300,
    test_ops: bool = True,
    temp_bytes: int = 0,
) -> Cpu:
    cpu = Cpu(ob1(*code, extra=extra, temp_bytes=temp_bytes), profile=profile, test_ops=test_ops)
    cpu.start()
    cpu.run(scans)
    return cpu


def db(number: int, size: int, data: bytes = b"", instance_of: int | None = None) -> Block:
    return Block(
        BlockKind.DB,
        number,
        data=data + bytes(max(0, size - len(data))),
        instance_of=instance_of,
    )


def var(name: str, type_: str, section: str, offset_bits: int, size_bits: int) -> Variable:
    return Variable(name, type_, section, offset_bits, size_bits)


STW = Register("STW")


BITS = ("FC", "RLO", "STA", "OR", "OS", "OV", "CC0", "CC1", "BR")


def stw_bits(word: int) -> dict[str, int]:
    return {name: (word >> k) & 1 for k, name in enumerate(BITS)}


def after(
    *code: Instruction, profile: Profile = Profile.S7_300, extra: tuple[Block, ...] = ()
) -> Cpu:
    """Run the code once in OB1 and return the CPU (registers as the code left them)."""
    cpu = run_ob1(*code, profile=profile, extra=extra)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def status(*code: Instruction, **kw: object) -> dict[str, int]:
    return stw_bits(after(*code, **kw).stw)  # type: ignore[arg-type]

"""LAR1 LAR2 TAR1 TAR2 CAR, +AR1 +AR2: the address registers.

``LAR1`` alone loads ACCU1, with an operand a DWORD or a P# constant, ``LAR1 AR2`` copies AR2.
``TAR1`` alone pushes ACCU1 into ACCU2 and loads AR1 into ACCU1, with an operand stores AR1.
``+AR1`` adds ACCU1-L (signed) or a P# offset to the address part (bits 0-23); the area stays.
No status bits change.
"""

from __future__ import annotations

from nasaq.cpu.codegen import access
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Constant, Instruction, Register


def emit_lar(ctx: Ctx, ins: Instruction) -> None:
    reg = f"ar{ins.op[-1]}"
    op = ins.operand
    if op is None:
        ctx.emit(f"{reg} = a1", defs=(reg,), uses=("a1",))
    elif isinstance(op, Register):
        other = op.name.lower()
        ctx.emit(f"{reg} = {other}", defs=(reg,), uses=(other,))
    elif isinstance(op, Constant):
        ctx.emit(f"{reg} = {op.pattern & 0xFFFFFFFF}", defs=(reg,))
    else:
        value = access.read_value(ctx, op, 32)
        ctx.emit(f"{reg} = {value.expr}", defs=(reg,), uses=value.uses)


def emit_tar(ctx: Ctx, ins: Instruction) -> None:
    reg = f"ar{ins.op[-1]}"
    op = ins.operand
    if op is None:
        ctx.emit("a2 = a1", defs=("a2",), uses=("a1",))
        ctx.emit(f"a1 = {reg}", defs=("a1",), uses=(reg,))
    elif isinstance(op, Register):
        other = op.name.lower()
        ctx.emit(f"{other} = {reg}", defs=(other,), uses=(reg,))
    else:
        access.write_value(ctx, op, reg, frozenset({reg}), 32)


def emit_car(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("ar1, ar2 = ar2, ar1", defs=("ar1", "ar2"), uses=("ar1", "ar2"))


def emit_add_ar(ctx: Ctx, ins: Instruction) -> None:
    reg = f"ar{ins.op[-1]}"
    op = ins.operand
    if isinstance(op, Constant):
        amount = str(op.pattern & 0xFFFFFF)
        uses: tuple[str, ...] = (reg,)
    else:
        amount = "(((a1 & 0xFFFF) ^ 0x8000) - 0x8000)"
        uses = (reg, "a1")
    ctx.emit(
        f"{reg} = {reg} & 0xFF000000 | ({reg} + {amount}) & 0xFFFFFF",
        defs=(reg,),
        uses=uses,
    )


EMITTERS: dict[str, Emitter] = {
    "LAR1": emit_lar,
    "LAR2": emit_lar,
    "TAR1": emit_tar,
    "TAR2": emit_tar,
    "CAR": emit_car,
    "TAR": emit_car,
    "+AR1": emit_add_ar,
    "+AR2": emit_add_ar,
}

"""TAK PUSH POP ENT LEAVE, INC DEC, ``+`` constant: accumulator moves, no status bits.

The S7-300 has two accumulators, the S7-400 four; PUSH and POP move the whole stack on the
S7-400, and ENT/LEAVE exist only there.
"""

from __future__ import annotations

from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Constant, ConstType, Instruction


def _four(ctx: Ctx) -> bool:
    return ctx.profile.accumulators == 4


def emit_tak(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1, a2 = a2, a1", defs=("a1", "a2"), uses=("a1", "a2"))


def emit_push(ctx: Ctx, ins: Instruction) -> None:
    if _four(ctx):
        ctx.emit("a4 = a3", defs=("a4",), uses=("a3",))
        ctx.emit("a3 = a2", defs=("a3",), uses=("a2",))
    ctx.emit("a2 = a1", defs=("a2",), uses=("a1",))


def emit_pop(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1 = a2", defs=("a1",), uses=("a2",))
    if _four(ctx):
        ctx.emit("a2 = a3", defs=("a2",), uses=("a3",))
        ctx.emit("a3 = a4", defs=("a3",), uses=("a4",))


def emit_ent_leave(ctx: Ctx, ins: Instruction) -> None:
    if not _four(ctx):
        ctx.error("SIM523", op=ins.op, cpu=ctx.profile.value)
        return
    if ins.op == "ENT":
        ctx.emit("a4 = a3", defs=("a4",), uses=("a3",))
        ctx.emit("a3 = a2", defs=("a3",), uses=("a2",))
    else:
        ctx.emit("a2 = a3", defs=("a2",), uses=("a3",))
        ctx.emit("a3 = a4", defs=("a3",), uses=("a4",))


def pop_after_math(ctx: Ctx) -> None:
    """Arithmetic on the S7-400 pulls ACCU3 into ACCU2 and ACCU4 into ACCU3."""
    if _four(ctx):
        ctx.emit("a2 = a3", defs=("a2",), uses=("a3",))
        ctx.emit("a3 = a4", defs=("a3",), uses=("a4",))


def _amount(ins: Instruction) -> int:
    op = ins.operand
    return int(op.value) if isinstance(op, Constant) else 1


def emit_inc_dec(ctx: Ctx, ins: Instruction) -> None:
    n = _amount(ins) & 0xFF
    sign = "+" if ins.op == "INC" else "-"
    ctx.emit(f"a1 = a1 & 0xFFFFFF00 | (a1 {sign} {n}) & 255", defs=("a1",), uses=("a1",))


def emit_add_constant(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if not isinstance(op, Constant):
        ctx.error("SIM522", op="+", detail="without a constant")
        return
    if op.type in (ConstType.DINT, ConstType.DWORD, ConstType.TIME, ConstType.REAL):
        ctx.emit(f"a1 = (a1 + {op.pattern & 0xFFFFFFFF}) & 0xFFFFFFFF", defs=("a1",), uses=("a1",))
    else:
        ctx.emit(
            f"a1 = a1 & 0xFFFF0000 | (a1 + {op.pattern & 0xFFFF}) & 0xFFFF",
            defs=("a1",),
            uses=("a1",),
        )


EMITTERS: dict[str, Emitter] = {
    "TAK": emit_tak,
    "PUSH": emit_push,
    "POP": emit_pop,
    "ENT": emit_ent_leave,
    "LEAVE": emit_ent_leave,
    "INC": emit_inc_dec,
    "DEC": emit_inc_dec,
    "+": emit_add_constant,
}

"""SSI SSD SLW SRW SLD SRD RLD RRD RLDA RRDA.

The count comes from the operand or from ACCU2-LL. Count 0 changes nothing (not even the status
word); otherwise CC1 is the last bit shifted out and CC0, OV are cleared. Word shifts by more than
16 (double word: 32) give 0 and CC1 0; SSI/SSD saturate at 16/32.
"""

from __future__ import annotations

from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Constant, Instruction

_STATUS = ("a1", "cc1", "cc0", "ov")


def emit_shift(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if isinstance(op, Constant):
        count = int(op.value) & 0xFF
        if count == 0:
            return
        ctx.emit(
            f"a1, cc1, cc0, ov = _SHIFT({ins.op!r}, a1, {count}, 0, 0, 0)",
            defs=_STATUS,
            uses=("a1",),
        )
        return
    ctx.emit(
        f"a1, cc1, cc0, ov = _SHIFT({ins.op!r}, a1, a2 & 255, cc1, cc0, ov)",
        defs=_STATUS,
        uses=("a1", "a2", "cc1", "cc0", "ov"),
    )


def emit_rotate_cc1(ctx: Ctx, ins: Instruction) -> None:
    r = ctx.tmp("r")
    if ins.op == "RLDA":
        ctx.emit(f"{r} = (a1 << 1 | cc1) & 0xFFFFFFFF", defs=(r,), uses=("a1", "cc1"))
        ctx.emit("cc1 = a1 >> 31", defs=("cc1",), uses=("a1",))
    else:
        ctx.emit(f"{r} = a1 >> 1 | cc1 << 31", defs=(r,), uses=("a1", "cc1"))
        ctx.emit("cc1 = a1 & 1", defs=("cc1",), uses=("a1",))
    ctx.emit(f"a1 = {r}", defs=("a1",), uses=(r,))
    ctx.emit("cc0 = 0", defs=("cc0",))
    ctx.emit("ov = 0", defs=("ov",))


EMITTERS: dict[str, Emitter] = {
    **dict.fromkeys(("SSI", "SSD", "SLW", "SRW", "SLD", "SRD", "RLD", "RRD"), emit_shift),
    "RLDA": emit_rotate_cc1,
    "RRDA": emit_rotate_cc1,
}

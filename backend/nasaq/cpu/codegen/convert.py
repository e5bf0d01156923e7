"""BTI ITB BTD DTB ITD DTR, INVI INVD NEGI NEGD NEGR, RND RND+ RND- TRUNC, CAW CAD.

Invalid BCD digits are a programming error (OB121); ITB/DTB/RND... out of range set OV and OS
and keep ACCU1. NEGI/NEGD set CC1 CC0 OV OS like +I/+D; the other conversions leave the status
word alone.
"""

from __future__ import annotations

from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Instruction


def emit_bcd_in(ctx: Ctx, ins: Instruction) -> None:
    helper = "_BTI" if ins.op == "BTI" else "_BTD"
    ctx.emit(ctx.guarded_call([f"a1 = {helper}(a1)"]), defs=("a1",), uses=("a1",), keep=True)


def emit_bcd_out(ctx: Ctx, ins: Instruction) -> None:
    helper = "_ITB" if ins.op == "ITB" else "_DTB"
    ctx.emit(f"a1, ov, os = {helper}(a1, os)", defs=("a1", "ov", "os"), uses=("a1", "os"))


def emit_itd(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1 = (((a1 & 0xFFFF) ^ 0x8000) - 0x8000) & 0xFFFFFFFF", defs=("a1",), uses=("a1",))


def emit_dtr(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1 = _DTR(a1)", defs=("a1",), uses=("a1",))


def emit_invert(ctx: Ctx, ins: Instruction) -> None:
    mask = "0xFFFF" if ins.op == "INVI" else "0xFFFFFFFF"
    ctx.emit(f"a1 = a1 ^ {mask}", defs=("a1",), uses=("a1",))


def emit_negate(ctx: Ctx, ins: Instruction) -> None:
    r = ctx.tmp("r")
    if ins.op == "NEGI":
        ctx.emit(f"{r} = -(((a1 & 0xFFFF) ^ 0x8000) - 0x8000)", defs=(r,), uses=("a1",))
        ctx.emit(f"a1 = a1 & 0xFFFF0000 | {r} & 0xFFFF", defs=("a1",), uses=("a1", r))
        bits = 16
    else:
        ctx.emit(f"{r} = -((a1 ^ 0x80000000) - 0x80000000)", defs=(r,), uses=("a1",))
        ctx.emit(f"a1 = {r} & 0xFFFFFFFF", defs=("a1",), uses=(r,))
        bits = 32
    from nasaq.cpu.codegen.integer_math import _status

    _status(ctx, r, bits, truncated_sign=True)


def emit_negr(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1 = a1 ^ 0x80000000", defs=("a1",), uses=("a1",))


def emit_round(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(f"a1, ov, os = _ROUND({ins.op!r}, a1, os)", defs=("a1", "ov", "os"), uses=("a1", "os"))


def emit_caw(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1 = a1 & 0xFFFF0000 | (a1 & 255) << 8 | a1 >> 8 & 255", defs=("a1",), uses=("a1",))


def emit_cad(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(
        "a1 = (a1 & 255) << 24 | (a1 & 0xFF00) << 8 | a1 >> 8 & 0xFF00 | a1 >> 24",
        defs=("a1",),
        uses=("a1",),
    )


EMITTERS: dict[str, Emitter] = {
    "BTI": emit_bcd_in,
    "BTD": emit_bcd_in,
    "ITB": emit_bcd_out,
    "DTB": emit_bcd_out,
    "ITD": emit_itd,
    "DTR": emit_dtr,
    "INVI": emit_invert,
    "INVD": emit_invert,
    "NEGI": emit_negate,
    "NEGD": emit_negate,
    "NEGR": emit_negr,
    "RND": emit_round,
    "RND+": emit_round,
    "RND-": emit_round,
    "TRUNC": emit_round,
    "CAW": emit_caw,
    "CAD": emit_cad,
}

"""+I -I *I /I and +D -D *D /D MOD, with CC1 CC0 OV OS as the S7 manuals' tables give them.

INT results go to ACCU1-L (ACCU1-H kept), except *I (32-bit product in ACCU1) and /I (quotient
in ACCU1-L, remainder in ACCU1-H). CC1/CC0 follow the sign of the stored (truncated) result for
+ and -, of the true result for * and /; OV marks a result outside the type, OS keeps it.
Division by zero sets CC1 CC0 OV OS and leaves ACCU1 as it was; the CPU does not stop.
Each status bit is its own statement, so bits nobody reads are never computed.
"""

from __future__ import annotations

from nasaq.cpu.codegen.accumulators import pop_after_math
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Instruction

SX16 = "(((a{n} & 0xFFFF) ^ 0x8000) - 0x8000)"
SX32 = "((a{n} ^ 0x80000000) - 0x80000000)"


def _status(ctx: Ctx, r: str, bits: int, truncated_sign: bool) -> None:
    lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    mask = (1 << bits) - 1
    if truncated_sign:
        ctx.emit(f"cc1 = 1 if 0 < {r} & {mask} <= {hi} else 0", defs=("cc1",), uses=(r,))
        ctx.emit(f"cc0 = {r} >> {bits - 1} & 1", defs=("cc0",), uses=(r,))
    else:
        ctx.emit(f"cc1 = 1 if {r} > 0 else 0", defs=("cc1",), uses=(r,))
        ctx.emit(f"cc0 = 1 if {r} < 0 else 0", defs=("cc0",), uses=(r,))
    ctx.emit(f"ov = 0 if {lo} <= {r} <= {hi} else 1", defs=("ov",), uses=(r,))
    ctx.emit(f"if not {lo} <= {r} <= {hi}: os = 1", defs=("os",), uses=("os", r))


def emit_add_sub_int(ctx: Ctx, ins: Instruction) -> None:
    r = ctx.tmp("r")
    sym = "+" if ins.op == "+I" else "-"
    known = ctx.known.get("a1")
    rhs = str(((known & 0xFFFF) ^ 0x8000) - 0x8000) if known is not None else SX16.format(n=1)
    uses = ("a2",) if known is not None else ("a1", "a2")
    ctx.emit(f"{r} = {SX16.format(n=2)} {sym} {rhs}", defs=(r,), uses=uses)
    ctx.emit(f"a1 = a1 & 0xFFFF0000 | {r} & 0xFFFF", defs=("a1",), uses=("a1", r))
    pop_after_math(ctx)
    _status(ctx, r, 16, truncated_sign=True)


def emit_add_sub_dint(ctx: Ctx, ins: Instruction) -> None:
    r = ctx.tmp("r")
    sym = "+" if ins.op == "+D" else "-"
    ctx.emit(f"{r} = {SX32.format(n=2)} {sym} {SX32.format(n=1)}", defs=(r,), uses=("a1", "a2"))
    ctx.emit(f"a1 = {r} & 0xFFFFFFFF", defs=("a1",), uses=(r,))
    pop_after_math(ctx)
    _status(ctx, r, 32, truncated_sign=True)


def emit_mul(ctx: Ctx, ins: Instruction) -> None:
    r = ctx.tmp("r")
    bits = 16 if ins.op == "*I" else 32
    sx = SX16 if bits == 16 else SX32
    ctx.emit(f"{r} = {sx.format(n=2)} * {sx.format(n=1)}", defs=(r,), uses=("a1", "a2"))
    ctx.emit(f"a1 = {r} & 0xFFFFFFFF", defs=("a1",), uses=(r,))
    pop_after_math(ctx)
    _status(ctx, r, bits, truncated_sign=False)


def emit_div(ctx: Ctx, ins: Instruction) -> None:
    bits = 16 if ins.op == "/I" else 32
    sx = SX16 if bits == 16 else SX32
    hi = (1 << (bits - 1)) - 1
    n, d, q, rem = ctx.tmp("n"), ctx.tmp("d"), ctx.tmp("q"), ctx.tmp("m")
    if ins.op == "/I":
        store = f"    a1 = ({rem} & 0xFFFF) << 16 | {q} & 0xFFFF"
    elif ins.op == "/D":
        store = f"    a1 = {q} & 0xFFFFFFFF"
    else:  # MOD
        store = f"    a1 = {rem} & 0xFFFFFFFF"
    result = rem if ins.op == "MOD" else q
    ctx.emit(
        [
            f"{n} = {sx.format(n=2)}",
            f"{d} = {sx.format(n=1)}",
            f"if {d}:",
            f"    {q} = abs({n}) // abs({d})",
            f"    if ({n} < 0) != ({d} < 0): {q} = -{q}",
            f"    {rem} = {n} - {q} * {d}",
            store,
            f"    cc1 = 1 if {result} > 0 else 0",
            f"    cc0 = 1 if {result} < 0 else 0",
            f"    ov = 1 if {result} > {hi} else 0",
            "    if ov: os = 1",
            "else:",
            "    cc1 = cc0 = ov = os = 1",
        ],
        defs=("a1", "cc1", "cc0", "ov", "os"),
        uses=("a1", "a2", "os"),
    )
    pop_after_math(ctx)


EMITTERS: dict[str, Emitter] = {
    "+I": emit_add_sub_int,
    "-I": emit_add_sub_int,
    "*I": emit_mul,
    "/I": emit_div,
    "+D": emit_add_sub_dint,
    "-D": emit_add_sub_dint,
    "*D": emit_mul,
    "/D": emit_div,
    "MOD": emit_div,
}

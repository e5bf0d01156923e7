"""+R -R *R /R and ABS SQR SQRT EXP LN SIN COS TAN ASIN ACOS ATAN (see ``nasaq.cpu.realnum``)."""

from __future__ import annotations

from nasaq.cpu.codegen.accumulators import pop_after_math
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Instruction

_STATUS = ("a1", "cc1", "cc0", "ov", "os")


def emit_arith(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(
        f"a1, cc1, cc0, ov, os = _RARITH({ins.op[0]!r}, a2, a1, os)",
        defs=_STATUS,
        uses=("a1", "a2", "os"),
    )
    pop_after_math(ctx)


def emit_function(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(
        f"a1, cc1, cc0, ov, os = _RFUNC({ins.op!r}, a1, os)",
        defs=_STATUS,
        uses=("a1", "os"),
    )


def emit_abs(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("a1 = a1 & 0x7FFFFFFF", defs=("a1",), uses=("a1",))


EMITTERS: dict[str, Emitter] = {
    "+R": emit_arith,
    "-R": emit_arith,
    "*R": emit_arith,
    "/R": emit_arith,
    "ABS": emit_abs,
    **dict.fromkeys(
        ("SQR", "SQRT", "EXP", "LN", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN"), emit_function
    ),
}

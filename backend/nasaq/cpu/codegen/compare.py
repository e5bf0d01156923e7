"""==I <>I >I <I >=I <=I and the D and R forms: ACCU2 compared with ACCU1.

The result is the new RLO (not combined with the previous one; /FC 1, OR 0, STA = RLO);
CC1 CC0 say how ACCU2 relates to ACCU1 (1 0 greater, 0 1 less, 0 0 equal), OV is cleared.
REAL comparisons with a NaN operand set CC1 CC0 OV OS and give RLO 0. Signed integers compare
as unsigned after flipping the sign bit, which saves the sign extension.
"""

from __future__ import annotations

from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Instruction

_RELATIONS = {"==": "==", "<>": "!=", ">": ">", "<": "<", ">=": ">=", "<=": "<="}


def _operands(ctx: Ctx, kind: str) -> tuple[str, str, frozenset[str]]:
    if kind == "I":
        known = ctx.known.get("a1")
        right = str((known & 0xFFFF) ^ 0x8000) if known is not None else "((a1 & 0xFFFF) ^ 0x8000)"
        uses = {"a2"} if known is not None else {"a1", "a2"}
        return "((a2 & 0xFFFF) ^ 0x8000)", right, frozenset(uses)
    return "(a2 ^ 0x80000000)", "(a1 ^ 0x80000000)", frozenset({"a1", "a2"})


def emit_compare(ctx: Ctx, ins: Instruction) -> None:
    relation, kind = _RELATIONS[ins.op[:-1]], ins.op[-1]
    if kind == "R":
        ctx.emit(
            f"rlo, cc1, cc0, ov, os = _RCMP(a2, a1, {relation!r}, os)",
            defs=("rlo", "cc1", "cc0", "ov", "os"),
            uses=("a1", "a2", "os"),
        )
    else:
        left, right, uses = _operands(ctx, kind)
        x, y = ctx.tmp("x"), ctx.tmp("y")
        ctx.emit(f"{x} = {left}", defs=(x,), uses=uses & {"a2"})
        ctx.emit(f"{y} = {right}", defs=(y,), uses=uses & {"a1"})
        ctx.emit(f"rlo = 1 if {x} {relation} {y} else 0", defs=("rlo",), uses=(x, y))
        ctx.emit(f"cc1 = 1 if {x} > {y} else 0", defs=("cc1",), uses=(x, y))
        ctx.emit(f"cc0 = 1 if {x} < {y} else 0", defs=("cc0",), uses=(x, y))
        ctx.emit("ov = 0", defs=("ov",))
    ctx.emit("sta = rlo", defs=("sta",), uses=("rlo",))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 1", defs=("fc",), known={"fc": 1})


EMITTERS: dict[str, Emitter] = {
    f"{rel}{kind}": emit_compare for rel in _RELATIONS for kind in ("I", "D", "R")
}

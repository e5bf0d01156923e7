"""AW OW XOW (ACCU1-L) and AD OD XOD (ACCU1) with ACCU2 or a constant.

CC1 = 1 when the result is not zero; CC0 and OV are cleared. ACCU1-H stays for the word forms.
"""

from __future__ import annotations

from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Constant, Instruction

_SYMBOLS = {"A": "&", "O": "|", "X": "^"}


def emit_word_logic(ctx: Ctx, ins: Instruction) -> None:
    word = ins.op.endswith("W")
    sym = _SYMBOLS[ins.op[0]]
    op = ins.operand
    mask = 0xFFFF if word else 0xFFFFFFFF
    if isinstance(op, Constant):
        other, uses = str(op.pattern & mask), {"a1"}
    else:
        other, uses = "a2", {"a1", "a2"}
    if word:
        ctx.emit(f"a1 = a1 & 0xFFFF0000 | (a1 {sym} {other}) & 0xFFFF", defs=("a1",), uses=uses)
        ctx.emit("cc1 = 1 if a1 & 0xFFFF else 0", defs=("cc1",), uses=("a1",))
    else:
        ctx.emit(f"a1 = (a1 {sym} {other}) & 0xFFFFFFFF", defs=("a1",), uses=uses)
        ctx.emit("cc1 = 1 if a1 else 0", defs=("cc1",), uses=("a1",))
    ctx.emit("cc0 = 0", defs=("cc0",))
    ctx.emit("ov = 0", defs=("ov",))


EMITTERS: dict[str, Emitter] = dict.fromkeys(
    ("AW", "OW", "XOW", "AD", "OD", "XOD"), emit_word_logic
)

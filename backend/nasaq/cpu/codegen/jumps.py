"""JU JC JCN JCB JNB JBI JNBI JO JOS JZ JN JP JM JPZ JMZ JUO, JL and LOOP.

JC/JCN/JCB/JNB set RLO 1, STA 1, OR 0, /FC 0 whether they jump or not (JCB/JNB first copy the
RLO into BR); JBI/JNBI set STA 1, OR 0, /FC 0; JOS clears OS; the others leave the status
word alone. LOOP decrements ACCU1-L and jumps while it is not 0.
"""

from __future__ import annotations

from nasaq.cpu.codegen.access import STATUS_CONDITIONS
from nasaq.cpu.codegen.model import Ctx, Emitter, Term
from nasaq.ir import Instruction, LabelRef, StatusCondition

_CONDITIONS = {
    "JO": StatusCondition.OV,
    "JOS": StatusCondition.OS,
    "JZ": StatusCondition.EQ0,
    "JN": StatusCondition.NE0,
    "JP": StatusCondition.GT0,
    "JM": StatusCondition.LT0,
    "JPZ": StatusCondition.GE0,
    "JMZ": StatusCondition.LE0,
    "JUO": StatusCondition.UO,
}
JUMPS = frozenset({"JU", "JC", "JCN", "JCB", "JNB", "JBI", "JNBI", "LOOP", "JL", *_CONDITIONS})


def label_index(ctx: Ctx, ins: Instruction) -> int | None:
    op = ins.operand
    if not isinstance(op, LabelRef):
        return None
    found = ctx.block.labels.get(op.name)
    if found is None:
        for i, other in enumerate(ctx.block.code):
            if other.label == op.name:
                return i
    return found


def _target(ctx: Ctx, ins: Instruction) -> int | None:
    target = label_index(ctx, ins)
    if target is None:
        ctx.error("SIM522", op=ins.op, detail=f"to a missing label {ins.operand}")
    return target


def _chain_end(ctx: Ctx) -> None:
    ctx.emit("rlo = 1", defs=("rlo",))
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_jump(ctx: Ctx, ins: Instruction) -> None:
    target = _target(ctx, ins)
    if target is None:
        return
    op = ins.op
    if op == "JU":
        ctx.set_term(Term("jump", target=target))
        return
    j = ctx.tmp("j")
    if op in ("JC", "JCN", "JCB", "JNB"):
        ctx.emit(f"{j} = {'rlo' if op in ('JC', 'JCB') else 'rlo ^ 1'}", defs=(j,), uses=("rlo",))
        if op in ("JCB", "JNB"):
            ctx.emit("br = rlo", defs=("br",), uses=("rlo",))
        _chain_end(ctx)
    elif op in ("JBI", "JNBI"):
        ctx.emit(f"{j} = {'br' if op == 'JBI' else 'br ^ 1'}", defs=(j,), uses=("br",))
        ctx.emit("sta = 1", defs=("sta",))
        ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
        ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})
    else:
        expr, uses = STATUS_CONDITIONS[_CONDITIONS[op]]
        ctx.emit(f"{j} = {expr}", defs=(j,), uses=uses)
        if op == "JOS":
            ctx.emit("os = 0", defs=("os",))
    ctx.set_term(Term("cond", cond=j, uses=frozenset({j}), target=target))


def emit_loop(ctx: Ctx, ins: Instruction) -> None:
    target = _target(ctx, ins)
    if target is None:
        return
    ctx.emit("a1 = a1 & 0xFFFF0000 | (a1 - 1) & 0xFFFF", defs=("a1",), uses=("a1",))
    ctx.set_term(Term("cond", cond="a1 & 0xFFFF", uses=frozenset({"a1"}), target=target))


def emit_jump_list(ctx: Ctx, ins: Instruction) -> None:
    default = _target(ctx, ins)
    if default is None:
        return
    entries: list[int] = []
    for k in range(ctx.index + 1, default):
        entry = ctx.block.code[k]
        target = label_index(ctx, entry) if entry.op == "JU" else None
        if target is None:
            ctx.error("SIM525", label=str(ins.operand))
            return
        entries.append(target)
    ctx.set_term(
        Term("jl", cond="a1 & 255", uses=frozenset({"a1"}), target=default, targets=entries)
    )


EMITTERS: dict[str, Emitter] = {
    **{op: emit_jump for op in JUMPS if op not in ("LOOP", "JL")},
    "LOOP": emit_loop,
    "JL": emit_jump_list,
}

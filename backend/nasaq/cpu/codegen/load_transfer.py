"""L, T, L STW / T STW, L DBNO DBLG DINO DILG, L/LC of timers and counters.

``L`` pushes ACCU1 into ACCU2 (ACCU3/4 untouched on the S7-400) and loads the value
zero-extended; ``T`` stores the low byte/word/dword of ACCU1. No status bits change, except
``T STW``, which writes all nine bits (/FC ... BR). ``L STW`` on an S7-300 loads only RLO, OS,
OV, CC0, CC1 and BR; /FC, STA and OR come out 0 (STL manual, note under L STW).
"""

from __future__ import annotations

from nasaq.cpu.codegen import access
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.cpu.status_word import (
    BIT_OF,
    PACK_EXPR,
    PACK_EXPR_300,
    S7_300_L_STW,
    STATUS_NAMES,
)
from nasaq.ir import (
    BlockKind,
    Constant,
    ConstType,
    CounterRef,
    Instruction,
    MemoryIndirect,
    ParamRef,
    Register,
    TimerRef,
)


def push_load(
    ctx: Ctx, expr: str, uses: frozenset[str] | set[str], known: int | None = None
) -> None:
    ctx.emit("a2 = a1", defs=("a2",), uses=("a1",))
    ctx.emit(
        f"a1 = {expr}", defs=("a1",), uses=uses, known={"a1": known} if known is not None else None
    )


def _timer_counter_load(ctx: Ctx, ins: Instruction) -> bool:
    op = ins.operand
    target = None
    if isinstance(op, TimerRef | CounterRef):
        target = "T" if isinstance(op, TimerRef) else "C"
    elif isinstance(op, MemoryIndirect) and op.target in ("T", "C"):
        target = op.target
    elif isinstance(op, ParamRef) and op.width is None:
        target = "P"
    if target is None:
        return False
    assert op is not None
    number = access.number_of(ctx, op, target)
    method = "load_bcd" if ins.op == "LC" else "load"
    value = ctx.tmp("v")
    if target == "P":
        assert isinstance(op, ParamRef)
        target = "C" if access.param_type(ctx, op.name) == "COUNTER" else "T"
    call = f"{value} = {'_T' if target == 'T' else '_C'}.{method}({number})"
    uses = (number,) if number and number.startswith("_p") else ()
    ctx.emit(ctx.guarded_call([call], f"{value} = 0"), defs=(value,), uses=uses, keep=True)
    push_load(ctx, value, {value})
    return True


def _fc_parameter_pointer(ctx: Ctx, op: Constant) -> int | None:
    """``L P##param`` in an FC: the parameter slot whose pointer the call provides (a pointer to
    the actual operand, or into the V area for a parameter passed as a DB pointer); None for
    every other constant."""
    if op.type is not ConstType.POINTER or not op.text.startswith("P##"):
        return None
    if ctx.block.kind is not BlockKind.FC:
        return None
    name = op.text[3:].strip().strip('"')
    sections = ("IN", "OUT", "IN_OUT", "RETURN")
    if not any(var.name == name and var.section in sections for var in ctx.block.interface):
        return None
    ctx.param_pointers = True
    return access.param_slot(ctx, ParamRef(-1, name, None))


def emit_load(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if _timer_counter_load(ctx, ins):
        return
    if isinstance(op, Register) and op.name in ("STW", "DBNO", "DBLG", "DINO", "DILG"):
        if op.name == "STW" and ctx.profile.accumulators == 2:  # S7-300
            push_load(ctx, f"({PACK_EXPR_300})", set(S7_300_L_STW))
        elif op.name == "STW":
            push_load(ctx, f"({PACK_EXPR})", set(STATUS_NAMES))
        elif op.name == "DBNO":
            push_load(ctx, "dbno", {"dbno"})
        elif op.name == "DINO":
            push_load(ctx, "dino", {"dino"})
        elif op.name == "DBLG":
            push_load(ctx, "len(db)", {"db"})
        else:
            push_load(ctx, "len(di)", {"di"})
        return
    if isinstance(op, Constant):
        slot = _fc_parameter_pointer(ctx, op)
        if slot is not None:
            push_load(ctx, f"m.vptrs[{slot}]", set())
            return
        push_load(ctx, str(op.pattern & 0xFFFFFFFF), set(), known=op.pattern & 0xFFFFFFFF)
        return
    assert op is not None
    value = access.read_value(ctx, op)
    push_load(ctx, value.expr, value.uses)


def emit_transfer(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if isinstance(op, Register) and op.name == "STW":
        for name in STATUS_NAMES:
            ctx.emit(f"{name} = a1 >> {BIT_OF[name]} & 1", defs=(name,), uses=("a1",))
        return
    assert op is not None
    if ctx.uses_mcr:
        ctx.emit("_w = a1 if not mcra or m.mcr else 0", defs=("_w",), uses=("a1", "mcra"))
        access.write_value(ctx, op, "_w", frozenset({"_w"}))
    else:
        access.write_value(ctx, op, "a1", frozenset({"a1"}))


EMITTERS: dict[str, Emitter] = {"L": emit_load, "LC": emit_load, "T": emit_transfer}

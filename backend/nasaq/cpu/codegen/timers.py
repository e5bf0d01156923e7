"""SP SE SD SS SF, FR, R for timers and CU CD S R FR for counters (run time in
``nasaq.cpu.timers`` / ``nasaq.cpu.counters``). They end the logic chain: OR 0, /FC 0."""

from __future__ import annotations

from nasaq.cpu.codegen import access
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import CounterRef, Instruction, MemoryIndirect, ParamRef, TimerRef

_TIMER_STARTS = ("SP", "SE", "SD", "SS", "SF")


def _number(ctx: Ctx, ins: Instruction) -> tuple[str, frozenset[str]]:
    op = ins.operand
    assert op is not None
    number = access.number_of(ctx, op, "T")
    assert number is not None
    return number, frozenset({number}) if number.startswith("_p") else frozenset()


def _end(ctx: Ctx) -> None:
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_timer(ctx: Ctx, ins: Instruction) -> None:
    number, uses = _number(ctx, ins)
    if ins.op in _TIMER_STARTS:
        call, extra = f"_T.start({ins.op!r}, {number}, rlo, a1)", {"rlo", "a1"}
    elif ins.op == "FR":
        call, extra = f"_T.enable({number}, rlo)", {"rlo"}
    else:
        call, extra = f"_T.reset({number}, rlo)", {"rlo"}
    ctx.emit(ctx.guarded_call([call]), uses=uses | extra, keep=True)
    _end(ctx)


def emit_counter(ctx: Ctx, ins: Instruction) -> None:
    number, uses = _number(ctx, ins)
    method = {"CU": "up", "CD": "down", "S": "set", "R": "reset", "FR": "enable"}[ins.op]
    args = f"{number}, rlo, a1" if ins.op == "S" else f"{number}, rlo"
    extra = {"rlo", "a1"} if ins.op == "S" else {"rlo"}
    ctx.emit(ctx.guarded_call([f"_C.{method}({args})"]), uses=uses | extra, keep=True)
    _end(ctx)


def emit_param_timer_counter(ctx: Ctx, ins: Instruction) -> None:
    """``SD #t`` / ``CU #c`` in an FC: the parameter's declared type says which it is."""
    op = ins.operand
    assert isinstance(op, ParamRef)
    if access.param_type(ctx, op.name) == "COUNTER":
        emit_counter(ctx, ins)
    else:
        emit_timer(ctx, ins)


def emit_fr(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if isinstance(op, CounterRef) or (isinstance(op, MemoryIndirect) and op.target == "C"):
        emit_counter(ctx, ins)
    elif isinstance(op, TimerRef | MemoryIndirect):
        emit_timer(ctx, ins)
    else:
        emit_param_timer_counter(ctx, ins)


EMITTERS: dict[str, Emitter] = {
    **dict.fromkeys(_TIMER_STARTS, emit_timer),
    "FR": emit_fr,
    "CU": emit_counter,
    "CD": emit_counter,
}

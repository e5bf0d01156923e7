"""Bit logic: A AN O ON X XN, O, the nesting stack, = S R, SET CLR NOT SAVE, FP FN.

Status word rules (S7-300 instruction list): a first check (/FC = 0) loads the RLO, later checks
combine with it; ``O`` between AND groups parks the partial result in OR; every check sets
STA to the operand's signal state and /FC to 1; =, S and R end the chain (/FC 0, OR 0,
STA = the RLO written). Where /FC and OR are known at compile time the combination folds away.
"""

from __future__ import annotations

from nasaq.cpu.codegen import access
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Block, CounterRef, Instruction, MemoryIndirect, ParamRef, TimerRef

MAX_NESTING = 7
OPENERS = {"A(": "A", "AN(": "AN", "O(": "O", "ON(": "O N", "X(": "X", "XN(": "X N"}


def analyse_nesting(block: Block) -> tuple[bool, list[int], list[str]]:
    """Static nesting: depth before every instruction and the kind of bracket each ``)`` closes.

    Static mode (locals instead of a run-time stack) needs brackets that no jump enters or
    leaves: no labels or jumps inside brackets, never deeper than 7, no stray ``)``.
    """
    depth = 0
    stack: list[str] = []
    depths: list[int] = []
    kinds: list[str] = []
    static = True
    for ins in block.code:
        depths.append(depth)
        kind = ""
        if depth and (ins.label or ins.op.startswith("J") or ins.op == "LOOP"):
            static = False
        if ins.op in OPENERS:
            stack.append(ins.op)
            depth += 1
            if depth > MAX_NESTING:
                static = False
        elif ins.op == ")":
            if not stack:
                static = False
            else:
                kind = stack.pop()
                depth -= 1
        kinds.append(kind)
    return static, depths, kinds


def _value(ctx: Ctx, ins: Instruction) -> tuple[str, frozenset[str]]:
    op = ins.operand
    assert op is not None
    value = access.read_bit(ctx, op)
    if value.expr.startswith("_") or value.expr.isdigit():
        return value.expr, value.uses
    name = ctx.tmp("v")
    ctx.emit(f"{name} = {value.expr}", defs=(name,), uses=value.uses)
    return name, frozenset({name})


def _neg(v: str) -> str:
    return f"({v} ^ 1)"


def emit_and(ctx: Ctx, ins: Instruction) -> None:
    v, uses = _value(ctx, ins)
    vv = _neg(v) if ins.op == "AN" else v
    fc, orb = ctx.known.get("fc"), ctx.known.get("orb")
    ctx.emit(f"sta = {v}", defs=("sta",), uses=uses)
    if fc == 0:
        ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
        ctx.emit(f"rlo = {vv}", defs=("rlo",), uses=uses)
    elif fc == 1 and orb == 0:
        ctx.emit(f"rlo = rlo & {vv}", defs=("rlo",), uses=uses | {"rlo"})
    elif fc == 1:
        ctx.emit(f"rlo = rlo & {vv} | orb", defs=("rlo",), uses=uses | {"rlo", "orb"})
    else:
        ctx.emit("orb = orb & fc", defs=("orb",), uses=("orb", "fc"))
        ctx.emit(
            f"rlo = (rlo | fc ^ 1) & {vv} | orb",
            defs=("rlo",),
            uses=uses | {"rlo", "fc", "orb"},
        )
    ctx.emit("fc = 1", defs=("fc",), known={"fc": 1})


def emit_or_xor(ctx: Ctx, ins: Instruction) -> None:
    v, uses = _value(ctx, ins)
    vv = _neg(v) if ins.op in ("ON", "XN") else v
    sym = "|" if ins.op in ("O", "ON") else "^"
    fc = ctx.known.get("fc")
    ctx.emit(f"sta = {v}", defs=("sta",), uses=uses)
    if fc == 0:
        ctx.emit(f"rlo = {vv}", defs=("rlo",), uses=uses)
    elif fc == 1:
        ctx.emit(f"rlo = rlo {sym} {vv}", defs=("rlo",), uses=uses | {"rlo"})
    else:
        ctx.emit(f"rlo = rlo & fc {sym} {vv}", defs=("rlo",), uses=uses | {"rlo", "fc"})
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 1", defs=("fc",), known={"fc": 1})


def emit_o(ctx: Ctx, ins: Instruction) -> None:
    if ins.operand is not None:
        emit_or_xor(ctx, ins)
        return
    # "And before Or": park the AND group's result in OR
    fc = ctx.known.get("fc")
    if fc == 0:
        ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
        ctx.emit("sta = 1", defs=("sta",))
        ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})
        return
    ctx.emit("orb = (rlo | orb) & fc", defs=("orb",), uses=("rlo", "orb", "fc"))
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("fc = rlo & fc", defs=("fc",), uses=("rlo", "fc"))


def emit_open(ctx: Ctx, ins: Instruction) -> None:
    kind = ins.op
    if ctx.nest_static:
        depth = ctx.nest_depth[ctx.index] + 1
        if depth > MAX_NESTING:
            ctx.error("SIM514")
            return
        for reg in ("rlo", "orb", "fc"):
            known = ctx.known.get(reg)
            name = f"_n{depth}{reg}"
            if known is not None:
                ctx.emit(f"{name} = {known}", defs=(name,))
            else:
                ctx.emit(f"{name} = {reg}", defs=(name,), uses=(reg,))
    else:
        k = ctx.error_site("SIM514")
        ctx.emit(
            [
                f"if len(NS) >= {MAX_NESTING}:",
                f"    _ERR({k})",
                "else:",
                f"    NS.append(({kind!r}, rlo, orb, fc))",
            ],
            uses=("rlo", "orb", "fc"),
            keep=True,
        )
        ctx.locals_needed.add("NS")
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_close(ctx: Ctx, ins: Instruction) -> None:
    if ctx.nest_static:
        depth = ctx.nest_depth[ctx.index]
        kind = ctx.nest_kinds[ctx.index]
        if depth == 0 or not kind:
            ctx.error("SIM515")
            return
        r, o, f = f"_n{depth}rlo", f"_n{depth}orb", f"_n{depth}fc"
        cur = "(rlo ^ 1)" if kind in ("AN(", "ON(", "XN(") else "rlo"
        if kind in ("A(", "AN("):
            ctx.emit(f"orb = {o} & {f}", defs=("orb",), uses=(o, f))
            ctx.emit(
                f"rlo = ({r} | {f} ^ 1) & {cur} | orb",
                defs=("rlo",),
                uses=(r, f, "rlo", "orb"),
            )
        else:
            sym = "|" if kind in ("O(", "ON(") else "^"
            ctx.emit(f"rlo = {r} & {f} {sym} {cur}", defs=("rlo",), uses=(r, f, "rlo"))
            ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    else:
        k = ctx.error_site("SIM515")
        ctx.locals_needed.add("NS")
        ctx.emit(
            [
                "if NS:",
                "    rlo, orb = _PAREN(NS.pop(), rlo)",
                "else:",
                f"    _ERR({k})",
            ],
            defs=("rlo", "orb"),
            uses=("rlo", "orb"),
            keep=True,
        )
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("fc = 1", defs=("fc",), known={"fc": 1})


def paren_close(entry: tuple[str, int, int, int], rlo: int) -> tuple[int, int]:
    """Run-time ``)`` for blocks whose brackets need the dynamic nesting stack."""
    kind, r, o, f = entry
    cur = rlo ^ 1 if kind in ("AN(", "ON(", "XN(") else rlo
    if kind in ("A(", "AN("):
        orb = o & f
        return ((r | f ^ 1) & cur) | orb, orb
    if kind in ("O(", "ON("):
        return (r & f) | cur, 0
    return (r & f) ^ cur, 0


def mcr_value(ctx: Ctx, value: str) -> str:
    """Under an active MCR area with MCR bit 0, assignments write 0."""
    if not ctx.uses_mcr:
        return value
    return f"({value} if not mcra or m.mcr else 0)"


def emit_assign(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    assert op is not None
    if ctx.uses_mcr:
        ctx.emit("_w = rlo if not mcra or m.mcr else 0", defs=("_w",), uses=("rlo", "mcra"))
        value, uses = "_w", frozenset({"_w"})
    else:
        value, uses = "rlo", frozenset({"rlo"})
    access.write_bit(ctx, op, value, uses)
    ctx.emit(f"sta = {value}", defs=("sta",), uses=uses)
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_set_reset(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if isinstance(op, CounterRef) or (isinstance(op, MemoryIndirect) and op.target == "C"):
        from nasaq.cpu.codegen.timers import emit_counter

        emit_counter(ctx, ins)
        return
    if isinstance(op, TimerRef) or (isinstance(op, MemoryIndirect) and op.target == "T"):
        from nasaq.cpu.codegen.timers import emit_timer

        emit_timer(ctx, ins)
        return
    if isinstance(op, ParamRef) and op.width is None:
        from nasaq.cpu.codegen.timers import emit_param_timer_counter

        emit_param_timer_counter(ctx, ins)
        return
    assert op is not None
    cond = "rlo and (not mcra or m.mcr)" if ctx.uses_mcr else "rlo"
    uses = frozenset({"rlo", "mcra"} if ctx.uses_mcr else {"rlo"})
    access.set_bit(ctx, op, cond, uses, 1 if ins.op == "S" else 0)
    ctx.emit("sta = rlo", defs=("sta",), uses=("rlo",))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_set(ctx: Ctx, ins: Instruction) -> None:
    value = 1 if ins.op == "SET" else 0
    ctx.emit(f"rlo = {value}", defs=("rlo",))
    ctx.emit(f"sta = {value}", defs=("sta",))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_not(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("rlo ^= 1", defs=("rlo",), uses=("rlo",))
    ctx.emit("sta = 1", defs=("sta",))


def emit_save(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit("br = rlo", defs=("br",), uses=("rlo",))


def emit_edge(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    assert op is not None
    memory = access.read_bit(ctx, op)
    fm = ctx.tmp("fm")
    ctx.emit(f"{fm} = {memory.expr}", defs=(fm,), uses=memory.uses)
    access.write_bit(ctx, op, "rlo", frozenset({"rlo"}))
    ctx.emit("sta = rlo", defs=("sta",), uses=("rlo",))
    if ins.op == "FP":
        ctx.emit(f"rlo = rlo & ({fm} ^ 1)", defs=("rlo",), uses=("rlo", fm))
    else:
        ctx.emit(f"rlo = (rlo ^ 1) & {fm}", defs=("rlo",), uses=("rlo", fm))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("fc = 1", defs=("fc",), known={"fc": 1})


def emit_check(ctx: Ctx, ins: Instruction) -> None:
    if ins.op in ("A", "AN"):
        emit_and(ctx, ins)
    else:
        emit_or_xor(ctx, ins)


EMITTERS: dict[str, Emitter] = {
    "A": emit_check,
    "AN": emit_check,
    "O": emit_o,
    "ON": emit_check,
    "X": emit_check,
    "XN": emit_check,
    **dict.fromkeys(OPENERS, emit_open),
    ")": emit_close,
    "=": emit_assign,
    "S": emit_set_reset,
    "R": emit_set_reset,
    "SET": emit_set,
    "CLR": emit_set,
    "NOT": emit_not,
    "SAVE": emit_save,
    "FP": emit_edge,
    "FN": emit_edge,
}

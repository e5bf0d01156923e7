"""Compiles one ir.Block to one Python function, once.

1. Split the code into basic blocks (labels, jumps, block ends).
2. Emit statements per basic block; facts about /FC and OR flow forward between basic blocks
   (iterated to a fixed point), so most logic chains compile without run-time tests.
3. Liveness over the basic-block graph removes statements whose results are never read
   (everything is live at block end and at calls); single-use temporaries are inlined.
4. Lay out the basic blocks as a chain of ``if bb == k`` tests inside ``while`` loops: every
   backward jump's span becomes its own ``while`` loop, so a LOOP body runs in one Python loop.
   Each basic block adds its instruction count to ``n`` once per entry; loop heads check ``n``
   against the watchdog limit.

``instrumented`` is the debugger's second compilation: before every instruction the block calls
``_B(index, L, P, a1, a2, fc, rlo, sta, orb, os, ov, cc0, cc1, br, ar1, ar2, db, di)`` (where
breakpoints and steps hold, so a value changed there is what the instruction reads) and after it
``_H(...)`` with the registers as the instruction left them (every status bit computed, none
folded away), which the block status records. The fast path never pays for either.
"""

from __future__ import annotations

import gc
import re
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from nasaq.cpu.codegen.bit_logic import analyse_nesting
from nasaq.cpu.codegen.calls import SYNC_IN, SYNC_OUT
from nasaq.cpu.codegen.model import ALL, REGISTERS, STATUS, Ctx, ErrorSite, Stmt, Term
from nasaq.cpu.codegen.registry import EMITTERS, TERMINATORS
from nasaq.cpu.profile import Profile
from nasaq.ir import Block, Program

_TEMP = re.compile(r"^(_[a-z]+\d+) = (.+)$")
_TEMP_NAME = re.compile(r"\b_[a-z]+\d+\b")
# Instructions that cannot run without an operand (the IR may still carry one without).
NEEDS_OPERAND = frozenset(
    {"A", "AN", "ON", "X", "XN", "=", "S", "R", "FP", "FN", "L", "LC", "T"}
    | {"SP", "SE", "SD", "SS", "SF", "FR", "CU", "CD"}
)


class EmitterError(Exception):
    """An emitter failed on instruction ``index`` of ``block`` (a bug in the simulator)."""

    def __init__(self, block: Block, index: int) -> None:
        super().__init__(f"{block.kind.value}{block.number} instruction {index}")
        self.block = block
        self.index = index


@dataclass(slots=True)
class Compiled:
    block: Block
    function: Callable[..., None]
    frame_size: int
    param_slots: list[str]
    call_sites: list[Any]
    errors: list[ErrorSite]
    line_map: dict[int, int]  # generated source line -> instruction index
    filename: str
    source: str
    namespace: dict[str, Any]
    param_pointers: bool = False  # the block loads P##param (FC): m.vptrs is built per call


@dataclass(slots=True)
class _BB:
    start: int
    end: int  # exclusive
    stmts: list[Stmt] = field(default_factory=list)
    term: Term = field(default_factory=lambda: Term("fall"))
    succ: list[int] = field(default_factory=list)


def _basic_blocks(block: Block) -> list[_BB]:
    code = block.code
    leaders = {0}
    for i, ins in enumerate(code):
        if ins.label:
            leaders.add(i)
        if ins.op in TERMINATORS:
            leaders.add(i + 1)
    for index in block.labels.values():
        leaders.add(index)
    starts = sorted(k for k in leaders if 0 <= k < len(code))
    if not starts:
        starts = [0]
    ends = [*starts[1:], len(code)]
    return [_BB(s, e) for s, e in zip(starts, ends, strict=True)]


def _emit_bb(ctx: Ctx, bb: _BB, entry: dict[str, int]) -> dict[str, int]:
    ctx.known = dict(entry)
    ctx.stmts = []
    ctx.term = None
    for i in range(bb.start, bb.end):
        ctx.index = i
        ins = ctx.block.code[i]
        emitter = EMITTERS.get(ins.op)
        if emitter is None:
            ctx.error("SIM522", op=ins.op, detail="")
            continue
        if ins.operand is None and ins.op in NEEDS_OPERAND:
            ctx.error("SIM522", op=ins.op, detail="without an operand")
            continue
        if ctx.instrumented:
            _emit_hook(ctx, i, "_B")
        try:
            emitter(ctx, ins)
        except Exception as exc:  # a simulator bug: the CPU reports SIM500 at this instruction
            raise EmitterError(ctx.block, i) from exc
        if ctx.instrumented:
            _emit_hook(ctx, i, "_H")
    bb.stmts = ctx.stmts
    bb.term = ctx.term or Term("fall")
    return ctx.known


HOOK_REGISTERS = ("a1", "a2", *STATUS, "ar1", "ar2", "db", "di")


def _emit_hook(ctx: Ctx, index: int, hook: str) -> None:
    """The debugger's call before (``_B``) or after (``_H``) instruction ``index``: it reads every
    register, so liveness keeps them all computed; registers the compiler knows as constants are
    passed as those."""
    known = ctx.known
    args = ", ".join(str(known[r]) if r in known else r for r in HOOK_REGISTERS)
    uses = [r for r in HOOK_REGISTERS if r not in known]
    line = f"{hook}({index}, L, P, {args})"
    ctx.stmts.append(Stmt([line], frozenset(), frozenset(uses), True, index))


def _successors(bbs: list[_BB], b: int, at: dict[int, int]) -> list[int]:
    """Successor basic blocks; len(bbs) stands for the block end."""
    term = bbs[b].term
    nxt = b + 1
    exit_ = len(bbs)
    if term.kind == "fall":
        return [nxt]
    if term.kind == "jump":
        return [at[term.target]]
    if term.kind == "cond":
        return [at[term.target], nxt]
    if term.kind == "ret":
        return [exit_]
    if term.kind == "cret":
        return [exit_, nxt]
    return [*(at[t] for t in term.targets), at[term.target]]


def _meet(states: list[dict[str, int]]) -> dict[str, int]:
    if not states:
        return {}
    first = states[0]
    return {k: v for k, v in first.items() if all(s.get(k) == v for s in states[1:])}


def compile_block(
    block: Block,
    program: Program,
    profile: Profile,
    bind: dict[str, Any],
    instrumented: bool = False,
) -> Compiled:
    """The Python function of ``block``. Compiling makes many small objects that live until
    the end (statements, lines, states): the cyclic collector's passes would scan them again
    and again, about 40 % of the time for a large block (a 200-step S7-Graph FB), so it is off
    meanwhile, as in the parsers."""
    gc_was_enabled = gc.isenabled()
    gc.disable()
    try:
        return _compile_block(block, program, profile, bind, instrumented)
    finally:
        if gc_was_enabled:
            gc.enable()


def _compile_block(
    block: Block,
    program: Program,
    profile: Profile,
    bind: dict[str, Any],
    instrumented: bool,
) -> Compiled:
    bbs = _basic_blocks(block)
    at = {bb.start: k for k, bb in enumerate(bbs)}
    at[len(block.code)] = len(bbs)
    static, depths, kinds = analyse_nesting(block)
    initial = {"fc": 0, "orb": 0}

    entries: list[dict[str, int] | None] = [None] * len(bbs)
    entries[0] = initial
    ctx = _new_ctx(block, program, profile, instrumented, bind, static, depths, kinds)
    for _ in range(20):
        ctx = _new_ctx(block, program, profile, instrumented, bind, static, depths, kinds)
        exits: list[dict[str, int] | None] = [None] * len(bbs)
        for k, bb in enumerate(bbs):
            exits[k] = _emit_bb(ctx, bb, entries[k] or {})
        for k in range(len(bbs)):
            bbs[k].succ = _successors(bbs, k, at)
        preds: dict[int, list[int]] = {k: [] for k in range(len(bbs))}
        for k, bb in enumerate(bbs):
            for s in bb.succ:
                if s < len(bbs):
                    preds[s].append(k)
        new_entries: list[dict[str, int] | None] = []
        for k in range(len(bbs)):
            states = [exits[p] for p in preds[k] if exits[p] is not None]
            state = _meet([s for s in states if s is not None])
            if k == 0:
                state = _meet([initial, state]) if preds[0] else dict(initial)
            elif not preds[k]:
                state = {}
            new_entries.append(state)
        if new_entries == entries:
            break
        entries = new_entries
    _eliminate_dead(bbs)
    for bb in bbs:
        bb.stmts = _inline_temps(bb)
    return _assemble(block, ctx, bbs, at, bind)


def _new_ctx(
    block: Block,
    program: Program,
    profile: Profile,
    instrumented: bool,
    bind: dict[str, Any],
    static: bool,
    depths: list[int],
    kinds: list[str],
) -> Ctx:
    ctx = Ctx(block, program, profile, instrumented)
    ctx.globals["_TEST_OPS"] = bind.get("_TEST_OPS", False)
    ctx.nest_static = static
    ctx.nest_depth = depths
    ctx.nest_kinds = kinds
    return ctx


def _eliminate_dead(bbs: list[_BB]) -> None:
    live_in: list[frozenset[str]] = [frozenset()] * len(bbs)
    changed = True
    while changed:
        changed = False
        for k in range(len(bbs) - 1, -1, -1):
            live = _live_in(bbs[k], _live_out(bbs, k, live_in), prune=False)
            if live != live_in[k]:
                live_in[k] = live
                changed = True
    for k, bb in enumerate(bbs):
        _live_in(bb, _live_out(bbs, k, live_in), prune=True)


def _live_out(bbs: list[_BB], k: int, live_in: list[frozenset[str]]) -> set[str]:
    out: set[str] = set()
    for s in bbs[k].succ:
        out |= ALL if s >= len(bbs) else live_in[s]
    return out


def _live_in(bb: _BB, live: set[str], prune: bool) -> frozenset[str]:
    live = set(live) | bb.term.uses
    kept: list[Stmt] = []
    for stmt in reversed(bb.stmts):
        if stmt.keep or (stmt.defs & live):
            live -= stmt.defs
            live |= stmt.uses
            kept.append(stmt)
    if prune:
        kept.reverse()
        bb.stmts = kept
    return frozenset(live)


def _inline_temps(bb: _BB) -> list[Stmt]:
    """``_v = expr`` used once, by the very next one-line statement: substitute it.

    Linear in the block's size: where each temporary is named is counted once up front (a merge
    only moves names defined earlier, which are already decided), so a 5,000-line SCL function
    compiles as fast per line as a short one.
    """
    stmts = list(bb.stmts)
    named = [Counter(_TEMP_NAME.findall(" ".join(stmt.lines))) for stmt in stmts]
    after: Counter[str] = Counter()  # the temporaries' occurrences in stmts[k + 1 :]
    for counts in named:
        after.update(counts)
    out: list[Stmt] = []
    for k, stmt in enumerate(stmts):
        after.subtract(named[k])
        match = _TEMP.match(stmt.lines[0]) if len(stmt.lines) == 1 else None
        if match and k + 1 < len(stmts) and len(stmts[k + 1].lines) == 1 and not stmt.keep:
            name, expr = match.groups()
            nxt = stmts[k + 1]
            if (
                named[k + 1][name] == 1
                and after[name] == 1
                and name not in _TEMP_NAME.findall(bb.term.cond)
            ):
                pattern = re.compile(rf"\b{name}\b")
                line = pattern.sub(f"({expr})", nxt.lines[0])  # generated code has no "\\"
                stmts[k + 1] = Stmt(
                    [line],
                    nxt.defs,
                    (nxt.uses - {name}) | stmt.uses,
                    nxt.keep,
                    nxt.index,
                )
                continue
        out.append(stmt)
    return out


# -- layout ----------------------------------------------------------------------------------


@dataclass(slots=True)
class _Region:
    head: int
    tail: int
    children: list[_Region] = field(default_factory=list)


def _regions(bbs: list[_BB]) -> list[_Region]:
    spans: dict[int, int] = {}
    for k, bb in enumerate(bbs):
        for s in bb.succ:
            if s <= k:
                spans[s] = max(spans.get(s, s), k)
    ordered = sorted(spans.items(), key=lambda item: (item[0], -item[1]))
    roots: list[_Region] = []
    stack: list[_Region] = []
    for head, tail in ordered:
        while stack and head > stack[-1].tail:
            stack.pop()
        if stack and tail > stack[-1].tail:
            continue  # crosses its enclosing loop: left to the outer dispatch
        region = _Region(head, tail)
        (stack[-1].children if stack else roots).append(region)
        stack.append(region)
    return roots


class _Writer:
    def __init__(self) -> None:
        self.lines: list[str] = []
        self.line_map: dict[int, int] = {}

    def add(self, indent: int, text: str, index: int | None = None) -> None:
        self.lines.append("    " * indent + text)
        if index is not None:
            self.line_map[len(self.lines)] = index


def _assemble(
    block: Block, ctx: Ctx, bbs: list[_BB], at: dict[int, int], bind: dict[str, Any]
) -> Compiled:
    used: set[str] = set()
    written: set[str] = set()
    for bb in bbs:
        for stmt in bb.stmts:
            if any(line.strip() == SYNC_OUT for line in stmt.lines):
                continue
            used |= (stmt.uses | stmt.defs) & ALL
            written |= stmt.defs & ALL
        used |= bb.term.uses & ALL
    regs = [r for r in REGISTERS if r in used]
    out_regs = [r for r in REGISTERS if r in written]
    n_bbs = len(bbs)
    first_index = {k: bb.start for k, bb in enumerate(bbs)}

    w = _Writer()
    w.add(0, "def _block(m, L, V, P):")
    for r in regs:
        w.add(1, f"{r} = m.{r}")
    w.add(1, "n = m.n")
    w.add(1, "lim = m.lim")
    for name in sorted(ctx.locals_needed - {"NS"}):
        w.add(1, f"{name} = _{name}")
    if "NS" in ctx.locals_needed:
        w.add(1, "NS = []")
    if ctx.uses_mcr:
        w.add(1, "mcra = 0")
    for slot in range(len(ctx.param_slots)):
        w.add(1, f"_P{slot}b, _P{slot}o, _P{slot}t = P[{slot}]")
    w.add(1, "bb = 0")
    w.add(1, "while True:")
    w.add(2, f"if n > lim: _WD({first_index.get(0, 0)})", 0)

    def sync_out(indent: int) -> None:
        for r in out_regs:
            w.add(indent, f"m.{r} = {r}")
        w.add(indent, "m.n = n")

    def sync_in(indent: int) -> None:
        for r in regs:
            w.add(indent, f"{r} = m.{r}")
        w.add(indent, "n = m.n")

    def emit_stmt(indent: int, stmt: Stmt) -> None:
        for line in stmt.lines:
            stripped = line.lstrip(" ")
            extra = (len(line) - len(stripped)) // 4
            if stripped == SYNC_OUT:
                sync_out(indent + extra)
            elif stripped == SYNC_IN:
                sync_in(indent + extra)
            else:
                w.add(indent + extra, stripped, stmt.index)

    def jump(indent: int, src: int, dst: int, index: int) -> None:
        w.add(indent, f"bb = {dst}", index)
        if dst <= src:
            w.add(indent, "continue", index)

    def emit_bb(indent: int, k: int, guard: bool) -> None:
        bb = bbs[k]
        if guard:
            w.add(indent, f"if bb == {k}:")
            indent += 1
        count = bb.end - bb.start
        last = max(bb.end - 1, bb.start)
        if count:
            w.add(indent, f"n += {count}", bb.start)
        for stmt in bb.stmts:
            emit_stmt(indent, stmt)
        term = bb.term
        nxt = k + 1
        if term.kind == "fall":
            w.add(indent, f"bb = {nxt}", last)
        elif term.kind == "jump":
            jump(indent, k, at[term.target], last)
        elif term.kind == "ret":
            w.add(indent, f"bb = {n_bbs}", last)
        elif term.kind == "cret":
            w.add(indent, f"bb = {n_bbs} if {term.cond} else {nxt}", last)
        elif term.kind == "cond":
            dst = at[term.target]
            if dst > k:
                w.add(indent, f"bb = {dst} if {term.cond} else {nxt}", last)
            else:
                w.add(indent, f"if {term.cond}:", last)
                jump(indent + 1, k, dst, last)
                w.add(indent, f"bb = {nxt}", last)
        else:  # jl
            table = [at[t] for t in term.targets]
            default = at[term.target]
            w.add(indent, f"_jl = {term.cond}", last)
            w.add(indent, f"bb = {tuple(table)!r}[_jl] if _jl < {len(table)} else {default}", last)
            if any(t <= k for t in (*table, default)):
                w.add(indent, f"if bb <= {k}: continue", last)

    def emit_range(indent: int, lo: int, hi: int, regions: list[_Region]) -> None:
        k = lo
        by_head = {r.head: r for r in regions}
        while k <= hi:
            region = by_head.get(k)
            if region is not None:
                cond = (
                    f"bb == {k}"
                    if region.head == region.tail
                    else (f"{region.head} <= bb <= {region.tail}")
                )
                w.add(indent, f"while {cond}:")
                w.add(indent + 1, f"if n > lim: _WD({first_index[k]})", first_index[k])
                if region.head == region.tail and not region.children:
                    emit_bb(indent + 1, k, guard=False)
                else:
                    emit_range(indent + 1, region.head, region.tail, region.children)
                k = region.tail + 1
            else:
                emit_bb(indent, k, guard=True)
                k += 1

    if n_bbs:
        emit_range(2, 0, n_bbs - 1, _regions(bbs))
    w.add(2, f"if bb >= {n_bbs}: break")
    sync_out(1)
    source = "\n".join(w.lines) + "\n"
    debug = " debug" if ctx.instrumented else ""
    filename = f"<nasaq {block.kind.value}{block.number}{debug}>"
    namespace: dict[str, Any] = dict(bind)
    namespace.update(ctx.globals)
    code = compile(source, filename, "exec")
    exec(code, namespace)
    return Compiled(
        block=block,
        function=namespace["_block"],
        frame_size=ctx.frame_size,
        param_slots=list(ctx.param_slots),
        call_sites=list(ctx.call_sites),
        errors=list(ctx.errors),
        line_map=w.line_map,
        filename=filename,
        source=source,
        namespace=namespace,
        param_pointers=ctx.param_pointers,
    )

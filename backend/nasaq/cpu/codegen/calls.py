"""CALL UC CC, BE BEU BEC, OPN CDB: block instructions.

A call is one statement that writes the caller's registers back to the machine, lets the run
time (``nasaq.cpu.calls``) set up frame, parameters and instance DB, runs the callee and reloads
the registers. Afterwards, as after any CALL on an S7: OS 0, OR 0, STA 1, /FC 0 (CC also RLO 1).
BE/BEU/BEC end the block with the same status bits.
"""

from __future__ import annotations

from nasaq.cpu.calls import ELEMENTARY_BITS, PARAM_SECTIONS, CallSite, passed_as_db_pointer
from nasaq.cpu.codegen import access
from nasaq.cpu.codegen.model import ALL, Ctx, Emitter, Term
from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    Constant,
    Direct,
    Instruction,
    MemoryIndirect,
    ParamRef,
    RegisterIndirect,
)

SYNC_OUT = "#SYNC_OUT"
SYNC_IN = "#SYNC_IN"


def _after_call(ctx: Ctx) -> None:
    ctx.emit("os = 0", defs=("os",))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def _site(ctx: Ctx, site: CallSite) -> int:
    ctx.call_sites.append(site)
    return len(ctx.call_sites) - 1


def _call_lines(ctx: Ctx, k: int, target: str = "") -> list[str]:
    arg = f", {target}" if target else ""
    return [SYNC_OUT, f"_CALL({k}, L, V, P{arg})", SYNC_IN]


def emit_call(ctx: Ctx, ins: Instruction) -> None:
    info = ins.call
    if info is None:
        op = ins.operand
        if isinstance(op, BlockRef):
            emit_uc(ctx, ins)
            return
        ctx.error("SIM522", op="CALL", detail="without a block")
        return
    caller_slots: dict[str, int] = {}
    for arg in info.args:
        if isinstance(arg.value, ParamRef):
            caller_slots[arg.value.name] = access.param_slot(ctx, arg.value)
    site = CallSite(
        kind=info.block.kind,
        number=info.block.number,
        instance=info.instance,
        args=info.args,
        index=ctx.index,
        caller_slots=caller_slots,
    )
    _v_area(ctx, site, info.block, info.args)
    k = _site(ctx, site)
    ctx.emit(_call_lines(ctx, k), defs=ALL, uses=ALL | {"mcra"}, keep=True)
    _after_call(ctx)


def _v_area(ctx: Ctx, site: CallSite, callee: BlockRef, args: tuple[CallArg, ...]) -> None:
    """Reserve what an FC call keeps in the caller's local data (the callee's V area), as STEP 7
    does: a 6-byte DB pointer per ARRAY, STRUCT, UDT, STRING, DATE_AND_TIME or POINTER parameter,
    a 10-byte ANY per ANY parameter, a copy of every constant actual, and a copy of a DB element
    passed to an elementary parameter whose address the FC takes (``L P##param``)."""
    if callee.kind is not BlockKind.FC:
        return
    block = ctx.program.blocks.get((BlockKind.FC, callee.number))
    if block is None:
        return
    formals = {var.name: var for var in block.interface if var.section in PARAM_SECTIONS}
    # Every call uses the same area after the block's own local data, as STEP 7 does.
    cursor = _v_base(ctx)

    def take(size: int) -> int:
        nonlocal cursor
        offset = cursor
        cursor += size + (size & 1)
        return offset

    pointed = {
        ins.operand.text[3:].strip().strip('"')
        for ins in block.code
        if isinstance(ins.operand, Constant) and ins.operand.text.startswith("P##")
    }
    for arg in args:
        formal = formals.get(arg.name)
        if formal is None:
            continue
        type_ = formal.type.strip().upper()
        size = max(2, (formal.size_bits + 7) // 8)
        if passed_as_db_pointer(formal):
            site.vslots[arg.name] = take(6)
            if isinstance(arg.value, ParamRef) and type_ != "POINTER":
                # The caller's own parameter passed on: if it lies in the caller's caller's
                # local data, no DB pointer reaches it from the callee (nasaq.cpu.calls).
                site.vforward[arg.name] = take(size)
        elif type_ == "ANY":
            site.vslots[arg.name] = take(10)
        if isinstance(arg.value, Constant) and type_ not in ("POINTER", "ANY"):
            site.vconsts[arg.name] = take(size)
        elif arg.name in pointed and _in_a_db(arg.value) and type_ in ELEMENTARY_BITS:
            site.vcopies[arg.name] = take(size)
    ctx.cover(cursor)


def _v_base(ctx: Ctx) -> int:
    """Where the V area of the block's calls starts: after the declared temporaries, the 20 bytes
    of OB start information and every L address the block uses directly (even)."""
    if ctx.v_base is None:
        end = max(ctx.block.temp_bytes, 20 if ctx.block.kind is BlockKind.OB else 0)
        for ins in ctx.block.code:
            for operand in (
                ins.operand,
                *(arg.value for arg in (ins.call.args if ins.call else ())),
            ):
                if isinstance(operand, Direct) and operand.area is Area.L:
                    end = max(end, operand.byte + max(1, int(operand.width) // 8))
        ctx.v_base = end + (end & 1)
    return ctx.v_base


def _in_a_db(operand: object) -> bool:
    return isinstance(operand, Direct | RegisterIndirect) and operand.area in (Area.DB, Area.DI)


def emit_uc(ctx: Ctx, ins: Instruction) -> None:
    """UC/CC FC n (or FB n, with the DI register as it is): no parameters."""
    op = ins.operand
    target = ""
    if isinstance(op, BlockRef):
        kind, number = op.kind, op.number
    elif isinstance(op, MemoryIndirect) and op.target in ("FC", "FB"):
        kind = BlockKind(op.target)
        target = access.number_of(ctx, op, op.target) or "0"
        number = 0
    elif isinstance(op, ParamRef):
        kind = BlockKind.FB if access.param_type(ctx, op.name) == "BLOCK_FB" else BlockKind.FC
        target = f"_P{access.param_slot(ctx, op)}o"
        number = 0
    else:
        ctx.error("SIM522", op=ins.op, detail="with this operand")
        return
    site = CallSite(kind=kind, number=number, instance=None, args=(), index=ctx.index, raw=True)
    k = _site(ctx, site)
    lines = _call_lines(ctx, k, target)
    uses = ALL | ({target} if target.startswith("_p") else set())
    if ins.op == "CC":
        j = ctx.tmp("j")
        ctx.emit(f"{j} = rlo", defs=(j,), uses=("rlo",))
        ctx.emit(
            [f"if {j}:", *("    " + line for line in lines)], defs=ALL, uses=uses | {j}, keep=True
        )
        _after_call(ctx)
        ctx.emit("rlo = 1", defs=("rlo",))
        return
    ctx.emit(lines, defs=ALL, uses=uses, keep=True)
    _after_call(ctx)


def _block_end_status(ctx: Ctx) -> None:
    _after_call(ctx)


def emit_be(ctx: Ctx, ins: Instruction) -> None:
    _block_end_status(ctx)
    ctx.set_term(Term("ret"))


def emit_bec(ctx: Ctx, ins: Instruction) -> None:
    j = ctx.tmp("j")
    ctx.emit(f"{j} = rlo", defs=(j,), uses=("rlo",))
    ctx.emit(f"if {j}: os = 0", defs=("os",), uses=("os", j))
    ctx.emit("rlo = 1", defs=("rlo",))
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})
    ctx.set_term(Term("cret", cond=j, uses=frozenset({j})))


def emit_opn(ctx: Ctx, ins: Instruction) -> None:
    op = ins.operand
    if isinstance(op, BlockRef) and op.kind in (BlockKind.DB, BlockKind.DI):
        access.open_db(ctx, op.number, instance=op.kind is BlockKind.DI)
        return
    if isinstance(op, MemoryIndirect) and op.target in ("DB", "DI"):
        number = access.number_of(ctx, op, op.target)
        reg, num = ("di", "dino") if op.target == "DI" else ("db", "dbno")
        ctx.emit(
            ctx.guarded_call([f"{reg}, {num} = _OPEN({number})"]),
            defs=(reg, num),
            uses=(reg, num, number or ""),
            keep=True,
        )
        return
    if isinstance(op, ParamRef):
        slot = access.param_slot(ctx, op)
        ctx.emit(
            ctx.guarded_call([f"db, dbno = _OPEN(_P{slot}o)"]),
            defs=("db", "dbno"),
            uses=("db", "dbno"),
            keep=True,
        )
        return
    ctx.error("SIM522", op="OPN", detail="with this operand")


def emit_cdb(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(
        "db, di, dbno, dino = di, db, dino, dbno",
        defs=("db", "di", "dbno", "dino"),
        uses=("db", "di", "dbno", "dino"),
    )


def emit_nop(ctx: Ctx, ins: Instruction) -> None:
    return


EMITTERS: dict[str, Emitter] = {
    "CALL": emit_call,
    "UC": emit_uc,
    "CC": emit_uc,
    "BE": emit_be,
    "BEU": emit_be,
    "BEC": emit_bec,
    "OPN": emit_opn,
    "CDB": emit_cdb,
    "NOP": emit_nop,
    "BLD": emit_nop,
}

"""Code for reading and writing operands: direct, indirect, parameters, timers, counters.

Fixed-size areas (I Q M PI PQ and the block's own frame) are range-checked at compile time.
Data blocks and computed addresses are accessed inside ``try``/``except IndexError`` (free in
Python 3.11 while nothing goes wrong), so a bad address becomes an area length error at exactly
that instruction and execution can continue after OB121, as on a real CPU. Writes store the
highest byte first, so a failing write changes nothing.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.cpu.codegen.model import Ctx
from nasaq.cpu.memory import address_text
from nasaq.cpu.pointers import AREA_CODES
from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    Constant,
    CounterRef,
    Direct,
    MemoryIndirect,
    Operand,
    ParamRef,
    Register,
    RegisterIndirect,
    StatusCondition,
    TimerRef,
    Width,
)

_FIXED = {Area.I: "I", Area.Q: "Q", Area.M: "M", Area.PI: "PI", Area.PQ: "PQ"}
# A block that computes L addresses (L [LD 0], [AR1, ...]) gets at least this much local data.
COMPUTED_L_BYTES = 256

STATUS_CONDITIONS: dict[StatusCondition, tuple[str, frozenset[str]]] = {
    StatusCondition.EQ0: ("(cc1 | cc0) ^ 1", frozenset({"cc0", "cc1"})),
    StatusCondition.NE0: ("cc1 ^ cc0", frozenset({"cc0", "cc1"})),
    StatusCondition.GT0: ("cc1 & (cc0 ^ 1)", frozenset({"cc0", "cc1"})),
    StatusCondition.LT0: ("cc0 & (cc1 ^ 1)", frozenset({"cc0", "cc1"})),
    StatusCondition.GE0: ("cc0 ^ 1", frozenset({"cc0"})),
    StatusCondition.LE0: ("cc1 ^ 1", frozenset({"cc1"})),
    StatusCondition.OV: ("ov", frozenset({"ov"})),
    StatusCondition.OS: ("os", frozenset({"os"})),
    StatusCondition.BR: ("br", frozenset({"br"})),
    StatusCondition.UO: ("cc1 & cc0", frozenset({"cc0", "cc1"})),
}


@dataclass(slots=True)
class Loc:
    """A resolved memory location: ``buf[byte]`` (bit ``bit``), as source expressions."""

    buf: str
    byte: str  # an int literal or a local name
    bit: str
    width: int
    uses: frozenset[str]
    guarded: bool  # may raise IndexError
    text: str | None  # static address text, None when computed at run time
    addr: str = ""  # local holding the bit address when computed at run time
    area: Area | None = None
    periph: bool = False


def _plus(byte: str, k: int) -> str:
    if k == 0:
        return byte
    return str(int(byte) + k) if byte.isdigit() else f"{byte} + {k}"


def read_expr(loc: Loc) -> str:
    b, buf = loc.byte, loc.buf
    if loc.width == 1:
        if loc.bit == "0":
            return f"{buf}[{b}] & 1"
        return f"{buf}[{b}] >> {loc.bit} & 1"
    if loc.width == 8:
        return f"{buf}[{b}]"
    if loc.width == 16:
        return f"{buf}[{b}] << 8 | {buf}[{_plus(b, 1)}]"
    return (
        f"{buf}[{b}] << 24 | {buf}[{_plus(b, 1)}] << 16 | "
        f"{buf}[{_plus(b, 2)}] << 8 | {buf}[{_plus(b, 3)}]"
    )


def write_lines(loc: Loc, value: str) -> list[str]:
    """Store ``value`` (a local or literal) at ``loc``; highest address first."""
    b, buf = loc.byte, loc.buf
    if loc.width == 1:
        if loc.bit.isdigit():
            mask = 1 << int(loc.bit)
            return [f"{buf}[{b}] = {buf}[{b}] | {mask} if {value} else {buf}[{b}] & {255 ^ mask}"]
        return [
            f"{buf}[{b}] = {buf}[{b}] | (1 << {loc.bit}) if {value} "
            f"else {buf}[{b}] & ~(1 << {loc.bit}) & 255"
        ]
    if loc.width == 8:
        return [f"{buf}[{b}] = {value} & 255"]
    if loc.width == 16:
        return [f"{buf}[{_plus(b, 1)}] = {value} & 255", f"{buf}[{b}] = {value} >> 8 & 255"]
    return [
        f"{buf}[{_plus(b, 3)}] = {value} & 255",
        f"{buf}[{_plus(b, 2)}] = {value} >> 8 & 255",
        f"{buf}[{_plus(b, 1)}] = {value} >> 16 & 255",
        f"{buf}[{b}] = {value} >> 24 & 255",
    ]


def open_db(ctx: Ctx, number: int, instance: bool = False) -> None:
    """``OPN DB n`` / the implicit open of ``DB5.DBW 2``: DB register := DB n."""
    reg, num = ("di", "dino") if instance else ("db", "dbno")
    if not instance and ctx.known.get("dbno") == number:
        return
    dbs = ctx.program.blocks
    if number == 0:
        ctx.emit(
            f"{reg} = _EMPTY; {num} = 0", defs=(reg, num), known={num: 0} if not instance else None
        )
        return
    block = dbs.get((BlockKind.DB, number))
    if block is None:
        ctx.error("SIM505", number=number)
        return
    name = f"_D{number}"  # every loaded DB is bound under this name
    known = {num: number} if not instance else None
    ctx.emit(f"{reg} = {name}; {num} = {number}", defs=(reg, num), known=known)


def _direct_loc(ctx: Ctx, op: Direct, width: int, write: bool) -> Loc | None:
    byte, bit = op.byte, op.bit
    size = 1 if width == 1 else width // 8
    text = address_text(op.area, width, byte, bit, op.db)
    area = op.area
    if area in _FIXED:
        buf = _FIXED[area]
        periph = area in (Area.PI, Area.PQ)
        limit = (
            ctx.profile.peripheral_bytes
            if periph
            else (ctx.profile.marker_bytes if area is Area.M else ctx.profile.process_image_bytes)
        )
        if byte < 0 or byte + size > limit:
            if periph:
                ctx.error("SIM519" if write else "SIM518", address=text)
            else:
                ctx.error("SIM504" if write else "SIM503", address=text)
            return None
        ctx.locals_needed.add(buf)
        return Loc(
            buf, str(byte), str(bit), width, frozenset(), False, text, area=area, periph=periph
        )
    if area is Area.L:
        ctx.cover(byte + size)
        return Loc("L", str(byte), str(bit), width, frozenset(), False, text, area=area)
    if area is Area.V:
        return Loc("V", str(byte), str(bit), width, frozenset(), True, text, area=area)
    if area is Area.DB:
        if op.db is not None:
            open_db(ctx, op.db)
        return Loc("db", str(byte), str(bit), width, frozenset({"db"}), True, text, area=area)
    if area is Area.DI:
        return Loc("di", str(byte), str(bit), width, frozenset({"di"}), True, text, area=area)
    raise AssertionError(area)


def _area_buf(area: Area) -> tuple[str, frozenset[str]]:
    if area in _FIXED:
        return _FIXED[area], frozenset()
    if area is Area.DB:
        return "db", frozenset({"db"})
    if area is Area.DI:
        return "di", frozenset({"di"})
    return ("L" if area is Area.L else "V"), frozenset()


def _computed_loc(ctx: Ctx, area: Area | None, addr: str, width: int, write: bool) -> Loc:
    """Location at bit address ``addr`` (a local); ``area`` None means area-crossing."""
    b = ctx.tmp("b")
    if area is None or area is Area.L:
        ctx.cover(COMPUTED_L_BYTES)
    if area is None:
        # the area comes from the pointer's bits 24-26: pick the buffer at run time
        buf = ctx.tmp("buf")
        periph_name = "PQ" if write else "PI"
        ctx.emit(
            f"{buf} = ({periph_name}, I, Q, M, db, di, L, V)[{addr} >> 24 & 7]; "
            f"{b} = ({addr} & 524287) >> 3",
            defs=(buf, b),
            uses=(addr, "db", "di"),
        )
        ctx.locals_needed.update((periph_name, "I", "Q", "M"))
        bit = ctx.tmp("bit")
        ctx.emit(f"{bit} = {addr} & 7", defs=(bit,), uses=(addr,))
        return Loc(buf, b, bit, width, frozenset({buf, b, bit}), True, None, addr, None)
    buf, buf_uses = _area_buf(area)
    if area in _FIXED:
        ctx.locals_needed.add(buf)
    ctx.emit(f"{b} = {addr} >> 3", defs=(b,), uses=(addr,))
    bit = "0"
    loc_uses = buf_uses | {b}
    if width == 1:
        bit = ctx.tmp("bit")
        ctx.emit(f"{bit} = {addr} & 7", defs=(bit,), uses=(addr,))
        loc_uses = loc_uses | {bit}
    periph = area in (Area.PI, Area.PQ)
    return Loc(buf, b, bit, width, loc_uses, True, None, addr, area, periph)


def _pointer_value(ctx: Ctx, pointer: Direct | RegisterIndirect, width: int) -> str:
    """Read the memory-indirect pointer (DWORD area pointer, or WORD number) into a local."""
    value = read_value(ctx, pointer, width)
    name = ctx.tmp("p")
    ctx.emit(f"{name} = {value.expr}", defs=(name,), uses=value.uses)
    return name


def _alignment_check(ctx: Ctx, addr: str, width: int, area: Area | None, write: bool) -> None:
    if width == 1:
        return
    k = ctx.error_site("SIM521" if write else "SIM520", dynamic_area=_prefix(area), width=width)
    ctx.emit(f"if {addr} & 7: _ERR({k}, {addr})", uses=(addr,), keep=True)


def _prefix(area: Area | None) -> str:
    return area.value if area is not None else "*"


def resolve(ctx: Ctx, op: Operand, width: int, write: bool = False) -> Loc | None:
    """The location of a memory operand, emitting any address arithmetic it needs."""
    if isinstance(op, Direct):
        return _direct_loc(ctx, op, width, write)
    if isinstance(op, RegisterIndirect):
        ar = f"ar{op.register}"
        addr = ctx.tmp("a")
        if op.area is None:
            # area-crossing: keep the area bits for _computed_loc, add the offset to the address
            ctx.emit(
                f"{addr} = ({ar} & 0x07000000) | (({ar} & 524287) + {op.offset_bits})",
                defs=(addr,),
                uses=(ar,),
            )
        else:
            ctx.emit(f"{addr} = ({ar} & 524287) + {op.offset_bits}", defs=(addr,), uses=(ar,))
        return _computed_loc(ctx, op.area, addr, width, write)
    if isinstance(op, MemoryIndirect):
        ptr = _pointer_value(ctx, op.pointer, 32)
        addr = ctx.tmp("a")
        ctx.emit(f"{addr} = {ptr} & 524287", defs=(addr,), uses=(ptr,))
        area = op.area if op.area is not None else Area.M
        _alignment_check(ctx, addr, width, area, write)
        return _computed_loc(ctx, area, addr, width, write)
    if isinstance(op, ParamRef):
        slot = param_slot(ctx, op)
        b, o, t = f"_P{slot}b", f"_P{slot}o", f"_P{slot}t"
        offset = op.bit_offset
        if offset:
            byte = ctx.tmp("b")
            ctx.emit(f"{byte} = {o} + ({t} + {offset}) // 8", defs=(byte,))
            bit = ctx.tmp("bit")
            ctx.emit(f"{bit} = ({t} + {offset}) % 8", defs=(bit,))
            return Loc(b, byte, bit, width, frozenset({byte, bit}), True, None)
        return Loc(b, o, t, width, frozenset(), True, None)
    return None


def param_slot(ctx: Ctx, op: ParamRef) -> int:
    slot = ctx.params.get(op.name)
    if slot is None:
        slot = len(ctx.param_slots)
        ctx.params[op.name] = slot
        ctx.param_slots.append(op.name)
    return slot


@dataclass(slots=True)
class Value:
    expr: str
    uses: frozenset[str]


def _guarded_read(ctx: Ctx, loc: Loc, write: bool = False) -> Value:
    expr = read_expr(loc)
    if not loc.guarded:
        return Value(f"({expr})", loc.uses)
    name = ctx.tmp("v")
    k = _site(ctx, loc, write=False)
    addr = f", {loc.addr}" if loc.addr else ""
    ctx.emit(
        ctx.guarded([f"{name} = {expr}"], [f"{name} = _ERR({k}{addr})"]),
        defs=(name,),
        uses=loc.uses | ({loc.addr} if loc.addr else set()),
        keep=True,
    )
    return Value(name, frozenset({name}))


def _site(ctx: Ctx, loc: Loc, write: bool) -> int:
    code = ("SIM519" if write else "SIM518") if loc.periph else "SIM504" if write else "SIM503"
    if loc.text is not None:
        return ctx.error_site(code, address=loc.text)
    if loc.addr:
        return ctx.error_site(code, dynamic_area=_prefix(loc.area), width=loc.width)
    return ctx.error_site(code, address=f"parameter ({loc.width} bits)")


def read_bit(ctx: Ctx, op: Operand) -> Value:
    """A 0/1 expression for the bit operand of A/O/X/FP..., timers, counters, conditions."""
    if isinstance(op, StatusCondition):
        expr, uses = STATUS_CONDITIONS[op]
        return Value(f"({expr})", uses)
    if isinstance(op, TimerRef | CounterRef):
        obj = "_T" if isinstance(op, TimerRef) else "_C"
        name = ctx.tmp("v")
        ctx.emit(
            ctx.guarded_call([f"{name} = {obj}.status({op.number})"], f"{name} = 0"),
            defs=(name,),
            keep=True,
        )
        return Value(name, frozenset({name}))
    if isinstance(op, MemoryIndirect) and op.target in ("T", "C"):
        number = _pointer_value(ctx, op.pointer, 16)
        obj = "_T" if op.target == "T" else "_C"
        name = ctx.tmp("v")
        ctx.emit(
            ctx.guarded_call([f"{name} = {obj}.status({number})"], f"{name} = 0"),
            defs=(name,),
            uses=(number,),
            keep=True,
        )
        return Value(name, frozenset({name}))
    if isinstance(op, Register):
        from nasaq.cpu.codegen.test_ops import register_value

        return register_value(ctx, op)
    if isinstance(op, Constant):
        return Value(str(op.pattern & 1), frozenset())
    if isinstance(op, ParamRef) and param_type(ctx, op.name) in ("TIMER", "COUNTER"):
        obj = "_T" if param_type(ctx, op.name) == "TIMER" else "_C"
        name = ctx.tmp("v")
        number = f"_P{param_slot(ctx, op)}o"
        ctx.emit(
            ctx.guarded_call([f"{name} = {obj}.status({number})"], f"{name} = 0"),
            defs=(name,),
            keep=True,
        )
        return Value(name, frozenset({name}))
    loc = resolve(ctx, op, 1)
    if loc is None:
        return Value("0", frozenset())
    return _guarded_read(ctx, loc)


def read_value(ctx: Ctx, op: Operand, width: int | None = None) -> Value:
    """The unsigned value of a byte/word/dword operand (or constant, register, T/C)."""
    if isinstance(op, Constant):
        return Value(str(op.pattern & 0xFFFFFFFF), frozenset())
    if isinstance(op, Register):
        from nasaq.cpu.codegen.test_ops import register_value

        return register_value(ctx, op)
    w: int
    if isinstance(op, Direct | RegisterIndirect):
        w = op.width
    elif isinstance(op, MemoryIndirect):
        w = op.width or width or 16
    elif isinstance(op, ParamRef):
        w = op.width or width or 32
    else:
        ctx.error("SIM522", op=ctx.ins.op, detail=f"with {type(op).__name__} {op}")
        return Value("0", frozenset())
    loc = resolve(ctx, op, int(w))
    if loc is None:
        return Value("0", frozenset())
    return _guarded_read(ctx, loc)


def write_value(ctx: Ctx, op: Operand, value: str, uses: frozenset[str], width: int = 0) -> None:
    """Store ``value`` (a local or literal, already masked or not) into a memory operand."""
    if isinstance(op, Direct | RegisterIndirect):
        w = int(op.width)
    elif isinstance(op, MemoryIndirect):
        w = int(op.width or width or 16)
    elif isinstance(op, ParamRef):
        w = int(op.width or width or 32)
    else:
        ctx.error("SIM522", op=ctx.ins.op, detail=f"to {type(op).__name__}")
        return
    loc = resolve(ctx, op, w, write=True)
    if loc is None:
        return
    _store(ctx, loc, value, uses)


def _store(ctx: Ctx, loc: Loc, value: str, uses: frozenset[str]) -> None:
    lines = write_lines(loc, value)
    if (
        loc.area is Area.PQ
        and ctx.profile.pq_updates_piq
        and loc.text is not None
        and int(loc.byte) + max(1, loc.width // 8) <= ctx.profile.process_image_bytes
    ):
        ctx.locals_needed.add("Q")
        lines += write_lines(
            Loc("Q", loc.byte, loc.bit, loc.width, frozenset(), False, None), value
        )
    all_uses = uses | loc.uses | ({loc.addr} if loc.addr else set())
    if loc.guarded:
        k = _site(ctx, loc, write=True)
        addr = f", {loc.addr}" if loc.addr else ""
        lines = ctx.guarded(lines, [f"_ERR({k}{addr})"])
    ctx.emit(lines, uses=all_uses, keep=True)


def write_bit(ctx: Ctx, op: Operand, value: str, uses: frozenset[str]) -> None:
    loc = resolve(ctx, op, 1, write=True)
    if loc is None:
        return
    _store(ctx, loc, value, uses)


def set_bit(ctx: Ctx, op: Operand, cond: str, uses: frozenset[str], bit_value: int) -> None:
    """``S``/``R``: write ``bit_value`` only when ``cond`` holds."""
    loc = resolve(ctx, op, 1, write=True)
    if loc is None:
        return
    b, buf = loc.byte, loc.buf
    if loc.bit.isdigit():
        mask = 1 << int(loc.bit)
        line = f"{buf}[{b}] |= {mask}" if bit_value else f"{buf}[{b}] &= {255 ^ mask}"
    else:
        line = (
            f"{buf}[{b}] |= 1 << {loc.bit}"
            if bit_value
            else f"{buf}[{b}] &= ~(1 << {loc.bit}) & 255"
        )
    lines = [f"if {cond}:", "    " + line]
    all_uses = uses | loc.uses | ({loc.addr} if loc.addr else set())
    if loc.guarded:
        k = _site(ctx, loc, write=True)
        addr = f", {loc.addr}" if loc.addr else ""
        lines = ctx.guarded(lines, [f"_ERR({k}{addr})"])
    ctx.emit(lines, uses=all_uses, keep=True)


def number_of(ctx: Ctx, op: Operand, kind: str) -> str | None:
    """Timer/counter/DB/block number of ``T 5``, ``T [MW 4]``, ``#timer_param``."""
    if isinstance(op, TimerRef | CounterRef):
        return str(op.number)
    if isinstance(op, BlockRef):
        return str(op.number)
    if isinstance(op, MemoryIndirect):
        return _pointer_value(ctx, op.pointer, 16)
    if isinstance(op, ParamRef):
        slot = param_slot(ctx, op)
        return f"_P{slot}o"
    return None


def param_type(ctx: Ctx, name: str) -> str:
    """Declared type of an FC parameter (``TIMER``, ``INT`` ...), upper case; "" if unknown."""
    for var in ctx.block.interface:
        if var.name == name:
            return var.type.strip().upper()
    return ""


def area_code(area: Area) -> int:
    return AREA_CODES[area]


def width_of(op: Operand) -> int | None:
    if isinstance(op, Direct | RegisterIndirect):
        return int(op.width)
    if isinstance(op, MemoryIndirect | ParamRef):
        return int(op.width) if op.width is not None else None
    return None


BIT = Width.BIT

"""Block calls at run time: frames, FC parameters by reference, FB instance data, SFCs, SFBs.

FC parameters are references ``(buffer, byte, bit)`` resolved when the call executes, so the FC
reads and writes the actual operand (constants get a fresh scratch copy per call). Timer,
counter and block parameters are ``(None, number, 0)``. An FB call opens the instance DB as DI,
sets AR2 to P#DBX 0.0 (multi-instance: AR2 plus the instance offset), copies IN and IN_OUT into
the instance before and OUT and IN_OUT out of it after the call, as STEP 7's CALL macro does; a
structured IN_OUT (STRING, ARRAY, STRUCT, UDT, DT) is a DB pointer to the actual instead. A
STRING input or output is copied as an assignment copies it: the characters that fit and their
number, never the target's maximum length.
As with the block stack of a real CPU, the DB and DI registers are restored when the callee
returns, except that ``CALL FB n, DB m`` leaves them as STEP 7's macro does (DB = DB m, DI as
before; the callee starts with DB = the caller's DI; a multi-instance call too, after which both
registers hold the caller's DI). AR2 is restored after FB calls and after
every CALL made from an FB (STEP 7's CALL macro keeps the caller's instance base).
FC parameters of ARRAY, STRUCT, UDT, STRING, DATE_AND_TIME or POINTER type also get a 6-byte DB
pointer in the caller's local data (the callee's V area), which ``L P##param`` points to.
An FC that passes such a parameter of its own on to another FC passes the pointer on, as STEP 7
does; when it points into the local data of the FC's caller (a constant or a temporary there),
which no area pointer of the callee reaches, the data is copied into the FC's local data for the
call and back after it, so the callee reads and writes what the FC was given.
The IEC counters and timers (SFB 0-5, ``nasaq.cpu.iec_blocks``) are FBs whose body is Python:
their calls go through the same instance and parameter handling; so are the IEC library FCs
(CONCAT, I_STRNG, AD_DT_TM ..., ``nasaq.cpu.iec_library``, loaded as FCs of the program).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from nasaq.cpu import iec_blocks, tia_comm, tia_control
from nasaq.cpu.clock import Clock
from nasaq.cpu.errors import CpuError, CpuStopError, location
from nasaq.cpu.memory import read_bytes, write_bytes
from nasaq.cpu.pointers import ANY_TYPES, area_pointer
from nasaq.ir import (
    Area,
    Block,
    BlockKind,
    BlockRef,
    CallArg,
    Constant,
    ConstType,
    CounterRef,
    Direct,
    MemoryIndirect,
    MultiInstance,
    Operand,
    ParamRef,
    RegisterIndirect,
    TimerRef,
    Variable,
)
from nasaq.ir.types import ACCU_TYPES, NUMBER_TYPES, TYPE_ALIASES
from nasaq.ir.types import ELEMENTARY_BITS as ELEMENTARY_BITS_ALL

if TYPE_CHECKING:
    from nasaq.cpu.codegen.compiler import Compiled
    from nasaq.cpu.machine import Machine
    from nasaq.cpu.memory import Memory
    from nasaq.cpu.profile import Profile

Ref = tuple[Any, int, int]  # (bytearray | None, byte or number, bit)

# Elementary parameters that fit an accumulator, under every name a declaration may use.
ELEMENTARY_BITS: dict[str, int] = {name: ELEMENTARY_BITS_ALL[name] for name in ACCU_TYPES} | {
    alias: ELEMENTARY_BITS_ALL[name] for alias, name in TYPE_ALIASES.items() if name in ACCU_TYPES
}
PARAM_SECTIONS = ("IN", "OUT", "IN_OUT", "RETURN")
_GLOBAL_AREAS = frozenset({Area.I, Area.Q, Area.M, Area.PI, Area.PQ})


@dataclass(slots=True)
class CallSite:
    kind: BlockKind
    number: int
    instance: BlockRef | MultiInstance | None
    args: tuple[CallArg, ...]
    index: int
    caller_slots: dict[str, int] = field(default_factory=dict)
    raw: bool = False  # UC/CC: no parameters, no instance handling
    plan: list[Any] | None = None  # FC parameter plan, built at the first call
    plan_for: Any = None
    vslots: dict[str, int] = field(default_factory=dict)  # DB pointers in the caller's frame
    vconsts: dict[str, int] = field(default_factory=dict)  # constants copied into that frame
    vcopies: dict[str, int] = field(default_factory=dict)  # DB elements copied in and back
    vforward: dict[str, int] = field(default_factory=dict)  # passed-on parameters, when copied


_DB_POINTER = re.compile(r"\s*P#DB\s*(\d+)\s*\.", re.IGNORECASE)
_ANY_TEXT = re.compile(
    r"\s*P#(?:DB\s*(?P<db>\d+)\s*\.)?\s*[A-Z]*\s*\d+\.\d+\s+(?P<type>\w+)\s+(?P<count>\d+)",
    re.IGNORECASE,
)
_ANY_OF_WIDTH = {
    1: ANY_TYPES["BOOL"],
    8: ANY_TYPES["BYTE"],
    16: ANY_TYPES["WORD"],
    32: ANY_TYPES["DWORD"],
}


def constant_bytes(constant: Constant, size: int) -> bytes:
    """The bytes a constant stands for as an actual parameter of ``size`` bytes: the 8 BCD bytes
    of a DT; a STRING's maximum and current length, then its characters (cut to the maximum)
    and zeros up to the size; any other constant's pattern, right-aligned."""
    if constant.type is ConstType.DATE_AND_TIME:
        return (constant.pattern & (1 << 64) - 1).to_bytes(8, "big")
    if constant.type is not ConstType.STRING:
        width = max(1, min(size, 4))
        return (constant.pattern & (1 << 8 * width) - 1).to_bytes(width, "big")
    count = max(0, int(constant.value))
    chars = (constant.pattern & (1 << 8 * count) - 1).to_bytes(count, "big")
    maximum = max(0, min(size - 2, 254)) if size >= 2 else len(chars)
    chars = chars[:maximum]
    return bytes((maximum, len(chars))) + chars + bytes(max(0, maximum - len(chars)))


def _copy_string(source: bytearray, start: int, target: bytearray, at: int) -> None:
    """An FB's STRING input or output copied in or out: ``min(current length of the source,
    maximum length of the target)`` characters and that length; the target's byte 0 (its
    maximum length) stays."""
    if not (0 <= start <= len(source) - 2 and 0 <= at <= len(target) - 2):
        raise CpuError("SIM503", address=f"byte {start} of a STRING parameter")
    count = min(source[start + 1], target[at], len(source) - start - 2, len(target) - at - 2)
    target[at + 1] = count
    target[at + 2 : at + 2 + count] = source[start + 2 : start + 2 + count]


def _forward_size(var: Variable | None) -> int:
    return max(2, (var.size_bits + 7) // 8) if var is not None else 2


def _copy_forwarded(ref: Ref, frame: bytearray, at: int, size: int, is_string: bool) -> None:
    """A passed-on parameter copied into the caller's local data: a STRING as its maximum
    length (cut to the copy), current length and characters, anything else byte for byte."""
    buf, start, _bit = ref
    count = max(0, min(size, len(buf) - start, len(frame) - at))
    frame[at : at + count] = buf[start : start + count]
    if is_string and count >= 2:
        frame[at] = min(frame[at], count - 2)
        frame[at + 1] = min(frame[at + 1], frame[at])


def _copy_back_forwarded(frame: bytearray, at: int, size: int, ref: Ref, is_string: bool) -> None:
    """What the callee left in the copy goes back (a STRING keeps the original's maximum)."""
    buf, start, _bit = ref
    count = max(0, min(size, len(buf) - start, len(frame) - at))
    if is_string and count >= 2:
        length = min(frame[at + 1], buf[start], count - 2)
        buf[start + 1] = length
        buf[start + 2 : start + 2 + length] = frame[at + 2 : at + 2 + length]
        return
    buf[start : start + count] = frame[at : at + count]


def passed_as_db_pointer(var: Variable) -> bool:
    """FC parameters STEP 7 passes as a 6-byte DB pointer: everything that is not elementary
    (ARRAY, STRUCT, UDT, STRING, DATE_AND_TIME, POINTER), except ANY and block/timer numbers."""
    type_ = _type_of(var)
    return type_ not in ELEMENTARY_BITS and type_ not in NUMBER_TYPES and type_ != "ANY"


def _type_of(var: Variable | None) -> str:
    return var.type.strip().upper() if var is not None else ""


def _width(var: Variable | None) -> int:
    type_ = _type_of(var)
    if type_ in ELEMENTARY_BITS:
        return ELEMENTARY_BITS[type_]
    if type_ in NUMBER_TYPES:
        return 16
    return 0


class Calls:
    """Runs CALL/UC/CC for one CPU. ``handle`` reports a recoverable error at the call site
    (OB121 or STOP); ``compiled`` looks up the compiled callee."""

    def __init__(
        self,
        machine: Machine,
        memory: Memory,
        profile: Profile,
        compiled: Callable[[BlockKind, int], Compiled | None],
        handle: Callable[[CpuError, Compiled, int], int],
        test_ops: bool = False,
        clock_reset: Callable[[], None] | None = None,
    ) -> None:
        self.m = machine
        self.memory = memory
        self.profile = profile
        self.compiled = compiled
        self.handle = handle
        self.test_ops = test_ops  # awlsim's own SFCs (negative numbers) exist only then
        self.clock_reset = clock_reset  # restarts the clock memory (awlsim's SFC -4)
        self.tick_offset = 0  # added to the virtual clock for TIME_TCK (moved by SFC -4)
        self.clock = Clock()  # the time of day SFC 1 READ_CLK reads (``nasaq.cpu.clock``)
        self._db_ids: dict[int, int] | None = None
        self._system_fbs: dict[int, Compiled] = {}  # SFB 0-5, made at their first call
        self.comm = tia_comm.Session()  # this CPU's connections and data logs

    # -- entry from generated code --------------------------------------------------------------
    def call(
        self,
        site: CallSite,
        caller: Compiled,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
        target: int | None = None,
    ) -> None:
        number = site.number if target is None else int(target)
        try:
            if site.kind is BlockKind.SFC:
                self._sfc(site, number, frame, vframe, params)
                return
            callee = self.compiled(site.kind, number)
            if callee is None:
                callee = self._system_fb(number) if site.kind is BlockKind.SFB else None
                if callee is None:
                    raise CpuError("SIM506", block=f"{site.kind.value} {number}")
            keep_ar2 = caller.block.kind is BlockKind.FB and not site.raw
            self._invoke(site, callee, frame, vframe, params, keep_ar2)
        except CpuStopError as stop:
            if stop.where is None:
                stop.where = location(caller, site.index)
            raise
        except CpuError as error:
            self.handle(error, caller, site.index)

    def _invoke(
        self,
        site: CallSite,
        callee: Compiled,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
        keep_ar2: bool = False,
    ) -> None:
        """Run ``callee``. ``keep_ar2``: the caller is an FB, whose CALL macro saves and
        restores AR2 (its instance base) around the call, whatever the callee does with it."""
        m = self.m
        block_name = f"{callee.block.kind.value} {callee.block.number}"
        if m.depth >= self.profile.nesting_depth:
            raise CpuStopError("SIM508", limit=self.profile.nesting_depth, block=block_name)
        size = callee.frame_size
        if m.lstack + size > self.profile.lstack_bytes:
            raise CpuStopError("SIM509", limit=self.profile.lstack_bytes, block=block_name)
        saved_db, saved_dbno, saved_di, saved_dino, saved_ar2 = m.db, m.dbno, m.di, m.dino, m.ar2
        callee_params: list[Ref] = []
        fb_instance: tuple[bytearray, int] | None = None
        kind = callee.block.kind
        forwarded: list[tuple[Ref, int, int, bool]] | None = None
        if (kind is BlockKind.FB or kind is BlockKind.SFB) and not site.raw:
            fb_instance = self._enter_fb(site, callee, frame, vframe, params)
        elif not site.raw:
            callee_params = self._fc_params(site, callee, frame, vframe, params)
            if site.vslots:
                forwarded = self._write_db_pointers(
                    site, callee, frame, vframe, params, callee_params
                )
        saved_vptrs = m.vptrs
        if callee.param_pointers:
            m.vptrs = self._param_pointers(site, callee, frame, callee_params)
        if fb_instance is not None and isinstance(site.instance, BlockRef | MultiInstance):
            m.db, m.dbno = saved_di, saved_dino
        m.fc = m.orb = m.os = 0
        m.sta = 1
        callee_frame = bytearray(size)
        m.depth += 1
        m.lstack += size
        try:
            callee.function(m, callee_frame, frame, callee_params)
        finally:
            m.depth -= 1
            m.lstack -= size
            m.vptrs = saved_vptrs
        if fb_instance is not None and isinstance(site.instance, BlockRef):
            # CALL FB n, DB m is STEP 7's macro TDB / OPN DI m / UC FB n / TDB: the callee
            # starts with DB = the caller's DI, and the caller goes on with DB = the instance
            # DB and DI as it was (its own DB register is lost).
            m.db, m.dbno = fb_instance[0], site.instance.number
            m.di, m.dino = saved_di, saved_dino
        elif fb_instance is not None and isinstance(site.instance, MultiInstance):
            # A multi-instance the same way (COMPATIBILITY.md, "Multi-instance calls"): the
            # callee starts with DB = the caller's DI (the DB that holds the multi-instance),
            # and the caller goes on with that DB in both registers.
            m.db, m.dbno = saved_di, saved_dino
            m.di, m.dino = saved_di, saved_dino
        else:
            m.db, m.dbno, m.di, m.dino = saved_db, saved_dbno, saved_di, saved_dino
        if fb_instance is not None or keep_ar2:
            m.ar2 = saved_ar2
        if fb_instance is not None:
            self._leave_fb(site, callee, fb_instance, frame, vframe, params)
        elif site.vcopies:
            self._copy_back(site, callee, frame, vframe, params)
        if forwarded is not None:
            for ref, offset, size, is_string in forwarded:
                _copy_back_forwarded(frame, offset, size, ref, is_string)
        m.os = m.orb = m.fc = 0
        m.sta = 1

    # -- FC parameter pointers --------------------------------------------------------------------
    def _area_pointer(self, ref: Ref, frame: bytearray) -> tuple[int, int]:
        """(DB number, area-crossing pointer) of the location a parameter reference names, as the
        callee sees it: the caller's local data is its V area."""
        buf, byte, bit = ref
        address = (byte << 3) | bit
        if buf is frame:
            return 0, area_pointer(Area.V, byte, bit)
        if buf is not None:
            for area in _GLOBAL_AREAS:
                if buf is self.memory.area(area):
                    return 0, area_pointer(area, byte, bit)
            number = self._db_numbers().get(id(buf))
            if number is not None:
                return number, 0x84000000 | address
        return 0, 0

    def _db_numbers(self) -> dict[int, int]:
        if self._db_ids is None:
            self._db_ids = {id(buf): number for number, buf in self.memory.dbs.items()}
        return self._db_ids

    def _pointer_to(
        self,
        actual: Operand,
        site: CallSite,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> tuple[int, int]:
        """(DB number, area-crossing pointer) that a POINTER parameter gets for ``actual``: a
        pointer constant as written, else the actual's address (the DB need not exist)."""
        if isinstance(actual, Constant):
            found = _DB_POINTER.match(actual.text)
            return (int(found[1]) if found else 0), actual.pattern & 0xFFFFFFFF
        if isinstance(actual, Direct):
            address = (actual.byte << 3) | actual.bit
            if actual.area is Area.DB:
                number = actual.db if actual.db is not None else self.m.dbno
                return number, 0x84000000 | address
            if actual.area is Area.DI:
                return self.m.dino, 0x84000000 | address
            if actual.area is Area.L:
                return 0, area_pointer(Area.V, actual.byte, actual.bit)
            if actual.area in _GLOBAL_AREAS:
                return 0, area_pointer(actual.area, actual.byte, actual.bit)
        return self._area_pointer(
            self.locate(actual, frame, vframe, params, site.caller_slots), frame
        )

    def _any_bytes(
        self,
        actual: Operand,
        site: CallSite,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> bytes:
        """The 10-byte ANY an ANY parameter gets: ``P#M 10.0 BYTE 7`` as written, an address as
        one element of its width (BOOL, BYTE, WORD, DWORD)."""
        if isinstance(actual, Constant):
            found = _ANY_TEXT.match(actual.text)
            number = int(found["db"]) if found and found["db"] else 0
            type_code = ANY_TYPES.get(found["type"].upper(), 2) if found else 2
            count = int(found["count"]) if found else 1
            pointer = actual.pattern & 0xFFFFFFFF
            if pointer >> 24 == 0x85:  # the caller's instance: its DB, from AR2's offset on
                address = (pointer & 0x7FFFF) + (self.m.ar2 & 0x7FFFF)
                number, pointer = self.m.dino, 0x84000000 | address
        else:
            number, pointer = self._pointer_to(actual, site, frame, vframe, params)
            width = int(getattr(actual, "width", None) or 8)
            type_code, count = _ANY_OF_WIDTH.get(width, 2), 1
        return (
            bytes((0x10, type_code))
            + count.to_bytes(2, "big")
            + number.to_bytes(2, "big")
            + pointer.to_bytes(4, "big")
        )

    def _copy_back(
        self,
        site: CallSite,
        callee: Compiled,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> None:
        """OUT and IN_OUT parameters that were copied into the V area go back to the DB."""
        formals = {v.name: v for v in callee.block.interface if v.section in PARAM_SECTIONS}
        for arg in site.args:
            offset = site.vcopies.get(arg.name)
            formal = formals.get(arg.name)
            if offset is None or formal is None or formal.section == "IN":
                continue
            width = _width(formal)
            buf, byte, bit = self.locate(arg.value, frame, vframe, params, site.caller_slots)
            self._store(buf, byte, width, self._load(frame, offset, width, 0), bit)

    def _write_db_pointers(
        self,
        site: CallSite,
        callee: Compiled,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
        refs: list[Ref],
    ) -> list[tuple[Ref, int, int, bool]] | None:
        """Fill the caller's DB pointers for the FC's ARRAY/STRUCT/.../POINTER parameters.
        A passed-on parameter that no pointer reaches is copied: the copies to take back
        after the call, None when there is none."""
        forwarded: list[tuple[Ref, int, int, bool]] | None = None
        formals = {v.name: v for v in callee.block.interface if v.section in PARAM_SECTIONS}
        actuals = {a.name: a.value for a in site.args}
        for slot, name in enumerate(callee.param_slots):
            offset = site.vslots.get(name)
            if offset is None or slot >= len(refs):
                continue
            actual = actuals.get(name)
            type_ = _type_of(formals.get(name))
            if type_ == "ANY":
                if actual is not None:
                    frame[offset : offset + 10] = self._any_bytes(
                        actual, site, frame, vframe, params
                    )
                continue
            if type_ == "POINTER" and actual is not None:
                number, pointer = self._pointer_to(actual, site, frame, vframe, params)
            else:
                number, pointer = self._area_pointer(refs[slot], frame)
                copy_at = site.vforward.get(name)
                if pointer == 0 and copy_at is not None and refs[slot][0] is not None:
                    size = _forward_size(formals.get(name))
                    is_string = type_.startswith("STRING")
                    _copy_forwarded(refs[slot], frame, copy_at, size, is_string)
                    if forwarded is None:
                        forwarded = []
                    forwarded.append((refs[slot], copy_at, size, is_string))
                    refs[slot] = (frame, copy_at, 0)
                    number, pointer = 0, area_pointer(Area.V, copy_at)
            frame[offset : offset + 6] = number.to_bytes(2, "big") + pointer.to_bytes(4, "big")
        return forwarded

    def _param_pointers(
        self, site: CallSite, callee: Compiled, frame: bytearray, refs: list[Ref]
    ) -> list[int]:
        """``L P##param`` for every parameter slot of the callee: P#V to the DB pointer for the
        parameters passed that way, else a pointer to the actual operand."""
        pointers: list[int] = []
        for slot, name in enumerate(callee.param_slots):
            offset = site.vslots.get(name)
            if offset is not None:
                pointers.append(area_pointer(Area.V, offset))
            elif slot < len(refs):
                pointers.append(self._area_pointer(refs[slot], frame)[1])
            else:
                pointers.append(0)
        return pointers

    # -- FC parameters ----------------------------------------------------------------------------
    def _fc_params(
        self,
        site: CallSite,
        callee: Compiled,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> list[Ref]:
        plan = site.plan
        if plan is None or site.plan_for is not callee:
            plan = site.plan = self._fc_plan(site, callee)
            site.plan_for = callee
        return [item if type(item) is tuple else item(frame, vframe, params) for item in plan]

    def _fc_plan(self, site: CallSite, callee: Compiled) -> list[Any]:
        """Per call site, once: a fixed reference where the actual allows it (markers, I/Q,
        DB n, numbers), else a maker run at each call (frames, constants, indirect)."""
        formals = {v.name: v for v in callee.block.interface if v.section in PARAM_SECTIONS}
        actuals = {a.name: a.value for a in site.args}
        plan: list[Any] = []
        for name in callee.param_slots:
            formal, actual = formals.get(name), actuals.get(name)
            plan.append(self._plan_item(actual, formal, site))
        return plan

    def _plan_item(self, actual: Operand | None, formal: Variable | None, site: CallSite) -> Any:
        if formal is not None and actual is not None and formal.name in site.vcopies:
            copy_offset, width = site.vcopies[formal.name], _width(formal)

            def copy_in(frame: bytearray, vframe: bytearray, params: list[Ref]) -> Ref:
                buf, byte, bit = self.locate(actual, frame, vframe, params, site.caller_slots)
                self._store(frame, copy_offset, width, self._load(buf, byte, width, bit), 0)
                return frame, copy_offset, 0

            return copy_in
        if (
            formal is not None
            and _type_of(formal) in ("ANY", "POINTER")
            and formal.name in site.vslots
        ):
            pointer_offset = site.vslots[formal.name]  # the parameter is the pointer in V

            def pointer_in_frame(frame: bytearray, vframe: bytearray, params: list[Ref]) -> Ref:
                return frame, pointer_offset, 0

            return pointer_in_frame
        if isinstance(actual, Constant) and formal is not None and formal.name in site.vconsts:
            offset = site.vconsts[formal.name]
            literal = constant_bytes(actual, (formal.size_bits + 7) // 8)

            def in_frame(frame: bytearray, vframe: bytearray, params: list[Ref]) -> Ref:
                frame[offset : offset + len(literal)] = literal
                return frame, offset, 0

            return in_frame
        if isinstance(actual, TimerRef | CounterRef | BlockRef):
            return (None, actual.number, 0)
        if isinstance(actual, Direct) and actual.area in (Area.I, Area.Q, Area.M, Area.PI, Area.PQ):
            return (self.memory.area(actual.area), actual.byte, actual.bit)
        if isinstance(actual, Direct) and actual.area is Area.DB and actual.db is not None:
            found = self.memory.dbs.get(actual.db)
            if found is not None:
                return (found, actual.byte, actual.bit)
        if isinstance(actual, Direct) and actual.area is Area.L:
            byte, bit = actual.byte, actual.bit
            return lambda frame, vframe, params: (frame, byte, bit)
        if isinstance(actual, ParamRef) and not actual.bit_offset:
            slot = site.caller_slots.get(actual.name, -1)
            if slot >= 0:
                return lambda frame, vframe, params: (
                    params[slot]
                    if slot < len(params)
                    else (
                        bytearray(4),
                        0,
                        0,
                    )
                )

        def make(frame: bytearray, vframe: bytearray, params: list[Ref]) -> Ref:
            return self._reference(actual, formal, site, frame, vframe, params)

        return make

    def _reference(
        self,
        actual: Operand | None,
        formal: Variable | None,
        site: CallSite,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> Ref:
        width = _width(formal)
        size = max(4, ((formal.size_bits + 7) // 8) if formal is not None else 4)
        if actual is None:
            return bytearray(size), 0, 0
        if isinstance(actual, Constant):
            if width == 1:
                return bytearray((actual.pattern & 1,)), 0, 0
            if actual.type in (ConstType.DATE_AND_TIME, ConstType.STRING):
                return bytearray(constant_bytes(actual, size)), 0, 0
            nbytes = max(1, width // 8) if width else 4
            data = (actual.pattern & ((1 << (8 * nbytes)) - 1)).to_bytes(nbytes, "big")
            return bytearray(data), 0, 0
        if isinstance(actual, TimerRef | CounterRef | BlockRef):
            return None, actual.number, 0
        if isinstance(actual, MemoryIndirect) and actual.target is not None:
            return None, self._indirect_number(actual, site, frame, vframe, params), 0
        return self.locate(actual, frame, vframe, params, site.caller_slots)

    def _indirect_number(
        self,
        actual: MemoryIndirect,
        site: CallSite,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> int:
        """The timer, counter or block number of ``T [MW 4]``, ``DB [MW 14]`` ... as an actual."""
        buf, byte, bit = self.locate(actual.pointer, frame, vframe, params, site.caller_slots)
        return self._load(buf, byte, 16, bit)

    def locate(
        self,
        op: Operand,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
        caller_slots: dict[str, int],
    ) -> Ref:
        """Buffer and address of a memory operand in the caller's context."""
        m, _mem = self.m, self.memory
        if isinstance(op, ParamRef):
            slot = caller_slots.get(op.name)
            if slot is None or slot >= len(params):
                return bytearray(4), 0, 0
            buf, byte, bit = params[slot]
            total = byte * 8 + bit + op.bit_offset
            return buf, total // 8, total % 8
        if isinstance(op, Direct):
            return self._buffer(op.area, op.db, frame, vframe), op.byte, op.bit
        if isinstance(op, RegisterIndirect):
            ar = m.ar1 if op.register == 1 else m.ar2
            address = (ar & 0x7FFFF) + op.offset_bits
            if op.area is None:
                from nasaq.cpu.pointers import CODE_AREAS

                area = CODE_AREAS[(ar >> 24) & 7]
            else:
                area = op.area
            return self._buffer(area, None, frame, vframe), address >> 3, address & 7
        if isinstance(op, MemoryIndirect):
            pbuf, pbyte, pbit = self.locate(op.pointer, frame, vframe, params, caller_slots)
            pointer = read_bytes(pbuf, pbyte, 32, pbit)
            address = pointer & 0x7FFFF
            return self._buffer(op.area or Area.M, None, frame, vframe), address >> 3, address & 7
        raise CpuError("SIM526", name="?", block="?", actual=type(op).__name__)

    def _buffer(self, area: Area, db: int | None, frame: bytearray, vframe: bytearray) -> bytearray:
        m, mem = self.m, self.memory
        if area is Area.L:
            return frame
        if area is Area.V:
            return vframe
        if area is Area.DB:
            if db is None:
                return m.db
            found = mem.dbs.get(db)
            if found is None:
                raise CpuError("SIM505", number=db)
            return found
        if area is Area.DI:
            return m.di
        return mem.area(area)

    # -- FB instance data -----------------------------------------------------------------------
    def _enter_fb(
        self,
        site: CallSite,
        callee: Compiled,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> tuple[bytearray, int]:
        """Copy IN/IN_OUT into the instance (actuals seen with the caller's registers), then
        switch DI and AR2 to the instance."""
        m = self.m
        instance = site.instance
        if isinstance(instance, MultiInstance):
            base = (m.ar2 & 0x7FFFF) + instance.offset_bits
            buf, dino, ar2 = m.di, m.dino, (m.ar2 & 0xFF000000) | base
        elif isinstance(instance, BlockRef):
            found = self.memory.dbs.get(instance.number)
            if found is None:
                raise CpuError("SIM505", number=instance.number)
            buf, base, dino, ar2 = found, 0, instance.number, 0x84000000
        else:  # CALL FB without instance: keep DI and AR2 as they are
            buf, base, dino, ar2 = m.di, m.ar2 & 0x7FFFF, m.dino, m.ar2
        for var, actual in self._fb_args(site, callee)[0]:
            self._copy(
                actual,
                site,
                frame,
                vframe,
                params,
                buf,
                base + var.offset_bits,
                var,
                into_instance=True,
            )
        m.di, m.dino, m.ar2 = buf, dino, ar2
        return buf, base

    def _leave_fb(
        self,
        site: CallSite,
        callee: Compiled,
        instance: tuple[bytearray, int],
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
    ) -> None:
        buf, base = instance
        for var, actual in self._fb_args(site, callee)[1]:
            self._copy(
                actual,
                site,
                frame,
                vframe,
                params,
                buf,
                base + var.offset_bits,
                var,
                into_instance=False,
            )

    def _fb_args(self, site: CallSite, callee: Compiled) -> Any:
        """(IN and IN_OUT, OUT and IN_OUT) as (formal, actual) pairs, worked out once per site."""
        if site.plan is None or site.plan_for is not callee:
            actuals = {a.name: a.value for a in site.args}
            pairs = [(v, actuals[v.name]) for v in callee.block.interface if v.name in actuals]
            site.plan = [
                [(v, a) for v, a in pairs if v.section in ("IN", "IN_OUT")],
                [(v, a) for v, a in pairs if v.section in ("OUT", "IN_OUT")],
            ]
            site.plan_for = callee
        return site.plan

    def _copy(
        self,
        actual: Operand,
        site: CallSite,
        frame: bytearray,
        vframe: bytearray,
        params: list[Ref],
        buf: bytearray,
        bit_address: int,
        var: Variable,
        into_instance: bool,
    ) -> None:
        width = _width(var)
        byte, bit = bit_address >> 3, bit_address & 7
        if _type_of(var) == "ANY":  # the instance gets an ANY for the actual
            if into_instance:
                literal = self._any_bytes(actual, site, frame, vframe, params)
                self._check(buf, byte, 80)
                buf[byte : byte + 10] = literal
            return
        if _type_of(var) == "POINTER":  # the instance gets a DB pointer to the actual
            if into_instance:
                number, pointer = self._pointer_to(actual, site, frame, vframe, params)
                self._check(buf, byte, 48)
                buf[byte : byte + 6] = number.to_bytes(2, "big") + pointer.to_bytes(4, "big")
            return
        if var.section == "IN_OUT" and var.size_bits == 48 and passed_as_db_pointer(var):
            # a structured IN_OUT: the instance holds a DB pointer to the actual, which the FB
            # reads and writes through; nothing is copied back
            if into_instance:
                ref = self.locate(actual, frame, vframe, params, site.caller_slots)
                number, pointer = self._area_pointer(ref, frame)
                self._check(buf, byte, 48)
                buf[byte : byte + 6] = number.to_bytes(2, "big") + pointer.to_bytes(4, "big")
            return
        if into_instance and isinstance(actual, Constant):
            if actual.type in (ConstType.DATE_AND_TIME, ConstType.STRING):
                literal = constant_bytes(actual, (var.size_bits + 7) // 8)
                self._check(buf, byte, len(literal) * 8)
                buf[byte : byte + len(literal)] = literal
                return
            self._store(buf, byte, width or 32, actual.pattern, bit)
            return
        if isinstance(actual, TimerRef | CounterRef | BlockRef):
            if into_instance:
                self._store(buf, byte, 16, actual.number, 0)
            return
        if isinstance(actual, MemoryIndirect) and actual.target is not None:
            if into_instance:
                number = self._indirect_number(actual, site, frame, vframe, params)
                self._store(buf, byte, 16, number, 0)
            return
        if isinstance(actual, Direct) and actual.area in _GLOBAL_AREAS:
            src_buf, src_byte, src_bit = self.memory.area(actual.area), actual.byte, actual.bit
        else:
            src_buf, src_byte, src_bit = self.locate(
                actual, frame, vframe, params, site.caller_slots
            )
        if width == 0 and var.type[:6].upper() == "STRING":  # as an SCL assignment
            if into_instance:
                _copy_string(src_buf, src_byte, buf, byte)
            else:
                _copy_string(buf, byte, src_buf, src_byte)
            return
        if width == 0:  # STRUCT, ARRAY ...: copy the bytes
            count = (var.size_bits + 7) // 8
            if into_instance:
                data = src_buf[src_byte : src_byte + count]
                self._check(buf, byte, count * 8)
                buf[byte : byte + len(data)] = data
            else:
                self._check(src_buf, src_byte, count * 8)
                src_buf[src_byte : src_byte + count] = buf[byte : byte + count]
            return
        if into_instance:
            value = self._load(src_buf, src_byte, width, src_bit)
            self._store(buf, byte, width, value, bit)
        else:
            value = self._load(buf, byte, width, bit)
            self._store(src_buf, src_byte, width, value, src_bit)

    @staticmethod
    def _check(buf: bytearray, byte: int, width: int) -> None:
        if byte < 0 or byte + max(1, width // 8) > len(buf):
            raise CpuError("SIM503", address=f"byte {byte} of a parameter")

    def _load(self, buf: bytearray, byte: int, width: int, bit: int) -> int:
        try:
            return read_bytes(buf, byte, width, bit)
        except IndexError:
            raise CpuError("SIM503", address=f"byte {byte} (parameter)") from None

    def _store(self, buf: bytearray, byte: int, width: int, value: int, bit: int) -> None:
        try:
            write_bytes(buf, byte, width, value, bit)
        except IndexError:
            raise CpuError("SIM504", address=f"byte {byte} (parameter)") from None

    # -- system function blocks -------------------------------------------------------------------
    def _system_fb(self, number: int) -> Compiled | None:
        """SFB ``number`` as an FB whose body is Python (``nasaq.cpu.iec_blocks``), so a call
        runs through ``_invoke`` like any FB call: instance, parameters in and out, registers."""
        found = self._system_fbs.get(number)
        if found is None:
            body = iec_blocks.BODIES.get(number) or self.comm.bodies.get(number)
            if body is None:
                return None
            found = self._system_fbs[number] = self._python_fb(number, body)
        return found

    def _python_fb(self, number: int, body: iec_blocks.Body) -> Compiled:
        from nasaq.cpu.codegen.compiler import Compiled  # codegen imports this module

        size = iec_blocks.INSTANCE_BYTES[number]
        name = f"SFB {number}"

        def run(m: Machine, callee_frame: bytearray, frame: bytearray, params: list[Ref]) -> None:
            buf, base = m.di, (m.ar2 & 0x7FFFF) >> 3
            if base + size > len(buf):
                raise CpuError("SIM503", address=f"the instance data of {name} (DI {m.dino})")
            m.br = body(buf, base, (m.now + self.tick_offset) & iec_blocks.TIME_MASK)

        block = Block(
            BlockKind.SFB,
            number,
            name=iec_blocks.NAMES[number],
            interface=iec_blocks.INTERFACES[number],
        )
        return Compiled(block, run, 0, [], [], [], {}, f"<{name}>", "", {})

    # -- system functions -------------------------------------------------------------------------
    def _sfc(
        self, site: CallSite, number: int, frame: bytearray, vframe: bytearray, params: list[Ref]
    ) -> None:
        if number in tia_control.SFC_BODIES:  # RUNTIME (``nasaq.cpu.tia_control``)
            actuals = {
                arg.name.upper(): self.locate(arg.value, frame, vframe, params, site.caller_slots)
                for arg in site.args
            }
            self.m.br = tia_control.SFC_BODIES[number](actuals, self.m.now + self.tick_offset)
            return
        if number in tia_comm.SFC_BODIES:  # RD_SINFO, AG_SEND, AG_RECV (``cpu.tia_comm``)
            refs: dict[str, Ref] = {}
            for arg in site.args:
                name = arg.name.upper()
                if isinstance(arg.value, Constant):
                    size = tia_comm.parameter_bytes(number, name)
                    refs[name] = (bytearray(constant_bytes(arg.value, size)), 0, 0)
                else:
                    refs[name] = self.locate(arg.value, frame, vframe, params, site.caller_slots)
            self.m.br = tia_comm.SFC_BODIES[number](self.comm, refs)
            return
        if number == 46:  # STP
            raise CpuStopError("SIM502")
        if number == 43:  # RE_TRIGR: the simulator's scan budget is not a cycle-time monitor
            self.m.br = 1
            return
        if number == 64:  # TIME_TCK: RET_VAL := ms since start, from the virtual clock
            for arg in site.args:
                if arg.name.upper() == "RET_VAL":
                    buf, byte, bit = self.locate(
                        arg.value, frame, vframe, params, site.caller_slots
                    )
                    ticks = (self.m.now + self.tick_offset) & 0x7FFFFFFF
                    self._store(buf, byte, 32, ticks, bit)
            return
        if number == 1:  # READ_CLK: CDT := the time of day, RET_VAL := 0
            for arg in site.args:
                buf, byte, bit = self.locate(arg.value, frame, vframe, params, site.caller_slots)
                if arg.name.upper() == "CDT":
                    if byte < 0 or byte + 8 > len(buf):
                        raise CpuError("SIM504", address=f"byte {byte} (CDT)")
                    buf[byte : byte + 8] = self.clock.date_and_time(self.m.now)
                elif arg.name.upper() == "RET_VAL":
                    self._store(buf, byte, 16, 0, bit)
            self.m.br = 1
            return
        if number < 0 and self.test_ops:
            self._awlsim_sfc(site, number, frame, vframe, params)
            return
        raise CpuError("SIM506", block=f"SFC {number}")

    def _awlsim_sfc(
        self, site: CallSite, number: int, frame: bytearray, vframe: bytearray, params: list[Ref]
    ) -> None:
        """awlsim's own system functions, which its self-checking programs call (test_ops only):
        SFC -3 ``__SHUTDOWN`` (SHUTDOWN_TYPE 1 ends the simulator, 2 stops the CPU: both are a
        stop requested by the program here) and SFC -4 ``__CLKRST`` (the system time restarts
        100 ms before TIME_TCK wraps round at 2**31 ms, and the clock memory restarts at 0).
        awlsim's SFC -2 ``__REBOOT`` is not emulated (SIM506)."""
        if number == -3:
            kind = self._int_input(site, "SHUTDOWN_TYPE", frame, vframe, params)
            if kind in (1, 2):
                raise CpuStopError("SIM502")
            raise CpuError("SIM526", name="SHUTDOWN_TYPE", block="SFC -3", actual=str(kind))
        if number == -4:
            self.tick_offset = 0x7FFFFFFF - 100 - self.m.now
            if self.clock_reset is not None:
                self.clock_reset()
            self.m.br = 1
            return
        raise CpuError("SIM506", block=f"SFC {number}")

    def _int_input(
        self, site: CallSite, name: str, frame: bytearray, vframe: bytearray, params: list[Ref]
    ) -> int:
        """The INT actual of input ``name`` of a system function call (0 when it is missing)."""
        for arg in site.args:
            if arg.name.upper() != name:
                continue
            if isinstance(arg.value, Constant):
                raw = arg.value.pattern & 0xFFFF
            else:
                buf, byte, bit = self.locate(arg.value, frame, vframe, params, site.caller_slots)
                raw = self._load(buf, byte, 16, bit)
            return raw - 0x10000 if raw & 0x8000 else raw
        return 0

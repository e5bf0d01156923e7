"""CALL: the called block, its instance, and the actual parameters checked against the formal
ones (name, assignment, type): STEP 7's rules for FCs (every parameter assigned, RET_VAL
included) and FBs (parameters optional, except structured IN_OUT ones).

Actual values the IR passes in a form of their own: a ``DT#`` constant (DATE_AND_TIME) and a
character constant for a STRING parameter (STRING, its length in ``value``); for an ANY
parameter, a declared variable at a fixed address becomes the ANY constant STEP 7 makes of it
(``P#DB5.DBX 2.0 INT 1``), so the CPU gets its type; ``DB [MW 14]`` and the like are numbers
read at run time for BLOCK_DB, BLOCK_FC, BLOCK_FB, TIMER and COUNTER parameters."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    CallInfo,
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
)
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.stl import ast
from nasaq.lang.stl.bind import Param
from nasaq.lang.stl.build import unquote_chars
from nasaq.lang.stl.constants import POINTER_AREAS
from nasaq.lang.stl.resolve import Resolved, Resolver, Scope, cache_key
from nasaq.lang.system_blocks import SFB_INTERFACES, SFB_NAMES, s7_1500_only
from nasaq.lang.system_types import parse as parse_type
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    StringType,
    StructType,
    is_reference,
    type_text,
    width_of,
)

# TIA's data type choices of IEC timers and counters, and the one each has on S7-300/400.
INSTRUCTION_TYPES = {"time_type": "Time", "value_type": "Int"}

CONSTANT_FITS = {
    "BOOL": {ConstType.BOOL},
    "BYTE": {ConstType.BYTE},
    "CHAR": {ConstType.CHAR},
    "WORD": {ConstType.WORD, ConstType.BYTE, ConstType.BYTES},
    "INT": {ConstType.INT},
    "DWORD": {ConstType.DWORD, ConstType.WORD, ConstType.BYTE, ConstType.BYTES},
    "DINT": {ConstType.DINT, ConstType.INT},
    "REAL": {ConstType.REAL},
    "S5TIME": {ConstType.S5TIME},
    "TIME": {ConstType.TIME},
    "DATE": {ConstType.DATE},
    "TIME_OF_DAY": {ConstType.TOD},
}

# The elementary types an ANY names by their own type code (others are passed as BYTEs).
ANY_TYPES = frozenset(
    {
        "BOOL",
        "BYTE",
        "CHAR",
        "WORD",
        "INT",
        "DWORD",
        "DINT",
        "REAL",
        "DATE",
        "TIME_OF_DAY",
        "TIME",
        "S5TIME",
        "DATE_AND_TIME",
    }
)

_UNITS = (("DWORD", 32), ("WORD", 16), ("BYTE", 8), ("BOOL", 1))


@dataclass(slots=True)
class AutoInstance:
    """An instance DB that a CALL names but no source defines: it is generated."""

    db: int
    fb: BlockType
    file: str
    loc: ast.Loc


def same_type(left: DataType, right: DataType) -> bool:
    """Structural equality: member types in order (names may differ, as STEP 7 allows)."""
    if isinstance(left, StructType) and isinstance(right, StructType):
        return len(left.fields) == len(right.fields) and all(
            same_type(a.type, b.type) for a, b in zip(left.fields, right.fields, strict=True)
        )
    if isinstance(left, ArrayType) and isinstance(right, ArrayType):
        return left.dims == right.dims and same_type(left.element, right.element)
    return type_text(left) == type_text(right)


def fits(formal: DataType, actual: Resolved, section: str) -> bool:
    """Whether the actual parameter may be passed to a formal of type ``formal``."""
    operand = actual.operand
    if isinstance(operand, MultiInstance):
        return False
    if section != "IN" and isinstance(operand, Constant):
        # an ANY in/out or output takes a pointer constant (STEP 7: ``ADDR_1 := P#DB10.DBX0.0
        # BYTE 10`` of GET, SFB 14; ``OUT := P#M 20.0 BYTE 2`` of ATH, FC 94); any other
        # constant has no place to be written back to
        any_pointer = isinstance(formal, Elementary) and formal.name == "ANY"
        return any_pointer and operand.type is ConstType.POINTER
    if isinstance(formal, StringType):
        if isinstance(operand, Constant):
            return (
                operand.type in (ConstType.CHAR, ConstType.STRING)
                and len(unquote_chars(operand.text)) <= formal.length
            )
        return isinstance(actual.type, StringType)
    if not isinstance(formal, Elementary):
        return actual.type is not None and same_type(formal, actual.type)
    name = formal.name
    if name == "ANY":
        return not isinstance(operand, Constant) or operand.type is not ConstType.DATE_AND_TIME
    if name == "POINTER":
        return not isinstance(operand, Constant) or operand.type is ConstType.POINTER
    if name in ("TIMER", "COUNTER") or name.startswith("BLOCK_"):
        return _fits_reference(name, actual)
    if name == "DATE_AND_TIME":  # a DT# constant too: STEP 7 copies it like any IN value
        if isinstance(operand, Constant):
            return operand.type is ConstType.DATE_AND_TIME
        return isinstance(actual.type, Elementary) and actual.type.name == name
    if isinstance(operand, Constant):
        return operand.type in CONSTANT_FITS.get(name, set())
    if actual.type is not None:
        return isinstance(actual.type, Elementary) and actual.type.name == name
    width = getattr(operand, "width", None)
    return width is not None and width == width_of(formal)


_INDIRECT_OF = {"TIMER": "T", "COUNTER": "C", "BLOCK_DB": "DB", "BLOCK_FC": "FC", "BLOCK_FB": "FB"}


def _fits_reference(name: str, actual: Resolved) -> bool:
    operand = actual.operand
    if isinstance(operand, MemoryIndirect):  # DB [MW 14]: the number comes from a word
        return operand.target is not None and operand.target == _INDIRECT_OF.get(name)
    if isinstance(operand, ParamRef):
        return isinstance(actual.type, Elementary) and actual.type.name == name
    if name == "TIMER":
        return isinstance(operand, TimerRef)
    if name == "COUNTER":
        return isinstance(operand, CounterRef)
    wanted = {"BLOCK_DB": BlockKind.DB, "BLOCK_FC": BlockKind.FC, "BLOCK_FB": BlockKind.FB}
    return isinstance(operand, BlockRef) and operand.kind is wanted.get(name, operand.kind)


def _is_any(data_type: DataType) -> bool:
    return isinstance(data_type, Elementary) and data_type.name == "ANY"


def describe(actual: Resolved) -> str:
    if actual.type is not None:
        return f"{actual.text} ({type_text(actual.type)})"
    if isinstance(actual.operand, Constant):
        return f"{actual.text} ({actual.operand.type.value})"
    return actual.text


@cache  # a system FB's interface is fixed: its parameters are listed once (read, not changed)
def _system_parameters(number: int) -> list[Param]:
    params: list[Param] = []
    for section, name, type_name in SFB_INTERFACES[number]:
        if section != "STAT":
            params.append(Param(name, section, parse_type(type_name), len(params)))
    return params


class CallLowerer:
    def __init__(self, scope: Scope, resolver: Resolver, auto: dict[int, AutoInstance]) -> None:
        self.scope = scope
        self.resolver = resolver
        self.auto = auto
        self._known: dict[tuple[object, ...], CallInfo] = {}

    def call(self, node: ast.InstrNode) -> CallInfo | None:
        """The call of ``CALL``. A block repeats the same calls (generated code above all): one
        written the same way is lowered once, unless lowering it reported something."""
        key = _call_key(node)
        found = self._known.get(key) if key is not None else None
        if found is not None:
            return found
        reported = len(self.scope.diagnostics)
        found = self._call(node)
        if key is not None and found is not None and len(self.scope.diagnostics) == reported:
            self._known[key] = found
        return found

    def _call(self, node: ast.InstrNode) -> CallInfo | None:
        if node.attributes and not self.instruction_types(node, node.attributes):
            return None
        if not node.operands:
            self.scope.report("STL202", node.loc, mnemonic="CALL", expected="a block")
            return None
        if len(node.operands) > 2:
            extra = node.operands[2]
            self.scope.report(
                "STL204",
                extra.loc,
                mnemonic="CALL",
                operand="a third operand",
                expected="a block and its instance data block",
            )
            return None
        target = self.resolver.operand(node.operands[0])
        if target is None:
            return None
        operand = target.operand
        instance: BlockRef | MultiInstance | None = None
        if isinstance(operand, MultiInstance):
            assert isinstance(target.type, BlockType)
            block = BlockRef(BlockKind(target.type.kind), target.type.number)
            instance = operand
            if len(node.operands) > 1:
                self.scope.report(
                    "STL204",
                    node.operands[1].loc,
                    mnemonic="CALL",
                    operand=target.text,
                    expected="no instance data block",
                )
                return None
        elif isinstance(operand, BlockRef) and operand.kind in (
            BlockKind.FC,
            BlockKind.FB,
            BlockKind.SFC,
            BlockKind.SFB,
        ):
            block = operand
            found = self.instance(node, block)
            if found is False:
                return None
            instance = found if isinstance(found, BlockRef) else None
        else:
            self.scope.report(
                "STL234",
                node.operands[0].loc,
                name=target.text,
                actual=target.text,
                expected="an FC, FB, SFC or SFB",
            )
            return None
        params = self.formal_parameters(block, node.loc)
        if params is False:
            return None
        known = params if isinstance(params, list) else None
        args = self.arguments(block, known, node.args or [], node.loc)
        return CallInfo(block, instance, tuple(args))

    def instruction_types(self, node: ast.InstrNode, attributes: dict[str, str]) -> bool:
        """TIA's ``{time_type := 'Time'}`` / ``{value_type := 'Int'}`` after ``CALL``: the
        S7-1200/1500 family's choice of data type for an IEC timer or counter. Nasaq's timers
        and counters are the S7-300/400 SFBs (TIME, INT), so only those types are accepted."""
        if not is_s7_1500(self.scope.index.profile):
            first = next(iter(attributes.items()))
            what = f"{{{first[0]} := '{first[1]}'}}"
            self.scope.report("STL500", node.loc, what=what, profile=self.scope.index.profile)
            return False
        for name, value in attributes.items():
            supported = INSTRUCTION_TYPES.get(name.casefold())
            if supported is not None and value.casefold() != supported.casefold():
                self.scope.report(
                    "STL602", node.loc, attribute=name, value=value, supported=supported
                )
                return False
        return True

    def instance(self, node: ast.InstrNode, block: BlockRef) -> BlockRef | bool | None:
        is_fb = block.kind in (BlockKind.FB, BlockKind.SFB)
        if len(node.operands) < 2:
            if is_fb:
                self.scope.report("STL221", node.loc, block=f"{block.kind.value} {block.number}")
                return False
            return None
        if not is_fb:
            self.scope.report(
                "STL204",
                node.operands[1].loc,
                mnemonic="CALL",
                operand=f"{block.kind.value} {block.number}",
                expected="no instance data block",
            )
            return False
        found = self.resolver.operand(node.operands[1])
        if found is None:
            return False
        db = found.operand
        if not isinstance(db, BlockRef) or db.kind is not BlockKind.DB:
            self.scope.report(
                "STL234",
                node.operands[1].loc,
                name=found.text,
                actual=found.text,
                expected="an instance data block",
            )
            return False
        fb_type = BlockType(block.kind.value, block.number)
        info = self.scope.index.blocks.get((BlockKind.DB, db.number))
        if info is None:
            if db.number not in self.auto:
                self.auto[db.number] = AutoInstance(db.number, fb_type, self.scope.file, node.loc)
                self.scope.report(
                    "STL229",
                    node.loc,
                    db=f"DB {db.number}",
                    block=f"{block.kind.value} {block.number}",
                )
            elif self.auto[db.number].fb != fb_type:
                self.scope.report(
                    "STL222",
                    node.loc,
                    db=f"DB {db.number}",
                    block=f"{block.kind.value} {block.number}",
                )
        elif info.db_type != fb_type and not _same_layout(info.db_type, fb_type):
            self.scope.report(
                "STL222", node.loc, db=f"DB {db.number}", block=f"{block.kind.value} {block.number}"
            )
        return db

    def formal_parameters(self, block: BlockRef, where: ast.Loc) -> list[Param] | bool | None:
        """The callee's parameters; None when unknown (system blocks), False when missing."""
        info = self.scope.index.blocks.get((block.kind, block.number))
        if info is not None:
            return info.params
        if block.kind is BlockKind.SFB and block.number in SFB_INTERFACES:
            profile = self.scope.index.profile
            if s7_1500_only(block.number) and not is_s7_1500(profile):  # PID_Compact ...
                what = SFB_NAMES[block.number]
                self.scope.report("STL500", where, what=what, profile=profile)
                return False
            return _system_parameters(block.number)
        if block.kind in (BlockKind.SFC, BlockKind.SFB):
            return None
        self.scope.report("STL213", where, block=f"{block.kind.value} {block.number}")
        return False

    def any_actual(self, actual: Resolved, operand: Operand) -> Operand:
        """What an ANY parameter gets. A declared variable at a fixed address (``"DB".x``,
        ``P#DB42.x``, a symbol with a type) becomes the ANY constant STEP 7 makes of it, so its
        type reaches the CPU; anything else (``M 12.2``, ``DB50.DBD 10``, locals) is passed as
        it is and its access width tells the type. An FB's own variable reached through AR2
        (``DI [AR2, P#4.0]``, SCL's instance data) is ``P#DI 4.0 ...`` too: the CPU adds AR2's
        offset (a multi-instance's place in the instance DB) when it builds the ANY."""
        if isinstance(operand, Constant) and actual.pointee is not None:
            return self.any_constant(operand, actual.pointee, widest=True)
        if (
            isinstance(operand, RegisterIndirect)
            and operand.register == 2
            and operand.area is Area.DI
            and actual.type is not None
        ):
            bits = operand.offset_bits
            text = f"P#DI {bits >> 3}.{bits & 7}"
            pointer = Constant(ConstType.POINTER, (0x85 << 24) | bits, bits, text)
            return self.any_constant(pointer, actual.type)
        if isinstance(operand, Direct) and actual.type is not None:
            bits = operand.byte * 8 + operand.bit
            if operand.db is not None:
                text = f"P#DB{operand.db}.DBX {operand.byte}.{operand.bit}"
                area = POINTER_AREAS["DB"]
            elif operand.area in (Area.I, Area.Q, Area.M):
                text = f"P#{operand.area.value} {operand.byte}.{operand.bit}"
                area = POINTER_AREAS[operand.area.value]
            elif operand.area is Area.L:  # the caller's local data: V as the callee sees it
                text = f"P#V {operand.byte}.{operand.bit}"
                area = 0x87
            elif operand.area is Area.DI:  # the CPU puts the instance DB's number in
                text = f"P#DI {operand.byte}.{operand.bit}"
                area = 0x85
            else:
                return operand
            pointer = Constant(ConstType.POINTER, (area << 24) | bits, bits, text)
            return self.any_constant(pointer, actual.type)
        return operand

    def any_constant(self, pointer: Constant, pointee: DataType, widest: bool = False) -> Constant:
        """``P#DB42.DBX 4.0`` → ``P#DB42.DBX 4.0 INT 1``: the ANY STEP 7 makes of a variable
        (an elementary type once, an array of one as its elements, anything else as BYTEs).
        ``widest``: awlsim's ``P#DB42.x`` extension means DWORDs, WORDs or BYTEs, the widest
        that divides the size, for what is not (an array of) an elementary type."""
        bits = self.resolver.layout.size_bits(pointee)
        type_name, count = "BYTE", bits // 8
        if widest:
            name, width = next(unit for unit in _UNITS if bits % unit[1] == 0)
            type_name, count = name, bits // width
        if isinstance(pointee, Elementary) and pointee.name in ANY_TYPES:
            type_name, count = pointee.name, 1
        elif isinstance(pointee, ArrayType):
            element = pointee.element
            if isinstance(element, Elementary) and element.name in ANY_TYPES:
                type_name, count = element.name, pointee.count
        text = f"{pointer.text} {type_name} {count}"
        return Constant(pointer.type, pointer.pattern, pointer.value, text)

    def arguments(
        self,
        block: BlockRef,
        params: list[Param] | None,
        args: list[ast.CallArgNode],
        where: ast.Loc,
    ) -> list[CallArg]:
        label = f"{block.kind.value} {block.number}"
        by_name = {param.name.upper(): param for param in params or []}
        assigned: set[str] = set()
        result: list[CallArg] = []
        for arg in args:
            key = arg.name.upper()
            formal = by_name.get(key)
            if params is not None and formal is None:
                self.scope.report("STL212", arg.loc, block=label, param=arg.name)
                continue
            if key in assigned:
                self.scope.report("STL231", arg.loc, param=arg.name)
                continue
            if arg.value is None:
                continue
            assigned.add(key)
            actual = self.resolver.operand(arg.value)
            if actual is None:
                continue
            if formal is not None and not fits(formal.type, actual, formal.section):
                self.scope.report(
                    "STL210",
                    arg.value.loc,
                    param=formal.name,
                    block=label,
                    formal=f"{formal.section} {type_text(formal.type)}",
                    actual=describe(actual),
                )
                continue
            value = actual.operand
            if isinstance(value, MultiInstance):
                continue
            if formal is not None and _is_any(formal.type):
                value = self.any_actual(actual, value)
            elif isinstance(value, Constant) and formal and isinstance(formal.type, StringType):
                length = len(unquote_chars(value.text))  # 'AB' is a CHAR constant elsewhere
                value = Constant(ConstType.STRING, value.pattern, length, value.text)
            result.append(CallArg(formal.name if formal else arg.name, value))
        for param in params or []:
            if param.name.upper() in assigned:
                continue
            required = block.kind in (BlockKind.FC, BlockKind.SFC) or (
                param.section == "IN_OUT" and is_reference(param.type)
            )
            if required:
                self.scope.report("STL211", where, param=param.name, block=label)
        return result


def _call_key(node: ast.InstrNode) -> tuple[object, ...] | None:
    """What a call is lowered from: ``cache_key`` of its operands and of its arguments, with
    their names (None when one has none)."""
    key: list[object] = []
    for operand in node.operands:
        found = cache_key(operand)
        if found is None:
            return None
        key.append(found)
    for arg in node.args or ():
        value = None if arg.value is None else cache_key(arg.value)
        if value is None and arg.value is not None:
            return None
        key += (arg.name, value)
    return tuple(key)


def _same_layout(db_type: object, fb_type: BlockType) -> bool:
    """An instance of one IEC timer SFB serves the others (TP, TON and TOF share one interface):
    TIA Portal's IEC_TIMER instance DB is called as ``"DB".TP(...)`` or ``.TON(...)``."""
    if not isinstance(db_type, BlockType) or db_type.kind != "SFB" or fb_type.kind != "SFB":
        return False
    mine = SFB_INTERFACES.get(db_type.number)
    return mine is not None and mine is SFB_INTERFACES.get(fb_type.number)

"""Source operands → IR operands, following the conventions of ``nasaq.ir.operands``:

- ``#temp`` → ``Direct`` in L at its offset in the block's stack frame;
- ``#var`` of an FB (IN, OUT, IN_OUT, STAT, members of multi-instances) → ``RegisterIndirect``
  in DI through AR2, as STEP 7 compiles it; ``CALL #inst`` → ``MultiInstance``;
- ``#param`` of an FC → ``ParamRef`` (by reference through the call frame);
- ``"DB".member`` / ``DB5.DBW 2`` → ``Direct`` with ``db`` set;
- ``"Symbol"`` → whatever its address in the symbol table is;
- constants → ``Constant`` with the ACCU1 pattern (see ``constants``);
- ``P#DB42.member`` / ``P#"Data".member`` (awlsim extension, test instructions only) → the
  ``Constant`` STEP 7 writes as ``P#DB42.DBX 4.0``, with the member's type as ``pointee`` (a CALL
  turns it into ``P#DB42.DBX 4.0 INT 1`` for an ANY parameter);
- ``#str[i]`` / ``"DB".str[i]``: character ``i`` of a STRING, a CHAR at byte ``2 + i - 1`` of it
  (awlsim extension: STEP 7's STL has no index into a STRING; test instructions only).

Every failure is a diagnostic and ``None``; the caller goes on with the next instruction.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic
from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    Constant,
    ConstType,
    CounterRef,
    Direct,
    MemoryIndirect,
    MultiInstance,
    Operand,
    ParamRef,
    Register,
    RegisterIndirect,
    StatusCondition,
    TimerRef,
    Width,
)
from nasaq.lang.layout import Slot
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.stl import ast, constants
from nasaq.lang.stl.addresses import BLOCK_PREFIXES, AddressError, Parsed, parse_address, split_area
from nasaq.lang.stl.bind import BlockInfo, ProgramIndex
from nasaq.lang.stl.build import unquote_chars
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.mnemonics import NAMES
from nasaq.lang.tia_system import tia_system
from nasaq.lang.types import BlockType, DataType, Elementary, Field, StringType, width_of

REGISTERS = frozenset({"STW", "AR1", "AR2", "DBNO", "DBLG", "DINO", "DILG"})
STATUS_WORDS = {"OV": "OV", "OS": "OS", "BR": "BR", "BIE": "BR", "UO": "UO"}
STW_BITS = {
    "FC": "FC",
    "/FC": "FC",
    "ER": "FC",
    "/ER": "FC",
    "RLO": "RLO",
    "VKE": "RLO",
    "STA": "STA",
    "OR": "OR",
    "OS": "OS",
    "OV": "OV",
    "CC0": "CC0",
    "A0": "CC0",
    "CC1": "CC1",
    "A1": "CC1",
    "BR": "BR",
    "BIE": "BR",
}
STW_BIT_ORDER = ("FC", "RLO", "STA", "OR", "OS", "OV", "CC0", "CC1", "BR")
AREA_CROSSING = {"X": Width.BIT, "B": Width.BYTE, "W": Width.WORD, "D": Width.DWORD}
INDIRECT_TARGETS = {
    "T": "T",
    "C": "C",
    "Z": "C",
    "DB": "DB",
    "DI": "DI",
    "FC": "FC",
    "FB": "FB",
    "SFC": "SFC",
    "SFB": "SFB",
}
NUMBERED_TARGETS = {
    "TIMER": "T",
    "COUNTER": "C",
    "BLOCK_DB": "DB",
    "BLOCK_FC": "FC",
    "BLOCK_FB": "FB",
}
AREA_POINTER = {Area.DI: 0x85, Area.L: 0x86, Area.DB: 0x84}
_DB_VARIABLE_POINTER = re.compile(
    r'^P#(?:DB(?P<db>\d+)|"(?P<symbol>[^"]*)")(?P<path>(?:\.[^\W\d]\w*|\[[\d\s,]+\])+)$',
    re.IGNORECASE,
)
_POINTER_PATH = re.compile(r"\.([^\W\d]\w*)|\[([\d\s,]+)\]")


@dataclass(slots=True)
class Resolved:
    """An IR operand with the declared type of the variable it names (None for absolute
    addresses and constants) and the text as written, for messages."""

    operand: Operand | MultiInstance
    type: DataType | None
    text: str
    pointee: DataType | None = None  # P#DB42.member: the type of what the pointer points at


@dataclass(slots=True)
class Scope:
    index: ProgramIndex
    block: BlockInfo
    language: str
    test_ops: bool
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def file(self) -> str:
        return self.block.file

    def report(self, code: str, where: ast.Loc, **params: object) -> None:
        self.diagnostics.append(problem(code, self.file, where, **params))


def operand_text(node: ast.OperandNode) -> str:
    if isinstance(node, ast.AddressNode | ast.LiteralNode | ast.StatusNode):
        return node.text
    if isinstance(node, ast.BareNode):
        return f"{node.name} {node.arg}" if node.arg else node.name
    if isinstance(node, ast.SymbolNode):
        head = (
            f"#{node.name}" if node.local else node.name if node.absolute_db else f'"{node.name}"'
        )
        parts = [head]
        for part in node.path:
            if isinstance(part, list):
                parts.append("[" + ", ".join(str(i) for i in part) + "]")
            elif isinstance(part, ast.AddressNode):
                parts.append("." + part.text)
            else:
                parts.append("." + part)
        return "".join(parts)
    inner = operand_text(node.first)
    if node.second is not None:
        inner += ", " + operand_text(node.second)
    return f"{node.area or ''} [{inner}]".strip()


class Resolver:
    def __init__(self, scope: Scope) -> None:
        self.scope = scope
        self.index = scope.index
        self.layout = scope.index.layout
        self._locals: dict[str, tuple[Slot, bool]] | None = None
        self._known: dict[tuple[object, ...], Resolved] = {}

    # ---- entry ------------------------------------------------------------------------------

    def operand(self, node: ast.OperandNode) -> Resolved | None:
        """What an operand addresses. A block uses the same operands again and again (code
        that SCL generated, above all): one written the same way is resolved once, unless
        resolving it reported something (reported again at each use)."""
        key = cache_key(node)
        if key is None:
            return self._operand(node)
        found = self._known.get(key)
        if found is None:
            reported = len(self.scope.diagnostics)
            found = self._operand(node)
            if found is None or len(self.scope.diagnostics) != reported:
                return found
            self._known[key] = found
        return found

    def _operand(self, node: ast.OperandNode) -> Resolved | None:
        if isinstance(node, ast.AddressNode):
            return self.address(node.text, node.loc, node.text)
        if isinstance(node, ast.LiteralNode):
            return self.literal(node, node.text)
        text = operand_text(node)
        if isinstance(node, ast.StatusNode):
            return Resolved(StatusCondition(node.text), None, text)
        if isinstance(node, ast.BareNode):
            return self.bare(node, text)
        if isinstance(node, ast.IndirectNode):
            return self.indirect(node, text)
        if node.local:
            return self.local(node, text)
        return self.global_symbol(node, text)

    # ---- absolute ---------------------------------------------------------------------------

    def parsed_address(self, text: str, where: ast.Loc) -> Parsed | None:
        try:
            parsed = parse_address(text)
        except AddressError as error:
            self.scope.report("STL106", where, text=text, reason=str(error))
            return None
        if parsed.language is not None and parsed.language != self.scope.language:
            self.scope.report(
                "STL220",
                where,
                text=text,
                other=NAMES[parsed.language],
                used=NAMES[self.scope.language],
            )
        return parsed

    def address(self, text: str, where: ast.Loc, shown: str) -> Resolved | None:
        parsed = self.parsed_address(text, where)
        if parsed is None or not self.system_block_allowed(parsed, where, shown):
            return None
        if parsed.db is not None and self.optimized_absolute(parsed.db, where, shown):
            return None
        return Resolved(from_parsed(parsed), None, shown)

    def optimized_absolute(self, db: int, where: ast.Loc, text: str) -> bool:
        """STL604 for an absolute address in an optimized DB (TIA: it has none, STL names its
        variables); the code the SCL compiler writes for its own DBs is not checked."""
        index = self.scope.index
        if db not in index.optimized_dbs or self.scope.file in index.scl_files:
            return False
        self.scope.report("STL604", where, text=text, db=index.optimized_dbs[db])
        return True

    def system_block_allowed(self, parsed: Parsed, where: ast.Loc, text: str) -> bool:
        """awlsim's own system blocks (``SFC -3`` ...) are test instructions."""
        if parsed.kind == "block" and parsed.number < 0 and not self.scope.test_ops:
            self.scope.report("STL218", where, mnemonic=text)
            return False
        return True

    # ---- constants and words ----------------------------------------------------------------

    def literal(self, node: ast.LiteralNode, text: str) -> Resolved | None:
        if node.kind == "POINTER" and node.text[2:].startswith("#"):
            return self.local_pointer(node, text)
        if node.kind == "POINTER" and _DB_VARIABLE_POINTER.match(node.text):
            return self.db_variable_pointer(node, text)
        if node.kind == "TYPED" and not is_s7_1500(self.scope.index.profile):
            prefix = constants.typed_prefix(node.text)
            if prefix in constants.S7_1500_TYPED:  # STL stays S7-300/400 there
                what = f"{prefix}#"
                self.scope.report("STL500", node.loc, what=what, profile=self.scope.index.profile)
                return None
        try:
            raw = unquote_chars(node.text) if node.kind == "CHARS" else None
            constant = constants.parse_literal(node.kind, node.text, raw)
        except constants.ConstantError as error:
            self.scope.report(error.code, node.loc, **error.params)
            return None
        return Resolved(constant, None, text)

    def db_variable_pointer(self, node: ast.LiteralNode, text: str) -> Resolved | None:
        """``P#DB42.ARR1[2].V2`` / ``P#"Data".V``: awlsim's pointer to a DB variable, made the
        STEP 7 constant ``P#DB42.DBX 44.0`` (the DB number lives on in the text, as in STEP 7's
        ``P#DB42.DBX 44.0`` for a POINTER or ANY parameter)."""
        if not self.scope.test_ops:
            reason = "a pointer to a DB variable is an awlsim extension (enable test instructions)"
            self.scope.report("STL107", node.loc, text=text, reason=reason)
            return None
        match = _DB_VARIABLE_POINTER.match(node.text)
        assert match is not None
        head = f"DB {match['db']}" if match["db"] else match["symbol"]
        path: list[str | list[int] | ast.AddressNode] = []
        for member, index in _POINTER_PATH.findall(match["path"]):
            path.append(member if member else [int(part) for part in index.split(",")])
        symbolic = ast.SymbolNode(head, False, path, node.loc, absolute_db=bool(match["db"]))
        target = self.global_symbol(symbolic, text)
        if target is None:
            return None
        place = target.operand
        if not isinstance(place, Direct) or place.db is None:
            self.scope.report("STL235", node.loc, name=text, reason="no pointer can be made to it")
            return None
        bits = place.byte * 8 + place.bit
        shown = f"P#DB{place.db}.DBX {place.byte}.{place.bit}"
        constant = Constant(ConstType.POINTER, (AREA_POINTER[Area.DB] << 24) | bits, bits, shown)
        return Resolved(constant, None, text, pointee=target.type)

    def local_pointer(self, node: ast.LiteralNode, text: str) -> Resolved | None:
        """``P##var``: a pointer to a local variable (FB: DI offset; temp: L; FC parameter: V,
        whose offset the CPU knows only at run time, so the value is the parameter index)."""
        name = node.text[3:]
        target = self.local(ast.SymbolNode(name, True, [], node.loc), text, quiet_types=True)
        if target is None:
            return None
        operand = target.operand
        if isinstance(operand, RegisterIndirect | Direct) and operand.area in AREA_POINTER:
            bits = (
                operand.offset_bits
                if isinstance(operand, RegisterIndirect)
                else (operand.byte * 8 + operand.bit)
            )
            pattern = (AREA_POINTER[operand.area] << 24) | bits
            return Resolved(Constant(ConstType.POINTER, pattern, bits, node.text), None, text)
        if isinstance(operand, ParamRef):
            constant = Constant(ConstType.POINTER, 0x87000000, operand.index, node.text)
            return Resolved(constant, None, text)
        self.scope.report("STL235", node.loc, name=text, reason="no pointer can be made to it")
        return None

    def bare(self, node: ast.BareNode, text: str) -> Resolved | None:
        name = node.name.upper()
        if name.startswith("__"):
            return self.test_operand(node, name, text)
        if node.arg is None:
            if name in REGISTERS:
                return Resolved(Register(name), None, text)
            if name in STATUS_WORDS:
                return Resolved(StatusCondition(STATUS_WORDS[name]), None, text)
            if name in constants.BOOLEANS:
                return Resolved(constants.boolean(name), None, text)
            symbol = self.index.symbols.lookup(node.name)
            if symbol is not None:
                return self.symbol_target(symbol.parsed, symbol.type, [], node.loc, text)
            if self.declares_locally(name):  # STEP 7 Classic: a local name without its #
                return self.local(ast.SymbolNode(node.name, True, [], node.loc), text)
            system = tia_system(node.name)  # CALL PNIO_RECV: an instruction TIA writes bare
            if system is not None:
                self.scope.report("STL920", node.loc, name=system)
                return None
        self.scope.report("STL205", node.loc, name=text)
        return None

    def test_operand(self, node: ast.BareNode, name: str, text: str) -> Resolved | None:
        if not self.scope.test_ops:
            self.scope.report("STL218", node.loc, mnemonic=name)
            return None
        arg = (node.arg or "").upper()
        register: str | None = None
        if name == "__ACCU" and arg in ("1", "2", "3", "4"):
            register = f"ACCU{arg}"
        elif name == "__AR" and arg in ("1", "2"):
            register = f"AR{arg}"
        elif name == "__DBR" and arg in ("1", "2"):
            register = "DBNO" if arg == "1" else "DINO"
        elif name == "__STW":
            bit = STW_BITS.get(arg)
            if bit is None and arg.isdigit() and int(arg) < len(STW_BIT_ORDER):
                bit = STW_BIT_ORDER[int(arg)]
            if bit is not None:
                register = f"STW.{bit}"
        elif name in constants.TEST_CONSTANTS and not arg:
            pattern = constants.TEST_CONSTANTS[name]
            return Resolved(Constant(ConstType.REAL, pattern, 0.0, name), None, text)
        if register is None:
            self.scope.report("STL205", node.loc, name=text)
            return None
        return Resolved(Register(register), None, text)

    # ---- indirect ---------------------------------------------------------------------------

    def indirect(self, node: ast.IndirectNode, text: str) -> Resolved | None:
        prefix = node.area
        width: Width | None = None
        area: Area | None = None
        target: str | None = None
        if prefix is None:
            width = Width.BIT
        elif prefix in AREA_CROSSING:
            width = AREA_CROSSING[prefix]
        elif prefix in INDIRECT_TARGETS:
            target = INDIRECT_TARGETS[prefix]
        else:
            found = split_area(prefix)
            if found is None:
                self.scope.report("STL106", node.loc, text=text, reason=f"{prefix} is not an area")
                return None
            area, width, _ = found
        if node.second is not None:
            return self.register_indirect(node, text, width, area, target)
        if prefix in AREA_CROSSING or prefix is None:
            self.scope.report("STL106", node.loc, text=text, reason="use [AR1, P#x.y] here")
            return None
        pointer = self.operand(node.first)
        if pointer is None:
            return None
        if not isinstance(pointer.operand, Direct | RegisterIndirect):
            self.scope.report(
                "STL106",
                node.loc,
                text=text,
                reason="the pointer must be a memory word or double word (M, L, DB, DI)",
            )
            return None
        needed = Width.WORD if target is not None else Width.DWORD
        if pointer.operand.width is not needed or pointer.operand.area not in (
            Area.M,
            Area.L,
            Area.DB,
            Area.DI,
        ):
            kind = "word" if needed is Width.WORD else "double word"
            self.scope.report(
                "STL106",
                node.loc,
                text=text,
                reason=f"the pointer must be a {kind} in M, L, DB or DI",
            )
            return None
        return Resolved(MemoryIndirect(width, area, pointer.operand, target), None, text)

    def register_indirect(
        self,
        node: ast.IndirectNode,
        text: str,
        width: Width | None,
        area: Area | None,
        target: str | None,
    ) -> Resolved | None:
        first, second = node.first, node.second
        register = first.name.upper() if isinstance(first, ast.BareNode) else ""
        if register not in ("AR1", "AR2") or target is not None or width is None:
            self.scope.report("STL106", node.loc, text=text, reason="write [AR1, P#x.y]")
            return None
        offset = self.operand(second) if second is not None else None
        if offset is None:
            return None
        constant = offset.operand
        if (
            not isinstance(constant, Constant)
            or constant.type is not ConstType.POINTER
            or (constant.pattern >> 24)
        ):
            self.scope.report(
                "STL106", node.loc, text=text, reason="the offset is a pointer like P#2.0"
            )
            return None
        return Resolved(
            RegisterIndirect(width, area, int(register[2]), constant.pattern & 0x7FFFF), None, text
        )

    # ---- symbolic ---------------------------------------------------------------------------

    def locals(self) -> dict[str, tuple[Slot, bool]]:
        """The block's variables by upper-case name: (slot, in the instance data)."""
        if self._locals is None:
            block = self.scope.block
            found: dict[str, tuple[Slot, bool]] = {}
            if block.kind is BlockKind.FB:
                for slot in self.index.instance_layout(block):
                    found.setdefault(slot.name.upper(), (slot, True))
            for slot in self.index.temp_layout(block):
                found.setdefault(slot.name.upper(), (slot, False))
            self._locals = found
        return self._locals

    def local(self, node: ast.SymbolNode, text: str, quiet_types: bool = False) -> Resolved | None:
        block = self.scope.block
        wanted = node.name.upper()
        variable = self.locals().get(wanted)
        if variable is not None:
            slot, in_instance = variable
            if not in_instance:
                return self.slot_operand(slot, node, text, Area.L, register=False)
            if slot.by_reference and node.path:
                self.scope.report(
                    "STL235",
                    node.loc,
                    name=text,
                    reason="members of a structured IN_OUT parameter are not supported",
                )
                return None
            return self.slot_operand(slot, node, text, Area.DI, register=True)
        if block.kind is BlockKind.FC:
            for param in block.params:
                if param.name.upper() == wanted:
                    return self.parameter(param.index, param.name, param.type, node, text)
        constant = block.constants.get(wanted)
        if constant is not None:
            return self.local_constant(constant, node, text)
        if wanted in block.untyped:
            return None  # its type was reported at the declaration
        self.scope.report("STL206", node.loc, name=f"#{node.name}", block=block.label)
        return None

    def declares_locally(self, wanted: str) -> bool:
        """Whether the block declares ``wanted`` (upper case): a variable, parameter or constant."""
        block = self.scope.block
        return (
            wanted in self.locals()
            or wanted in block.constants
            or wanted in block.untyped
            or any(param.name.upper() == wanted for param in block.params)
        )

    def local_constant(self, constant: Field, node: ast.SymbolNode, text: str) -> Resolved | None:
        """``#Limit`` of a TIA ``VAR CONSTANT`` section: its value, as if written in place."""
        values = constant.initial if isinstance(constant.initial, list) else []
        value = values[0] if len(values) == 1 else None
        if node.path or not isinstance(value, ast.ValueNode):
            self.scope.report("STL601", node.loc, name=text)
            return None
        if value.kind == "IDENT":
            if value.text.upper() not in constants.BOOLEANS:
                self.scope.report("STL601", node.loc, name=text)
                return None
            return Resolved(constants.boolean(value.text.upper()), None, text)
        return self.literal(ast.LiteralNode(value.kind, value.text, node.loc), text)

    def parameter(
        self, index: int, name: str, data_type: DataType, node: ast.SymbolNode, text: str
    ) -> Resolved | None:
        if not node.path:
            return Resolved(ParamRef(index, name, width_of(data_type)), data_type, text)
        root = self.layout.place([Field(name, data_type)])[0]
        slot = self.walk(root, node.path, node.loc, text)
        if slot is None:
            return None
        operand = ParamRef(index, name, width_of(slot.type), slot.offset_bits)
        return Resolved(operand, slot.type, text)

    def slot_operand(
        self, root: Slot, node: ast.SymbolNode, text: str, area: Area, register: bool
    ) -> Resolved | None:
        slot = self.walk(root, node.path, node.loc, text)
        if slot is None:
            return None
        if isinstance(slot.type, BlockType) and slot.type.kind in ("FB", "SFB") and register:
            return Resolved(MultiInstance(slot.offset_bits, slot.name), slot.type, text)
        width = width_of(slot.type) or Width.BYTE
        place: Direct | RegisterIndirect
        if register:
            place = RegisterIndirect(width, area, 2, slot.offset_bits)
        else:
            byte, bit = divmod(slot.offset_bits, 8)
            place = Direct(area, width, byte, bit)
        return self.numbered(place, slot.type, text)

    @staticmethod
    def numbered(place: Direct | RegisterIndirect, data_type: DataType, text: str) -> Resolved:
        """A TIMER/COUNTER/BLOCK_* variable holds a number: it is used through that word,
        like ``SP T [DIW 4]`` (how STEP 7 compiles an FB's timer parameter)."""
        target = NUMBERED_TARGETS.get(data_type.name) if isinstance(data_type, Elementary) else None
        if target is None:
            return Resolved(place, data_type, text)
        if isinstance(place, Direct):
            word: Direct | RegisterIndirect = Direct(
                place.area, Width.WORD, place.byte, 0, place.db
            )
        else:
            word = RegisterIndirect(Width.WORD, place.area, place.register, place.offset_bits)
        return Resolved(MemoryIndirect(None, None, word, target), data_type, text)

    def walk(
        self, slot: Slot, path: list[str | list[int] | ast.AddressNode], where: ast.Loc, text: str
    ) -> Slot | None:
        current = slot
        shown = current.name
        for part in path:
            if isinstance(part, list) and isinstance(current.type, StringType):
                found = self.string_character(current, part, where, shown)
                if found is None:
                    return None
                current = found
                shown += f"[{part[0]}]"
            elif isinstance(part, list):
                found = self.layout.element(current, part)
                if found is None:
                    self.scope.report("STL217", where, name=shown, index=", ".join(map(str, part)))
                    return None
                current = found
                shown += "[" + ", ".join(map(str, part)) + "]"
            else:
                member = part.text if isinstance(part, ast.AddressNode) else part
                found = current.member(member)
                if found is None:
                    self.scope.report("STL216", where, name=shown, member=member)
                    return None
                current = found
                shown += "." + member
        return current

    def string_character(
        self, string: Slot, index: list[int], where: ast.Loc, shown: str
    ) -> Slot | None:
        """``#s[i]``: the i-th character of a STRING (awlsim extension, test instructions)."""
        assert isinstance(string.type, StringType)
        if not self.scope.test_ops:
            reason = (
                "STEP 7 has no index into a STRING (an awlsim extension, accepted with test "
                "instructions); its characters start at byte 2 of it"
            )
            self.scope.report("STL235", where, name=shown, reason=reason)
            return None
        if len(index) != 1 or not 1 <= index[0] <= string.type.length:
            self.scope.report("STL217", where, name=shown, index=", ".join(map(str, index)))
            return None
        offset = string.offset_bits + 16 + (index[0] - 1) * 8
        return Slot(f"{string.name}[{index[0]}]", Elementary("CHAR"), offset, 8)

    def declares(self, db_number: int, name: str) -> bool:
        """Whether DB ``db_number`` declares a variable ``name`` at its top level."""
        db = self.index.blocks.get((BlockKind.DB, db_number))
        if db is None or db.db_type is None or not name.isidentifier():
            return False
        return self.index.db_root(db).member(name) is not None

    def global_symbol(self, node: ast.SymbolNode, text: str) -> Resolved | None:
        if node.absolute_db:
            parsed = self.parsed_address(node.name, node.loc)
            if parsed is None:
                return None
            return self.symbol_target(parsed, "", node.path, node.loc, text)
        symbol = self.index.symbols.lookup(node.name)
        if symbol is None:
            self.scope.report("STL205", node.loc, name=f'"{node.name}"')
            return None
        return self.symbol_target(symbol.parsed, symbol.type, node.path, node.loc, text)

    def symbol_target(
        self,
        parsed: Parsed,
        type_name: str,
        path: list[str | list[int] | ast.AddressNode],
        where: ast.Loc,
        text: str,
    ) -> Resolved | None:
        if not path:
            if not self.system_block_allowed(parsed, where, text):
                return None
            declared = _symbol_type(type_name)
            return Resolved(from_parsed(parsed), declared, text)
        if parsed.kind != "block" or parsed.block is not BlockKind.DB:
            self.scope.report("STL216", where, name=text.split(".")[0], member=_first(path))
            return None
        first = path[0]
        if isinstance(first, ast.AddressNode) and self.declares(parsed.number, first.text):
            path = [first.text, *path[1:]]  # "Data".A1: a member whose name looks like an address
        elif isinstance(first, ast.AddressNode):
            if first.text.isidentifier() and not _is_address(first.text):
                self.scope.report("STL216", where, name=text.split(".")[0], member=first.text)
                return None
            found = self.parsed_address(first.text, first.loc)
            if found is None:
                return None
            if found.kind != "memory" or found.area is not Area.DB or found.db is not None:
                self.scope.report("STL216", where, name=text.split(".")[0], member=first.text)
                return None
            if self.optimized_absolute(parsed.number, where, text):
                return None
            operand = Direct(
                Area.DB, found.width or Width.BYTE, found.byte, found.bit, parsed.number
            )
            return Resolved(operand, None, text)
        db = self.index.blocks.get((BlockKind.DB, parsed.number))
        if db is None or db.db_type is None:
            self.scope.report("STL213", where, block=f"DB {parsed.number}")
            return None
        if isinstance(first, str) and first.upper() in db.untyped:
            return None  # its type was reported at the declaration
        slot = self.walk(self.index.db_root(db), path, where, text)
        if slot is None:
            return None
        byte, bit = divmod(slot.offset_bits, 8)
        width = width_of(slot.type) or Width.BYTE
        return self.numbered(Direct(Area.DB, width, byte, bit, parsed.number), slot.type, text)


def cache_key(node: ast.OperandNode, head: str = "") -> tuple[object, ...] | None:
    """What the resolution of an operand depends on (the operand as written, not where), after
    ``head``; None for those resolved at every use: symbols with an absolute part (``"DB".DBW
    2``, rare). A flat tuple where it can be: it is made for every use."""
    kind = type(node)
    if type(node) is ast.SymbolNode:
        if not node.path:
            return (head, kind, node.name, node.local, node.absolute_db)
        path: list[object] = []
        for part in node.path:
            if isinstance(part, ast.AddressNode):
                return None
            path.append(part if isinstance(part, str) else tuple(part))
        return (head, kind, node.name, node.local, node.absolute_db, *path)
    if isinstance(node, ast.LiteralNode):
        return (head, kind, node.kind, node.text)
    if isinstance(node, ast.AddressNode | ast.StatusNode):
        return (head, kind, node.text)
    if isinstance(node, ast.BareNode):
        return (head, kind, node.name, node.arg)
    if isinstance(node, ast.IndirectNode):  # DBW [AR1, P#0.0], I [MD 2]
        first = cache_key(node.first)
        second = () if node.second is None else cache_key(node.second)
        if first is None or second is None:
            return None
        return (head, kind, node.area, first, second)
    return None


def _is_address(text: str) -> bool:
    try:
        parse_address(text)
    except AddressError:
        return False
    return True


def from_parsed(parsed: Parsed) -> Operand:
    if parsed.kind == "timer":
        return TimerRef(parsed.number)
    if parsed.kind == "counter":
        return CounterRef(parsed.number)
    if parsed.kind == "block":
        assert parsed.block is not None
        return BlockRef(parsed.block, parsed.number)
    assert parsed.area is not None
    assert parsed.width is not None
    return Direct(parsed.area, parsed.width, parsed.byte, parsed.bit, parsed.db)


def _symbol_type(type_name: str) -> DataType | None:
    from nasaq.lang.types import elementary

    found = elementary(type_name) if type_name else None
    return found if isinstance(found, Elementary) else None


def _first(path: list[str | list[int] | ast.AddressNode]) -> str:
    first = path[0]
    if isinstance(first, ast.AddressNode):
        return first.text
    return str(first)


__all__ = ["BLOCK_PREFIXES", "Resolved", "Resolver", "Scope", "from_parsed", "operand_text"]

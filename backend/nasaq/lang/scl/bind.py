"""The project index of S7-SCL sources: blocks by kind, number and name, their interfaces as
``nasaq.lang.types`` types, and the standard S7-300/400 layout (``nasaq.lang.layout``) of
instance data, DBs and the L stack.

Numbering follows TIA Portal's automatic numbering:
- an absolute name (``FB10``, ``DB3``) keeps its number;
- a name the symbol table gives to a block of the same kind takes that number;
- the OB called ``Main`` is OB 1; any other OB is numbered by its event name as TIA does
  (``nasaq.lang.tia_names``: "Startup" OB 100, "Cyclic interrupt" OB 35/30 ..., on the
  S7-1200/1500 family any other name OB 123 up); on S7-300/400 an OB that is no event has no
  number (SCL205);
- every other FB, FC, DB (and UDT) takes the lowest number of its kind that no block uses, in
  source order, starting at 1. The absolute and symbol-table numbers are collected first, so a
  later ``FB1`` is never given away.
``PROGRAM`` is S7-SCL's alias of FUNCTION_BLOCK (the Main program, or ``PROGRAM OB1``, is an OB).

Names are case-insensitive (``casefold``). Declaration problems are ``SCL2xx`` diagnostics; a
variable whose type is unknown is kept with the ``UNKNOWN`` marker type so that later uses of it
do not produce further messages.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang import dtl, tia_iec, wide_text
from nasaq.lang.layout import Expansion, Layout, RecursiveTypeError, Slot
from nasaq.lang.ob_start_info import start_info
from nasaq.lang.profiles import DEFAULT_PROFILE, S7_1500_TYPES, is_s7_1500
from nasaq.lang.scl import ast, descriptor, jump_labels, optimized
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.symbols import Symbol, SymbolTable
from nasaq.lang.system_blocks import (
    F_TRIG_SFB,
    R_TRIG_SFB,
    SFB_INTERFACES,
    SFB_NAMES,
    s7_1500_only,
    sfb_number,
)
from nasaq.lang.system_types import system_fb_sections, system_type
from nasaq.lang.tia_names import ob_event, ob_number
from nasaq.lang.tia_system import tia_system
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
    elementary,
)

KIND_OF_KEYWORD = {
    "ORGANIZATION_BLOCK": BlockKind.OB,
    "FUNCTION_BLOCK": BlockKind.FB,
    "PROGRAM": BlockKind.FB,
    "FUNCTION": BlockKind.FC,
    "DATA_BLOCK": BlockKind.DB,
    "TYPE": BlockKind.UDT,
}
# IEC timers and counters as multi-instances: the system function blocks of S7-300/400; the
# edge detectors R_TRIG and F_TRIG (TIA Portal, every CPU family), numbered by Nasaq.
IEC_INSTANCES = {"CTU": 0, "CTD": 1, "CTUD": 2, "TP": 3, "TON": 4, "TOF": 5}
IEC_INSTANCES |= {"R_TRIG": R_TRIG_SFB, "F_TRIG": F_TRIG_SFB}
# TIA Portal's instance types of the S7-1200/1500 family (SCL500 under a classic profile), each
# laid out as the SFB that runs it: IEC_TIMER serves TP, TON and TOF (one layout), IEC_COUNTER
# is laid out as CTUD (``"C".CTU(...)`` on it runs CTUD, ``typecheck.iec_calls``).
TIA_IEC_TYPES = {
    "TP_TIME": 3,
    "TON_TIME": 4,
    "TOF_TIME": 5,
    "IEC_TIMER": 4,
    "CTU_INT": 0,
    "CTD_INT": 1,
    "CTUD_INT": 2,
    "IEC_COUNTER": 2,
}
TIA_IEC_TYPES |= tia_iec.INSTANCE_TYPES  # IEC_DCOUNTER ..., IEC_LTIMER (``nasaq.lang.tia_iec``)
AUTO_NUMBERED = (BlockKind.FB, BlockKind.FC, BlockKind.DB, BlockKind.UDT)
SECTION_OF_KEYWORD = {
    "VAR_INPUT": "IN",
    "VAR_OUTPUT": "OUT",
    "VAR_IN_OUT": "IN_OUT",
    "VAR": "STAT",
    "VAR_STAT": "STAT",
    "VAR_TEMP": "TEMP",
}
# A variable whose declared type is unknown (already reported): never reported again.
# Parameter types of the S7-1200/1500 family that are no elementary type (SCL500 under a classic
# profile; ``scl.descriptor`` under S7-1500).
_PARAMETER_ONLY = frozenset({"VARIANT", "DB_ANY"})
UNKNOWN = Elementary("UNKNOWN")
VOID = Elementary("VOID")


@dataclass(slots=True)
class Constant:
    """A ``CONST`` (or TIA ``VAR CONSTANT``) entry: its value when it is a number."""

    name: str
    node: ast.Expr
    value: int | float | None


@dataclass(slots=True)
class Variable:
    """A declared interface variable: ``section`` IN, OUT, IN_OUT, STAT or TEMP."""

    name: str
    section: str
    type: DataType
    loc: ast.Loc


@dataclass(slots=True)
class SclBlock:
    kind: BlockKind
    number: int
    name: str  # as written (without quotes), or the symbol of an absolute name
    file: str
    node: ast.Block
    sections: list[tuple[str, list[Field]]] = field(default_factory=list)
    variables: dict[str, Variable] = field(default_factory=dict)  # casefolded name
    constants: dict[str, Constant] = field(default_factory=dict)  # casefolded name
    return_type: DataType | None = None
    db_type: DataType | None = None  # DB: StructType, or BlockType of its FB/UDT
    labels: set[str] = field(default_factory=set)  # casefolded
    external: bool = False  # compiled by another front end (see ``SclIndex.add_external``)
    optimized: bool = False  # S7_Optimized_Access := 'TRUE' under S7-1500 (``scl.optimized``)

    @property
    def label(self) -> str:
        return f"{self.kind.value} {self.number}"

    def fields(self, section: str) -> list[Field]:
        return [declared for name, group in self.sections if name == section for declared in group]


def _start_information(info: SclBlock) -> None:
    """An optimized OB's event inputs TIA declares itself (``nasaq.lang.ob_start_info``)."""
    inputs = start_info(info.name, info.number)
    taken = info.variables  # a TEMP of the same name is the user's own
    fields = [Field(n, Elementary(kind), None) for n, kind in inputs if n.casefold() not in taken]
    if fields:
        info.sections.insert(0, ("IN", fields))
    where = info.node.name.loc
    for declared in fields:
        info.variables.setdefault(
            declared.name.casefold(), Variable(declared.name, "IN", declared.type, where)
        )


class SclIndex:
    """All blocks of the sources, numbered, declared and laid out (lazily, cached)."""

    def __init__(self, symbols: SymbolTable | None = None, profile: str = DEFAULT_PROFILE) -> None:
        self.symbols = symbols if symbols is not None else SymbolTable()
        self.profile = profile  # ``nasaq.lang.profiles``: what the checker accepts depends on it
        self.blocks: dict[tuple[BlockKind, int], SclBlock] = {}
        self.by_name: dict[str, SclBlock] = {}
        self.layout = Layout(self._expand)
        self.diagnostics: list[Diagnostic] = []
        # Instance DBs no DATA_BLOCK declares (``FB1.DB5(...)``, a symbol ``DB 5`` of type
        # ``FB 1``): DB number → its FB. Filled by the checker (``typecheck.instances``).
        self.implicit_dbs: dict[int, BlockType] = {}
        self._instances: dict[tuple[BlockKind, int], tuple[list[Slot], int]] = {}
        self._dbs: dict[int, tuple[list[Slot], int]] = {}
        self._temps: dict[tuple[BlockKind, int], tuple[list[Slot], int]] = {}

    # ---- lookup -----------------------------------------------------------------------------

    def get(self, kind: BlockKind, number: int) -> SclBlock | None:
        return self.blocks.get((kind, number))

    def named(self, name: str) -> SclBlock | None:
        """A block by its name (``Motor``), its absolute id (``FB10``) or its symbol."""
        found = self.by_name.get(name.casefold())
        if found is not None:
            return found
        absolute = _absolute(name)
        if absolute is not None:
            return self.blocks.get(absolute)
        symbol = self.symbols.get(name)
        if symbol is not None and symbol.parsed.kind == "block" and symbol.parsed.block:
            return self.blocks.get((symbol.parsed.block, symbol.parsed.number))
        return None

    def symbol(self, name: str) -> Symbol | None:
        return self.symbols.get(name)

    def db_type_of(self, number: int) -> DataType | None:
        """What DB ``number`` is made of: its declaration, or the FB of an implicit instance DB."""
        found = self.blocks.get((BlockKind.DB, number))
        if found is not None:
            return found.db_type
        return self.implicit_dbs.get(number)

    def __iter__(self) -> Iterator[SclBlock]:
        return iter(sorted(self.blocks.values(), key=lambda b: (b.kind.value, b.number)))

    # ---- blocks of other languages ----------------------------------------------------------

    def add_external(self, kind: BlockKind, number: int, name: str, file: str) -> SclBlock:
        """A block compiled by another front end (STL): its number is taken, its name known;
        its interface comes later (``SclBlock.sections``, ``return_type``), before checking."""
        keyword = {v: k for k, v in KIND_OF_KEYWORD.items() if k != "PROGRAM"}[kind]
        node = ast.Block(keyword, ast.BlockName(name or f"{kind.value}{number}", absolute=not name))
        info = SclBlock(kind, number, name or f"{kind.value}{number}", file, node, external=True)
        self.blocks[(kind, number)] = info
        if name:
            self.by_name[name.casefold()] = info
        return info

    # ---- numbering --------------------------------------------------------------------------

    def add_sources(self, sources: list[ast.SourceFile]) -> None:
        """Numbers and declares every block of ``sources`` (call once, with all of them)."""
        pending: list[tuple[ast.Block, str, BlockKind]] = []
        placed: list[SclBlock] = []
        for source in sources:
            for node in source.blocks:
                kind = KIND_OF_KEYWORD.get(node.kind.upper())
                if kind is None:
                    continue
                found = self._explicit(node, source.file, kind)
                if isinstance(found, tuple):
                    info = self._register(node, source.file, *found)
                    if info is not None:
                        placed.append(info)
                elif found is None:
                    pending.append((node, source.file, kind))
        for node, file, kind in pending:
            if kind is BlockKind.OB:
                event_number = self._ob_number(node, file)
                if event_number is None:
                    continue
                number = event_number
            else:
                number = 1
                while (kind, number) in self.blocks:
                    number += 1
            info = self._register(node, file, kind, number)
            if info is not None:
                placed.append(info)
        for info in placed:
            self._declare(info)

    def _explicit(
        self, node: ast.Block, file: str, kind: BlockKind
    ) -> tuple[BlockKind, int] | bool | None:
        """The block's id when its name fixes it; None: to be numbered; False: reported."""
        name = node.name
        if name.absolute:
            absolute = _absolute(name.text)
            wanted = (BlockKind.OB, BlockKind.FB) if node.kind.upper() == "PROGRAM" else (kind,)
            if absolute is None or absolute[0] not in wanted:
                self.diagnostics.append(
                    problem("SCL204", file, name.loc, name=name.text, kind=kind.value)
                )
                return False
            return absolute
        symbol = self.symbols.get(name.text)
        if symbol is not None and symbol.parsed.kind == "block" and symbol.parsed.block is kind:
            return kind, symbol.parsed.number
        program = node.kind.upper() == "PROGRAM"  # a FUNCTION_BLOCK called Main is an FB
        if name.text.casefold() == "main" and (kind is BlockKind.OB or program):
            return BlockKind.OB, 1
        return None

    def _ob_number(self, node: ast.Block, file: str) -> int | None:
        """An OB named by its event, as TIA numbers it (``nasaq.lang.tia_names``); reported
        when there is no number for it."""
        name = node.name.text
        taken = {number for kind, number in self.blocks if kind is BlockKind.OB}
        number = ob_number(name, taken, self.profile)
        if number is not None:
            return number
        event = ob_event(name)
        if event is None and optimized.marked(node):
            # TIA's further program-cycle OB of an optimized (S7-1200/1500) source.
            what = f'The organization block "{name}" (a program-cycle OB numbered from 123)'
            self.diagnostics.append(
                problem("SCL500", file, node.name.loc, what=what, profile=self.profile)
            )
            return None
        if event is None:
            self.diagnostics.append(problem("SCL205", file, node.name.loc, name=name))
            return None
        numbers = ", ".join(str(n) for n in event.classic)
        self.diagnostics.append(problem("SCL602", file, node.name.loc, name=name, numbers=numbers))
        return None

    def _register(
        self, node: ast.Block, file: str, kind: BlockKind, number: int
    ) -> SclBlock | None:
        key = node.name.text.casefold()
        first = self.blocks.get((kind, number)) or (
            None if node.name.absolute else self.by_name.get(key)
        )
        if first is not None:
            self.diagnostics.append(
                problem(
                    "SCL203",
                    file,
                    node.name.loc,
                    block=node.name.text,
                    file=first.file,
                    line=first.node.loc.line,
                )
            )
            return None
        name = node.name.text
        if node.name.absolute:
            symbol = self.symbols.block_symbol(kind, number)
            name = symbol.name if symbol is not None else name
        info = SclBlock(kind, number, name, file, node)
        self.blocks[(kind, number)] = info
        if not node.name.absolute:
            self.by_name[key] = info
        return info

    # ---- declarations -----------------------------------------------------------------------

    def _declare(self, info: SclBlock) -> None:
        node = info.node
        jump_labels.rejoin(node.code)
        optimized.declare(self, info)
        for section in node.sections:
            if isinstance(section, ast.ConstSection):
                for const in section.decls:
                    if isinstance(const, ast.ConstDecl):
                        value = self.const_value(info, const.value)
                        info.constants[const.name.casefold()] = Constant(
                            const.name, const.value, value
                        )
            elif isinstance(section, ast.LabelSection):
                info.labels.update(label.casefold() for label in section.names)
            elif _is_constant_section(section):
                # first, as CONST: TIA exports VAR CONSTANT after the arrays it bounds
                for decl in section.decls:
                    if isinstance(decl, ast.VarDecl) and not decl.init:
                        _default_constant(info, decl)
                    elif isinstance(decl, ast.VarDecl) and decl.init:
                        first = decl.init[0]
                        if not isinstance(first, ast.InitRepeat | ast.InitList | ast.InitStruct):
                            for part in decl.names:
                                value = self.const_value(info, first)
                                info.constants[part.name.casefold()] = Constant(
                                    part.name, first, value
                                )
        for section in node.sections:
            if not isinstance(section, ast.VarSection) or _is_constant_section(section):
                continue
            kind = section.kind.upper()
            name = SECTION_OF_KEYWORD.get(kind, "STAT")
            if info.kind in (BlockKind.FC, BlockKind.OB) and name == "STAT":
                name = "TEMP"  # VAR of an FC or OB is temporary
            fields = self._fields(info, section.decls, name)
            info.sections.append((name, fields))
        if info.kind is BlockKind.OB and info.optimized and not info.fields("IN"):
            _start_information(info)
        if node.return_type is not None:
            info.return_type = self.type_of(info, node.return_type)
        if info.kind in (BlockKind.DB, BlockKind.UDT):
            info.db_type = self._db_type(info)

    def _fields(
        self, info: SclBlock, decls: list[ast.VarDecl | ast.Bad], section: str | None
    ) -> list[Field]:
        fields: list[Field] = []
        seen: set[str] = set()
        for decl in decls:
            if not isinstance(decl, ast.VarDecl):
                continue
            data_type = self.type_of(info, decl.type)
            misplaced = not _takes_descriptor(info, section, data_type)
            if descriptor.is_descriptor(data_type) and misplaced:
                self.diagnostics.append(
                    problem(
                        "SCL550",
                        info.file,
                        decl.type.loc,
                        what=descriptor.describe(data_type),
                        section=section or "STRUCT",
                    )
                )
                data_type = UNKNOWN
            for part in decl.names:
                key = part.name.casefold()
                duplicate = key in seen or (section is not None and key in info.variables)
                if duplicate:
                    self.diagnostics.append(
                        problem("SCL206", info.file, part.loc, name=part.name, block=info.label)
                    )
                    continue
                seen.add(key)
                fields.append(Field(part.name, data_type, decl.init))
                if section is not None:
                    info.variables[key] = Variable(part.name, section, data_type, part.loc)
        return fields

    def _db_type(self, info: SclBlock) -> DataType | None:
        node = info.node
        for source in node.sources[1:]:
            self.diagnostics.append(problem("SCL207", info.file, source.loc, block=info.label))
        if node.sources:
            source = node.sources[0]
            if isinstance(source, ast.StructType):
                return self.type_of(info, source)
            made_of = self.named(source.text)
            iec = None
            if made_of is None and not source.quoted:
                iec = self._iec(info, source.text, source.loc)
            if iec is not None:  # a single-instance IEC timer/counter DB (TIA)
                return iec if iec.number >= 0 else None
            if made_of is None or made_of.kind not in (BlockKind.FB, BlockKind.UDT):
                self._unknown_type(info, source.text, source.loc, source.quoted)
                return None
            return BlockType(made_of.kind.value, made_of.number)
        # TIA: a global DB declared with VAR sections
        fields = [declared for _section, group in info.sections for declared in group]
        return StructType(tuple(fields))

    def type_of(self, info: SclBlock, node: ast.TypeNode) -> DataType:
        """The type a declaration names; unknown types are reported and give ``UNKNOWN``."""
        if isinstance(node, ast.StructType):
            return StructType(tuple(self._fields(info, node.members, None)))
        if isinstance(node, ast.ArrayType):
            dims: list[tuple[int, int]] = []
            if any(dim.low is None for dim in node.dims):  # ARRAY[*]
                return self._open_array(info, node)
            for dim in node.dims:
                low = self._bound(info, dim.low, dim.loc)
                high = None if low is None else self._bound(info, dim.high, dim.loc)
                if low is None or high is None:
                    return UNKNOWN
                if high < low:
                    self.diagnostics.append(
                        problem("SCL208", info.file, dim.loc, low=low, high=high)
                    )
                    return UNKNOWN
                dims.append((low, high))
            element = self.type_of(info, node.element)
            return UNKNOWN if element == UNKNOWN else ArrayType(tuple(dims), element)
        if not node.quoted:
            if node.name.upper() == "VOID":
                return VOID
            found = elementary(node.name)
            if isinstance(found, StringType):
                if found.wide and not is_s7_1500(self.profile):
                    self._s7_1500_only(info, found.name, node.loc)
                    return UNKNOWN
                if node.length is None:
                    return found
                length = self._bound(info, node.length, node.loc)
                if length is None:
                    return UNKNOWN
                if not 0 <= length <= wide_text.longest(found):
                    self.diagnostics.append(
                        problem(
                            "SCL218",
                            info.file,
                            node.length.loc,
                            text=length,
                            type=found.name,
                            hint="",
                        )
                    )
                    return UNKNOWN
                return StringType(length, found.wide)
            if found is not None:
                classic = not is_s7_1500(self.profile)
                if classic and type(found) is Elementary and found.name in S7_1500_TYPES:
                    self._s7_1500_only(info, found.name, node.loc)
                    return UNKNOWN
                return found
            if node.name.upper() in _PARAMETER_ONLY:
                if not is_s7_1500(self.profile):
                    self._s7_1500_only(info, node.name.upper(), node.loc)
                    return UNKNOWN
                if node.name.upper() == "VARIANT":
                    return descriptor.VARIANT
                return descriptor.DB_ANY
        block = self.named(node.name)
        if block is not None and block.kind in (BlockKind.FB, BlockKind.UDT):
            return BlockType(block.kind.value, block.number)
        iec = None if node.quoted else self._iec(info, node.name, node.loc)
        if iec is not None:
            return iec if iec.number >= 0 else UNKNOWN
        system = None if node.quoted else system_type(node.name)
        if system is not None:  # HW_HSC, TCON_IP_v4 ... (``nasaq.lang.system_types``)
            if not is_s7_1500(self.profile):
                self._s7_1500_only(info, node.name, node.loc)
                return UNKNOWN
            return system
        if not node.quoted and node.name.upper() == dtl.NAME:  # after the program's own types
            if not is_s7_1500(self.profile):
                self._s7_1500_only(info, dtl.NAME, node.loc)
                return UNKNOWN
            return dtl.DTL
        absolute = _absolute(node.name)
        if absolute is not None and absolute[0] is BlockKind.SFB and absolute[1] in SFB_INTERFACES:
            return BlockType("SFB", absolute[1])
        self._unknown_type(info, node.name, node.loc, node.quoted)
        return UNKNOWN

    def _open_array(self, info: SclBlock, node: ast.ArrayType) -> DataType:
        """``ARRAY[*]`` (S7-1200/1500): every dimension open (``ARRAY[*, *]``), at most six."""
        if not is_s7_1500(self.profile):
            self._s7_1500_only(info, "ARRAY[*]", node.dims[0].loc)
            return UNKNOWN
        bad = next((dim for dim in node.dims if dim.low is not None), None)
        if bad is not None or len(node.dims) > descriptor.MAX_DIMS:
            where = bad.loc if bad is not None else node.loc
            self.diagnostics.append(problem("SCL551", info.file, where))
            return UNKNOWN
        element = self.type_of(info, node.element)
        if element == UNKNOWN:
            return UNKNOWN
        return descriptor.open_array(element, len(node.dims))

    def _unknown_type(self, info: SclBlock, name: str, loc: ast.Loc, quoted: bool) -> None:
        """SCL202, or SCL920 for a TIA system block/type Nasaq does not simulate (TIA writes
        those unquoted; a quoted name is a block of the user's)."""
        system = None if quoted else tia_system(name)
        if system is not None:
            self.diagnostics.append(problem("SCL920", info.file, loc, name=system))
        else:
            self.diagnostics.append(problem("SCL202", info.file, loc, type=name))

    def _iec(self, info: SclBlock, name: str, loc: ast.Loc) -> BlockType | None:
        """The SFB instance type an IEC type name stands for; None for other names. A TIA
        S7-1200/1500 name under a classic profile is SCL500 (then an SFB numbered -1)."""
        upper = name.upper()
        number = IEC_INSTANCES.get(upper)
        if number is not None:
            return BlockType("SFB", number)
        number = TIA_IEC_TYPES.get(upper)
        if number is None:
            number = sfb_number(upper)  # PID_Compact, TCON ... (``nasaq.lang.system_blocks``)
            if number is None:
                return None
            if not s7_1500_only(number):
                return BlockType("SFB", number)
        if not is_s7_1500(self.profile):
            named = upper if upper in TIA_IEC_TYPES else SFB_NAMES.get(number, upper)
            self._s7_1500_only(info, named, loc)  # (TON_TIME, IEC_DCOUNTER as written)
            return BlockType("SFB", -1)
        return BlockType("SFB", number)

    def _s7_1500_only(self, info: SclBlock, what: str, loc: ast.Loc) -> None:
        """SCL500 under a classic profile (``ARRAY[*]``, VARIANT and DB_ANY run under S7-1500:
        ``scl.descriptor``)."""
        if is_s7_1500(self.profile):
            return
        self.diagnostics.append(problem("SCL500", info.file, loc, what=what, profile=self.profile))

    def _bound(self, info: SclBlock, node: ast.Expr | None, where: ast.Loc) -> int | None:
        if node is None:  # ARRAY[*]: not supported on S7-300/400
            self.diagnostics.append(problem("SCL209", info.file, where))
            return None
        value = self.const_value(info, node)
        if not isinstance(value, int):
            self.diagnostics.append(problem("SCL209", info.file, node.loc))
            return None
        return value

    def const_value(self, info: SclBlock, node: ast.Expr) -> int | float | None:
        """The value of a constant expression of numbers and CONST names, else None."""
        if isinstance(node, ast.Paren):
            return self.const_value(info, node.inner)
        if isinstance(node, ast.Literal):
            text = node.text.replace("_", "")
            if node.kind == "INTEGER":
                return int(text)
            if node.kind == "REAL":
                return float(text)
            prefix, _, body = text.rpartition("#")
            integers = ("INT", "DINT", "SINT", "USINT", "UINT", "UDINT", "LINT", "ULINT")
            if prefix.upper() in integers and body.lstrip("+-").isdigit():
                return int(body)
            return None
        if isinstance(node, ast.Name | ast.Local):
            found = info.constants.get(node.name.casefold())
            return found.value if found is not None else None
        if isinstance(node, ast.Unary) and node.op in ("-", "+"):
            value = self.const_value(info, node.operand)
            return None if value is None else (-value if node.op == "-" else value)
        if isinstance(node, ast.Binary) and node.op in ("+", "-", "*", "DIV", "MOD"):
            left = self.const_value(info, node.left)
            right = self.const_value(info, node.right)
            if not isinstance(left, int) or not isinstance(right, int):
                return None
            if node.op in ("DIV", "MOD") and right == 0:
                return None
            return {
                "+": lambda: left + right,
                "-": lambda: left - right,
                "*": lambda: left * right,
                "DIV": lambda: int(left / right),
                "MOD": lambda: left - int(left / right) * right,
            }[node.op]()
        return None

    # ---- layouts ----------------------------------------------------------------------------

    def _expand(self, block: BlockType) -> Expansion:
        if block.kind == "SFB":
            return system_fb_sections(block.number)
        info = self.blocks.get((BlockKind(block.kind), block.number))
        if info is None:
            return None
        if info.kind is BlockKind.UDT:
            return info.db_type if isinstance(info.db_type, StructType) else StructType(())
        return [(name, group) for name, group in info.sections if name != "TEMP"]

    def expand(self, block: BlockType) -> Expansion:
        """What a UDT (its STRUCT) or an FB (its instance sections) contains."""
        return self._expand(block)

    def instance_layout(self, info: SclBlock) -> tuple[list[Slot], int]:
        """An FB's instance data (IN, OUT, IN_OUT, STAT) from offset 0, and its size in bits."""
        key = (info.kind, info.number)
        if key not in self._instances:
            sections = [(name, group) for name, group in info.sections if name != "TEMP"]
            try:
                self._instances[key] = self.layout.instance(sections)
            except RecursiveTypeError as error:
                self._recursive(info, error)
                self._instances[key] = ([], 0)
        return self._instances[key]

    def temp_layout(self, info: SclBlock) -> tuple[list[Slot], int]:
        """The block's VAR_TEMP in its L stack frame, from L 0.0, and the frame size in bits."""
        key = (info.kind, info.number)
        if key not in self._temps:
            fields = info.fields("TEMP")
            try:
                self._temps[key] = (
                    self.layout.place(fields, 0, "TEMP"),
                    self.layout.end_bits(fields),
                )
            except RecursiveTypeError as error:
                self._recursive(info, error)
                self._temps[key] = ([], 0)
        return self._temps[key]

    def db_layout(self, info: SclBlock) -> tuple[list[Slot], int]:
        """A DB's variables (its STRUCT, UDT or FB instance) and its size in bits."""
        if info.number not in self._dbs:
            self._dbs[info.number] = self._db_slots(info)
        return self._dbs[info.number]

    def _db_slots(self, info: SclBlock) -> tuple[list[Slot], int]:
        data_type = info.db_type
        try:
            if isinstance(data_type, StructType):
                fields = list(data_type.fields)
                return self.layout.place(fields), self.layout.end_bits(fields)
            if isinstance(data_type, BlockType):
                expansion = self._expand(data_type)
                if isinstance(expansion, StructType):
                    fields = list(expansion.fields)
                    return self.layout.place(fields), self.layout.end_bits(fields)
                if expansion is not None:
                    return self.layout.instance(expansion)
        except RecursiveTypeError as error:
            self._recursive(info, error)
        return [], 0

    def _recursive(self, info: SclBlock, error: RecursiveTypeError) -> None:
        name = f"{error.block.kind} {error.block.number}"
        self.diagnostics.append(problem("SCL210", info.file, info.node.name.loc, name=name))


# TIA exports a VAR CONSTANT member whose value is its type's default without the value
# (``STATE_RESET : Int;``): a constant 0 (FALSE for a BOOL, '' for a STRING).
_ZERO_CONSTANT_TYPES = frozenset(
    {"BOOL", "BYTE", "WORD", "DWORD", "LWORD", "SINT", "INT", "DINT", "LINT", "USINT", "UINT"}
    | {"UDINT", "ULINT", "REAL", "LREAL"}
)


def _default_constant(info: SclBlock, decl: ast.VarDecl) -> None:
    kind = decl.type.name.upper() if isinstance(decl.type, ast.NamedType) else ""
    if kind not in _ZERO_CONSTANT_TYPES and kind != "STRING":
        return
    for part in decl.names:
        if kind == "STRING":  # the empty text
            zero, value = ast.Literal("STRING", "''", loc=part.loc), None
        elif kind == "BOOL":
            zero, value = ast.Literal("BOOL", "FALSE", loc=part.loc), 0
        else:
            zero, value = ast.Literal("INTEGER", "0", loc=part.loc), 0
        info.constants[part.name.casefold()] = Constant(part.name, zero, value)


def _is_constant_section(section: object) -> bool:
    """A TIA ``VAR CONSTANT`` section."""
    if not isinstance(section, ast.VarSection) or section.modifier is None:
        return False
    return section.modifier.upper() == "CONSTANT"


def _takes_descriptor(info: SclBlock, section: str | None, data_type: DataType) -> bool:
    """Where TIA Portal accepts VARIANT and ``ARRAY[*]``: the parameters of an FC (IN, OUT,
    IN_OUT), a VARIANT as IN or IN_OUT of an FB, an ``ARRAY[*]`` as IN_OUT of an FB."""
    if section not in ("IN", "OUT", "IN_OUT"):
        return False
    if info.kind is BlockKind.FC or section == "IN_OUT":
        return True
    return section == "IN" and isinstance(data_type, descriptor.VariantParam)


def _absolute(text: str) -> tuple[BlockKind, int] | None:
    try:
        parsed = parse_address(text)
    except AddressError:
        return None
    if parsed.kind != "block" or parsed.block is None:
        return None
    return parsed.block, parsed.number


def bind(sources: list[ast.SourceFile], symbols: SymbolTable | None = None) -> SclIndex:
    """The index of ``sources``; its ``diagnostics`` hold the declaration problems."""
    index = SclIndex(symbols)
    index.add_sources(sources)
    return index

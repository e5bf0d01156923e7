"""The project index of S7-SCL sources: blocks by kind, number and name, their interfaces as
``nasaq.lang.types`` types, and the standard S7-300/400 layout (``nasaq.lang.layout``) of
instance data, DBs and the L stack.

Numbering follows TIA Portal's automatic numbering:
- an absolute name (``FB10``, ``DB3``) keeps its number;
- a name the symbol table gives to a block of the same kind takes that number;
- the OB called ``Main`` is OB 1;
- every other FB, FC, DB (and UDT) takes the lowest number of its kind that no block uses, in
  source order, starting at 1. The absolute and symbol-table numbers are collected first, so a
  later ``FB1`` is never given away. An OB without a number (other than ``Main``) is an error.
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
from nasaq.lang.layout import Expansion, Layout, RecursiveTypeError, Slot
from nasaq.lang.profiles import DEFAULT_PROFILE
from nasaq.lang.scl import ast
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.symbols import Symbol, SymbolTable
from nasaq.lang.system_blocks import SFB_INTERFACES
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
# IEC timers and counters as multi-instances: the system function blocks of S7-300/400.
IEC_INSTANCES = {"CTU": 0, "CTD": 1, "CTUD": 2, "TP": 3, "TON": 4, "TOF": 5}
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

    @property
    def label(self) -> str:
        return f"{self.kind.value} {self.number}"

    def fields(self, section: str) -> list[Field]:
        return [declared for name, group in self.sections if name == section for declared in group]


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
            if kind not in AUTO_NUMBERED:
                self.diagnostics.append(problem("SCL205", file, node.name.loc, name=node.name.text))
                continue
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
        if name.text.casefold() == "main" and kind in (BlockKind.OB, BlockKind.FB):
            return BlockKind.OB, 1
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
        for section in node.sections:
            if not isinstance(section, ast.VarSection):
                continue
            if section.modifier is not None and section.modifier.upper() == "CONSTANT":
                for decl in section.decls:
                    if isinstance(decl, ast.VarDecl) and decl.init:
                        first = decl.init[0]
                        if not isinstance(first, ast.InitRepeat | ast.InitList):
                            for part in decl.names:
                                value = self.const_value(info, first)
                                info.constants[part.name.casefold()] = Constant(
                                    part.name, first, value
                                )
                continue
            kind = section.kind.upper()
            name = SECTION_OF_KEYWORD.get(kind, "STAT")
            if info.kind in (BlockKind.FC, BlockKind.OB) and name == "STAT":
                name = "TEMP"  # VAR of an FC or OB is temporary
            fields = self._fields(info, section.decls, name)
            info.sections.append((name, fields))
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
            if made_of is None or made_of.kind not in (BlockKind.FB, BlockKind.UDT):
                self.diagnostics.append(problem("SCL202", info.file, source.loc, type=source.text))
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
                if node.length is None:
                    return found
                length = self._bound(info, node.length, node.loc)
                if length is None:
                    return UNKNOWN
                if not 0 <= length <= 254:
                    self.diagnostics.append(
                        problem(
                            "SCL218",
                            info.file,
                            node.length.loc,
                            text=length,
                            type="STRING",
                            hint="",
                        )
                    )
                    return UNKNOWN
                return StringType(length)
            if found is not None:
                return found
        block = self.named(node.name)
        if block is not None and block.kind in (BlockKind.FB, BlockKind.UDT):
            return BlockType(block.kind.value, block.number)
        iec = IEC_INSTANCES.get(node.name.upper())
        if iec is not None and not node.quoted:
            return BlockType("SFB", iec)
        absolute = _absolute(node.name)
        if absolute is not None and absolute[0] is BlockKind.SFB and absolute[1] in SFB_INTERFACES:
            return BlockType("SFB", absolute[1])
        self.diagnostics.append(problem("SCL202", info.file, node.loc, type=node.name))
        return UNKNOWN

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
            if prefix.upper() in ("INT", "DINT") and body.lstrip("+-").isdigit():
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
            interface = SFB_INTERFACES.get(block.number)
            if interface is None:
                return None
            sections: dict[str, list[Field]] = {}
            for section, name, type_name in interface:
                found = elementary(type_name)
                if found is not None:
                    sections.setdefault(section, []).append(Field(name, found))
            return list(sections.items())
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

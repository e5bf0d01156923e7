"""Binds parsed blocks into one program index: block numbers (through the symbol table for
``"Symbolic"`` ids), declared types, interfaces and layouts (instance data, L stack, DBs).

Everything a later phase looks up by block number or by ``#name`` lives here; it is computed
once per compilation, and layouts lazily, so UDTs and FBs may be declared in any order and in
any file of the program.
"""

from __future__ import annotations

from dataclasses import dataclass, field, is_dataclass
from dataclasses import fields as dataclass_fields

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang import wide_text
from nasaq.lang.layout import Expansion, Layout, RecursiveTypeError, Slot
from nasaq.lang.profiles import DEFAULT_PROFILE, needs_s7_1500
from nasaq.lang.stl import ast
from nasaq.lang.stl.addresses import AddressError, Parsed, parse_address
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.symbols import SymbolTable
from nasaq.lang.system_types import system_fb_sections
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
    "FUNCTION": BlockKind.FC,
    "DATA_BLOCK": BlockKind.DB,
    "TYPE": BlockKind.UDT,
}
SECTION_OF_KEYWORD = {
    "VAR_INPUT": "IN",
    "VAR_OUTPUT": "OUT",
    "VAR_IN_OUT": "IN_OUT",
    "VAR": "STAT",
    "VAR RETAIN": "STAT",  # TIA Portal: retentive or not, static data all the same
    "VAR NON_RETAIN": "STAT",
    "VAR DB_SPECIFIC": "STAT",
    "VAR_TEMP": "TEMP",
}
CONSTANT_SECTION = "VAR CONSTANT"  # TIA Portal's local constants: values, not data


@dataclass(slots=True)
class Param:
    """A formal parameter; ``index`` is its position in the call (FC: RET_VAL last)."""

    name: str
    section: str  # IN, OUT, IN_OUT, RETURN
    type: DataType
    index: int


@dataclass(slots=True)
class BlockInfo:
    kind: BlockKind
    number: int
    file: str
    node: ast.BlockNode
    name: str = ""
    language: str = "en"
    sections: list[tuple[str, list[Field]]] = field(default_factory=list)
    params: list[Param] = field(default_factory=list)
    return_type: DataType | None = None
    constants: dict[str, Field] = field(default_factory=dict)  # VAR CONSTANT, by upper name
    # Variables (upper-case) left out because their type was reported: their uses are not
    # reported again (one message for a missing UDT, not one per use).
    untyped: set[str] = field(default_factory=set)
    db_type: DataType | None = None  # DB: StructType, or BlockType of its FB/SFB/UDT
    builtin: bool = False  # an SFB from the system catalogue
    # filled lazily by ProgramIndex:
    instance: list[Slot] | None = None
    instance_bits: int = 0
    temp: list[Slot] | None = None
    temp_bits: int = 0

    @property
    def label(self) -> str:
        return f"{self.kind.value} {self.number}"

    def fields(self, section: str) -> list[Field]:
        return [declared for name, group in self.sections if name == section for declared in group]


class ProgramIndex:
    """All blocks of the program by (kind, number), with types and layouts."""

    def __init__(
        self, symbols: SymbolTable, test_ops: bool = False, profile: str = DEFAULT_PROFILE
    ) -> None:
        self.symbols = symbols
        self.test_ops = test_ops  # awlsim's own system blocks (SFB -1 ...) are accepted
        self.profile = profile  # the compiler's: S7-1200/1500 things need S7-1500
        self.blocks: dict[tuple[BlockKind, int], BlockInfo] = {}
        self.layout = Layout(self._expand)
        self.diagnostics: list[Diagnostic] = []
        self._db_roots: dict[tuple[BlockKind, int], Slot] = {}
        # the optimized DBs of the SCL sources (S7-1500), which STL reaches by name only (STL604),
        # and the files whose blocks the SCL compiler wrote (they address those DBs absolutely)
        self.optimized_dbs: dict[int, str] = {}
        self.scl_files: set[str] = set()

    # ---- block ids --------------------------------------------------------------------------

    def block_id(
        self, text: str, quoted: bool, file: str, where: ast.Loc
    ) -> tuple[BlockKind, int] | None:
        """``OB 1`` / ``"Main"`` → (kind, number); reports what is wrong."""
        if quoted:
            symbol = self.symbols.lookup(text)
            if symbol is None:
                self.diagnostics.append(problem("STL205", file, where, name=f'"{text}"'))
                return None
            parsed = symbol.parsed
            if not self.allowed(parsed, f'"{text}"', file, where):
                return None
            if parsed.kind != "block" or parsed.block is None:
                self.diagnostics.append(
                    problem(
                        "STL234",
                        file,
                        where,
                        name=f'"{text}"',
                        actual=symbol.address,
                        expected="a block",
                    )
                )
                return None
            return parsed.block, parsed.number
        try:
            parsed = parse_address(text)
        except AddressError as error:
            self.diagnostics.append(problem("STL106", file, where, text=text, reason=str(error)))
            return None
        if not self.allowed(parsed, text, file, where):
            return None
        if parsed.kind != "block" or parsed.block is None:
            self.diagnostics.append(
                problem("STL234", file, where, name=text, actual=text, expected="a block")
            )
            return None
        return parsed.block, parsed.number

    def allowed(self, parsed: Parsed, text: str, file: str, where: ast.Loc) -> bool:
        """awlsim's own system blocks (``SFC -3``) need test instructions enabled."""
        if parsed.kind == "block" and parsed.number < 0 and not self.test_ops:
            self.diagnostics.append(problem("STL218", file, where, mnemonic=text))
            return False
        return True

    def register(self, node: ast.BlockNode, file: str, language: str) -> BlockInfo | None:
        expected = KIND_OF_KEYWORD[node.keyword]
        found = self.block_id(node.ident, node.ident_quoted, file, node.loc)
        if found is None:
            return None
        kind, number = found
        if kind is not expected:
            self.diagnostics.append(
                problem(
                    "STL234",
                    file,
                    node.loc,
                    name=node.ident,
                    actual=kind.value,
                    expected=expected.value,
                )
            )
            return None
        if (kind, number) in self.blocks:
            first = self.blocks[(kind, number)]
            if kind is BlockKind.UDT and same_syntax(first.node.db_body, node.db_body):
                return None  # STEP 7 exports a UDT with every source that uses it: one UDT
            self.diagnostics.append(
                problem(
                    "STL215",
                    file,
                    node.loc,
                    block=f"{kind.value} {number}",
                    file=first.file,
                    line=first.node.loc.line,
                )
            )
            return None
        symbol = self.symbols.block_symbol(kind, number)
        info = BlockInfo(kind, number, file, node, symbol.name if symbol else "", language)
        self.blocks[(kind, number)] = info
        return info

    # ---- declarations -----------------------------------------------------------------------

    def declare(self, info: BlockInfo) -> None:
        """Types of the block's interface (or DB/UDT structure); reports unknown types."""
        node = info.node
        file = info.file
        for item in node.head:
            if isinstance(item, ast.VarSectionNode):
                fields = self.fields(item.decls, file, info.label, info.untyped)
                if item.kind == CONSTANT_SECTION:
                    info.constants.update((found.name.upper(), found) for found in fields)
                    continue
                section = SECTION_OF_KEYWORD.get(item.kind, "STAT")
                info.sections.append((section, fields))
        if node.return_type is not None:
            if info.kind is BlockKind.FB:
                self.diagnostics.append(
                    problem("STL109", file, node.return_type.loc, type=_type_name(node.return_type))
                )
            else:
                info.return_type = self.type_of(node.return_type, file)
        if info.kind in (BlockKind.DB, BlockKind.UDT) and isinstance(
            node.db_body, ast.StructTypeNode
        ):
            members = self.fields(node.db_body.members, file, "STRUCT", info.untyped)
            info.db_type = StructType(tuple(members))
        elif info.kind in (BlockKind.DB, BlockKind.UDT) and node.db_body is not None:
            info.db_type = self.type_of(node.db_body, file)
            db_type = info.db_type
            missing_udt = (
                isinstance(db_type, BlockType)
                and db_type.kind == "UDT"
                and (BlockKind.UDT, db_type.number) not in self.blocks
            )
            if missing_udt and isinstance(db_type, BlockType):
                self.diagnostics.append(
                    problem("STL213", file, node.db_body.loc, block=f"UDT {db_type.number}")
                )
        index = 0
        for section in ("IN", "OUT", "IN_OUT"):
            for declared in info.fields(section):
                info.params.append(Param(declared.name, section, declared.type, index))
                index += 1
        if info.kind is BlockKind.FC and info.return_type is not None:
            is_void = isinstance(info.return_type, Elementary) and info.return_type.name == "VOID"
            if not is_void:
                info.params.append(Param("RET_VAL", "RETURN", info.return_type, index))

    def fields(
        self,
        decls: list[ast.VarDeclNode],
        file: str,
        owner: str,
        untyped: set[str] | None = None,
    ) -> list[Field]:
        seen: set[str] = set()
        fields: list[Field] = []
        for decl in decls:
            key = decl.name.upper()
            if key in seen:
                self.diagnostics.append(
                    problem("STL223", file, decl.loc, name=decl.name, block=owner)
                )
                continue
            seen.add(key)
            data_type = self.type_of(decl.type, file)
            if data_type is None:
                if untyped is not None:
                    untyped.add(key)
                continue
            fields.append(Field(decl.name, data_type, decl.init, decl.comment))
        return fields

    def type_of(self, node: ast.TypeNode, file: str) -> DataType | None:
        if isinstance(node, ast.NamedTypeNode):
            if node.name == "VOID":
                return Elementary("VOID")  # only ever a return type: never laid out
            found = elementary(node.name)
            if found is None:
                system = self.symbols.system(node.name)  # TON, CTU ... written unquoted (TIA)
                if system is not None and system.parsed.block is BlockKind.SFB:
                    return BlockType("SFB", system.parsed.number)
                named = tia_system(node.name)  # PID_Compact, CONT_C ...: not simulated
                if named is not None:
                    self.diagnostics.append(problem("STL920", file, node.loc, name=named))
                    return None
                self.diagnostics.append(problem("STL224", file, node.loc, type=node.name))
                return None
            if isinstance(found, Elementary) and needs_s7_1500(found.name, self.profile):
                self.diagnostics.append(
                    problem("STL500", file, node.loc, what=found.name, profile=self.profile)
                )
                return None
            if isinstance(found, StringType) and needs_s7_1500(found.name, self.profile):
                self.diagnostics.append(
                    problem("STL500", file, node.loc, what=found.name, profile=self.profile)
                )
                return None
            if isinstance(found, StringType) and node.length is not None:
                if not 0 <= node.length <= wide_text.longest(found):
                    self.diagnostics.append(
                        problem(
                            "STL214",
                            file,
                            node.loc,
                            text=str(node.length),
                            type=found.name,
                            hint=f" (0 to {wide_text.longest(found)})",
                        )
                    )
                    return None
                return StringType(node.length, found.wide)
            return found
        if isinstance(node, ast.ArrayTypeNode):
            element = self.type_of(node.element, file)
            if element is None:
                return None
            for low, high in node.dims:
                if high < low:
                    self.diagnostics.append(
                        problem("STL217", file, node.loc, name="ARRAY", index=f"{low}..{high}")
                    )
                    return None
            return ArrayType(tuple(node.dims), element)
        if isinstance(node, ast.StructTypeNode):
            return StructType(tuple(self.fields(node.members, file, "STRUCT")))
        # a UDT, FB or SFB by number or symbol
        found_id = self.block_id(node.text, node.quoted, file, node.loc)
        if found_id is None:
            return None
        kind, number = found_id
        if kind not in (BlockKind.UDT, BlockKind.FB, BlockKind.SFB):
            self.diagnostics.append(
                problem("STL224", file, node.loc, type=f"{kind.value} {number}")
            )
            return None
        return BlockType(kind.value, number)

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

    def instance_layout(self, info: BlockInfo) -> list[Slot]:
        if info.instance is None:
            sections = [(name, group) for name, group in info.sections if name != "TEMP"]
            try:
                info.instance, info.instance_bits = self.layout.instance(sections)
            except RecursiveTypeError as error:
                self.recursive(info, error)
                info.instance, info.instance_bits = [], 0
        return info.instance

    def temp_layout(self, info: BlockInfo) -> list[Slot]:
        if info.temp is None:
            fields = info.fields("TEMP")
            try:
                info.temp = self.layout.place(fields, 0, "TEMP")
                info.temp_bits = self.layout.end_bits(fields)
            except RecursiveTypeError as error:
                self.recursive(info, error)
                info.temp, info.temp_bits = [], 0
        return info.temp

    def db_root(self, info: BlockInfo) -> Slot:
        """A DB (``info.db_type`` set) as one slot whose members are its variables, laid out
        once per compilation: symbolic accesses look their members up in it."""
        key = (info.kind, info.number)
        found = self._db_roots.get(key)
        if found is None:
            assert info.db_type is not None
            slots, size = self.slots_of_type(info.db_type, info)
            found = Slot(f"DB {info.number}", Elementary("BYTE"), 0, size, members=slots)
            self._db_roots[key] = found
        return found

    def slots_of_type(self, data_type: DataType, info: BlockInfo) -> tuple[list[Slot], int]:
        """Slots and size of a DB's structure (STRUCT, UDT or the instance of an FB/SFB)."""
        try:
            if isinstance(data_type, StructType):
                return (
                    self.layout.place(list(data_type.fields)),
                    self.layout.end_bits(list(data_type.fields)),
                )
            if isinstance(data_type, BlockType):
                expansion = self._expand(data_type)
                if isinstance(expansion, StructType):
                    fields = list(expansion.fields)
                    return self.layout.place(fields), self.layout.end_bits(fields)
                if expansion is not None:
                    return self.layout.instance(expansion)
        except RecursiveTypeError as error:
            self.recursive(info, error)
        return [], 0

    def recursive(self, info: BlockInfo, error: RecursiveTypeError) -> None:
        name = f"{error.block.kind} {error.block.number}"
        self.diagnostics.append(problem("STL233", info.file, info.node.loc, name=name))


def same_syntax(first: object, second: object) -> bool:
    """Whether two syntax trees are written alike, wherever they stand (``loc`` aside)."""
    if type(first) is not type(second):
        return False
    if isinstance(first, list) and isinstance(second, list):
        return len(first) == len(second) and all(map(same_syntax, first, second))
    if isinstance(first, dict) and isinstance(second, dict):
        return first.keys() == second.keys() and all(
            same_syntax(value, second[key]) for key, value in first.items()
        )
    if is_dataclass(first):
        return all(
            same_syntax(getattr(first, item.name), getattr(second, item.name))
            for item in dataclass_fields(first)
            if item.name not in ("loc", "end", "comment")
        )
    return first == second


def _type_name(node: ast.TypeNode) -> str:
    if isinstance(node, ast.NamedTypeNode):
        return node.name
    if isinstance(node, ast.RefTypeNode):
        return node.text
    return "STRUCT" if isinstance(node, ast.StructTypeNode) else "ARRAY"

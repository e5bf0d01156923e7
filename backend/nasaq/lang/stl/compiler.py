"""``compile_sources``: STL sources and symbol tables → one ``ir.Program`` and diagnostics.

Phases: read symbol tables → parse every STL file → detect each file's mnemonics → register
blocks (one index over all files, so a CALL may name a block of another file) → declare
interfaces and types → lower code blocks, data blocks and UDTs → resolve jumps. Blocks with
errors are still in the program, and ``ok`` tells whether anything was an error.
"""

from __future__ import annotations

import gc
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from nasaq.diagnostics import Diagnostic, Severity
from nasaq.ir import Block, BlockKind, Program, Variable
from nasaq.lang.layout import variables
from nasaq.lang.limits import MAX_SOURCE_CHARS, MAX_SOURCE_LINES, max_db_bytes
from nasaq.lang.profiles import DEFAULT_PROFILE, is_s7_1500
from nasaq.lang.stl import ast, converting
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.bind import BlockInfo, ProgramIndex
from nasaq.lang.stl.calls import AutoInstance
from nasaq.lang.stl.dbdata import DataBuilder
from nasaq.lang.stl.diag import problem, sort_key
from nasaq.lang.stl.library import LIBRARY_FILE, add_library_blocks
from nasaq.lang.stl.lower import CodeLowerer, LoweredCode, Shared, apply_code
from nasaq.lang.stl.mnemonics import detect
from nasaq.lang.stl.numbering import number_blocks
from nasaq.lang.stl.parse import ParseResult, parse_source
from nasaq.lang.stl.resolve import Scope
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES, SymbolTable, read_symbol_table
from nasaq.lang.types import BlockType, StructType, type_text

STL_SUFFIXES = (".awl", ".stl")
# TIA Portal exports a DB as ``.db`` and a PLC data type as ``.udt``: SCL syntax in both exports.
SCL_SUFFIXES = (".scl", ".db", ".udt")
LAD_SUFFIXES = (".lad", ".fbd")  # nasaq.lang.lad.text.SUFFIXES
GRAPH_SUFFIXES = (".graph",)  # nasaq.lang.graph.text.SUFFIXES
WATCH_TABLE_SUFFIXES = (".vat",)  # nasaq.workbench.watch_table: project files, not program
CPU_PROPERTIES_SUFFIXES = (".properties",)  # nasaq.workbench.cpu_properties: not program
PLANT_SUFFIXES = (".plant",)  # nasaq.plants.plant_file: the project's virtual plant, not program


@dataclass(frozen=True, slots=True)
class SourceFile:
    """One input file; ``text`` may be bytes (decoded as UTF-8, else Windows-1252)."""

    name: str
    text: str | bytes


@dataclass(slots=True)
class CompileResult:
    program: Program
    diagnostics: list[Diagnostic] = field(default_factory=list)
    # The STL that SCL blocks became (file, block), for ``nasaq compile --emit stl``.
    generated: list[tuple[str, ast.BlockNode]] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not any(item.severity is Severity.ERROR for item in self.diagnostics)


@dataclass(slots=True)
class _File:
    name: str
    parsed: ParseResult
    lines: list[str]
    language: str = "en"
    # A LAD/FBD file: the element id of each line of its generated STL (``Origin.element``).
    elements: list[str | None] | None = None


def decode(text: str | bytes) -> str:
    if isinstance(text, str):
        return text
    try:
        return text.decode("utf-8")
    except UnicodeDecodeError:
        return text.decode("cp1252", errors="replace")


def _suffix(name: str) -> str:
    dot = name.rfind(".")
    return name[dot:].lower() if dot >= 0 else ""


def _code_items(file: _File) -> Iterable[ast.CodeItem]:
    yield from file.parsed.source.loose_code
    for block in file.parsed.source.blocks:
        yield from block.code


def _language(file: _File, forced: str) -> str:
    if forced in ("de", "en"):
        return forced
    return mnemonic_set(_code_items(file))


def mnemonic_set(items: Iterable[ast.CodeItem]) -> str:
    """``"de"`` or ``"en"``: the mnemonic set code is written in, by its instructions and the
    address areas of their operands (``nasaq.lang.stl.mnemonics.detect``)."""
    mnemonics: list[str] = []
    areas: list[str | None] = []
    for item in items:
        if not isinstance(item, ast.InstrNode) or item.param_line:
            continue
        mnemonics.append(item.mnemonic.upper())
        for operand in item.operands:
            if isinstance(operand, ast.AddressNode):
                try:
                    areas.append(parse_address(operand.text).language)
                except AddressError:
                    continue
    return detect(mnemonics, areas)


def _attach_comments(decls: list[ast.VarDeclNode], comments: dict[int, str]) -> None:
    for decl in decls:
        decl.comment = comments.get(decl.loc.line, "")
        if isinstance(decl.type, ast.StructTypeNode):
            _attach_comments(decl.type.members, comments)


class _Compiler:
    def __init__(self, mnemonics: str, test_ops: bool, profile: str = DEFAULT_PROFILE) -> None:
        self.profile = profile
        self.mnemonics = mnemonics
        self.test_ops = test_ops
        self.diagnostics: list[Diagnostic] = []
        self.symbols = SymbolTable()
        self.files: list[_File] = []
        self.index = ProgramIndex(self.symbols, test_ops, profile)
        self.index.profile = profile
        self.program = Program()
        self.auto: dict[int, AutoInstance] = {}
        self.lowered: dict[tuple[BlockKind, int], LoweredCode] = {}
        self.shared: dict[str, Shared] = {}  # what blocks lower alike, by mnemonic language
        self.scl_sources: list[Any] = []  # nasaq.lang.scl.ast.SourceFile
        self.scl_lines: dict[str, list[str]] = {}
        self.generated: list[tuple[str, ast.BlockNode]] = []
        self.lad_files: dict[str, Any] = {}  # name -> nasaq.lang.lad.compile.LoweredFile
        self.unnumbered: set[int] = set()  # ids of the block nodes numbering could not number

    def read(self, sources: list[SourceFile]) -> None:
        for source in sources:
            suffix = _suffix(source.name)
            if suffix in SYMBOL_TABLE_SUFFIXES:
                text = decode(source.text)
                self.diagnostics += read_symbol_table(source.name, text, self.symbols)
        for source in sources:
            suffix = _suffix(source.name)
            if suffix in SYMBOL_TABLE_SUFFIXES or suffix in WATCH_TABLE_SUFFIXES:
                continue
            if suffix in CPU_PROPERTIES_SUFFIXES or suffix in PLANT_SUFFIXES:
                continue
            if self.too_many_lines(source):
                continue
            if suffix in SCL_SUFFIXES:
                self.read_scl(source)
                continue
            if suffix in LAD_SUFFIXES:
                self.read_lad(source)
                continue
            if suffix in GRAPH_SUFFIXES:
                self.read_graph(source)
                continue
            if suffix not in STL_SUFFIXES:
                self.diagnostics.append(
                    problem("STL110", source.name, ast.Loc(1, 1, 1, 1), file=source.name)
                )
                continue
            text = decode(source.text)
            if len(text) > MAX_SOURCE_CHARS:
                size = {"size_kb": len(text) // 1024, "limit_kb": MAX_SOURCE_CHARS // 1024}
                where = ast.Loc(1, 1, 1, 1)
                self.diagnostics.append(
                    problem("STL111", source.name, where, file=source.name, **size)
                )
                continue
            parsed = parse_source(source.name, text)
            self.diagnostics += parsed.diagnostics
            empty = not parsed.source.blocks and not any(
                isinstance(item, ast.InstrNode) for item in parsed.source.loose_code
            )
            if empty and not parsed.diagnostics:
                where = ast.Loc(1, 1, 1, 1)
                self.diagnostics.append(problem("STL112", source.name, where, file=source.name))
            file = _File(source.name, parsed, text.split("\n"))
            file.language = _language(file, self.mnemonics)
            self.files.append(file)
        self._publish_symbols()

    def too_many_lines(self, source: SourceFile) -> bool:
        """STL151 for a source of more lines than ``limits.MAX_SOURCE_LINES``, refused before
        it is read: it would take the parser and checker minutes."""
        text = source.text
        lines = (text.count("\n") if isinstance(text, str) else text.count(b"\n")) + 1
        if lines <= MAX_SOURCE_LINES:
            return False
        where = ast.Loc(1, 1, 1, 1)
        found = problem(
            "STL151", source.name, where, file=source.name, lines=lines, limit=MAX_SOURCE_LINES
        )
        self.diagnostics.append(found)
        return True

    def _publish_symbols(self) -> None:
        table = self.symbols.symbols.values()
        self.program.symbols = {symbol.name: symbol.address for symbol in table}
        self.program.symbol_types = {symbol.name: symbol.type for symbol in table if symbol.type}

    def read_scl(self, source: SourceFile) -> None:
        text = decode(source.text)
        where = ast.Loc(1, 1, 1, 1)
        if len(text) > MAX_SOURCE_CHARS:
            size = {"size_kb": len(text) // 1024, "limit_kb": MAX_SOURCE_CHARS // 1024}
            self.diagnostics.append(problem("STL111", source.name, where, file=source.name, **size))
            return
        from nasaq.lang.scl.parse import parse_source as parse_scl  # SCL builds on this package

        parsed = parse_scl(source.name, text)
        self.diagnostics += parsed.diagnostics
        if not parsed.source.blocks and not parsed.diagnostics:
            self.diagnostics.append(problem("STL112", source.name, where, file=source.name))
        self.scl_sources.append(parsed.source)
        self.scl_lines[source.name] = text.split("\n")

    def read_lad(self, source: SourceFile) -> None:
        """A LAD/FBD file is read as the STL its blocks lower to (``nasaq.lang.lad.compile``)."""
        text = decode(source.text)
        where = ast.Loc(1, 1, 1, 1)
        if len(text) > MAX_SOURCE_CHARS:
            size = {"size_kb": len(text) // 1024, "limit_kb": MAX_SOURCE_CHARS // 1024}
            self.diagnostics.append(problem("STL111", source.name, where, file=source.name, **size))
            return
        from nasaq.lang.lad.compile import lower_file  # LAD builds on this package

        self._read_lowered(source, lower_file(source.name, text))

    def read_graph(self, source: SourceFile) -> None:
        """An S7-Graph file is read as the STL its FBs lower to (``nasaq.lang.graph.compile``),
        its problems placed on the graph lines as a LAD file's are."""
        text = decode(source.text)
        if len(text) > MAX_SOURCE_CHARS:
            size = {"size_kb": len(text) // 1024, "limit_kb": MAX_SOURCE_CHARS // 1024}
            where = ast.Loc(1, 1, 1, 1)
            self.diagnostics.append(problem("STL111", source.name, where, file=source.name, **size))
            return
        from nasaq.lang.graph.compile import lower_file  # Graph builds on this package

        self._read_lowered(source, lower_file(source.name, text))

    def _read_lowered(self, source: SourceFile, lowered: Any) -> None:
        """A file read as generated STL (``LoweredFile``) with its line map."""
        from nasaq.lang.lad.compile import moved_to_lad

        where = ast.Loc(1, 1, 1, 1)
        self.lad_files[source.name] = lowered
        self.diagnostics += lowered.diagnostics
        # A Graph file comes with its syntax tree (``nasaq.lang.graph.lower_syntax``).
        parsed = getattr(lowered, "parsed", None) or parse_source(source.name, lowered.stl)
        self.diagnostics += [moved_to_lad(found, lowered) for found in parsed.diagnostics]
        if not parsed.source.blocks and not lowered.diagnostics:
            self.diagnostics.append(problem("STL112", source.name, where, file=source.name))
        file = _File(source.name, parsed, lowered.stl.split("\n"), elements=lowered.elements)
        file.language = _language(file, self.mnemonics)
        self.files.append(file)

    def converting_blocks(self) -> None:
        """SCALE/UNSCALE (FC 105/106) where the program calls them and lacks them."""
        items = (item for file in self.files for item in _code_items(file))
        blocks = [node for file in self.files for node in file.parsed.source.blocks]
        named = {node.ident.upper() for node in blocks if node.ident_quoted}
        named |= {block.name.text.upper() for source in self.scl_sources for block in source.blocks}
        wanted = converting.called(items, self.symbols, named)
        if not wanted:
            return
        scl_ids = [block.name.text for source in self.scl_sources for block in source.blocks]
        used = converting.fc_numbers([node.ident for node in blocks] + scl_ids)
        for text in converting.sources(wanted, self.symbols, used):
            parsed = parse_source(converting.LIBRARY_FILE, text)
            self.diagnostics += parsed.diagnostics
            self.files.append(_File(converting.LIBRARY_FILE, parsed, text.split("\n")))

    def number(self) -> None:
        """Numbers the blocks named by a symbol no table defines, as TIA does (``numbering``)."""
        self.converting_blocks()
        used: list[tuple[BlockKind, int]] = []
        for source in self.scl_sources:
            for scl_block in source.blocks:
                if scl_block.name.absolute:
                    try:
                        parsed = parse_address(scl_block.name.text)
                    except AddressError:
                        continue
                    if parsed.block is not None:
                        used.append((parsed.block, parsed.number))
        plain = ((file.name, node) for file in self.files for node in file.parsed.source.blocks)
        self.diagnostics += number_blocks(plain, self.symbols, used, self.profile, self.unnumbered)
        self._publish_symbols()

    def check_access(self, node: ast.BlockNode, file: str, info: BlockInfo) -> None:
        """``{ S7_Optimized_Access := 'TRUE' }``: only the S7-1200/1500 family has optimized
        blocks (there Nasaq lays them out as standard ones: STL reaches them symbolically, an
        absolute address in an optimized DB is STL604)."""
        for item in node.head:
            if not isinstance(item, ast.AttributesNode):
                continue
            for name, value in item.values.items():
                if name.casefold() != "s7_optimized_access" or value.upper() != "TRUE":
                    continue
                if not is_s7_1500(self.profile):
                    what = "an optimized block"
                    self.diagnostics.append(
                        problem("STL500", file, item.loc, what=what, profile=self.profile)
                    )
                elif info.kind is BlockKind.DB:
                    label = f"DB {info.number}"
                    shown = f'"{info.name}" ({label})' if info.name else label
                    self.index.optimized_dbs[info.number] = shown

    def register(self) -> list[tuple[BlockInfo, _File]]:
        registered: list[tuple[BlockInfo, _File]] = []
        self.number()
        for file in self.files:
            nodes = list(file.parsed.source.blocks)
            loose = file.parsed.source.loose_code
            if any(isinstance(item, ast.InstrNode) for item in loose):
                first = loose[0]
                where = first.loc
                nodes.append(
                    ast.BlockNode("ORGANIZATION_BLOCK", "OB 1", False, where, where, code=loose)
                )
            for node in nodes:
                if id(node) in self.unnumbered:
                    continue  # STL600 said why
                for item in node.head:
                    if isinstance(item, ast.VarSectionNode):
                        _attach_comments(item.decls, file.parsed.comments)
                if isinstance(node.db_body, ast.StructTypeNode):
                    _attach_comments(node.db_body.members, file.parsed.comments)
                info = self.index.register(node, file.name, file.language)
                if info is not None:
                    registered.append((info, file))
                    self.check_access(node, file.name, info)
        from nasaq.lang.scl.project import SclUnit  # SCL builds on this package

        unit = SclUnit(self.scl_sources, self.symbols, self.profile) if self.scl_sources else None
        if unit is not None:
            self.diagnostics += unit.bind(self.index.blocks)
        for info, _ in registered:
            self.index.declare(info)
        if unit is not None:
            unit.attach()
            blocks, problems = unit.lower()
            self.diagnostics += problems
            self.index.optimized_dbs.update(unit.optimized_dbs())
            self.index.scl_files = {name for name, _ in blocks}
            files: dict[str, _File] = {}
            self.generated = blocks
            generated: list[tuple[BlockInfo, _File]] = []
            for name, node in blocks:
                if name not in files:
                    empty = ParseResult(ast.SourceNode(name, [], []))
                    files[name] = _File(name, empty, self.scl_lines.get(name, []))
                info = self.index.register(node, name, "en")
                if info is not None:
                    generated.append((info, files[name]))
            for info, _ in generated:  # after all are registered: a DB may name a later UDT
                self.index.declare(info)
            registered += generated
            self._publish_symbols()
        registered += self.library_blocks(registered)
        return registered

    def library_blocks(
        self, registered: list[tuple[BlockInfo, _File]]
    ) -> list[tuple[BlockInfo, _File]]:
        """The IEC library FCs the program calls and does not define (``stl.library``)."""
        added = add_library_blocks(self.index, self.symbols, (info.node for info, _ in registered))
        if not added:
            return []
        file = _File(LIBRARY_FILE, ParseResult(ast.SourceNode(LIBRARY_FILE, [], [])), [])
        self.program.symbols = {s.name: s.address for s in self.symbols.symbols.values()}
        return [(info, file) for info in added]

    def build(self, registered: list[tuple[BlockInfo, _File]]) -> None:
        for info, file in registered:
            block = self.header(info)
            if info.kind in (BlockKind.OB, BlockKind.FB, BlockKind.FC):
                self.code_block(info, file, block)
            elif info.kind is BlockKind.DB:
                self.data_block(info, block)
            else:
                slots, _size = self.index.slots_of_type(info.db_type or StructType(()), info)
                block.interface = variables(slots)
            self.program.add(block)
        for auto in self.auto.values():
            self.auto_instance(auto)
        self.resolve_jumps()

    def header(self, info: BlockInfo) -> Block:
        block = Block(info.kind, info.number, name=info.name, file=info.file)
        for item in info.node.head:
            if isinstance(item, ast.TitleNode):
                block.title = item.text
            elif isinstance(item, ast.HeaderPropNode):
                block.attributes[item.key] = item.value
            elif isinstance(item, ast.AttributesNode):
                block.attributes.update(item.values)
            elif isinstance(item, ast.FlagNode):
                if item.name == "KNOW_HOW_PROTECT":
                    block.know_how_protect = True
                else:
                    block.attributes[item.name] = "true"
        return block

    def code_block(self, info: BlockInfo, file: _File, block: Block) -> None:
        interface: list[Variable] = []
        if info.kind is BlockKind.FB:
            interface += variables(self.index.instance_layout(info))
        elif info.kind is BlockKind.FC:
            for param in info.params:
                size = self.index.layout.size_bits(param.type)
                interface.append(
                    Variable(param.name, type_text(param.type), param.section, 0, size)
                )
            if info.return_type is not None:
                block.return_type = type_text(info.return_type)
        interface += variables(self.index.temp_layout(info))
        block.interface = interface
        block.temp_bytes = info.temp_bits // 8
        self.check_temp(info, block.temp_bytes)
        scope = Scope(self.index, info, info.language, self.test_ops)
        group = info.language
        if self.index.optimized_dbs and info.file in self.index.scl_files:
            group += " scl"  # its absolute addresses in optimized DBs are no STL604 for STL's
        shared = self.shared.setdefault(group, {})
        lowerer = CodeLowerer(scope, file.lines, self.auto, shared, file.elements)
        lowered = lowerer.lower(info.node.code)
        apply_code(block, lowered)
        self.lowered[(info.kind, info.number)] = lowered
        self.diagnostics += scope.diagnostics

    def data_block(self, info: BlockInfo, block: Block) -> None:
        data_type = info.db_type
        if data_type is None:
            if info.node.db_values:
                self.diagnostics.append(
                    problem("STL216", info.file, info.node.loc, name=info.label, member="...")
                )
            return
        if isinstance(data_type, BlockType) and data_type.kind in ("FB", "SFB"):
            block.instance_of = data_type.number
            block.attributes["instance_of"] = f"{data_type.kind} {data_type.number}"
            known = (BlockKind(data_type.kind), data_type.number) in self.index.blocks
            if not known and data_type.kind == "FB":
                self.diagnostics.append(
                    problem("STL213", info.file, info.node.loc, block=f"FB {data_type.number}")
                )
            if data_type.kind == "SFB" and self.index._expand(data_type) is None:
                return  # a system FB whose interface Nasaq does not know: the CPU lays it out
        slots, size = self.index.slots_of_type(data_type, info)
        block.interface = variables(slots)
        if self.db_too_large(info.file, info.node.loc, info.label, size):
            return
        builder = DataBuilder(self.index.layout, size, info.file)
        builder.defaults(slots)
        assigns = [
            item
            for item in info.node.db_values
            if isinstance(item, ast.DbAssignNode)
            and not (isinstance(item.path[0], str) and item.path[0].upper() in info.untyped)
        ]
        builder.actual_values(slots, assigns)
        block.data = bytes(builder.data)
        self.diagnostics += builder.diagnostics

    def check_temp(self, info: BlockInfo, size: int) -> None:
        """STL605 for a block whose local data (its VAR_TEMP and the temporaries the SCL compiler
        adds) exceed the L stack the profile's CPU has per priority class: STEP 7 compiles such
        a block, but the CPU could never call it (it goes to STOP, SIM509), so Nasaq says so
        when compiling (COMPATIBILITY.md, "L stack")."""
        from nasaq.cpu.profile import Profile  # the CPU's figures (lang does not load the CPU)

        limit = Profile(self.profile).lstack_bytes
        if size > limit:
            label = f"{info.kind.value} {info.number}"
            name = f'"{info.name}" ({label})' if info.name else label
            params = {"block": name, "size": size, "limit": limit, "profile": self.profile}
            self.diagnostics.append(problem("STL605", info.file, info.node.loc, **params))

    def db_too_large(self, file: str, loc: ast.Loc | None, label: str, size_bits: int) -> bool:
        """STL152 for a data block larger than the profile's limit (``limits.max_db_bytes``):
        its image is not built (a declared ARRAY[0..2000000000] would take gigabytes)."""
        limit = max_db_bytes(self.profile)
        size = size_bits // 8
        if size <= limit:
            return False
        params = {"name": label, "size": size, "limit": limit, "profile": self.profile}
        self.diagnostics.append(problem("STL152", file, loc or ast.Loc(1, 1, 1, 1), **params))
        return True

    def auto_instance(self, auto: AutoInstance) -> None:
        symbol = self.symbols.block_symbol(BlockKind.DB, auto.db)
        name = symbol.name if symbol is not None else ""
        block = Block(BlockKind.DB, auto.db, name=name, file=auto.file, instance_of=auto.fb.number)
        block.attributes["instance_of"] = f"{auto.fb.kind} {auto.fb.number}"
        expansion = self.index._expand(auto.fb)
        if isinstance(expansion, list):
            slots, size = self.index.layout.instance(expansion)
            block.interface = variables(slots)
            if self.db_too_large(auto.file, None, f"DB {auto.db}", size):
                self.program.add(block)
                return
            builder = DataBuilder(self.index.layout, size, auto.file)
            builder.defaults(slots)
            block.data = bytes(builder.data)
            self.diagnostics += builder.diagnostics
        self.program.add(block)

    def resolve_jumps(self) -> None:
        """Reports the jumps to a label that their block does not define (rare: the labels a
        block jumps to are compared first, at once)."""
        owners: dict[str, str] = {}
        for (kind, number), lowered in self.lowered.items():
            if {jump.label for jump in lowered.jumps} <= lowered.labels.keys():
                continue
            if not owners:
                owners = self.label_owners()
            info = self.index.blocks[(kind, number)]
            for jump in lowered.jumps:
                if jump.label in lowered.labels:
                    continue
                if jump.label in owners:
                    self.diagnostics.append(
                        problem(
                            "STL219",
                            info.file,
                            jump.loc,
                            label=jump.label,
                            other=owners[jump.label],
                        )
                    )
                else:
                    self.diagnostics.append(
                        problem("STL207", info.file, jump.loc, label=jump.label, block=info.label)
                    )

    def label_owners(self) -> dict[str, str]:
        """The first block that defines each label."""
        owners: dict[str, str] = {}
        for (kind, number), lowered in self.lowered.items():
            for label in lowered.labels:
                owners.setdefault(label, f"{kind.value} {number}")
        return owners


def compile_sources(
    sources: Iterable[SourceFile],
    mnemonics: str = "auto",
    test_ops: bool = False,
    profile: str = DEFAULT_PROFILE,
) -> CompileResult:
    """Compiles STL sources (``.awl``/``.stl``) with their symbol tables (``.sdf``, ``.asc``,
    ``.seq``, ``.csv``) into one program. ``mnemonics`` is ``"auto"`` (per file), ``"en"`` or
    ``"de"``; ``test_ops`` accepts awlsim's ``__ASSERT``-style self-check instructions and the
    few awlsim extensions listed in ``nasaq.lang.stl``; ``profile`` is the CPU family
    (``nasaq.lang.profiles``), which decides what the sources may use."""
    gc_was_enabled = gc.isenabled()
    # A compilation makes millions of small objects and frees few until it ends: the cyclic
    # collector would scan them again and again (a quarter of the time of a large source) to
    # find nothing. The syntax trees are freed (by reference counting) before it runs again.
    gc.disable()
    try:
        return _compile(list(sources), mnemonics, test_ops, profile)
    finally:
        if gc_was_enabled:
            gc.enable()


def _compile(
    sources: list[SourceFile], mnemonics: str, test_ops: bool, profile: str
) -> CompileResult:
    compiler = _Compiler(mnemonics, test_ops, profile)
    compiler.read(sources)
    compiler.diagnostics += compiler.index.diagnostics
    compiler.index.diagnostics = []
    read = len(compiler.diagnostics)
    registered = compiler.register()
    compiler.build(registered)
    compiler.diagnostics += compiler.index.diagnostics
    if compiler.lad_files:
        # What was found in the STL of a LAD file belongs to the LAD file's network.
        from nasaq.lang.lad.compile import moved_to_lad

        for k in range(read, len(compiler.diagnostics)):
            span = compiler.diagnostics[k].span
            lowered = compiler.lad_files.get(span.file or "") if span is not None else None
            if lowered is not None:
                compiler.diagnostics[k] = moved_to_lad(compiler.diagnostics[k], lowered)
    diagnostics = sorted(compiler.diagnostics, key=sort_key)
    return CompileResult(compiler.program, diagnostics, compiler.generated)

"""SCL sources inside a project compilation (``nasaq.lang.stl.compile_sources``), next to STL
sources: one block numbering, one symbol table, calls in both directions.

The STL compiler drives the steps in this order:
1. it registers the STL blocks (their numbers come from their names or the symbol table);
2. ``bind``: the SCL blocks are numbered around them (TIA numbering skips numbers STL took),
   and the SCL blocks that have a name get it in the symbol table, so STL can call ``"Motor"``;
3. it declares the STL interfaces; ``attach`` hands them to the SCL index (an SCL call of an
   STL FC is checked against the FC's parameters);
4. ``lower``: type check, and when the SCL sources have no error, STL syntax trees of the SCL
   blocks, which the STL compiler registers, declares and compiles with the rest.
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic, Severity
from nasaq.ir import BlockKind
from nasaq.lang.profiles import DEFAULT_PROFILE
from nasaq.lang.scl import ast, optimized
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.lower import lower_index
from nasaq.lang.scl.typecheck import check_index
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.stl import ast as stl
from nasaq.lang.stl.addresses import parse_address
from nasaq.lang.stl.bind import BlockInfo
from nasaq.lang.stl.symbols import Symbol, SymbolTable


class SclUnit:
    def __init__(
        self, sources: list[ast.SourceFile], symbols: SymbolTable, profile: str = DEFAULT_PROFILE
    ) -> None:
        self.sources = sources
        self.symbols = symbols
        self.index = SclIndex(symbols, profile)
        self.externals: list[tuple[SclBlock, BlockInfo]] = []

    def bind(self, stl_blocks: dict[tuple[BlockKind, int], BlockInfo]) -> list[Diagnostic]:
        for (kind, number), info in stl_blocks.items():
            if kind in (BlockKind.OB, BlockKind.FB, BlockKind.FC, BlockKind.DB, BlockKind.UDT):
                external = self.index.add_external(kind, number, info.name, info.file)
                self.externals.append((external, info))
        self.index.add_sources(self.sources)
        for block in self.index:
            if block.external or block.node.name.absolute:
                continue
            if self.symbols.get(block.name) is not None:
                continue
            address = f"{block.kind.value} {block.number}"
            where = block.node.name.loc
            self.symbols.symbols[block.name.casefold()] = Symbol(
                block.name, address, parse_address(address), "", "", block.file, where.line
            )
        return list(self.index.diagnostics)

    def optimized_dbs(self) -> dict[int, str]:
        """The optimized DBs (``scl.optimized``) by number, with the name a message shows."""
        return {
            block.number: optimized.db_label(self.index, block.number)
            for block in self.index
            if block.kind is BlockKind.DB
            and not block.external
            and optimized.optimized_db(self.index, block.number)
        }

    def attach(self) -> None:
        for external, info in self.externals:
            external.sections = list(info.sections)
            external.return_type = info.return_type
            external.db_type = info.db_type

    def lower(self) -> tuple[list[tuple[str, stl.BlockNode]], list[Diagnostic]]:
        contexts: dict[tuple[BlockKind, int], Context] = {}
        diagnostics = check_index(self.index, contexts)
        if any(item.severity is Severity.ERROR for item in diagnostics + self.index.diagnostics):
            return [], diagnostics
        blocks, problems = lower_index(self.index, contexts)
        return blocks + self.implicit_instances(), diagnostics + problems

    def implicit_instances(self) -> list[tuple[str, stl.BlockNode]]:
        """The instance DBs that calls like ``FB10.DB10(...)`` create (S7-SCL creates them at
        compile time when no DATA_BLOCK declares them)."""
        found: list[tuple[str, stl.BlockNode]] = []
        for number, made_of in sorted(self.index.implicit_dbs.items()):
            if self.index.get(BlockKind.DB, number) is not None:
                continue
            caller = next(iter(self.index), None)
            file = caller.file if caller is not None else ""
            where = stl.Loc(1, 1, 1, 1)
            node = stl.BlockNode("DATA_BLOCK", f"DB {number}", False, where, where)
            node.db_body = stl.RefTypeNode(f"{made_of.kind} {made_of.number}", False, where)
            found.append((file, node))
        return found

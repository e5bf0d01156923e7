"""A project's outline for the editor's completion, hover help and go to definition: its symbols
and every block with the members of its interface (a DB: of its data), flattened.

The editor asks for it after every change of a file, next to ``/blocks``, so the outline of the
same sources is kept (a few projects' worth): a compile takes milliseconds for the examples, but
a large plant's would be felt on every keystroke's autosave.

The members are the DB editor's rows (``nasaq.workbench.members``, with the line of each
declaration); the compiler does not keep an SCL declaration's comment, so it is read from that
line.
"""

from __future__ import annotations

import hashlib
import re
import threading
from collections import OrderedDict

from pydantic import BaseModel, Field

from nasaq.ir import Program
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES, SymbolTable, read_symbol_table
from nasaq.workbench.graph_outline import OutlineSequencer, graph_charts
from nasaq.workbench.members import Member, block_members
from nasaq.workbench.names import BlockLanguage, language_of
from nasaq.workbench.project_compile import compile_project
from nasaq.workbench.tree import KindName, user_blocks

_COMMENT = re.compile(r"//(.*)$")
_CACHE_SIZE = 8
# The temporaries the SCL compiler adds to a block's L stack (``_t1``): not the user's to name.
_GENERATED = re.compile(r"_t\d+")


class OutlineSymbol(BaseModel):
    name: str
    address: str = Field(description="As the table writes it, spacing normalised: 'Q 4.0'")
    type: str
    comment: str
    file: str
    line: int


class OutlineBlock(BaseModel):
    kind: KindName
    number: int
    name: str = Field(description="Symbolic name, empty when the block has none")
    language: BlockLanguage
    file: str
    line: int | None = Field(description="Line of the block's header")
    return_type: str | None = Field(description="FCs: the return type ('VOID', 'REAL')")
    instance_of: str | None = Field(description="Instance DBs: 'FB 10'")
    members: list[Member] = Field(
        description="The interface of a code block; the data of a DB (an instance DB's are "
        "its FB's)"
    )
    sequencers: list[OutlineSequencer] | None = Field(
        default=None,
        description="An S7-Graph FB: its sequencers, steps and transitions with their lines",
    )


class ProjectOutline(BaseModel):
    symbols: list[OutlineSymbol]
    blocks: list[OutlineBlock]


def _with_comment(member: Member, lines: dict[str, list[str]]) -> Member:
    """SCL declarations' comments are not kept by the compiler: read them from the line."""
    if member.comment or member.file not in lines or not member.line:
        return member
    text = lines[member.file]
    found = _COMMENT.search(text[member.line - 1]) if member.line <= len(text) else None
    return member.model_copy(update={"comment": found.group(1).strip()}) if found else member


def _blocks(program: Program, texts: dict[str, str]) -> list[OutlineBlock]:
    lines = {name: text.splitlines() for name, text in texts.items()}
    charts = {
        name: graph_charts(name, text)
        for name, text in texts.items()
        if language_of(name) == "graph"
    }
    return [
        OutlineBlock(
            kind=entry.kind,
            number=entry.number,
            name=entry.name,
            language=entry.language,
            file=entry.file,
            line=entry.line,
            return_type=block.return_type,
            instance_of=entry.instance_of,
            members=[
                _with_comment(member, lines)
                for member in block_members(block, program, texts)
                if member.line or _GENERATED.fullmatch(member.name) is None
            ],
            sequencers=_chart(charts, entry.file, entry.kind, entry.number, entry.name),
        )
        for block, entry in user_blocks(program.blocks.values(), texts)
    ]


def _chart(
    charts: dict[str, dict[str, list[OutlineSequencer]]],
    file: str,
    kind: str,
    number: int,
    name: str,
) -> list[OutlineSequencer] | None:
    found = charts.get(file)
    if found is None or kind != "FB":
        return None
    by_number = found.get(f"FB{number}")
    return by_number if by_number is not None else found.get(name.casefold())


def _symbols(sources: list[tuple[str, str]]) -> list[OutlineSymbol]:
    """The symbol tables read again: the program keeps only names, addresses and types."""
    table = SymbolTable()
    for name, text in sources:
        if name.lower().endswith(SYMBOL_TABLE_SUFFIXES):
            read_symbol_table(name, text, table)
    return [
        OutlineSymbol(
            name=symbol.name,
            address=symbol.address,
            type=symbol.type,
            comment=symbol.comment,
            file=symbol.file,
            line=symbol.line,
        )
        for symbol in table.symbols.values()
    ]


def _outline(sources: list[tuple[str, str]]) -> ProjectOutline:
    result = compile_project(sources)
    return ProjectOutline(symbols=_symbols(sources), blocks=_blocks(result.program, dict(sources)))


_cache: OrderedDict[bytes, ProjectOutline] = OrderedDict()
_cache_lock = threading.Lock()


def _key(sources: list[tuple[str, str]]) -> bytes:
    digest = hashlib.sha256()
    for name, text in sorted(sources):
        for part in (name, text):
            encoded = part.encode("utf-8", "surrogatepass")
            digest.update(len(encoded).to_bytes(8, "little"))
            digest.update(encoded)
    return digest.digest()


def outline(sources: list[tuple[str, str]]) -> ProjectOutline:
    """The outline of the files, compiled together (or kept from the last time they were the
    same). Slow for big projects the first time: call it in a thread."""
    key = _key(sources)
    with _cache_lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    found = _outline(sources)
    with _cache_lock:
        _cache[key] = found
        while len(_cache) > _CACHE_SIZE:
            _cache.popitem(last=False)
    return found

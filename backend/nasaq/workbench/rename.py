"""Rename a symbol, a block or a DB member everywhere in a project, as TIA Portal's "Rename"
does: sources (STL, SCL, LAD/FBD and S7-Graph text), symbol tables and watch tables (``.vat``).

What a name is comes from the compiler (``xref``): the symbol table and the program decide that
``"Motor"`` is ``Q 4.0`` or that ``"Data".Speed`` is a member of DB 5. Where it is written is
read token by token: a quoted name (``"Motor"``) or a member after a DB (``"Data".Speed``,
``DB5.Speed``), never inside a comment, a string, a title or another quoted name. The result is
compiled again, and a rename that would give the program more errors is refused (XRF710).

Rules (STEP 7's): a symbol has 1..24 characters, no double quote and no control character, and
neither starts nor ends with a blank; symbols are compared without regard to case, so a new name
that only another symbol has (in any case) is refused. A DB member is an identifier (letter or
``_`` first, then letters, digits, ``_``; no ``__``) of up to 24 characters, unique in its DB.
An instance DB's members are its FB's interface: they are renamed in the FB (not supported here,
XRF711). Nothing is changed when anything is refused.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from pydantic import BaseModel, Field

from nasaq.diagnostics import Severity
from nasaq.ir import Block, BlockKind, Program
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.compiler import SCL_SUFFIXES
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES, SymbolTable, read_symbol_table
from nasaq.workbench.members import block_members
from nasaq.workbench.names import language_of
from nasaq.workbench.project_compile import compile_project
from nasaq.workbench.tree import header_line, header_lines
from nasaq.workbench.xref import XrefError, _Names, _split_member

MAX_SYMBOL_CHARS = 24
WATCH_SUFFIXES = (".vat",)
_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_MEMBER_NAME = re.compile(r"(?!.*__)[A-Za-z_][A-Za-z0-9_]{0,23}")
_ABSOLUTE_DB = re.compile(r"DB\s*(\d+)", re.IGNORECASE)
_DB_ADDRESSES = frozenset({"DBX", "DBB", "DBW", "DBD"})
_LINE_TEXT = re.compile(r"(TITLE|COMMENT)\b", re.IGNORECASE)  # rest of the line is prose


class RenameChange(BaseModel):
    file: str
    line: int
    column: int = Field(description="1-based column of the first renamed token on the line")
    before: str = Field(description="The whole line before")
    after: str = Field(description="The whole line after")


class RenamePlan(BaseModel):
    target: str
    kind: str = Field(description="symbol, block or member")
    old_name: str
    new_name: str
    changes: list[RenameChange]
    texts: dict[str, str] = Field(description="The changed files' new texts", exclude=True)


@dataclass(frozen=True, slots=True)
class _Token:
    start: int
    end: int
    text: str  # inner text of a quoted name; the word itself otherwise
    quoted: bool


def _tokens(text: str, suffix: str) -> Iterator[_Token]:
    """Quoted names and words of a source, outside comments, strings and title lines."""
    scl = suffix in SCL_SUFFIXES
    prose = suffix in (".awl", ".stl", ".lad", ".fbd", ".graph")
    index, size = 0, len(text)
    line_start = True
    while index < size:
        char = text[index]
        if char == "\n":
            line_start = True
            index += 1
            continue
        if char in " \t\r":
            index += 1
            continue
        if prose and line_start and (match := _LINE_TEXT.match(text, index)):
            after = text[match.end() :].lstrip(" \t")
            if after.startswith(("=", ":")) and not after.startswith(":="):
                end = text.find("\n", index)
                index = size if end < 0 else end
                continue
        line_start = False
        if text.startswith("//", index):
            end = text.find("\n", index)
            index = size if end < 0 else end
        elif text.startswith("(*", index):
            end = text.find("*)", index + 2)
            index = size if end < 0 else end + 2
        elif scl and char == "{":
            end = text.find("}", index)
            index = size if end < 0 else end + 1
        elif char in "\"'":
            end = text.find(char, index + 1)
            newline = text.find("\n", index + 1)
            if end < 0 or 0 <= newline < end:
                index += 1  # an unclosed quote: the compiler reports it; read on
                continue
            if char == '"':
                yield _Token(index, end + 1, text[index + 1 : end], True)
            index = end + 1
        elif match := _IDENT.match(text, index):
            yield _Token(index, match.end(), match.group(), False)
            index = match.end()
        else:
            index += 1


def _member_after(text: str, token: _Token) -> tuple[int, int, str] | None:
    """The member written after a DB (``"Data".Speed``, ``DB5 . Speed``): its span and name."""
    index = token.end
    while index < len(text) and text[index] in " \t":
        index += 1
    if index >= len(text) or text[index] != ".":
        return None
    index += 1
    while index < len(text) and text[index] in " \t":
        index += 1
    match = _IDENT.match(text, index)
    if match is None or match.group().upper() in _DB_ADDRESSES:
        return None
    return match.start(), match.end(), match.group()


@dataclass(slots=True)
class _Edit:
    start: int
    end: int
    replacement: str


def _apply(text: str, edits: list[_Edit]) -> str:
    parts: list[str] = []
    last = 0
    for edit in sorted(edits, key=lambda item: item.start):
        parts.append(text[last : edit.start])
        parts.append(edit.replacement)
        last = edit.end
    parts.append(text[last:])
    return "".join(parts)


def _symbol_row(line: str, suffix: str, new_name: str) -> str:
    """The symbol table line with its name cell replaced, in the file's own format."""
    if suffix == "asc":
        offset = 4 if line[:4].strip(",").isdigit() and line[3:4] == "," else 0
        return line[:offset] + new_name.ljust(24)[:24] + line[offset + 24 :]
    if suffix == "seq":
        cells = line.split("\t")
        place = 1 if cells and cells[0].strip().isdigit() and len(cells) > 4 else 0
        cells[place] = new_name
        return "\t".join(cells)
    stripped = line.lstrip()
    lead = line[: len(line) - len(stripped)]
    if stripped.startswith('"'):
        close = stripped.find('"', 1)
        inner = stripped[1:close]
        padded = new_name.ljust(len(inner)) if inner != inner.rstrip() else new_name
        return f'{lead}"{padded}"{stripped[close + 1 :]}'
    delimiter = ";" if line.count(";") > line.count(",") else ","
    _, sep, rest = stripped.partition(delimiter)
    return f"{lead}{new_name}{sep}{rest}"


def check_symbol_name(name: str) -> None:
    if (
        not 0 < len(name) <= MAX_SYMBOL_CHARS
        or name != name.strip()
        or '"' in name
        or any(ord(char) < 32 or ord(char) == 127 for char in name)
    ):
        raise XrefError("XRF704", name=name, limit=MAX_SYMBOL_CHARS)


def _compile(sources: list[tuple[str, str]]) -> tuple[Program, int]:
    result = compile_project(sources)
    errors = sum(1 for item in result.diagnostics if item.severity == Severity.ERROR)
    return result.program, errors


def _symbol_tables(sources: list[tuple[str, str]]) -> SymbolTable:
    table = SymbolTable()
    for name, text in sources:
        if name.lower().endswith(SYMBOL_TABLE_SUFFIXES):
            read_symbol_table(name, text, table)
    return table


def _suffix(name: str) -> str:
    return name[name.rfind(".") :].lower() if "." in name else ""


def _renamable(name: str) -> bool:
    language = language_of(name)
    return (language is not None and language != "symbols") or _suffix(name) in WATCH_SUFFIXES


def _changes(old: dict[str, str], new: dict[str, str]) -> list[RenameChange]:
    found: list[RenameChange] = []
    for name in sorted(new):
        before, after = old[name].split("\n"), new[name].split("\n")
        for number, (first, second) in enumerate(zip(before, after, strict=True), start=1):
            if first != second:
                column = next(
                    (i for i, (a, b) in enumerate(zip(first, second, strict=False)) if a != b),
                    min(len(first), len(second)),
                )
                found.append(
                    RenameChange(
                        file=name,
                        line=number,
                        column=column + 1,
                        before=first.rstrip("\r"),
                        after=second.rstrip("\r"),
                    )
                )
    return found


def _rename_symbol(
    sources: list[tuple[str, str]], old: str, new: str, table: SymbolTable
) -> dict[str, str]:
    key = old.casefold()
    texts: dict[str, str] = {}
    for name, text in sources:
        edits: list[_Edit] = []
        if _renamable(name):
            for token in _tokens(text, _suffix(name)):
                if token.quoted and token.text.casefold() == key:
                    edits.append(_Edit(token.start, token.end, f'"{new}"'))
        elif name.lower().endswith(SYMBOL_TABLE_SUFFIXES):
            symbol = table.get(old)
            if symbol is not None and symbol.file == name:
                lines = text.split("\n")
                lines[symbol.line - 1] = _symbol_row(lines[symbol.line - 1], _suffix(name)[1:], new)
                texts[name] = "\n".join(lines)
            continue
        if edits:
            texts[name] = _apply(text, edits)
    return texts


def _db_names(program: Program, names: _Names, number: int) -> set[str]:
    """How sources may name DB ``number``: its symbol (casefolded) and ``DB<n>``."""
    found = {f"db{number}"}
    block = program.get(BlockKind.DB, number)
    if block is not None and block.name:
        found.add(block.name.casefold())
    for key, symbol in names.by_key.items():
        if program.symbols.get(symbol, "").replace(" ", "").upper() == f"DB{number}":
            found.add(key)
    return found


def _rename_member(
    sources: list[tuple[str, str]], program: Program, names: _Names, db: int, old: str, new: str
) -> dict[str, str]:
    block = program.get(BlockKind.DB, db)
    assert block is not None
    spellings = _db_names(program, names, db)
    key = old.casefold()
    texts = dict(sources)
    region = _db_region(texts.get(block.file, ""), block)
    edits: dict[str, list[_Edit]] = {}
    for name, text in sources:
        if not _renamable(name):
            continue
        tokens = list(_tokens(text, _suffix(name)))
        for token in tokens:
            spelled = token.text.casefold()
            if not token.quoted:
                absolute = _ABSOLUTE_DB.fullmatch(token.text)
                spelled = f"db{absolute.group(1)}" if absolute else ""
            if spelled in spellings:
                member = _member_after(text, token)
                if member is not None and member[2].casefold() == key:
                    edits.setdefault(name, []).append(_Edit(member[0], member[1], new))
            elif (
                name == block.file
                and region[0] <= token.start < region[1]
                and not token.quoted
                and token.text.casefold() == key
                and _declares(text, token)
            ):
                edits.setdefault(name, []).append(_Edit(token.start, token.end, new))
    return {name: _apply(texts[name], found) for name, found in edits.items()}


def _db_region(text: str, block: Block) -> tuple[int, int]:
    """Where the DB's source is in its file: from its header to its END_DATA_BLOCK."""
    line = header_line(block, header_lines(text)) or 1
    start = 0
    for _ in range(line - 1):
        start = text.find("\n", start) + 1
    end = text.upper().find("END_DATA_BLOCK", start)
    return start, len(text) if end < 0 else end


def _declares(text: str, token: _Token) -> bool:
    """The word is a declaration (``Speed : INT``) or a BEGIN-section assignment (``Speed :=``)
    at the start of its line."""
    line_start = text.rfind("\n", 0, token.start) + 1
    if text[line_start : token.start].strip():
        return False
    rest = text[token.end :].lstrip(" \t")
    return rest.startswith((":", "[", "."))


def plan_rename(sources: list[tuple[str, str]], target: str, new_name: str) -> RenamePlan:
    """Every change renaming ``target`` to ``new_name`` makes, or an XrefError refusing it."""
    program, errors = _compile(sources)
    names = _Names(program)
    if not target.strip().startswith('"') and _looks_absolute(target):
        symbol = names.of_text(" ".join(target.split()))
        if not symbol:
            raise XrefError("XRF708", target=target)
        target = f'"{symbol}"'
    head, member = _split_member(target)
    head = head.strip().strip('"')
    if member is None and "." in head and not target.strip().startswith('"'):
        head, _, written = head.partition(".")
        member = written
    if member is not None:
        texts, old, kind = _member_plan(sources, program, names, target, head, member, new_name)
    else:
        found = names.by_key.get(head.casefold())
        block_named = {block.name.casefold() for block in program.blocks.values() if block.name}
        if found is None and head.casefold() not in block_named:
            raise XrefError("XRF708" if _looks_absolute(head) else "XRF701", target=target)
        old = found or head
        check_symbol_name(new_name)
        if new_name == old:
            raise XrefError("XRF712", name=new_name)
        taken = names.by_key.get(new_name.casefold())
        if (taken is not None and taken.casefold() != old.casefold()) or (
            new_name.casefold() in block_named and new_name.casefold() != old.casefold()
        ):
            raise XrefError("XRF705", name=new_name, address=program.symbols.get(taken or "", ""))
        address = program.symbols.get(old, "")
        kind = "block" if found is None or _is_block(address) else "symbol"
        texts = _rename_symbol(sources, old, new_name, _symbol_tables(sources))
    renamed = [(name, texts.get(name, text)) for name, text in sources]
    _, after = _compile(renamed)
    if after > errors:
        raise XrefError("XRF710", name=new_name, errors=after - errors)
    return RenamePlan(
        target=target.strip(),
        kind=kind,
        old_name=old,
        new_name=new_name,
        changes=_changes(dict(sources), texts),
        texts=texts,
    )


def _looks_absolute(text: str) -> bool:
    try:
        parse_address(" ".join(text.split()))
    except AddressError:
        return False
    return True


def _is_block(address: str) -> bool:
    try:
        return parse_address(" ".join(address.split())).kind == "block"
    except AddressError:
        return False


def _member_plan(
    sources: list[tuple[str, str]],
    program: Program,
    names: _Names,
    target: str,
    head: str,
    member: str,
    new_name: str,
) -> tuple[dict[str, str], str, str]:
    symbol = names.by_key.get(head.casefold())
    address = (program.symbols.get(symbol, "") if symbol else head).replace(" ", "").upper()
    absolute = _ABSOLUTE_DB.fullmatch(address)
    if absolute is None:
        raise XrefError("XRF702", target=target, name=head)
    db = int(absolute.group(1))
    block = program.get(BlockKind.DB, db)
    if block is None:
        raise XrefError("XRF701", target=target)
    if block.instance_of is not None:
        raise XrefError("XRF711", target=target, name=head)
    rows = block_members(block, program, dict(sources))
    found = next(
        (row for row in rows if row.depth == 0 and row.name.casefold() == member.casefold()), None
    )
    if found is None:
        raise XrefError("XRF703", target=target, name=head, member=member)
    if _MEMBER_NAME.fullmatch(new_name) is None:
        raise XrefError("XRF706", name=new_name, limit=MAX_SYMBOL_CHARS)
    if new_name == found.name:
        raise XrefError("XRF712", name=new_name)
    if any(
        row.depth == 0 and row.name.casefold() == new_name.casefold() and row is not found
        for row in rows
    ):
        raise XrefError("XRF707", name=new_name, db=head)
    return _rename_member(sources, program, names, db, found.name, new_name), found.name, "member"

"""What a project's files compile to: the blocks of the project tree and the diagnostics.

The compiler takes every file at once (STL, SCL and symbol tables call and name each other), so
the tree is the program it builds, not a list kept beside the files. Where a block is defined is
found by its header line in its file (``FUNCTION_BLOCK "Motor"``, ``DATA_BLOCK DB 5``): the IR
keeps the file of each block but only its instructions' lines, and DBs and UDTs have none.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Literal

from pydantic import BaseModel, Field

from nasaq.diagnostics import Diagnostic
from nasaq.ir import Block, BlockKind
from nasaq.plants.plant_file import plant_file_problems
from nasaq.workbench.names import BlockLanguage, language_of
from nasaq.workbench.project_compile import compile_project

KindName = Literal["OB", "FB", "FC", "DB", "UDT"]
BLOCK_KINDS: dict[BlockKind, KindName] = {
    BlockKind.OB: "OB",
    BlockKind.FB: "FB",
    BlockKind.FC: "FC",
    BlockKind.DB: "DB",
    BlockKind.UDT: "UDT",
}
KIND_ORDER = {kind: place for place, kind in enumerate(BLOCK_KINDS.values())}

_HEADER = re.compile(
    r"^[ \t]*(?:ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION|DATA_BLOCK|TYPE)[ \t]+"
    r'("[^"\n]*"|\w+(?:[ \t]+\d+)?)',
    re.MULTILINE | re.IGNORECASE,
)
_ABSOLUTE = re.compile(r"(OB|FB|FC|DB|UDT)(\d+)")


class TreeBlock(BaseModel):
    kind: KindName
    number: int
    name: str = Field(description="Symbolic name, empty when the block has none")
    title: str
    language: BlockLanguage
    file: str
    line: int | None = Field(
        description="Line of the block's header in its file; null for an instance DB the "
        "compiler created for a CALL"
    )
    instance_of: str | None = Field(default=None, description="Instance DBs: 'FB 10'")


class ProjectBuild(BaseModel):
    blocks: list[TreeBlock]
    diagnostics: list[Diagnostic]


def header_lines(text: str) -> dict[str, int]:
    """Each block header's identity (``FB10``, or a casefolded symbol) -> its first line."""
    found: dict[str, int] = {}
    for match in _HEADER.finditer(text):
        ident = match.group(1)
        key = ident[1:-1].casefold() if ident.startswith('"') else ident.replace(" ", "").upper()
        if _ABSOLUTE.fullmatch(key) is None and not ident.startswith('"'):
            key = key.casefold()  # an SCL name written without quotes
        found.setdefault(key, text.count("\n", 0, match.start()) + 1)
    return found


def header_line(block: Block, headers: dict[str, int]) -> int | None:
    for key in (f"{block.kind.value}{block.number}", block.name.casefold()):
        if key and key in headers:
            return headers[key]
    origins = [item.origin for item in block.code if item.origin is not None]
    return origins[0].line if origins else None


def user_blocks(blocks: Iterable[Block], texts: dict[str, str]) -> list[tuple[Block, TreeBlock]]:
    """The blocks of the user's files (not the IEC library FCs the compiler adds), each with its
    entry in the tree, in the tree's order (by kind, then number)."""
    headers: dict[str, dict[str, int]] = {}
    found: list[tuple[Block, TreeBlock]] = []
    for block in blocks:
        language = language_of(block.file)
        kind = BLOCK_KINDS.get(block.kind)
        if kind is None or block.file not in texts or language is None or language == "symbols":
            continue
        if block.file not in headers:
            headers[block.file] = header_lines(texts[block.file])
        entry = TreeBlock(
            kind=kind,
            number=block.number,
            name=block.name,
            title=block.title,
            language=language,
            file=block.file,
            line=header_line(block, headers[block.file]),
            instance_of=block.attributes.get("instance_of"),
        )
        found.append((block, entry))
    return sorted(found, key=lambda pair: (KIND_ORDER[pair[1].kind], pair[1].number))


def build(sources: list[tuple[str, str]]) -> ProjectBuild:
    """Compiles the files together. Slow for big projects: call it in a thread."""
    result = compile_project(sources)
    blocks = [entry for _, entry in user_blocks(result.program.blocks.values(), dict(sources))]
    plant = plant_file_problems(sources)  # the .plant file, which the compiler skips
    return ProjectBuild(blocks=blocks, diagnostics=result.diagnostics + plant)

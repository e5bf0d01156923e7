"""Conversion between STL, LAD and FBD sources (``nasaq convert``, ``POST /api/convert``).

- LAD/FBD → STL always succeeds: the STL the blocks lower to (``to_stl``), what the CPU runs.
- LAD ↔ FBD always succeeds: both are views of the same network model; the file says which
  view its blocks are in (``LANGUAGE FBD``).
- S7-Graph → STL: the STL the FB compiles to (``nasaq.lang.graph.compile``); a Graph source
  converts to nothing else, and nothing converts to S7-Graph (LAD502, LAD503).
- STL → LAD/FBD goes network by network (``from_stl``): a network with LAD shape becomes a rung,
  any other stays STL inside the LAD block with the reason it does not convert, as STEP 7 shows
  an STL network in the LAD view. Those reasons come back as diagnostics (severity info).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Literal

from nasaq.diagnostics import Diagnostic, Span, render
from nasaq.lang.lad.compile import lower_file
from nasaq.lang.lad.from_stl import LiftedBlock, NotConvertible, lift_block
from nasaq.lang.lad.model import LadBlock, Network
from nasaq.lang.lad.text import SUFFIXES as LAD_SUFFIXES
from nasaq.lang.lad.text import number_network, parse_lad, print_lad
from nasaq.lang.lad.to_stl import temp_prefix

Target = Literal["stl", "lad", "fbd"]
TARGETS: tuple[Target, ...] = ("stl", "lad", "fbd")
STL_SUFFIXES = (".awl", ".stl")
GRAPH_SUFFIXES = (".graph",)  # nasaq.lang.graph.text.SUFFIXES

_BLOCK = re.compile(
    r"^[ \t]*(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)\b[^\n]*$", re.IGNORECASE | re.MULTILINE
)
_BEGIN = re.compile(r"^[ \t]*BEGIN\b", re.IGNORECASE | re.MULTILINE)
_TITLE = re.compile(r"^[ \t]*TITLE\s*=", re.IGNORECASE)
_NETWORK_HEAD = re.compile(r"^[ \t]*(NETWORK|TITLE\s*=)", re.IGNORECASE)
_BLOCK_END = re.compile(r"^[ \t]*END_(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)\b", re.I)


@dataclass(slots=True)
class Converted:
    """The converted source, its problems, and how many networks converted or stayed STL."""

    text: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    converted: int = 0
    kept: int = 0
    blocks: list[LadBlock] | None = None  # the LAD/FBD result as the model (the API's JSON)


def _suffix(name: str) -> str:
    return name[name.rfind(".") :].lower() if "." in name else ""


def convert(name: str, text: str, to: Target) -> Converted:
    """``text`` (the file ``name``, its kind by suffix) as ``to``."""
    suffix = _suffix(name)
    if suffix in GRAPH_SUFFIXES:
        return _from_graph(name, text, to)
    if suffix in LAD_SUFFIXES:
        return _from_lad(name, text, to)
    if suffix in STL_SUFFIXES:
        return _from_stl(name, text, to)
    problem = render("LAD501", Span(file=name, line=1, column=1), file=name)
    return Converted("", [problem])


def _from_graph(name: str, text: str, to: Target) -> Converted:
    """An S7-Graph FB converts to the STL it compiles to, as STEP 7 shows a Graph FB's code;
    its sequencer has no LAD/FBD form (LAD502)."""
    if to != "stl":
        problem = render("LAD502", Span(file=name, line=1, column=1), file=name, to=to.upper())
        return Converted("", [problem])
    from nasaq.lang.graph.compile import lower_file as lower_graph  # Graph builds on LAD

    lowered = lower_graph(name, text)
    return Converted(lowered.stl, lowered.diagnostics)


def refused_to_graph(name: str) -> Converted:
    """Nothing converts to S7-Graph: a sequencer is written, not derived from code (LAD503)."""
    return Converted("", [render("LAD503", Span(file=name, line=1, column=1), file=name)])


def _from_lad(name: str, text: str, to: Target) -> Converted:
    if to == "stl":
        lowered = lower_file(name, text)
        return Converted(lowered.stl, lowered.diagnostics)
    blocks, diagnostics = parse_lad(text, name)
    language = "FBD" if to == "fbd" else "LAD"
    shown = [block.model_copy(update={"language": language}) for block in blocks]
    rungs = sum(network.stl is None for block in blocks for network in block.networks)
    total = sum(len(block.networks) for block in blocks)
    return Converted(print_lad(shown), diagnostics, rungs, total - rungs, shown)


def _from_stl(name: str, text: str, to: Target) -> Converted:
    if to == "stl":
        return Converted(text)
    lifted = lift_block(text, name)
    lines = text.split("\n")
    heads: list[int | None] = list(_block_heads(text))
    if len(lifted.blocks) > len(heads):  # code outside blocks came first, as OB 1
        heads.insert(0, None)
    blocks: list[LadBlock] = []
    for number, block in enumerate(lifted.blocks):
        head = heads[number] if number < len(heads) else None
        declarations = _declarations(lines, head) if head is not None else ""
        networks = [
            _kept(network, lines, block, k)
            if isinstance(network, NotConvertible)
            else number_network(network)  # ids, as a parsed file has them
            for k, network in enumerate(block.networks)
        ]
        drawn = LadBlock(
            language="FBD" if to == "fbd" else "LAD",
            kind=block.kind,
            name=block.name,
            return_type=_return_type(lines, head) if block.kind == "FC" else None,
            title=block.title,
            networks=networks,
        )
        declarations = without_lowering_temps(declarations, print_lad([drawn]))
        blocks.append(drawn.model_copy(update={"declarations": declarations}))
    converted, kept = lifted.counts()
    return Converted(print_lad(blocks), list(lifted.diagnostics), converted, kept, blocks)


def _block_heads(text: str) -> list[int]:
    """The 0-based line of each code block's header, in order (DBs and UDTs are not here)."""
    return [text.count("\n", 0, match.start()) for match in _BLOCK.finditer(text)]


_TEMPS = re.compile(r"(?:\A|\n)VAR_TEMP\n((?:  (_lad\d*_t)\d+ : BOOL;\n)+)END_VAR\Z", re.IGNORECASE)
_TEMP_LINE = re.compile(r"  (_lad\d*_t)(\d+) : BOOL;")


def without_lowering_temps(declarations: str, body: str) -> str:
    """The declarations without the ``VAR_TEMP`` section the lowering appended for its
    temporaries (``_lad_t0 : BOOL;`` ...; ``_lad2_t`` when the declarations use ``_lad_t``), so
    that lowering the converted block again declares them once. Dropped only when it is that
    section exactly: at the end, numbered from 0, the prefix the lowering would choose for the
    declarations left, and named nowhere in the block's networks (``body``, its text)."""
    found = _TEMPS.search(declarations)
    if found is None:
        return declarations
    prefix = found.group(2)
    numbers = [
        line.group(2) for line in _TEMP_LINE.finditer(found.group(1)) if line.group(1) == prefix
    ]
    kept = declarations[: found.start()]
    generated = numbers == [str(k) for k in range(len(numbers))]
    if not generated or temp_prefix(kept) != prefix or prefix.lower() in body.lower():
        return declarations
    return kept


def _return_type(lines: list[str], head: int | None) -> str | None:
    if head is None:
        return None
    _, _, after = lines[head].partition(":")
    return after.strip().rstrip(";") or "VOID"


def _declarations(lines: list[str], head: int) -> str:
    """The lines between a block's header (and its TITLE) and BEGIN, as written."""
    body: list[str] = []
    for line in lines[head + 1 :]:
        if _BEGIN.match(line):
            break
        if not body and _TITLE.match(line):
            continue
        body.append(line)
    return "\n".join(body).strip("\n")


def _kept(reason: NotConvertible, lines: list[str], block: LiftedBlock, k: int) -> Network:
    """A network that stays STL: its lines from its start to the next network (or the block's
    end), without its NETWORK/TITLE header."""
    start = block.lines[k] if k < len(block.lines) else reason.line
    end = block.lines[k + 1] - 1 if k + 1 < len(block.lines) else len(lines)
    body: list[str] = []
    for line in lines[start - 1 : end]:
        if _BLOCK_END.match(line):
            break
        body.append(line)
    while body and _NETWORK_HEAD.match(body[0]):
        body.pop(0)
    title = next(
        (line.split("=", 1)[1].strip() for line in lines[start - 1 : end] if _TITLE.match(line)), ""
    )
    stl = "\n".join(body).rstrip()
    return Network(title=title, stl=stl, stl_reason=reason.code)

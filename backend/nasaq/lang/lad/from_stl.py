"""STL → LAD/FBD, one network at a time, as STEP 7 Classic converts a block's view.

A network converts when it is one RLO chain ending in assignments or boxes
(``nasaq.lang.lad.from_stl_rung`` reads it); otherwise it stays STL with a reason
(:class:`NotConvertible`, codes ``LAD302``..: see ``from_stl_reasons.REASONS``) naming the
instruction and its line. The lifter works on the STL parser's AST, so German and international
mnemonics, symbols and STEP 7 exports all read the same way; what ``to_stl`` writes
(``STL_PATTERNS.md``) lifts back to the same model, element ids aside.

Nothing raises for bad input: a syntax error in a network is a reason (``LAD302``) and the
parser's own diagnostics come back in :attr:`LiftResult.diagnostics`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic
from nasaq.lang.lad.from_stl_reasons import REASONS, NotConvertible, RefusalError, not_convertible
from nasaq.lang.lad.from_stl_rung import FinalBoxError, PinDirections, RungReader
from nasaq.lang.lad.from_stl_steps import Step, to_steps
from nasaq.lang.lad.model import LadBlock, Network
from nasaq.lang.stl import ast
from nasaq.lang.stl.compiler import mnemonic_set as language_of
from nasaq.lang.stl.parse import ParseResult, parse_source

__all__ = [
    "REASONS",
    "LiftResult",
    "LiftedBlock",
    "NotConvertible",
    "lift_block",
    "lift_network",
]

_CODE_BLOCKS = {"ORGANIZATION_BLOCK": "OB", "FUNCTION_BLOCK": "FB", "FUNCTION": "FC"}
_JUMPS = frozenset(
    {"JU", "JC", "JCN", "JCB", "JNB", "JBI", "JNBI", "JO", "JOS", "JZ", "JN", "JP", "JM", "JPZ"}
    | {"JMZ", "JUO", "LOOP"}
)
_DIRECTIONS = {"VAR_INPUT": "in", "VAR_OUTPUT": "out", "VAR_IN_OUT": "in_out"}


def lift_network(
    instructions: Sequence[ast.CodeItem],
    *,
    language: str = "en",
    title: str = "",
    comment: str = "",
    directions: PinDirections | None = None,
) -> Network | NotConvertible:
    """The network of ``instructions`` (its code items: instructions and labels; a TITLE is
    taken as the title) as a LAD network, or why it stays STL. ``language`` is the mnemonic
    set (``en``/``de``); ``directions`` says which CALL parameters are outputs. A network
    without instructions is an empty rung, one of only a label (``M001: NOP 0``, a jump
    target) an empty rung with that label."""
    for item in instructions:
        if isinstance(item, ast.TitleNode) and not title:
            title = item.text
        if isinstance(item, ast.BadNode):
            return not_convertible("LAD302", item.loc.line, "?")
    steps = to_steps(instructions, language)
    if not steps:  # an empty network: an empty rung, as STEP 7 shows it
        return Network(title=title, comment=comment)
    return _lift_steps(steps, title, comment, directions)


def _lift_steps(
    steps: list[Step], title: str, comment: str, directions: PinDirections | None
) -> Network | NotConvertible:
    reader = RungReader(steps, directions)
    try:
        label, logic, outputs = reader.read()
    except RefusalError as refusal:
        return refusal.reason
    except FinalBoxError:  # a box pattern read outside a chain: no LAD shape after all
        return not_convertible("LAD325", steps[-1].line, steps[-1].text)
    return Network.model_validate(
        {
            "title": title,
            "comment": comment,
            "label": label,
            "logic": {"elements": logic},
            "outputs": outputs,
        }
    )


@dataclass(slots=True)
class LiftedBlock:
    """One code block: its kind (OB/FB/FC), name as the source writes it, and per network
    either the LAD network or the reason it stays STL."""

    kind: str
    name: str
    title: str
    networks: list[Network | NotConvertible]
    lines: list[int] = field(default_factory=list)  # the line of each network's start

    def converted(self) -> bool:
        return all(isinstance(network, Network) for network in self.networks)

    def lad(self, declarations: str = "") -> LadBlock | None:
        """The whole block as LAD when every network converts."""
        networks = [n for n in self.networks if isinstance(n, Network)]
        if len(networks) != len(self.networks):
            return None
        return LadBlock.model_validate(
            {
                "kind": self.kind,
                "name": self.name,
                "title": self.title,
                "declarations": declarations,
                "networks": networks,
            }
        )


@dataclass(slots=True)
class LiftResult:
    file: str
    blocks: list[LiftedBlock]
    diagnostics: list[Diagnostic]  # the parser's, then one per network that stays STL

    def counts(self) -> tuple[int, int]:
        """(networks that convert, networks that stay STL)."""
        lifted = sum(isinstance(n, Network) for block in self.blocks for n in block.networks)
        total = sum(len(block.networks) for block in self.blocks)
        return lifted, total - lifted


def lift_block(source_text: str, file: str) -> LiftResult:
    """Every code block of an STL source, network by network (code outside blocks counts as
    one block, ``OB 1``, as the compiler reads it)."""
    parsed = parse_source(file, source_text)
    source = parsed.source
    language = language_of(
        [*source.loose_code, *(item for block in source.blocks for item in block.code)]
    )
    directions = _interfaces(source)
    blocks: list[LiftedBlock] = []
    diagnostics = list(parsed.diagnostics)
    if any(isinstance(item, ast.InstrNode) for item in source.loose_code):
        blocks.append(_block("OB", "OB 1", "", source.loose_code, language, directions, parsed))
    for node in source.blocks:
        kind = _CODE_BLOCKS.get(node.keyword)
        if kind is None:
            continue
        name = f'"{node.ident}"' if node.ident_quoted else node.ident
        title = next((h.text for h in node.head if isinstance(h, ast.TitleNode)), "")
        blocks.append(_block(kind, name, title, node.code, language, directions, parsed))
    for block in blocks:
        for number, network in enumerate(block.networks, start=1):
            if isinstance(network, NotConvertible):
                diagnostics.append(network.diagnostic(file, number))
    return LiftResult(file=file, blocks=blocks, diagnostics=diagnostics)


def _block(
    kind: str,
    name: str,
    title: str,
    code: Sequence[ast.CodeItem],
    language: str,
    directions: PinDirections,
    parsed: ParseResult,
) -> LiftedBlock:
    comments = parsed.comments
    groups = _networks(code)
    targets = _jump_targets(code)
    networks: list[Network | NotConvertible] = []
    lines: list[int] = []
    for start, items in groups:
        lines.append(start)
        title_text = next((i.text for i in items if isinstance(i, ast.TitleNode)), "")
        comment = _comment(items, comments)
        lifted = lift_network(
            items,
            language=language,
            title=title_text,
            comment=comment,
            directions=directions,
        )
        if isinstance(lifted, Network):
            inner = _inner_label(items, targets)
            if inner is not None:
                lifted = not_convertible("LAD304", inner.loc.line, inner.name)
            elif networks and _leaves_chain_open(networks[-1]):
                lifted = _continued_chain(items, language) or lifted
        networks.append(lifted)
    return LiftedBlock(kind=kind, name=name, title=title, networks=networks, lines=lines)


_CHAIN_OPS = frozenset({"A", "AN", "O", "ON", "X", "XN", "A(", "AN(", "O(", "ON(", "X(", "XN("})


def _leaves_chain_open(network: Network | NotConvertible) -> bool:
    """A network whose logic chain ends without an assignment leaves /FC = 1: the CPU goes on
    combining in the next network, as STEP 7 does (networks are only labels in the code)."""
    return isinstance(network, NotConvertible) and network.code == "LAD312"


def _continued_chain(items: Sequence[ast.CodeItem], language: str) -> NotConvertible | None:
    """LAD309 when the network starts by combining with the previous network's open chain: a
    rung starting at the rail would show a different program than the CPU runs."""
    steps = to_steps(items, language)
    if steps and steps[0].op in _CHAIN_OPS:
        return not_convertible("LAD309", steps[0].line, steps[0].text)
    return None


def _networks(code: Sequence[ast.CodeItem]) -> list[tuple[int, list[ast.CodeItem]]]:
    """The code split at NETWORK; code before the first NETWORK is a network of its own."""
    groups: list[tuple[int, list[ast.CodeItem]]] = []
    current: list[ast.CodeItem] | None = None
    for item in code:
        if isinstance(item, ast.NetworkNode):
            current = []
            groups.append((item.loc.line, current))
            continue
        if current is None:
            current = []
            groups.append((item.loc.line, current))
        current.append(item)
    return groups


def _comment(items: Sequence[ast.CodeItem], comments: Mapping[int, str]) -> str:
    """The ``//`` lines between the network's TITLE and its first instruction."""
    title = next((i for i in items if isinstance(i, ast.TitleNode)), None)
    first = next((i for i in items if not isinstance(i, ast.TitleNode)), None)
    if title is None or first is None:
        return ""
    lines = range(title.loc.line + 1, first.loc.line)
    return "\n".join(comments[line] for line in lines if line in comments)


def _jump_targets(code: Sequence[ast.CodeItem]) -> dict[str, int]:
    """Label → how many jumps of the block go to it."""
    found: dict[str, int] = {}
    for item in code:
        if not isinstance(item, ast.InstrNode) or not item.operands:
            continue
        if item.mnemonic.upper() in _JUMPS or item.mnemonic.upper().startswith("SP"):
            name = getattr(item.operands[0], "name", None)
            if isinstance(name, str):
                found[name] = found.get(name, 0) + 1
    return found


def _inner_label(items: Sequence[ast.CodeItem], targets: Mapping[str, int]) -> ast.LabelNode | None:
    """A label inside a converted network (a box's EN/ENO label) that another jump reaches."""
    seen_instruction = False
    for item in items:
        if isinstance(item, ast.InstrNode):
            seen_instruction = True
        elif isinstance(item, ast.LabelNode) and seen_instruction:
            own = sum(
                1
                for other in items
                if isinstance(other, ast.InstrNode)
                and other.operands
                and getattr(other.operands[0], "name", None) == item.name
            )
            if targets.get(item.name, 0) > own:
                return item
    return None


def _interfaces(source: ast.SourceNode) -> PinDirections:
    """Pin directions of the FCs/FBs declared in the same source (a CALL's parameters)."""
    table: dict[str, dict[str, str]] = {}
    for block in source.blocks:
        if block.keyword not in ("FUNCTION", "FUNCTION_BLOCK"):
            continue
        pins: dict[str, str] = {}
        for head in block.head:
            if isinstance(head, ast.VarSectionNode) and head.kind in _DIRECTIONS:
                for decl in head.decls:
                    pins[decl.name] = _DIRECTIONS[head.kind]
        if block.keyword == "FUNCTION":
            pins["RET_VAL"] = "out"
        name = f'"{block.ident}"' if block.ident_quoted else block.ident
        table[name.upper().replace(" ", "")] = pins

    def lookup(name: str) -> Mapping[str, str] | None:
        return table.get(name.upper().replace(" ", ""))

    return lookup

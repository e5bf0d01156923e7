"""The instructions of one STL network as the lifter reads them (``Step``).

The lifter works on the parser's AST, not on text: each ``InstrNode`` becomes a step with its
international mnemonic (German sources are translated with the file's mnemonic set), its operand
as written (the model keeps operands as the user wrote them) and the labels that stand before
it. CALL parameter lines (``NAME := x`` after a CALL without brackets) are folded into the
CALL's arguments.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from nasaq.lang.stl import ast
from nasaq.lang.stl.format import format_operand
from nasaq.lang.stl.mnemonics import to_international

OperandKind = str  # address | symbol | status | literal | indirect | bare | none


@dataclass(frozen=True, slots=True)
class Step:
    """One instruction: ``op`` is the international mnemonic in upper case (the spelling as
    written when the set lacks it); ``operand`` its text or None; ``args`` a CALL's
    parameters (name → operand text)."""

    op: str
    operand: str | None
    kind: OperandKind
    line: int
    text: str
    labels: tuple[str, ...] = ()
    args: tuple[tuple[str, str], ...] | None = None
    extra: tuple[str, ...] = ()  # further operands (``CALL FB 1, DB 1``: the instance DB)


def _kind(operand: ast.OperandNode) -> OperandKind:
    if isinstance(operand, ast.AddressNode):
        return "address"
    if isinstance(operand, ast.SymbolNode):
        return "symbol"
    if isinstance(operand, ast.StatusNode):
        return "status"
    if isinstance(operand, ast.LiteralNode):
        return "literal"
    if isinstance(operand, ast.IndirectNode):
        return "indirect"
    return "bare"


def operand_text(operand: ast.OperandNode) -> str:
    """The operand as written, with the column padding of STEP 7 exports (``MW    10``)
    closed up: the model holds ``MW 10``."""
    if isinstance(operand, ast.AddressNode):
        return " ".join(operand.text.split())
    return format_operand(operand)


def _text(op: str, operands: Sequence[str]) -> str:
    return f"{op} {', '.join(operands)}".strip()


def to_steps(items: Sequence[ast.CodeItem], language: str) -> list[Step]:
    """The network's instructions as steps; labels attach to the next instruction (a label
    at the very end becomes a ``NOP`` step so it is not lost)."""
    steps: list[Step] = []
    labels: list[str] = []
    for item in items:
        if isinstance(item, ast.LabelNode):
            labels.append(item.name)
            continue
        if not isinstance(item, ast.InstrNode):
            continue
        if item.param_line and steps and steps[-1].op == "CALL":
            call = steps[-1]
            value = operand_text(item.operands[0]) if item.operands else ""
            steps[-1] = replace(call, args=(*(call.args or ()), (item.mnemonic, value)))
            continue
        written = item.mnemonic.upper()
        op = to_international(written, language) or written
        texts = [operand_text(operand) for operand in item.operands]
        args: tuple[tuple[str, str], ...] | None = None
        if item.args is not None:
            args = tuple(
                (arg.name, operand_text(arg.value) if arg.value is not None else "")
                for arg in item.args
            )
        steps.append(
            Step(
                op=":=" if item.param_line else op,
                operand=texts[0] if texts else None,
                kind=_kind(item.operands[0]) if item.operands else "none",
                line=item.loc.line,
                text=_text(item.mnemonic, texts),
                labels=tuple(labels),
                args=args,
                extra=tuple(texts[1:]),
            )
        )
        labels = []
    if labels:
        line = items[-1].loc.line if items else 1
        steps.append(Step("NOP", "0", "literal", line, "NOP 0", tuple(labels)))
    return steps

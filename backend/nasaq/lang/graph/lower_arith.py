"""Arithmetic actions (``N A := B``, ``N A := F(B)``, ``N A := B op C``) → ``L``/``T`` STL.

S7-Graph picks the instruction by the operands' type: ``+I``/``+D``/``+R``, ``AW``/``AD`` …
The type comes from the target (a declared variable, a step time, the width of an address),
else from the operands; a REAL function (``SIN``) makes it REAL. A symbol of the symbol table is
not known here: when nothing tells the type the action is refused (GRA303) and the user declares
a local variable or writes an address.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from nasaq.lang.graph.lower_chart import Chart

Kind = str  # "I" 16-bit integer/word, "D" 32-bit integer/time/dword, "R" real

_ASSIGN = re.compile(r"^\s*(.+?)\s*:=\s*(.+?)\s*;?\s*$", re.DOTALL)
_CALL = re.compile(r"^([A-Za-z_]\w*)\s*\(\s*(.+?)\s*\)$")
_BINARY = re.compile(
    r"^(.+?)\s*(\+|-|\*|/|\bMOD\b|\bAND\b|\bOR\b|\bXOR\b|\bSHL\b|\bSHR\b|\bSSR\b|\bROL\b|\bROR\b)"
    r"\s*(.+)$",
    re.IGNORECASE,
)
_IDENTIFIER = re.compile(r"^[A-Za-z_]\w*$")
_INTEGER = re.compile(r"^[+-]?\d+$")
_REAL = re.compile(r"^[+-]?\d+\.\d*(E[+-]?\d+)?$|^[+-]?\d+E[+-]?\d+$", re.IGNORECASE)
_ADDRESS = re.compile(r"^(?:[IQEAM]|P[IQEA]|DB\d+\.DB|DI|DB)([BWD])\s*\d+$", re.IGNORECASE)

_TYPE_KINDS = {
    "INT": "I",
    "WORD": "I",
    "BYTE": "I",
    "CHAR": "I",
    "DATE": "I",
    "S5TIME": "I",
    "DINT": "D",
    "DWORD": "D",
    "TIME": "D",
    "TIME_OF_DAY": "D",
    "TOD": "D",
    "REAL": "R",
}
_OPERATORS: dict[str, dict[Kind, str]] = {
    "+": {"I": "+I", "D": "+D", "R": "+R"},
    "-": {"I": "-I", "D": "-D", "R": "-R"},
    "*": {"I": "*I", "D": "*D", "R": "*R"},
    "/": {"I": "/I", "D": "/D", "R": "/R"},
    "MOD": {"D": "MOD"},
    "AND": {"I": "AW", "D": "AD"},
    "OR": {"I": "OW", "D": "OD"},
    "XOR": {"I": "XOW", "D": "XOD"},
    "SHL": {"I": "SLW", "D": "SLD"},
    "SHR": {"I": "SRW", "D": "SRD"},
    "SSR": {"I": "SSI", "D": "SSD"},
    "ROL": {"D": "RLD"},
    "ROR": {"D": "RRD"},
}
_SHIFTS = ("SHL", "SHR", "SSR", "ROL", "ROR")
_REAL_FUNCTIONS = (
    "NEGR",
    "ABS",
    "SQR",
    "SQRT",
    "LN",
    "EXP",
    "SIN",
    "ASIN",
    "COS",
    "ACOS",
    "TAN",
    "ATAN",
)
_FUNCTIONS: dict[str, dict[Kind, str]] = {
    "BCD_TO_NUM": {"I": "BTI", "D": "BTD"},
    "NUM_TO_BCD": {"I": "ITB", "D": "DTB"},
    "INT_TO_DINT": {"I": "ITD", "D": "ITD"},
    "DINT_TO_REAL": {"D": "DTR", "R": "DTR"},
    "ROUND": {"R": "RND", "D": "RND"},
    "TRUNC": {"R": "TRUNC", "D": "TRUNC"},
    "NEG": {"I": "NEGI", "D": "NEGD", "R": "NEGR"},
    "NOT": {"I": "INVI", "D": "INVD"},
    "SWAP": {"I": "TAW", "D": "TAD"},
    "RLDA": {"D": "RLDA"},
    "RRDA": {"D": "RRDA"},
    **{name: {"R": name, "D": name, "I": name} for name in _REAL_FUNCTIONS},
}
# The kind of a function's argument when nothing else tells it.
_ARGUMENT_KIND = {"INT_TO_DINT": "I", "DINT_TO_REAL": "D", "ROUND": "R", "TRUNC": "R"}
_ARGUMENT_KIND |= dict.fromkeys(_REAL_FUNCTIONS, "R")


@dataclass(frozen=True, slots=True)
class ArithmeticProblem:
    """Why an arithmetic action cannot be compiled: a GRA3xx code and its parameters."""

    code: str
    params: dict[str, str]


class Arithmetic:
    """Lowers one assignment; ``declared`` is the user's variables (upper name → (name, type))."""

    def __init__(self, chart: Chart, declared: dict[str, tuple[str, str]]) -> None:
        self.chart = chart
        self.declared = declared

    def operand(self, text: str) -> str:
        """A name as the STL compiler reads it: a declared variable gets its ``#``, a step
        or transition variable becomes its member, an address loses nothing."""
        text = text.strip()
        member = self.chart.variable(text)
        if member is not None:
            return member
        if _IDENTIFIER.match(text) and text.upper() in self.declared:
            return "#" + self.declared[text.upper()][0]
        return text

    def kind_of(self, text: str) -> Kind | None:
        """The kind an operand's type asks for, None when it adapts (an integer literal) or
        is unknown (a symbol)."""
        text = text.strip()
        member = self.chart.variable(text)
        if member is not None:
            return "D" if member.endswith((".T", ".U")) else None
        name = text[1:] if text.startswith("#") else text
        if name.upper() in self.declared:
            return _TYPE_KINDS.get(self.declared[name.upper()][1])
        upper = text.upper().replace(" ", "")
        if upper.startswith(("T#", "TIME#", "L#", "DW#", "TOD#", "TIME_OF_DAY#")):
            return "D"
        if upper.startswith(("W#", "B#", "S5T#", "C#", "D#", "DATE#")):
            return "I"
        if _REAL.match(upper):
            return "R"
        address = _ADDRESS.match(text.replace(" ", ""))
        if address is not None:
            return "D" if address.group(1).upper() == "D" else "I"
        return None

    def lower(self, text: str) -> list[tuple[str, str]] | ArithmeticProblem:
        """The ``L``/``T`` lines of an assignment, or why it cannot be lowered."""
        match = _ASSIGN.match(text)
        if match is None:
            return ArithmeticProblem("GRA301", {"action": text.strip()})
        target, expression = match.group(1), match.group(2)
        target_kind = self.kind_of(target)
        call = _CALL.match(expression)
        if call is not None:
            return self._function(text, target, target_kind, call.group(1), call.group(2))
        binary = _BINARY.match(expression)
        if binary is not None:
            left, operator, right = binary.group(1), binary.group(2).upper(), binary.group(3)
            kinds = [target_kind, self.kind_of(left), self.kind_of(right)]
            kind = _pick(kinds if operator not in _SHIFTS else kinds[:2])
            if kind is None:
                return ArithmeticProblem("GRA303", {"action": text.strip()})
            instruction = _OPERATORS[operator].get(kind)
            if instruction is None:
                return ArithmeticProblem("GRA304", {"action": text.strip(), "operator": operator})
            if operator in _SHIFTS:  # count in ACCU2, value in ACCU1
                loads = [self._load(right, "I"), self._load(left, kind)]
            else:
                loads = [self._load(left, kind), self._load(right, kind)]
            return [*loads, (instruction, ""), ("T", self.operand(target))]
        kind = _pick([target_kind, self.kind_of(expression)]) or "I"
        return [self._load(expression, kind), ("T", self.operand(target))]

    def _function(
        self, text: str, target: str, target_kind: Kind | None, name: str, argument: str
    ) -> list[tuple[str, str]] | ArithmeticProblem:
        table = _FUNCTIONS.get(name.upper())
        if table is None:
            return ArithmeticProblem("GRA302", {"action": text.strip(), "function": name})
        kind = self.kind_of(argument) or _ARGUMENT_KIND.get(name.upper()) or target_kind
        if kind is None:
            return ArithmeticProblem("GRA303", {"action": text.strip()})
        instruction = table.get(kind)
        if instruction is None:
            return ArithmeticProblem("GRA304", {"action": text.strip(), "operator": name.upper()})
        return [self._load(argument, kind), (instruction, ""), ("T", self.operand(target))]

    def _load(self, text: str, kind: Kind) -> tuple[str, str]:
        text = text.strip()
        if _INTEGER.match(text):
            if kind == "R":
                return ("L", f"{int(text)}.0")
            if kind == "D":
                return ("L", f"L#{int(text)}")
        return ("L", self.operand(text))


def _pick(kinds: list[Kind | None]) -> Kind | None:
    """The first kind known (the target's first)."""
    for kind in kinds:
        if kind is not None:
            return kind
    return None

"""The STL code of one block as it is generated: instructions, labels and hidden temporaries.

Generated instructions are STL syntax nodes (``nasaq.lang.stl.ast``) whose ``loc`` is the SCL
statement or expression they come from: the STL compiler lowers them to IR with that location
as the origin, which is the source map (an SCL breakpoint is a set of STL instructions).

Labels are four characters, as STEP 7 allows (``A000``, ``A001`` ...). Hidden temporaries are
extra VAR_TEMP variables (``_t1`` ...) that nothing in SCL can name (SCL names cannot start
with ``_`` followed by nothing but digits and letters of our choice: see ``fresh_name``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.lang.stl import ast as stl
from nasaq.lang.stl.ast import Loc
from nasaq.lang.types import DataType, type_text

_DIGITS = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"
_START = Loc(1, 1, 1, 1)


@dataclass(slots=True)
class Temp:
    """A hidden VAR_TEMP variable; ``operand`` is how instructions name it."""

    name: str
    type: DataType


@dataclass(slots=True)
class Emitter:
    taken: set[str]  # casefolded names the block declares (hidden names avoid them)
    code: list[stl.CodeItem] = field(default_factory=list)
    temps: list[Temp] = field(default_factory=list)
    free: dict[str, list[Temp]] = field(default_factory=dict)
    loc: Loc = _START  # the SCL node being lowered: every instruction gets it
    _labels: int = 0
    _aliases: dict[str, str] = field(default_factory=dict)  # a label placed on another's spot
    _jumps: list[stl.InstrNode] = field(default_factory=list)  # to rename aliases in
    _names: int = 0

    # ---- instructions -----------------------------------------------------------------------

    def op(self, mnemonic: str, *operands: stl.OperandNode) -> None:
        self.code.append(stl.InstrNode(mnemonic, list(operands), None, self.loc))

    def call(self, target: list[stl.OperandNode], args: list[stl.CallArgNode]) -> None:
        self.code.append(stl.InstrNode("CALL", target, args, self.loc))

    def arg(self, name: str, value: stl.OperandNode) -> stl.CallArgNode:
        return stl.CallArgNode(name, value, self.loc)

    def load_text(self, kind: str, text: str) -> None:
        self.op("L", self.literal(kind, text))

    def literal(self, kind: str, text: str) -> stl.LiteralNode:
        return stl.LiteralNode(kind, text, self.loc)

    def address(self, text: str) -> stl.AddressNode:
        return stl.AddressNode(text, self.loc)

    # ---- labels -----------------------------------------------------------------------------

    def new_label(self) -> str:
        number = self._labels
        self._labels += 1
        letter, rest = divmod(number, 36**3)
        digits = ""
        for _ in range(3):
            rest, digit = divmod(rest, 36)
            digits = _DIGITS[digit] + digits
        return "ABCDEFGHIJKLMNOPQRSTUVWXYZ"[letter % 26] + digits

    def jump(self, mnemonic: str, label: str) -> None:
        node = stl.InstrNode(mnemonic, [stl.AddressNode(label, self.loc)], None, self.loc)
        self.code.append(node)
        self._jumps.append(node)

    def place(self, label: str) -> None:
        if self.code and isinstance(self.code[-1], stl.LabelNode):
            # one label per instruction: the second names the first (no NOP in a hot loop)
            self._aliases[label] = self.code[-1].name
            return
        self.code.append(stl.LabelNode(label, self.loc))

    def finish(self) -> list[stl.CodeItem]:
        """The code, with a ``NOP 0`` after a label that ends it (a label needs an instruction)."""
        if self.code and isinstance(self.code[-1], stl.LabelNode):
            self.op("NOP", self.literal("NUMBER", "0"))
        if self._aliases:
            for item in self._jumps:
                target = item.operands[0]
                if isinstance(target, stl.AddressNode) and target.text in self._aliases:
                    item.operands[0] = stl.AddressNode(self._aliases[target.text], target.loc)
        return self.code

    # ---- hidden temporaries -----------------------------------------------------------------

    def fresh_name(self) -> str:
        while True:
            self._names += 1
            name = f"_t{self._names}"
            if name.casefold() not in self.taken:
                return name

    def temp(self, data_type: DataType) -> Temp:
        """A free temporary of ``data_type``; give it back with ``release`` when its value is no
        longer needed (temporaries are reused, so a block's L stack stays small)."""
        pool = self.free.get(type_text(data_type))
        if pool:
            return pool.pop()
        found = Temp(self.fresh_name(), data_type)
        self.temps.append(found)
        return found

    def release(self, temp: Temp) -> None:
        self.free.setdefault(type_text(temp.type), []).append(temp)

    def ref(self, temp: Temp) -> stl.SymbolNode:
        return stl.SymbolNode(temp.name, True, [], self.loc)

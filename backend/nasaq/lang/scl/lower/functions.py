"""S7-SCL's built-in functions, compiled in line as S7-SCL does: conversions (``ITD``, ``DTR``,
``RND``, ``BTI`` ... or nothing, for the bit-pattern copies such as ``WORD_TO_INT``), the REAL
functions (``SQRT``, ``LN`` ...; ``LOG`` and ``EXPD`` through ``LN``/``EXP``), ``ABS``, shifts
and rotations, and the selections ``MAX``, ``MIN`` (any number of inputs), ``LIMIT``,
``SEL``, ``MUX`` (a K that names no input gives ELSE, or 0 without it, and ENO FALSE).

Rotating a BYTE or WORD uses the doubleword rotation on the value repeated across ACCU1
(``2#1101_0011`` → 16#D3D3D3D3), so the bits that leave one end come back at the other. Shift
and rotation counts come from ACCU2-L-L, as the STL instructions without operand take them.
"""

from __future__ import annotations

from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.calls import Calls
from nasaq.lang.scl.lower.places import LoweringError
from nasaq.lang.scl.typecheck import instructions
from nasaq.lang.scl.typecheck.rules.calls import REAL_FUNCTIONS
from nasaq.lang.types import Elementary

_LN10 = "2.302585e+00"
_DIRECT = {
    "INT_TO_DINT": ("INT", ["ITD"]),
    "INT_TO_REAL": ("INT", ["ITD", "DTR"]),
    "DINT_TO_REAL": ("DINT", ["DTR"]),
    "REAL_TO_DINT": ("REAL", ["RND"]),
    "REAL_TO_INT": ("REAL", ["RND"]),
    "ROUND": ("REAL", ["RND"]),
    "TRUNC": ("REAL", ["TRUNC"]),
    "CEIL": ("REAL", ["RND+"]),
    "FLOOR": ("REAL", ["RND-"]),
    "WORD_BCD_TO_INT": ("WORD", ["BTI"]),
    "BCD_TO_INT": ("WORD", ["BTI"]),
    "BYTE_BCD_TO_INT": ("BYTE", ["BTI"]),
    "INT_TO_BCD_WORD": ("INT", ["ITB"]),
    "INT_TO_BCD": ("INT", ["ITB"]),
    "INT_TO_BCD_BYTE": ("INT", ["ITB"]),
    "DWORD_BCD_TO_DINT": ("DWORD", ["BTD"]),
    "DINT_TO_BCD_DWORD": ("DINT", ["DTB"]),
    "BCD16_TO_INT": ("WORD", ["BTI"]),  # TIA's names
    "INT_TO_BCD16": ("INT", ["ITB"]),
    "BCD32_TO_DINT": ("DWORD", ["BTD"]),
    "DINT_TO_BCD32": ("DINT", ["DTB"]),
}
_SHIFTS = {
    ("SHL", 16): "SLW",
    ("SHR", 16): "SRW",
    ("SHL", 32): "SLD",
    ("SHR", 32): "SRD",
    ("ROL", 32): "RLD",
    ("ROR", 32): "RRD",
}


class Functions(Calls):
    def arguments(self, node: ast.Call, *names: str) -> list[ast.Expr]:
        """The arguments by formal name (``IN1``, ``N``), or in order when they are positional."""
        named = {(arg.name or "").upper(): arg.value for arg in node.args if arg.name}
        found: list[ast.Expr] = []
        positional = [arg.value for arg in node.args if not arg.name]
        for position, name in enumerate(names):
            if name in named:
                found.append(named[name])
            elif position < len(positional):
                found.append(positional[position])
            else:
                raise LoweringError(node.loc, f"a call without {name}")
        return found

    def function_value(self, node: ast.Call, name: str) -> None:
        em = self.em
        result = self.scalar_of(node)
        if "_TO_" in name or name in _DIRECT:
            self.conversion(node, name, result)
        elif name in REAL_FUNCTIONS:
            (value,) = self.arguments(node, "IN")
            self.load_value(value, "REAL")
            if name == "LOG":
                em.op("LN")
                em.load_text("REAL", _LN10)
                em.op("/R")
            elif name == "EXPD":
                em.load_text("REAL", _LN10)
                em.op("*R")
                em.op("EXP")
            else:
                em.op(name)
        elif name == "ABS":
            self.absolute_value(node, result)
        elif name in ("SHL", "SHR", "ROL", "ROR"):
            self.shift(node, name, result)
        elif name in ("MAX", "MIN"):
            values = [arg.value for arg in instructions.arguments(node, name)]
            self.extreme(node, name, result, values)
        elif name == "LIMIT":
            low, value, high = self.arguments(node, "MN", "IN", "MX")
            self.limit(low, value, high, result)
        elif name in ("SEL", "MUX"):
            self.select(node, name, result)
        else:
            raise LoweringError(node.loc, f"the function {name}")

    def function_condition(self, node: ast.Call, name: str) -> None:
        """RLO := a standard function with a BOOL result (``WORD_TO_BOOL``: its lowest bit)."""
        em = self.em
        if name == "SEL" or name in ("MAX", "MIN", "LIMIT", "MUX"):
            self.function_value(node, name)
        else:
            (value,) = self.arguments(node, "IN")
            self.load_value(value, self.scalar_of(value))
        em.load_text("NUMBER", "1")
        em.op("AW")
        em.load_text("NUMBER", "0")
        em.op("<>I")

    def conversion(self, node: ast.Call, name: str, result: str) -> None:
        (value,) = self.arguments(node, "IN")
        if name in _DIRECT:
            source, ops = _DIRECT[name]
            self.load_value(value, source)
            for op in ops:
                self.em.op(op)
            return
        source = self.scalar_of(value)
        if source == "BOOL":
            self.bool_value(value)
            return
        if source in ("STRING",) or result in ("STRING",):
            raise LoweringError(node.loc, f"the function {name}")
        self.load_value(value, source)
        if (result == "BYTE" or result == "CHAR") and source in ("DINT", "DWORD"):
            self.em.op("AD", self.em.literal("TYPED", "DW#16#FF"))  # the high word too
        elif result == "BYTE" or (result == "CHAR" and source != "BYTE"):
            self.em.op("AW", self.em.literal("TYPED", "W#16#FF"))
        elif result == "WORD" and source in ("DWORD", "DINT"):
            self.em.op("AD", self.em.literal("TYPED", "DW#16#FFFF"))
        elif result in ("DINT", "DWORD", "TIME", "DATE", "TIME_OF_DAY") and source == "INT":
            self.em.op("ITD")

    def absolute_value(self, node: ast.Call, result: str) -> None:
        em = self.em
        (value,) = self.arguments(node, "IN")
        if result == "REAL":
            self.load_value(value, "REAL")
            em.op("ABS")
            return
        temp = em.temp(Elementary("DWORD"))
        self.load_value(value, result)
        em.op("T", em.ref(temp))
        em.load_text("NUMBER", "0")
        em.op("<I" if result == "INT" else "<D")  # value < 0 (ACCU2 < ACCU1)
        em.op("L", em.ref(temp))
        done = em.new_label()
        em.jump("JCN", done)
        em.op("NEGI" if result == "INT" else "NEGD")
        em.place(done)
        em.release(temp)

    def shift(self, node: ast.Call, name: str, result: str) -> None:
        em = self.em
        value, count = self.arguments(node, "IN", "N")
        temp = em.temp(Elementary("DWORD"))
        self.load_value(value, result)
        if name in ("ROL", "ROR") and result in ("BYTE", "WORD"):
            em.load_text("TYPED", "DW#16#01010101" if result == "BYTE" else "L#65537")
            em.op("*D")
        em.op("T", em.ref(temp))
        self.load_value(count, "INT")
        if name in ("ROL", "ROR") and result in ("BYTE", "WORD"):
            em.load_text("NUMBER", "8" if result == "BYTE" else "16")
            em.op("/I")
            em.op("SRD", em.literal("NUMBER", "16"))  # the count modulo the width
        em.op("L", em.ref(temp))
        bits = 32 if result == "DWORD" or name in ("ROL", "ROR") else 16
        op = _SHIFTS.get((name, bits))
        if op is None:
            raise LoweringError(node.loc, f"{name} of a {result}")
        em.op(op)
        if name == "ROL" and result == "BYTE":
            em.op("SRD", em.literal("NUMBER", "24"))
        elif name == "ROL" and result == "WORD":
            em.op("SRD", em.literal("NUMBER", "16"))
        elif result == "BYTE":
            em.op("AW", em.literal("TYPED", "W#16#FF"))
        elif name == "ROR" and result == "WORD":
            em.op("AD", em.literal("TYPED", "DW#16#FFFF"))
        em.release(temp)

    def extreme(self, node: ast.Call, name: str, result: str, values: list[ast.Expr]) -> None:
        """MAX/MIN of any number of inputs, kept in a temporary while comparing."""
        em = self.em
        if not values:
            raise LoweringError(node.loc, f"{name} without inputs")
        kind = "DINT" if result in ("DINT", "TIME", "DWORD") else result
        suffix = {"INT": "I", "REAL": "R"}.get(kind, "D")
        best = em.temp(Elementary("DWORD"))
        candidate = em.temp(Elementary("DWORD"))
        self.load_value(values[0], kind)
        em.op("T", em.ref(best))
        for value in values[1:]:
            self.load_value(value, kind)
            em.op("T", em.ref(candidate))
            em.op("L", em.ref(best))
            em.op((">" if name == "MAX" else "<") + suffix)  # candidate > best
            keep = em.new_label()
            em.jump("JCN", keep)
            em.op("L", em.ref(candidate))
            em.op("T", em.ref(best))
            em.place(keep)
        em.op("L", em.ref(best))
        em.release(best)
        em.release(candidate)

    def limit(self, low: ast.Expr, value: ast.Expr, high: ast.Expr, result: str) -> None:
        """LIMIT(MN, IN, MX) = MIN(MAX(IN, MN), MX)."""
        em = self.em
        kind = "DINT" if result in ("DINT", "TIME", "DWORD") else result
        suffix = {"INT": "I", "REAL": "R"}.get(kind, "D")
        current = em.temp(Elementary("DWORD"))
        bound = em.temp(Elementary("DWORD"))
        self.load_value(value, kind)
        em.op("T", em.ref(current))
        for edge, compare in ((low, "<"), (high, ">")):
            self.load_value(edge, kind)
            em.op("T", em.ref(bound))
            em.op("L", em.ref(current))
            em.op("L", em.ref(bound))
            em.op(compare + suffix)  # current < low / current > high
            keep = em.new_label()
            em.jump("JCN", keep)
            em.op("L", em.ref(bound))
            em.op("T", em.ref(current))
            em.place(keep)
        em.op("L", em.ref(current))
        em.release(current)
        em.release(bound)

    def select(self, node: ast.Call, name: str, result: str) -> None:
        em = self.em
        done = em.new_label()
        if name == "SEL":
            choice, first, second = self.arguments(node, "G", "IN0", "IN1")
            other = em.new_label()
            self.condition(choice)
            self.drop_hoisted()
            em.jump("JC", other)
            self.load_value(first, result)
            em.jump("JU", done)
            em.place(other)
            self.load_value(second, result)
            em.place(done)
            return
        inputs: dict[int, ast.Expr] = {}
        otherwise: ast.Expr | None = None
        for arg in instructions.arguments(node, name):
            formal = (arg.name or "").upper()
            if formal == "ELSE":
                otherwise = arg.value
            elif arg.name is None:
                inputs[len(inputs)] = arg.value  # K first, then IN0, IN1 ... in order
            elif formal[2:].isdigit():
                inputs[int(formal[2:])] = arg.value
        (key,) = self.arguments(node, "K")
        temp = em.temp(Elementary("DINT"))
        self.load_value(key, "DINT")
        em.op("T", em.ref(temp))
        for position, value in sorted(inputs.items()):
            following = em.new_label()
            em.op("L", em.ref(temp))
            em.load_text("TYPED", f"L#{position}")
            em.op("==D")
            em.jump("JCN", following)
            self.load_value(value, result)
            em.jump("JU", done)
            em.place(following)
        # K names no input: ENO FALSE, the value ELSE (TIA), else 0 (*Nasaq*)
        status = getattr(self, "eno_status", None)
        if status is not None:
            em.op("CLR")
            em.op("=", em.ref(status))
        if otherwise is not None:
            self.load_value(otherwise, result)
        else:
            em.load_text("NUMBER", "0")
        em.place(done)
        em.release(temp)

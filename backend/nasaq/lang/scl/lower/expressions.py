"""Expressions: values into ACCU1, conditions into the RLO.

Values: ``load_value(node, want)`` leaves the value in ACCU1, converted to ``want`` (S7-SCL's
implicit conversions: ITD, DTR). A binary operation loads its left operand, then its right one
(``L`` pushes the left into ACCU2) and operates; when the right operand needs code of its own,
it goes first into a temporary. INT arithmetic works on ACCU1-L (``+I``), DINT and TIME on the
doubleword (``+D``), REAL on IEEE values (``+R``); ``MOD`` of INTs is the remainder ``/I``
leaves in ACCU1-H; ``**`` is ``EXP(LN(a) * b)`` as in S7-SCL.

Conditions: ``condition(node)`` starts a new logic string and leaves the result in the RLO:
``AND`` chains ``A``, ``OR`` chains ``O``, ``XOR`` chains ``X``; a sub-expression of another kind
is put in brackets (``A(`` ... ``)``); a comparison is ``L a; L b; >I``. Anything inside a
condition that needs jumps or a call (FC calls, MAX, SEL, a BOOL used as a number) is computed
first into a temporary ("hoisted"), because a jump or a CALL would end the open logic string.
"""

from __future__ import annotations

from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.literals import stl_constant
from nasaq.lang.scl.lower.places import Base, LoweringError
from nasaq.lang.scl.lower.slices import bit_result, load_slice
from nasaq.lang.scl.typecheck.types import scalar, wider
from nasaq.lang.stl import ast as stl
from nasaq.lang.types import Elementary

_ARITHMETIC = {
    "INT": {"+": "+I", "-": "-I", "*": "*I", "/": "/I", "DIV": "/I"},
    "DINT": {"+": "+D", "-": "-D", "*": "*D", "/": "/D", "DIV": "/D", "MOD": "MOD"},
    "REAL": {"+": "+R", "-": "-R", "*": "*R", "/": "/R"},
}
_WORD_LOGIC = {
    ("AND", 16): "AW",
    ("OR", 16): "OW",
    ("XOR", 16): "XOW",
    ("&", 16): "AW",
    ("AND", 32): "AD",
    ("OR", 32): "OD",
    ("XOR", 32): "XOD",
    ("&", 32): "AD",
}
_COMPARE = {"=": "==", "<>": "<>", "<": "<", ">": ">", "<=": "<=", ">=": ">="}
_SWAPPED = {"=": "=", "<>": "<>", "<": ">", ">": "<", "<=": ">=", ">=": "<="}
# Operations whose operands may be loaded in either order (comparisons are then mirrored).
_SWAPPABLE = frozenset(["+", "*", "AND", "&", "OR", "XOR", *_COMPARE])
COMPARISONS = frozenset(_COMPARE)
LOGIC = frozenset(["AND", "&", "OR", "XOR"])
# Types whose values are doublewords in ACCU1 (compared and computed with the D instructions).
_DOUBLE = frozenset(["DINT", "TIME", "DATE", "TIME_OF_DAY", "DWORD"])
_MAX_BRACKETS = 7


class Expressions(Base):
    def __init__(self, *args: object, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.brackets = 0

    # ---- values -----------------------------------------------------------------------------

    def load_value(self, node: ast.Expr, want: str) -> None:
        """ACCU1 := the value of ``node`` as a ``want``."""
        while isinstance(node, ast.Paren):
            node = node.inner
        em = self.em
        kind = type(node)
        if kind is ast.Name or kind is ast.Local:  # the commonest operand, straight
            assert isinstance(node, ast.Name | ast.Local)
            variable = self.ctx.variable(node.name)  # (a CONST is no variable)
            have = scalar(variable.type) if variable is not None else None
            if variable is not None and have is not None and have != "BOOL":
                em.op("L", stl.SymbolNode(variable.name, True, [], node.loc))
                self.convert(have, want)
                return
        elif id(node) in self.hoisted:
            temp = self.hoisted[id(node)]
            em.op("L", em.ref(temp))
            self.convert(scalar(temp.type) or want, want)
            return
        value = self.constant(node)
        if value is not None:
            target = want if want != "BOOL" else "INT"
            if value.kind == "real" and want in ("INT", "DINT"):
                target = "REAL"
            em.load_text(*stl_constant(value, target))
            return
        have = self.scalar_of(node)
        if have == "BOOL":
            self.bool_value(node)
            return
        if isinstance(node, ast.Unary):
            self.unary(node, have)
        elif isinstance(node, ast.Slice):
            load_slice(self, node)
        elif isinstance(node, ast.Binary):
            self.binary(node, have)
        elif isinstance(node, ast.Call):
            self.call_value(node)
        else:
            em.op("L", self.operand(self.access(node), node.loc))
        self.convert(have, want)

    def convert(self, have: str, want: str) -> None:
        """S7-SCL's implicit widening: INT → DINT → REAL (bit strings are already zero-filled)."""
        if have == want:
            return
        if have == "INT" and want in ("DINT", "REAL", "TIME"):
            self.em.op("ITD")
            if want == "REAL":
                self.em.op("DTR")
        elif have in ("DINT",) and want == "REAL":
            self.em.op("DTR")

    def unary(self, node: ast.Unary, have: str) -> None:
        em = self.em
        self.load_value(node.operand, have)
        if node.op == "-":
            em.op({"INT": "NEGI", "REAL": "NEGR"}.get(have, "NEGD"))
        elif node.op == "NOT":
            if have in ("BYTE", "WORD"):
                em.op("INVI")
                if have == "BYTE":
                    em.op("AW", em.literal("TYPED", "W#16#FF"))
            else:
                em.op("INVD")

    def binary(self, node: ast.Binary, have: str) -> None:
        em = self.em
        op = node.op
        exponent = self.constant(node.right) if op == "**" else None
        if exponent is not None and exponent.kind == "int" and 0 <= int(exponent.number) <= 8:
            self.power(node.left, int(exponent.number))  # also for a negative base
            return
        if op == "**":
            self.load_value(node.left, "REAL")
            em.op("LN")
            temp = em.temp(Elementary("REAL"))
            em.op("T", em.ref(temp))
            self.load_value(node.right, "REAL")
            em.op("L", em.ref(temp))
            em.op("*R")
            em.op("EXP")
            em.release(temp)
            return
        if op in LOGIC:
            bits = 32 if have == "DWORD" else 16
            self.operands(node, have)
            em.op(_WORD_LOGIC[(op, bits)])
            return
        kind = "DINT" if have in _DOUBLE else have
        if kind == "INT" and op == "MOD":
            self.operands(node, "INT")
            em.op("/I")
            em.op("SRD", em.literal("NUMBER", "16"))
            return
        table = _ARITHMETIC.get(kind)
        if table is None or op not in table:
            raise LoweringError(node.loc, f"{op} on {have}")
        self.operands(node, kind)
        em.op(table[op])

    def power(self, base: ast.Expr, exponent: int) -> None:
        """``x ** n`` for a small constant n, by multiplication (``LN`` needs a positive x)."""
        em = self.em
        self.load_value(base, "REAL")
        if exponent == 0:
            em.load_text("REAL", "1.0")
            return
        temp = em.temp(Elementary("REAL"))
        em.op("T", em.ref(temp))
        for _ in range(exponent - 1):
            em.op("L", em.ref(temp))
            em.op("*R")
        em.release(temp)

    def operands(self, node: ast.Binary, want: str) -> bool:
        """ACCU2 := left, ACCU1 := right (both as ``want``); True when they were loaded the
        other way round (a simple left operand after a complex right one, which saves a
        temporary: the caller swaps a comparison, and commutative operations do not care)."""
        em = self.em
        if self.simple(node.right):
            self.load_value(node.left, want)
            self.load_value(node.right, want)
            return False
        if self.simple(node.left) and node.op in _SWAPPABLE:
            self.load_value(node.right, want)
            self.load_value(node.left, want)
            return True
        self.load_value(node.right, want)
        temp = em.temp(Elementary("DWORD"))
        em.op("T", em.ref(temp))
        self.load_value(node.left, want)
        em.op("L", em.ref(temp))
        em.release(temp)
        return False

    def simple(self, node: ast.Expr) -> bool:
        """Loaded by one ``L`` with no conversion code that would disturb ACCU2."""
        while isinstance(node, ast.Paren):
            node = node.inner
        if id(node) in self.hoisted or self.constant(node) is not None:
            return True
        if isinstance(node, ast.Name | ast.Local | ast.Symbol | ast.Address):
            return True
        if isinstance(node, ast.Member | ast.Index):
            try:
                access = self.access(node)
            except LoweringError:
                return False
            return self.plain(access)
        return False

    def bool_value(self, node: ast.Expr) -> None:
        """ACCU1 := 1 or 0 (a BOOL used as a number, e.g. in BOOL_TO_WORD)."""
        em = self.em
        self.condition(node)
        false, done = em.new_label(), em.new_label()
        em.jump("JCN", false)
        em.load_text("NUMBER", "1")
        em.jump("JU", done)
        em.place(false)
        em.load_text("NUMBER", "0")
        em.place(done)

    # ---- conditions -------------------------------------------------------------------------

    def condition(self, node: ast.Expr) -> None:
        """RLO := ``node`` (a BOOL expression), in a new logic string."""
        self.hoist(node)
        inner = node
        while isinstance(inner, ast.Paren):
            inner = inner.inner
        if isinstance(inner, ast.Binary) and inner.op in COMPARISONS:
            self.compare(inner)
            return
        value = self.constant(inner)
        if value is not None and id(inner) not in self.hoisted:
            self.em.op("SET" if value.number else "CLR")
            return
        self.logic(inner, "A")

    def logic(self, node: ast.Expr, op: str) -> None:
        """Combines ``node`` into the open logic string with ``op`` (A, O or X)."""
        em = self.em
        while isinstance(node, ast.Paren):
            node = node.inner
        if id(node) in self.hoisted:
            em.op(op, em.ref(self.hoisted[id(node)]))
            return
        if isinstance(node, ast.Name) and node.name.upper() == "ENO" and not self.declared(node):
            em.op(op, stl.BareNode("BR", None, em.loc))  # the ENO of the last call (its BR)
            return
        if self.is_variable(node) and self.access(node).root == "ok":
            # OK is FALSE after an arithmetic error: the OS bit holds one since OK was set
            self.open(op)
            em.op("A", em.ref(self.ok_flag()))
            em.op("AN", stl.BareNode("OS", None, em.loc))
            self.close()
            return
        if isinstance(node, ast.Binary) and node.op in LOGIC:
            chain = {"AND": "A", "&": "A", "OR": "O", "XOR": "X"}[node.op]
            if chain == op:
                self.logic(node.left, chain)
                self.logic(node.right, chain)
                return
            self.bracket(op, node, chain)
            return
        if isinstance(node, ast.Unary) and node.op == "NOT":
            inner = node.operand
            while isinstance(inner, ast.Paren):
                inner = inner.inner
            if self.is_variable(inner):
                em.op(op + "N", self.operand(self.access(inner), inner.loc))
            else:
                self.bracket(op + "N", inner, "A")
            return
        if isinstance(node, ast.Binary) and node.op in COMPARISONS:
            self.open(op)
            self.compare(node)
            self.close()
            return
        value = self.constant(node)
        if value is not None:
            self.open(op)
            em.op("SET" if value.number else "CLR")
            self.close()
            return
        if self.is_variable(node):
            em.op(op, self.operand(self.access(node), node.loc))
            return
        raise LoweringError(node.loc, "this condition")  # pragma: no cover - hoisted

    def declared(self, node: ast.Name) -> bool:
        return self.ctx.variable(node.name) is not None

    def bracket(self, op: str, node: ast.Expr, chain: str) -> None:
        self.open(op)
        self.logic(node, chain)
        self.close()

    def open(self, op: str) -> None:
        self.brackets += 1
        if self.brackets > _MAX_BRACKETS:
            raise LoweringError(self.em.loc, "a condition nested deeper than 7 brackets")
        self.em.op(op + "(")

    def close(self) -> None:
        self.brackets -= 1
        self.em.op(")")

    def is_variable(self, node: ast.Expr) -> bool:
        variables = ast.Name | ast.Local | ast.Symbol | ast.Address | ast.Member | ast.Index
        return isinstance(node, variables | ast.IndexedAddress)

    def compare(self, node: ast.Binary) -> None:
        em = self.em
        left, right = self.type_of(node.left), self.type_of(node.right)
        kind = wider(scalar(left) or "", scalar(right) or "") or scalar(left) or "INT"
        if kind == "DINT" and "DWORD" in (scalar(left), scalar(right)):
            kind = "DWORD"  # `4294967295 = dw`: the constant as the DWORD's bits
        if kind == "BOOL":
            em.op("X(")
            self.logic(node.left, "X")
            self.logic(node.right, "X")
            em.op(")")
            if node.op == "=":
                em.op("NOT")
            return
        if kind in ("INT", "S5TIME"):
            suffix = "I"
        elif kind == "REAL":
            suffix = "R"
        elif kind in ("STRING",):
            raise LoweringError(node.loc, "comparing STRINGs")
        else:
            suffix = "D"
            # DWORD stays DWORD: its constants above 2**31 load as DW#16#…, not as L# (STL214)
            if kind != "DWORD" and (kind in _DOUBLE or kind in ("BYTE", "WORD", "CHAR")):
                kind = "DINT"
        swapped = self.operands(node, kind if kind != "S5TIME" else "INT")
        op = _SWAPPED[node.op] if swapped else node.op
        em.op(_COMPARE[op] + suffix)

    # ---- hoisting ---------------------------------------------------------------------------

    def hoist(self, node: ast.Expr) -> None:
        """Computes into temporaries what a logic string cannot contain (see the module doc):
        calls, and the operations S7-SCL computes by calling a library FC."""
        kind = type(node)
        if kind is ast.Name or kind is ast.Local or kind is ast.Literal:
            return
        for child in _children(node):
            self.hoist(child)
        if id(node) in self.hoisted:
            return
        if kind is ast.Call:
            assert isinstance(node, ast.Call)
            self.hoisted[id(node)] = self.call_result(node)
        elif isinstance(node, ast.Slice) and node.width == "X":  # x.%X3: computed, then
            self.hoisted[id(node)] = bit_result(self, node)  # read in the logic string
        elif kind is ast.Binary:
            assert isinstance(node, ast.Binary)
            name = self.library_operation(node)
            if name is not None:
                self.hoisted[id(node)] = self.library_result(node, name)

    def drop_hoisted(self) -> None:
        for temp in self.hoisted.values():
            self.em.release(temp)
        self.hoisted.clear()

    # ---- provided by the call part ----------------------------------------------------------

    def call_value(self, node: ast.Call) -> None:  # pragma: no cover - overridden
        raise NotImplementedError

    def call_result(self, node: ast.Call) -> Temp:  # pragma: no cover - overridden
        raise NotImplementedError

    # ---- provided by the STRING and DATE_AND_TIME parts -------------------------------------

    def library_operation(self, node: ast.Expr) -> str | None:  # pragma: no cover - overridden
        raise NotImplementedError

    def library_result(self, node: ast.Binary, name: str) -> Temp:  # pragma: no cover
        raise NotImplementedError


def _children(node: ast.Expr) -> list[ast.Expr]:
    if isinstance(node, ast.Paren):
        return [node.inner]
    if isinstance(node, ast.Unary):
        return [node.operand]
    if isinstance(node, ast.Binary):
        return [node.left, node.right]
    if isinstance(node, ast.Call):
        return []  # a call's arguments are its own business
    if isinstance(node, ast.Index):
        return [node.base, *node.indices]
    if isinstance(node, ast.Member):
        return [node.base]
    if isinstance(node, ast.Slice):
        return [] if node.width == "X" else [node.base]
    if isinstance(node, ast.IndexedAddress):
        return list(node.indices)
    return []

"""The S7-1200/1500 elementary types in S7-SCL code (COMPATIBILITY.md, "S7-1500 profile").

**SINT, USINT, UINT, UDINT** live in the accumulators with their own widths: a variable loads
zero-filled (``L`` of a byte or word), and wherever the value meets another type or a
comparison it is normalised: SINT sign-extended (``SLD 24``, ``SSD 24``), USINT and UINT cut to
their bits (``AD``). Their ``+ - *`` are the doubleword's (``+D``), which wraps exactly as TIA's
8/16/32-bit arithmetic does once the result is stored into its width; ``/``, ``DIV`` and ``MOD``
work on the normalised values. UDINT compares as unsigned (both operands with the top bit
flipped, then ``<D``); its ``DIV``/``MOD`` call the library (``DIV_UDINT``), its conversion to
REAL splits it into two halves.

**LINT, ULINT, LREAL, LWORD, LTIME** are 8 bytes that no accumulator holds: they move as two
doublewords (``dates.copy_dt``) and every operation calls a hidden library FC whose body is
Python (``nasaq.lang.long_library``): ``lr := a + b`` is ``CALL "ADD_LREAL" (IN1 := a, IN2 := b,
RET_VAL := lr)``, a comparison is hoisted into a BOOL temporary as a STRING comparison is.
An operand of another type is converted first, into a temporary, by the conversion FC of its
implicit conversion (``DINT_TO_LINT``); a constant is written into a temporary as its 8 bytes.
All conversions of these types (``LREAL_TO_REAL``, ``UINT_TO_INT`` ...) are library FCs too.
"""

from __future__ import annotations

from nasaq.ir.types import LONG_TYPES
from nasaq.lang import long_library
from nasaq.lang.iec_library import FUNCTIONS
from nasaq.lang.s7_1500_types import CONVERSIONS
from nasaq.lang.s7_1500_values import encode
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.dates import Dates
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.expressions import COMPARISONS
from nasaq.lang.scl.lower.literals import Value
from nasaq.lang.scl.lower.places import Access, LoweringError
from nasaq.lang.scl.lower.references import Result
from nasaq.lang.scl.lower.strings import unparen
from nasaq.lang.scl.typecheck.types import scalar, wider
from nasaq.lang.stl import ast as stl
from nasaq.lang.stl.constants import ConstantError, duration_ms
from nasaq.lang.types import DataType, Elementary

# The narrow S7-1500 integers: computed as DINTs, normalised by these instructions.
_NORMALISE = {
    "SINT": (("SLD", "24"), ("SSD", "24")),
    "USINT": (("AD", "DW#16#FF"),),
    "UINT": (("AD", "DW#16#FFFF"),),
}
_NARROW = frozenset(_NORMALISE)
_DINT_FORM = _NARROW | {"UDINT"}
_TOP_BIT = "DW#16#80000000"
_INTEGER_OPS = {"+": "+D", "-": "-D", "*": "*D", "/": "/D", "DIV": "/D", "MOD": "MOD"}
_COMPARE = {"=": "==D", "<>": "<>D", "<": "<D", ">": ">D", "<=": "<=D", ">=": ">=D"}
_SWAPPED = {"=": "=", "<>": "<>", "<": ">", ">": "<", "<=": ">=", ">=": "<="}
_NS_PER_MS = 1_000_000


def is_long(kind: str | None) -> bool:
    """An 8-byte S7-1500 type, which no accumulator holds."""
    return kind in LONG_TYPES


class Longs(Dates):
    # ---- the narrow integers in the accumulators ---------------------------------------------

    def load_value(self, node: ast.Expr, want: str) -> None:
        if want in _DINT_FORM:
            value = self.constant(unparen(node))
            if value is not None and value.kind == "int" and id(unparen(node)) not in self.hoisted:
                number = int(value.number) & 0xFFFFFFFF
                self.em.load_text("TYPED", f"DW#16#{number:X}")
                return
        if is_long(want):
            raise LoweringError(node.loc, f"a {want} value in the accumulator")
        super().load_value(node, want)

    def convert(self, have: str, want: str) -> None:
        if have == want or (have not in _DINT_FORM and want not in _DINT_FORM):
            super().convert(have, want)
            return
        em = self.em
        if have in _NARROW:
            for mnemonic, operand in _NORMALISE[have]:
                kind = "NUMBER" if operand.isdigit() else "TYPED"
                em.op(mnemonic, em.literal(kind, operand))
            have = "DINT"
        if have == "UDINT" and want == "REAL":
            self.udint_to_real()
            return
        if have == "INT" and want in _DINT_FORM:
            em.op("ITD")  # (an INT's bits, the narrow store keeps what it needs)
            return
        super().convert(have if have not in _DINT_FORM else "DINT", want)

    def loop_kind(self, kind: str) -> str:
        """The type a FOR loop counts in: a SINT, USINT or UINT counter as a DINT."""
        return "DINT" if kind in _NARROW else kind

    def udint_to_real(self) -> None:
        """ACCU1 (a UDINT) → REAL: the upper half times 65536 plus the lower half."""
        em = self.em
        temp = em.temp(Elementary("DWORD"))
        em.op("T", em.ref(temp))
        em.op("SRD", em.literal("NUMBER", "16"))
        em.op("DTR")
        em.load_text("REAL", "6.5536e4")
        em.op("*R")
        em.op("L", em.ref(temp))
        em.op("AD", em.literal("TYPED", "DW#16#FFFF"))
        em.op("DTR")
        em.op("+R")
        em.release(temp)

    def simple(self, node: ast.Expr) -> bool:
        inner = unparen(node)
        udint = scalar(self.type_of(inner)) == "UDINT"
        if udint and id(inner) not in self.hoisted and self.constant(inner) is None:
            return False  # its conversion to REAL needs the second accumulator
        return super().simple(node)

    def binary(self, node: ast.Binary, have: str) -> None:
        if have not in _DINT_FORM:
            super().binary(node, have)
            return
        op = node.op
        if have == "UDINT" and op in ("/", "DIV", "MOD"):
            temp = self.library_result(node, f"{'MOD' if op == 'MOD' else 'DIV'}_UDINT")
            self.em.op("L", self.em.ref(temp))
            self.em.release(temp)
            return
        if op not in _INTEGER_OPS:
            raise LoweringError(node.loc, f"{op} on {have}")
        self.operands(node, "DINT" if have != "UDINT" else "UDINT")
        self.em.op(_INTEGER_OPS[op])

    def compare(self, node: ast.Binary) -> None:
        if id(node) in self.hoisted:
            super().compare(node)
            return
        left, right = scalar(self.type_of(node.left)), scalar(self.type_of(node.right))
        kind = wider(left or "", right or "") or left
        if kind not in _DINT_FORM:
            super().compare(node)
            return
        em = self.em
        if kind == "UDINT":  # unsigned: both with the top bit flipped, then signed
            self.load_value(node.left, "UDINT")
            em.op("XOD", em.literal("TYPED", _TOP_BIT))
            temp = em.temp(Elementary("DWORD"))
            em.op("T", em.ref(temp))
            self.load_value(node.right, "UDINT")
            em.op("XOD", em.literal("TYPED", _TOP_BIT))
            em.op("L", em.ref(temp))  # ACCU2 := the right operand, ACCU1 := the left one
            em.release(temp)
            em.op(_COMPARE[_SWAPPED[node.op]])
            return
        swapped = self.operands(node, "DINT")
        em.op(_COMPARE[_SWAPPED[node.op] if swapped else node.op])

    # ---- the 8-byte values ----------------------------------------------------------------------

    def library_operation(self, node: ast.Expr) -> str | None:
        if isinstance(node, ast.Binary) and node.op in COMPARISONS:
            kind = self.long_kind(node)
            if kind is not None:
                return long_library.operation(node.op, kind)
        return super().library_operation(node)

    def long_kind(self, node: ast.Binary) -> str | None:
        """The 8-byte type two operands are compared or computed in, None for other types."""
        left, right = scalar(self.type_of(node.left)), scalar(self.type_of(node.right))
        kind = wider(left or "", right or "") or left
        return kind if is_long(kind) else None

    def assign_text(self, stmt: ast.Assign) -> None:
        kind = scalar(self.type_of(stmt.target))
        if is_long(kind):
            assert kind is not None
            self.store_long(stmt.value, self.access(stmt.target), kind, stmt.loc)
            return
        super().assign_text(stmt)

    def store_long(self, value: ast.Expr, target: Access, kind: str, loc: ast.Loc) -> None:
        """``target`` (an 8-byte variable of type ``kind``) := ``value``."""
        em = self.em
        data_type = Elementary(kind)
        inner = unparen(value)
        hoisted = id(inner) in self.hoisted
        constant = None if hoisted else self.constant(inner)
        if constant is not None:
            place = self.locate(target, data_type, loc)
            self.reach(place)
            self.write_bytes(self.long_bytes(constant, kind, inner), 0)
            self.release_place(place)
            return
        have = scalar(self.type_of(inner))
        if have == kind and (hoisted or self.is_variable(inner)):
            self.copy_places(self.access(inner), data_type, target, data_type, loc)
            return
        temp = None if self.direct(target) else em.temp(data_type)
        result: Result = temp if temp is not None else self.operand(target, loc)
        self.long_value(inner, kind, have, result)
        if temp is not None:
            self.copy_places(Access("temp", temp=temp), data_type, target, data_type, loc)
            em.release(temp)

    def long_value(self, node: ast.Expr, kind: str, have: str | None, result: Result) -> None:
        """``result`` := ``node`` (not a constant, not a plain copy) as a ``kind``."""
        if have != kind:
            name = f"{have}_TO_{kind}"
            if have is None or name not in CONVERSIONS:
                raise LoweringError(node.loc, f"this {kind} value")
            self.library_call(name, [node], result)
        elif isinstance(node, ast.Binary):
            operation = long_library.operation(node.op, kind)
            if operation is None or operation not in FUNCTIONS:
                raise LoweringError(node.loc, f"{node.op} on {kind}")
            self.library_call(operation, [node.left, node.right], result)
        elif isinstance(node, ast.Unary) and node.op in ("-", "NOT"):
            self.library_call(
                f"{'NEG' if node.op == '-' else 'NOT'}_{kind}", [node.operand], result
            )
        elif isinstance(node, ast.Unary) and node.op == "+":
            self.long_value(node.operand, kind, have, result)
        elif isinstance(node, ast.Call):
            self.user_call(node, result)
        else:
            raise LoweringError(node.loc, f"this {kind} value")

    def long_bytes(self, value: Value, kind: str, node: ast.Expr) -> bytes:
        """The 8 bytes of a constant as a ``kind``."""
        if value.kind in ("int", "real"):
            number: int | float = value.number
            if kind == "LTIME" and value.kind == "int" and not _is_ltime_literal(node):
                number = int(number) * _NS_PER_MS  # an untyped number of milliseconds
            return encode(kind, number)
        if value.kind == "TIME" and kind == "LTIME":
            try:
                return encode(kind, duration_ms(value.text, value.text) * _NS_PER_MS)
            except ConstantError:
                raise LoweringError(node.loc, f"T#{value.text}") from None
        raise LoweringError(node.loc, f"this {kind} constant")

    def input_actual(
        self, value: ast.Expr, formal: DataType | None
    ) -> tuple[stl.OperandNode, Temp | None]:
        kind = scalar(formal) if formal is not None else None
        if formal is not None and kind in _DINT_FORM and self.constant(unparen(value)) is not None:
            temp = self.em.temp(formal)  # STL has no SINT/UINT/UDINT constants: a temporary
            self.load_value(value, kind)
            self.em.op("T", self.em.ref(temp))
            return self.em.ref(temp), temp
        if formal is None or not is_long(kind):
            return super().input_actual(value, formal)
        assert kind is not None
        em = self.em
        inner = unparen(value)
        hoisted = self.hoisted.get(id(inner))
        if hoisted is not None and scalar(hoisted.type) == kind:  # (else converted below)
            return em.ref(hoisted), None
        if self.constant(inner) is None and self.is_variable(inner):
            access = self.access(inner)
            if scalar(self.type_of(inner)) == kind and self.direct(access):
                return self.operand(access, inner.loc), None
        temp = em.temp(formal)
        self.store_long(inner, Access("temp", temp=temp), kind, inner.loc)
        return em.ref(temp), temp


def _is_ltime_literal(node: ast.Expr) -> bool:
    inner = unparen(node)
    while isinstance(inner, ast.Unary):
        inner = unparen(inner.operand)
    return isinstance(inner, ast.Literal) and inner.text.upper().startswith(("LT#", "LTIME#"))


__all__ = ["Longs", "is_long"]

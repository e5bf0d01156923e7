"""TIA's slice access (``x.%X3``, ``w.%B1``, ``d.%W0``, ``l.%D1``) lowered to STL on the
value of the whole variable, so it works wherever the variable is (temporaries, instance data,
DBs, array elements chosen at run time): a part is read by shifting the value right and masking
it; it is written by loading the variable, clearing the part, ORing the new part in and storing
the variable back. Part n counts from the least significant end (``%X0`` is bit 0 of the value,
which in memory is the last byte's bit 0). Bases of 64 bits are not lowered (``SCL301``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.places import LoweringError
from nasaq.lang.scl.typecheck.rules.slices import PARTS, WIDTHS
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.lower.expressions import Expressions

BOOL = Elementary("BOOL")
DWORD = Elementary("DWORD")


def _shape(low: Expressions, node: ast.Slice) -> tuple[str, int, int]:
    """The base's type name, the part's shift and its mask (before the shift)."""
    kind = low.scalar_of(node.base)
    if WIDTHS.get(kind, 64) > 32:
        raise LoweringError(node.loc, "a slice of a 64-bit value")
    bits = PARTS[node.width][0]
    return kind, node.index * bits, (1 << bits) - 1


def _dword(number: int) -> str:
    return f"DW#16#{number & 0xFFFFFFFF:X}"


def load_slice(low: Expressions, node: ast.Slice) -> None:
    """ACCU1 := the part (zero-filled), as a BYTE, WORD or DWORD (a BOOL as 0 or 1)."""
    em = low.em
    kind, shift, mask = _shape(low, node)
    low.load_value(node.base, kind)
    if shift:
        em.op("SRD", em.literal("NUMBER", str(shift)))
    if shift + mask.bit_length() < WIDTHS[kind] or kind in ("INT", "SINT", "DINT"):
        em.op("AD", em.literal("TYPED", _dword(mask)))


def bit_result(low: Expressions, node: ast.Slice) -> Temp:
    """A BOOL temporary holding ``x.%Xn`` (computed before the logic string that reads it)."""
    em = low.em
    load_slice(low, node)
    em.op("L", em.literal("NUMBER", "0"))
    em.op("<>D")
    temp = em.temp(BOOL)
    em.op("=", em.ref(temp))
    return temp


def assign_slice(low: Expressions, target: ast.Slice, value: ast.Expr) -> None:
    """``x.%Xn := value`` and the wider parts: the variable with the part replaced."""
    em = low.em
    kind, shift, mask = _shape(low, target)
    keep = ~(mask << shift)
    result = em.temp(DWORD)
    if target.width == "X":
        low.load_value(target.base, kind)
        em.op("AD", em.literal("TYPED", _dword(keep)))
        em.op("T", em.ref(result))
        low.condition(value)
        skip = em.new_label()
        em.jump("JCN", skip)
        em.op("L", em.ref(result))
        em.op("OD", em.literal("TYPED", _dword(mask << shift)))
        em.op("T", em.ref(result))
        em.place(skip)
    else:
        part = em.temp(DWORD)
        low.load_value(value, PARTS[target.width][1])
        em.op("AD", em.literal("TYPED", _dword(mask)))
        if shift:
            em.op("SLD", em.literal("NUMBER", str(shift)))
        em.op("T", em.ref(part))
        low.load_value(target.base, kind)
        em.op("AD", em.literal("TYPED", _dword(keep)))
        em.op("L", em.ref(part))
        em.op("OD")
        em.op("T", em.ref(result))
        em.release(part)
    store(low, target.base, result)
    em.release(result)


def store(low: Expressions, node: ast.Expr, value: Temp) -> None:
    """``node := value`` for a variable of up to 32 bits (``value`` a DWORD temporary)."""
    if isinstance(node, ast.Slice):  # w.%B1.%X0 := ...: the byte, then the word
        part = low.em.temp(DWORD)
        kind, shift, mask = _shape(low, node)
        em = low.em
        low.load_value(node.base, kind)
        em.op("AD", em.literal("TYPED", _dword(~(mask << shift))))
        em.op("L", em.ref(value))
        if shift:
            em.op("SLD", em.literal("NUMBER", str(shift)))
        em.op("OD")
        em.op("T", em.ref(part))
        store(low, node.base, part)
        em.release(part)
        return
    operand = low.operand(low.access(node), node.loc)
    low.em.op("L", low.em.ref(value))
    low.em.op("T", operand)

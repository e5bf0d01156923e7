"""Rule: TIA Portal's slice access ``x.%X3``, ``w.%B1``, ``d.%W0``, ``l.%D1`` (S7-1200/1500
only: ``SCL500`` under a classic profile). The base is a bit string or an integer (BYTE, WORD,
DWORD, LWORD, SINT ... ULINT) at least as wide as the part (``SCL702``); the part's number
counts from the least significant end and must lie inside the base (``SCL701``). The slice is
a BOOL, BYTE, WORD or DWORD that may be read and written."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import ERROR, Type, describe, is_silent, scalar
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

# Bits of the types a slice may be taken of.
WIDTHS = {
    "BYTE": 8,
    "WORD": 16,
    "DWORD": 32,
    "LWORD": 64,
    "SINT": 8,
    "USINT": 8,
    "INT": 16,
    "UINT": 16,
    "DINT": 32,
    "UDINT": 32,
    "LINT": 64,
    "ULINT": 64,
}
# Each part: its width in bits and its type.
PARTS = {"X": (1, "BOOL"), "B": (8, "BYTE"), "W": (16, "WORD"), "D": (32, "DWORD")}
_TYPES = {name: Elementary(name) for _, name in PARTS.values()}


def slice_access(ctx: Context, node: ast.Slice) -> Type:
    base = ctx.type_of(node.base)
    if base is ERROR:  # reported (an inner slice under a classic profile too)
        return base
    profile = ctx.index.profile
    if not is_s7_1500(profile):
        return ctx.report("SCL500", node.loc, what=ctx.text(node), profile=profile)
    if is_silent(base):
        return base
    name = scalar(base)
    width = WIDTHS.get(name or "") if isinstance(base, Elementary) else None
    bits, part = PARTS[node.width]
    if width is None or width < bits:
        return ctx.report("SCL702", node.loc, text=ctx.text(node), type=describe(base))
    count = width // bits
    if node.index >= count:
        return ctx.report(
            "SCL701", node.loc, text=ctx.text(node), type=name, count=count, last=count - 1
        )
    return _TYPES[part]


__all__ = ["PARTS", "WIDTHS", "slice_access"]

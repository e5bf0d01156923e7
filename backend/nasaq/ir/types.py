"""Sizes of the S7 elementary types: one table for the compilers (layout, checks) and the CPU
(parameter passing). Interface variables carry their type as text (``ir.Variable.type``)."""

from __future__ import annotations

import re

ELEMENTARY_BITS: dict[str, int] = {
    "BOOL": 1,
    "BYTE": 8,
    "CHAR": 8,
    "WORD": 16,
    "INT": 16,
    "S5TIME": 16,
    "DATE": 16,
    "DWORD": 32,
    "DINT": 32,
    "REAL": 32,
    "TIME": 32,
    "TIME_OF_DAY": 32,
    "DATE_AND_TIME": 64,
    "POINTER": 48,
    "ANY": 80,
    "TIMER": 16,
    "COUNTER": 16,
    "BLOCK_FB": 16,
    "BLOCK_FC": 16,
    "BLOCK_DB": 16,
    "BLOCK_SDB": 16,
    # S7-1200/1500 only (``nasaq.lang.profiles.S7_1500_TYPES``): the compilers refuse them for
    # a classic CPU. In a standard (non-optimized) block they are big-endian like the others.
    "SINT": 8,
    "USINT": 8,
    "UINT": 16,
    "UDINT": 32,
    "LINT": 64,
    "ULINT": 64,
    "LREAL": 64,
    "LWORD": 64,
    "LTIME": 64,
    "WCHAR": 16,  # one UTF-16 code unit (``nasaq.lang.wide_text``)
}
TYPE_ALIASES = {"TOD": "TIME_OF_DAY", "DT": "DATE_AND_TIME"}
# The 64-bit values no accumulator holds: moved as 8 bytes, computed by hidden library FCs.
LONG_TYPES = frozenset({"LINT", "ULINT", "LREAL", "LWORD", "LTIME"})
NUMBER_TYPES = frozenset({"TIMER", "COUNTER", "BLOCK_FB", "BLOCK_FC", "BLOCK_DB", "BLOCK_SDB"})
# Types whose value fits an accumulator: what L/T/A/= may address directly.
ACCU_TYPES = frozenset(
    name for name, bits in ELEMENTARY_BITS.items() if bits <= 32 and name not in NUMBER_TYPES
)


_ARRAY = re.compile(r"^ARRAY\s*\[(?P<dims>[^\]]*)\]\s*OF\s+(?P<element>.+)$", re.IGNORECASE)
_DIM = re.compile(r"^\s*(-?\d+)\s*\.\.\s*(-?\d+)\s*$")


def array_shape(type_text: str) -> tuple[list[tuple[int, int]], str] | None:
    """``ARRAY[1..3, 0..1] OF INT`` → ``([(1, 3), (0, 1)], "INT")``; None for any other type."""
    match = _ARRAY.match(type_text.strip())
    if match is None:
        return None
    dims = [_DIM.match(part) for part in match["dims"].split(",")]
    if not all(dims):
        return None
    return [(int(dim[1]), int(dim[2])) for dim in dims if dim], match["element"].strip()

"""The status word: bit positions as ``L STW`` loads them, and the names of its register locals.

Generated code keeps each bit in its own local variable (0 or 1); these helpers pack and unpack
them only where the whole word is needed (``L STW``, ``T STW``, the API).
"""

from __future__ import annotations

# (local name, bit position): /FC RLO STA OR OS OV CC0 CC1 BR
STATUS_BITS: tuple[tuple[str, int], ...] = (
    ("fc", 0),
    ("rlo", 1),
    ("sta", 2),
    ("orb", 3),
    ("os", 4),
    ("ov", 5),
    ("cc0", 6),
    ("cc1", 7),
    ("br", 8),
)
STATUS_NAMES: tuple[str, ...] = tuple(name for name, _ in STATUS_BITS)
BIT_OF: dict[str, int] = dict(STATUS_BITS)

# ``Register("STW.RLO")`` of the test pseudo-ops → local name
TEST_BIT_NAMES: dict[str, str] = {
    "FC": "fc",
    "/FC": "fc",
    "RLO": "rlo",
    "STA": "sta",
    "OR": "orb",
    "OS": "os",
    "OV": "ov",
    "CC0": "cc0",
    "CC1": "cc1",
    "BR": "br",
}

# The expression generated code uses to build the word from the locals (``L STW``).
PACK_EXPR = " | ".join(f"{name} << {bit}" if bit else name for name, bit in STATUS_BITS)

# ``L STW`` on an S7-300 loads only bits 1 and 4-8 (RLO OS OV CC0 CC1 BR); /FC, STA and OR read as
# 0 (STL manual, L STW). An S7-400 loads all nine bits. ``T STW`` writes all nine on both.
S7_300_L_STW: tuple[str, ...] = ("rlo", "os", "ov", "cc0", "cc1", "br")
PACK_EXPR_300 = " | ".join(f"{name} << {BIT_OF[name]}" for name in S7_300_L_STW)


def pack(values: dict[str, int]) -> int:
    return sum((values[name] & 1) << bit for name, bit in STATUS_BITS)


def unpack(word: int) -> dict[str, int]:
    return {name: (word >> bit) & 1 for name, bit in STATUS_BITS}

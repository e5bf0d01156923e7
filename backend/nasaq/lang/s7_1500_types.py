"""The S7-1200/1500 elementary types as the compilers see them: ranges, TIA Portal's implicit
conversions, the explicit ``*_TO_*`` functions, and the result type of an operation.

Implicit conversions (TIA Portal's table for S7-1200/1500 with the IEC check on; only what
loses nothing, and integers to the floating-point types, as S7-SCL's INT → REAL):
- signed: SINT → INT → DINT → LINT; unsigned: USINT → UINT → UDINT → ULINT;
- an unsigned type into every wider signed one (USINT → INT, UINT → DINT, UDINT → LINT);
- every integer into LREAL, those up to 32 bits into REAL too, REAL → LREAL;
- bit strings BOOL → BYTE → WORD → DWORD → LWORD; TIME → LTIME.
Two operands of different types are computed in the smaller type both convert to (INT with
UINT in DINT, DINT with UDINT in LINT, LINT with ULINT in LREAL); everything else needs a
``*_TO_*`` function, which exists between every two of the integer, bit-string and floating
types, and between LTIME and LINT/TIME. The classic types keep S7-SCL's rules (``types``).
"""

from __future__ import annotations

from functools import cache

# Value ranges of every integer type (the classic INT and DINT too, for the mixed cases).
INTEGER_RANGES: dict[str, tuple[int, int]] = {
    "SINT": (-(2**7), 2**7 - 1),
    "INT": (-(2**15), 2**15 - 1),
    "DINT": (-(2**31), 2**31 - 1),
    "LINT": (-(2**63), 2**63 - 1),
    "USINT": (0, 2**8 - 1),
    "UINT": (0, 2**16 - 1),
    "UDINT": (0, 2**32 - 1),
    "ULINT": (0, 2**64 - 1),
}
NEW_INTEGERS = ("SINT", "USINT", "UINT", "UDINT", "LINT", "ULINT")
FLOATS = ("REAL", "LREAL")
BIT_STRINGS = ("BOOL", "BYTE", "WORD", "DWORD", "LWORD")
ALL_INTEGERS = frozenset(INTEGER_RANGES)
ALL_NUMBERS = ALL_INTEGERS | frozenset(FLOATS)
LWORD_LIMIT = 2**64 - 1
# LTIME is a LINT of nanoseconds.
LTIME_RANGE = INTEGER_RANGES["LINT"]
# The types two different operands meet in, smallest first.
_COMMON = ("INT", "DINT", "LINT", "LREAL")


@cache
def widens(source: str, target: str) -> bool:
    """Whether TIA converts ``source`` to ``target`` silently (see the module doc)."""
    if source == target:
        return True
    if source in INTEGER_RANGES and target in INTEGER_RANGES:
        low, high = INTEGER_RANGES[source]
        goal_low, goal_high = INTEGER_RANGES[target]
        return goal_low <= low and high <= goal_high
    if source in ALL_NUMBERS and target in FLOATS:
        return target == "LREAL" or source not in ("LREAL", "LINT", "ULINT")
    if source in BIT_STRINGS and target in BIT_STRINGS:
        return BIT_STRINGS.index(source) < BIT_STRINGS.index(target)
    return source == "TIME" and target == "LTIME"


@cache
def common(left: str, right: str) -> str | None:
    """The type an operation on ``left`` and ``right`` is computed in, if there is one."""
    if widens(left, right):
        return right
    if widens(right, left):
        return left
    if left in ALL_NUMBERS and right in ALL_NUMBERS:
        return next(name for name in _COMMON if widens(left, name) and widens(right, name))
    return None


def _conversions() -> frozenset[str]:
    """Every ``A_TO_B`` between the integers, bit strings (not BOOL) and REAL/LREAL where A or
    B is an S7-1200/1500 type, and LTIME's own."""
    values = [*INTEGER_RANGES, *FLOATS, "BYTE", "WORD", "DWORD", "LWORD"]
    new = {*NEW_INTEGERS, "LREAL", "LWORD"}
    names = {
        f"{source}_TO_{target}"
        for source in values
        for target in values
        if source != target and (source in new or target in new)
    }
    names |= {"LTIME_TO_LINT", "LINT_TO_LTIME", "LTIME_TO_TIME", "TIME_TO_LTIME"}
    names |= {"LTIME_TO_DINT", "DINT_TO_LTIME", "LTIME_TO_LREAL"}
    return frozenset(names)


CONVERSIONS = _conversions()

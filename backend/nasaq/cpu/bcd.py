"""BCD helpers shared by timers, counters and the conversion instructions."""

from __future__ import annotations

from nasaq.cpu.errors import CpuError


def bcd_to_int(value: int, digits: int, op: str) -> int:
    """Decode ``digits`` BCD digits (no sign); invalid digits raise the programming error."""
    result = 0
    for position in range(digits - 1, -1, -1):
        digit = (value >> (4 * position)) & 0xF
        if digit > 9:
            raise CpuError("SIM512", value=f"16#{value:X}", op=op)
        result = result * 10 + digit
    return result


def int_to_bcd(value: int, digits: int) -> int:
    result = 0
    for position in range(digits):
        result |= (value % 10) << (4 * position)
        value //= 10
    return result

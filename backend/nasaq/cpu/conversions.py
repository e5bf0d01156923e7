"""Run-time parts of the conversion and shift instructions (BCD, rounding, variable shifts)."""

from __future__ import annotations

from nasaq.cpu.bcd import bcd_to_int, int_to_bcd


def bti(a1: int) -> int:
    """BTI: 3 BCD digits in ACCU1-L, sign in bit 15, to INT in ACCU1-L (ACCU1-H kept)."""
    value = bcd_to_int(a1 & 0xFFF, 3, "BTI")
    if a1 & 0x8000:
        value = -value
    return (a1 & 0xFFFF0000) | (value & 0xFFFF)


def btd(a1: int) -> int:
    value = bcd_to_int(a1 & 0xFFFFFFF, 7, "BTD")
    if a1 & 0x80000000:
        value = -value
    return value & 0xFFFFFFFF


def itb(a1: int, os: int) -> tuple[int, int, int]:
    """ITB: (ACCU1, OV, OS); beyond ±999 only OV and OS change."""
    value = ((a1 & 0xFFFF) ^ 0x8000) - 0x8000
    if not -999 <= value <= 999:
        return a1, 1, 1
    bcd = int_to_bcd(abs(value), 3) | (0xF000 if value < 0 else 0)
    return (a1 & 0xFFFF0000) | bcd, 0, os


def dtb(a1: int, os: int) -> tuple[int, int, int]:
    value = (a1 ^ 0x80000000) - 0x80000000
    if not -9999999 <= value <= 9999999:
        return a1, 1, 1
    return int_to_bcd(abs(value), 7) | (0xF0000000 if value < 0 else 0), 0, os


def shift(kind: str, a1: int, count: int, cc1: int, cc0: int, ov: int) -> tuple[int, int, int, int]:
    """Shift/rotate with the count from ACCU2-LL: (ACCU1, CC1, CC0, OV); count 0 changes nothing."""
    if count == 0:
        return a1, cc1, cc0, ov
    if kind in ("SSI", "SLW", "SRW"):
        word = a1 & 0xFFFF
        if kind == "SSI":
            n = min(count, 16)
            signed = (word ^ 0x8000) - 0x8000
            out, result = (signed >> (n - 1)) & 1, signed >> n
        elif count > 16:
            out, result = 0, 0
        elif kind == "SLW":
            out, result = (word >> (16 - count)) & 1, word << count
        else:
            out, result = (word >> (count - 1)) & 1, word >> count
        return (a1 & 0xFFFF0000) | (result & 0xFFFF), out, 0, 0
    if kind == "SSD":
        n = min(count, 32)
        signed = (a1 ^ 0x80000000) - 0x80000000
        return (signed >> n) & 0xFFFFFFFF, (signed >> (n - 1)) & 1, 0, 0
    if kind in ("SLD", "SRD"):
        if count > 32:
            return 0, 0, 0, 0
        if kind == "SLD":
            return (a1 << count) & 0xFFFFFFFF, (a1 >> (32 - count)) & 1, 0, 0
        return a1 >> count, (a1 >> (count - 1)) & 1, 0, 0
    n = count % 32
    if kind == "RLD":
        result = ((a1 << n) | (a1 >> (32 - n))) & 0xFFFFFFFF
        return result, result & 1, 0, 0
    result = ((a1 >> n) | (a1 << (32 - n))) & 0xFFFFFFFF
    return result, result >> 31, 0, 0

"""Addresses and values as users type them on the command line and in scenario files.

``I0.0 IB0 IW0 ID0`` (likewise Q, M, and the German E, A), ``DB1.DBX0.0 DB1.DBB0 DB1.DBW0
DB1.DBD0``, timers ``T1`` and counters ``C1`` (German ``Z1``). Spaces between the area and the
number are allowed (``I 0.0``), as STEP 7 writes them.
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

from nasaq.diagnostics.phrases import Phrase, phrase
from nasaq.ir import Area, Direct, Width

_AREAS = {"I": Area.I, "E": Area.I, "Q": Area.Q, "A": Area.Q, "M": Area.M}
_WIDTHS = {"": Width.BIT, "X": Width.BIT, "B": Width.BYTE, "W": Width.WORD, "D": Width.DWORD}

_MEMORY = re.compile(r"^(?P<area>[IEQAM])\s*(?P<size>[BWD]?)\s*(?P<byte>\d+)(?:\.(?P<bit>\d+))?$")
_DB = re.compile(r"^DB\s*(?P<db>\d+)\s*\.\s*DB(?P<size>[XBWD])\s*(?P<byte>\d+)(?:\.(?P<bit>\d+))?$")
_TIMER = re.compile(r"^T\s*(?P<n>\d+)$")
_COUNTER = re.compile(r"^[CZ]\s*(?P<n>\d+)$")


class AddressError(ValueError):
    """An address or value the user typed that Nasaq cannot read; the message says why, and
    ``phrase`` (when set) says it without the address, for the UI to translate."""

    def __init__(self, message: str, phrase: Phrase | None = None) -> None:
        super().__init__(message)
        self.phrase = phrase


@dataclass(frozen=True, slots=True)
class TimerAddress:
    number: int


@dataclass(frozen=True, slots=True)
class CounterAddress:
    number: int


Address = Direct | TimerAddress | CounterAddress


def _direct(area: Area, size: str, byte: str, bit: str | None, db: int | None, text: str) -> Direct:
    width = _WIDTHS[size]
    if width is Width.BIT:
        if bit is None:
            reason = phrase("bit_needs_number", example=f"{text}.0")
            raise AddressError(f"{text}: {reason}", reason)
        if int(bit) > 7:
            reason = phrase("bit_number_range")
            raise AddressError(f"{text}: {reason}", reason)
        return Direct(area, width, int(byte), int(bit), db)
    if bit is not None:
        reason = phrase("bit_only")
        raise AddressError(f"{text}: {reason}", reason)
    return Direct(area, width, int(byte), 0, db)


def parse_address(text: str) -> Address:
    """Reads one address; raises :class:`AddressError` with the reason."""
    cleaned = text.strip().upper()
    if match := _MEMORY.match(cleaned):
        area = _AREAS[match["area"]]
        return _direct(area, match["size"], match["byte"], match["bit"], None, cleaned)
    if match := _DB.match(cleaned):
        db = int(match["db"])
        if db == 0:
            reason = phrase("no_db_zero")
            raise AddressError(f"{cleaned}: {reason}", reason)
        return _direct(Area.DB, match["size"], match["byte"], match["bit"], db, cleaned)
    if match := _TIMER.match(cleaned):
        return TimerAddress(int(match["n"]))
    if match := _COUNTER.match(cleaned):
        return CounterAddress(int(match["n"]))
    reason = phrase("not_an_address", text=repr(text))
    raise AddressError(str(reason), reason)


def address_text(address: Direct) -> str:
    """The canonical spelling of a direct address, as reports show it."""
    size = {Width.BIT: "", Width.BYTE: "B", Width.WORD: "W", Width.DWORD: "D"}[address.width]
    if address.db is not None:
        size = size or "X"
        where = f"DB{address.db}.DB{size}{address.byte}"
    else:
        where = f"{address.area.value}{size}{address.byte}"
    return f"{where}.{address.bit}" if address.width is Width.BIT else where


def encode_value(address: Direct, value: int | float | str) -> int:
    """The unsigned bit pattern to store for ``value`` at ``address``.

    Integers may be negative (two's complement), written ``16#..`` or ``2#..``; a real is allowed
    for doublewords and stored as IEEE 754 single precision.
    """
    bits = int(address.width)
    if isinstance(value, str):
        value = parse_number(value)
    if isinstance(value, bool):
        value = int(value)
    if isinstance(value, float):
        if address.width is not Width.DWORD:
            raise AddressError(f"{address_text(address)}: a real value needs a doubleword")
        packed: int = struct.unpack(">I", struct.pack(">f", value))[0]
        return packed
    low, high = -(1 << (bits - 1)), (1 << bits) - 1
    if address.width is Width.BIT:
        low = 0
    if not low <= value <= high:
        raise AddressError(f"{address_text(address)}: {value} does not fit in {bits} bit(s)")
    return value & high


def parse_number(text: str) -> int | float:
    """``5``, ``-3``, ``16#FF``, ``2#1010``, ``1.5`` → a Python number."""
    cleaned = text.strip().upper().replace("_", "")
    try:
        if cleaned.startswith(("16#", "-16#")):
            sign = -1 if cleaned.startswith("-") else 1
            return sign * int(cleaned.split("#", 1)[1], 16)
        if cleaned.startswith(("2#", "-2#")):
            sign = -1 if cleaned.startswith("-") else 1
            return sign * int(cleaned.split("#", 1)[1], 2)
        if any(mark in cleaned for mark in ".E"):
            return float(cleaned)
        return int(cleaned, 10)
    except ValueError:
        raise AddressError(
            f"{text!r} is not a number (examples: 5, -3, 16#FF, 2#1010, 2.5)"
        ) from None


def signed(value: int, width: Width) -> int:
    """The two's-complement reading of an unsigned value of ``width`` bits."""
    bits = int(width)
    return value - (1 << bits) if bits > 1 and value >> (bits - 1) else value


def as_real(pattern: int) -> float:
    real: float = struct.unpack(">f", struct.pack(">I", pattern & 0xFFFFFFFF))[0]
    return real

"""Area pointers (32-bit ``P#`` values), the 6-byte POINTER and the 10-byte ANY.

Layout of a 32-bit area pointer: bit 31 set marks an area-crossing pointer, bits 24-26 hold the
area, bits 3-18 the byte address and bits 0-2 the bit address. Area codes follow STEP 7:
16#80 P (peripheral), 16#81 I, 16#82 Q, 16#83 M, 16#84 DB, 16#85 DI, 16#86 L, 16#87 V.
"""

from __future__ import annotations

from nasaq.ir import Area

AREA_CODES: dict[Area, int] = {
    Area.PI: 0,
    Area.PQ: 0,
    Area.I: 1,
    Area.Q: 2,
    Area.M: 3,
    Area.DB: 4,
    Area.DI: 5,
    Area.L: 6,
    Area.V: 7,
}
CODE_AREAS: dict[int, Area] = {
    0: Area.PI,
    1: Area.I,
    2: Area.Q,
    3: Area.M,
    4: Area.DB,
    5: Area.DI,
    6: Area.L,
    7: Area.V,
}
ADDRESS_MASK = 0x7FFFF  # bits 0-18: byte * 8 + bit
CROSSING = 0x80000000

# ANY data type codes (byte 1 of an ANY)
ANY_TYPES: dict[str, int] = {
    "BOOL": 1,
    "BYTE": 2,
    "CHAR": 3,
    "WORD": 4,
    "INT": 5,
    "DWORD": 6,
    "DINT": 7,
    "REAL": 8,
    "DATE": 9,
    "TIME_OF_DAY": 10,
    "TIME": 11,
    "S5TIME": 12,
    "DATE_AND_TIME": 14,
    "STRING": 19,
}


def area_pointer(area: Area, byte: int, bit: int = 0) -> int:
    """The area-crossing pointer ``P#M 10.3`` as ``L P#...`` loads it."""
    return CROSSING | (AREA_CODES[area] << 24) | ((byte << 3) | bit)


def internal_pointer(byte: int, bit: int = 0) -> int:
    return (byte << 3) | bit


def split(pointer: int) -> tuple[int, int]:
    """(area code 0..7, bit address) of a pointer; the area is meaningful only if crossing."""
    return (pointer >> 24) & 7, pointer & ADDRESS_MASK


def any_pointer(area: Area, byte: int, bit: int, type_code: int, count: int, db: int = 0) -> bytes:
    """The 10 bytes of an ANY: 16#10, type, repetition factor, DB number, area pointer."""
    pointer = area_pointer(area, byte, bit)
    return (
        bytes((0x10, type_code))
        + count.to_bytes(2, "big")
        + db.to_bytes(2, "big")
        + (pointer.to_bytes(4, "big"))
    )


def pointer6(area: Area, byte: int, bit: int, db: int = 0) -> bytes:
    """The 6 bytes of a POINTER parameter: DB number, then an area-crossing pointer."""
    return db.to_bytes(2, "big") + area_pointer(area, byte, bit).to_bytes(4, "big")

"""Memory areas of the CPU: process images, peripheral I/O, markers, data blocks.

Everything is a ``bytearray`` (big-endian words and double words, as on the S7), so generated code
can index it directly. The L stack is not here: each block invocation gets its own frame
(``bytearray``) and the caller's frame is its V area.
"""

from __future__ import annotations

from nasaq.ir import Area, Block, BlockKind, Program, Width

_PREFIX: dict[Area, str] = {
    Area.I: "I",
    Area.Q: "Q",
    Area.M: "M",
    Area.L: "L",
    Area.V: "V",
    Area.DB: "DB",
    Area.DI: "DI",
    Area.PI: "PI",
    Area.PQ: "PQ",
}
_SUFFIX: dict[int, str] = {8: "B", 16: "W", 32: "D"}


def address_text(area: Area, width: int, byte: int, bit: int = 0, db: int | None = None) -> str:
    """``MW 600``, ``DB5.DBX 2.1``, ``PIW 256``, ``L 0.3`` — the address as STL writes it."""
    prefix = _PREFIX[area]
    if width == 1:
        name = {Area.DB: "DBX", Area.DI: "DIX", Area.PI: "PI", Area.PQ: "PQ"}.get(area, prefix)
        text = f"{name} {byte}.{bit}"
    else:
        text = f"{prefix}{_SUFFIX[width]} {byte}"
    return f"DB{db}.{text}" if db is not None and area is Area.DB else text


def _layout_bytes(variables: list[object]) -> int:
    end = 0
    for var in variables:
        offset = getattr(var, "offset_bits", 0)
        size = getattr(var, "size_bits", 0)
        section = getattr(var, "section", "")
        if section in ("TEMP", "RETURN"):
            continue
        end = max(end, offset + size)
    size_bytes = (end + 7) // 8
    return size_bytes + (size_bytes & 1)


def db_size(block: Block, program: Program) -> int:
    """Length of a DB: its data, or its layout (own interface or its FB's) if that is longer."""
    layout = block.interface
    if block.instance_of is not None:
        fb = program.get(BlockKind.FB, block.instance_of)
        if fb is not None:
            layout = fb.interface
    return max(len(block.data), _layout_bytes(list(layout)))


class Memory:
    """All global memory of one CPU. ``dbs`` keeps the same bytearray objects for its lifetime, so
    compiled code may bind them."""

    def __init__(self, program: Program, pi_bytes: int, periph_bytes: int, m_bytes: int) -> None:
        self.I = bytearray(pi_bytes)  # PII
        self.Q = bytearray(pi_bytes)  # PIQ
        self.M = bytearray(m_bytes)
        self.PI = bytearray(periph_bytes)  # peripheral inputs (what the process delivers)
        self.PQ = bytearray(periph_bytes)  # peripheral outputs (what the modules output)
        self._areas = {
            Area.I: self.I,
            Area.Q: self.Q,
            Area.M: self.M,
            Area.PI: self.PI,
            Area.PQ: self.PQ,
        }
        self.program = program
        self.dbs: dict[int, bytearray] = {}
        self._initial: dict[int, bytes] = {}
        for (kind, number), block in program.blocks.items():
            if kind is BlockKind.DB:
                size = db_size(block, program)
                data = bytes(block.data) + bytes(size - len(block.data))
                self._initial[number] = data
                self.dbs[number] = bytearray(data)

    def reload_dbs(self) -> None:
        """Memory reset: DBs get their initial (downloaded) values back, in place."""
        for number, data in self._initial.items():
            self.dbs[number][:] = data

    def area(self, area: Area) -> bytearray:
        return self._areas[area]


def read_bytes(buf: bytearray, byte: int, width: int, bit: int = 0) -> int:
    """Unsigned big-endian value at ``byte`` (bit ``bit`` for width 1); IndexError if outside."""
    if byte < 0:
        raise IndexError(byte)
    if width == Width.BIT:
        return (buf[byte] >> bit) & 1
    count = width >> 3
    if byte + count > len(buf):
        raise IndexError(byte)
    return int.from_bytes(buf[byte : byte + count], "big")


def write_bytes(buf: bytearray, byte: int, width: int, value: int, bit: int = 0) -> None:
    if byte < 0:
        raise IndexError(byte)
    if width == Width.BIT:
        if value & 1:
            buf[byte] |= 1 << bit
        else:
            buf[byte] &= ~(1 << bit) & 0xFF
        return
    count = width >> 3
    if byte + count > len(buf):
        raise IndexError(byte)
    buf[byte : byte + count] = (value & ((1 << width) - 1)).to_bytes(count, "big")

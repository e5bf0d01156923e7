"""What the debugger needs to know about one code block, worked out once: the source line and
network of every instruction, where SCL statements start, the block's own variables and where
they live while it runs, and which breakpoint locations have code."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from nasaq.diagnostics.phrases import phrase
from nasaq.ir import Area, Block, BlockKind, Direct, Program, Variable
from nasaq.lang.stl.compiler import SCL_SUFFIXES
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import Location
from nasaq.monitor.values import ELEMENTARY_BITS, decode

MAX_LOCALS = 400  # variables listed at a hold (array elements included)
MAX_ARRAY_ELEMENTS = 32
_BLOCK_NAME = re.compile(r"^\s*(OB|FB|FC)\s*(\d+)\s*$", re.IGNORECASE)
_HIDDEN = re.compile(r"^_t\d+$")  # the SCL compiler's own temporaries (lang/scl/lower/emitter.py)
_ARRAY = re.compile(r"^ARRAY\s*\[\s*(-?\d+)\s*\.\.\s*(-?\d+)\s*\]\s*OF\s+(\w+)$", re.IGNORECASE)


@dataclass(frozen=True, slots=True)
class Slot:
    """A variable of the block: where it lives while the block runs."""

    name: str
    type: str
    home: str  # "L" (frame), "DI" (instance data, relative to AR2), "P" (FC parameter slot)
    bit_offset: int  # L/DI: bit offset; P: the parameter slot
    bits: int


@dataclass(slots=True)
class BlockInfo:
    block: Block
    name: str
    language: str  # "stl", "scl", "lad", "fbd" or "graph": the language of the block's source
    file: str | None
    lines: list[int | None]
    networks: list[int]
    statement_start: list[bool]
    slots: list[Slot] = field(default_factory=list)
    by_name: dict[str, Slot] = field(default_factory=dict)

    def slot_at(self, direct: Direct) -> Slot | None:
        """The variable an L or DI operand of this block addresses, if it is one."""
        home = "L" if direct.area is Area.L else "DI" if direct.area is Area.DI else None
        if home is None:
            return None
        at, width = direct.byte * 8 + direct.bit, int(direct.width)
        for slot in self.slots:
            if slot.home != home:
                continue
            if slot.bit_offset == at and slot.bits == width:
                return slot
            # an 8-byte value moves as two doublewords: either half names the whole variable
            if slot.bits == 64 and width == 32 and at in (slot.bit_offset, slot.bit_offset + 32):
                return slot
        return None


def block_name(block: Block) -> str:
    return f"{block.kind.value}{block.number}"


def parse_block_name(text: str, program: Program) -> tuple[BlockKind, int]:
    """``FC1``, ``FB 10``, ``OB1`` or a block's symbol: its (kind, number); MON613 if it is not a
    code block of the program."""
    match = _BLOCK_NAME.match(text)
    if match:
        key = (BlockKind(match[1].upper()), int(match[2]))
    else:
        wanted = text.strip().strip('"').casefold()
        found = [k for k, b in program.blocks.items() if b.name and b.name.casefold() == wanted] + [
            (BlockKind(a.split()[0].upper()), int(a.split()[1]))
            for name, a in program.symbols.items()
            if name.casefold() == wanted and _BLOCK_NAME.match(a)
        ]
        key = found[0] if found else (BlockKind.FC, -1)
    block = program.get(*key)
    if block is None or block.kind not in (BlockKind.OB, BlockKind.FB, BlockKind.FC):
        raise MonitorError("MON613", block=text.strip())
    return key


def block_info(block: Block) -> BlockInfo:
    code = block.code
    lines: list[int | None] = []
    files: set[str] = set()
    networks: list[int] = []
    firsts = sorted((net.first, k + 1) for k, net in enumerate(block.networks))
    current = 1
    pointer = 0
    for index, ins in enumerate(code):
        while pointer < len(firsts) and firsts[pointer][0] <= index:
            current = firsts[pointer][1]
            pointer += 1
        origin = ins.origin
        lines.append(origin.line if origin is not None else None)
        if origin is not None:
            files.add(origin.file)
        networks.append(origin.network if origin and origin.network else current)
    targets = set(block.labels.values()) | {k for k, ins in enumerate(code) if ins.label}
    starts = [k == 0 or lines[k] != lines[k - 1] or k in targets for k in range(len(code))]
    file = sorted(files)[0] if files else None
    suffix = file.lower().rsplit(".", 1)[-1] if file is not None and "." in file else ""
    language = "scl" if f".{suffix}" in SCL_SUFFIXES else suffix
    language = language if language in ("scl", "lad", "fbd", "graph") else "stl"
    info = BlockInfo(block, block_name(block), language, file, lines, networks, starts)
    info.slots = [
        slot for slot in _slots(block) if not (language == "scl" and _HIDDEN.match(slot.name))
    ]
    info.by_name = {slot.name.casefold(): slot for slot in info.slots}
    return info


def _slots(block: Block) -> list[Slot]:
    slots: list[Slot] = []
    param_slot = 0
    for variable in block.interface:
        if block.kind is BlockKind.FC and variable.section in ("IN", "OUT", "IN_OUT", "RETURN"):
            if variable.section != "RETURN" or (block.return_type or "VOID") != "VOID":
                bits = ELEMENTARY_BITS.get(variable.type.upper(), 0)
                if bits:
                    slots.append(Slot(variable.name, variable.type.upper(), "P", param_slot, bits))
                param_slot += 1
            continue
        if variable.section == "TEMP":
            _flatten(variable, variable.name, "L", 0, slots)
        elif block.kind is BlockKind.FB and variable.section in ("IN", "OUT", "IN_OUT", "STAT"):
            _flatten(variable, variable.name, "DI", 0, slots)
    return slots[:MAX_LOCALS]


def _flatten(variable: Variable, name: str, home: str, base: int, out: list[Slot]) -> None:
    if len(out) >= MAX_LOCALS:
        return
    type_text = variable.type.upper()
    offset = base + variable.offset_bits
    bits = ELEMENTARY_BITS.get(type_text)
    if bits is not None:
        out.append(Slot(name, type_text, home, offset, bits))
        return
    match = _ARRAY.match(variable.type.strip())
    if match and match[3].upper() in ELEMENTARY_BITS:
        low, high, element = int(match[1]), int(match[2]), match[3].upper()
        size = ELEMENTARY_BITS[element]
        stride = size if size == 1 else max(size, 8)
        if size > 8 and stride % 16:
            stride += 16 - stride % 16
        for k in range(min(high - low + 1, MAX_ARRAY_ELEMENTS)):
            out.append(Slot(f"{name}[{low + k}]", element, home, offset + k * stride, size))
        return
    for member in variable.members:
        _flatten(member, f"{name}.{member.name}", home, offset, out)


def read_slot(slot: Slot, frame: bytearray, di: bytearray, ar2: int, params: list[Any]) -> Any:
    """The value of ``slot`` in the running block (frame, instance data at AR2, parameters)."""
    if slot.home == "P":
        if slot.bit_offset >= len(params):
            return None
        buf, byte, bit = params[slot.bit_offset]
        if buf is None:
            return byte  # timer, counter or block number
        return decode(slot.type, _read(buf, byte * 8 + bit, slot.bits))
    buf = frame if slot.home == "L" else di
    base = (ar2 & 0x7FFFF) if slot.home == "DI" else 0
    return decode(slot.type, _read(buf, base + slot.bit_offset, slot.bits))


def write_slot(
    slot: Slot, pattern: int, frame: bytearray, di: bytearray, ar2: int, params: list[Any]
) -> None:
    if slot.home == "P":
        buf, byte, bit = params[slot.bit_offset]
        if buf is None:
            raise MonitorError("MON606", target=slot.name, reason=phrase("param_fixed"))
        _write(buf, byte * 8 + bit, slot.bits, pattern)
        return
    buf = frame if slot.home == "L" else di
    base = (ar2 & 0x7FFFF) if slot.home == "DI" else 0
    _write(buf, base + slot.bit_offset, slot.bits, pattern)


def _read(buf: bytearray, at_bits: int, bits: int) -> int | None:
    byte = at_bits >> 3
    if bits == 1:
        return (buf[byte] >> (at_bits & 7)) & 1 if byte < len(buf) else None
    size = bits // 8
    if byte + size > len(buf):
        return None
    return int.from_bytes(buf[byte : byte + size], "big")


def _write(buf: bytearray, at_bits: int, bits: int, pattern: int) -> None:
    byte = at_bits >> 3
    if bits == 1:
        if byte < len(buf):
            mask = 1 << (at_bits & 7)
            buf[byte] = (buf[byte] | mask) if pattern & 1 else (buf[byte] & ~mask & 0xFF)
        return
    size = bits // 8
    if byte + size <= len(buf):
        buf[byte : byte + size] = (pattern & ((1 << bits) - 1)).to_bytes(size, "big")


def breakpoint_indices(info: BlockInfo, location: Location) -> list[int]:
    """The instructions a breakpoint at ``location`` holds before: the starts of a line's
    statements (SCL: a FOR line starts its initialisation, its test and its step), the first
    instruction of an STL line or of a network, or one instruction. MON604 when there is no code."""
    code = info.block.code
    if location.instruction is not None:
        if location.instruction >= len(code):
            raise MonitorError(
                "MON604",
                where=phrase(
                    "where_instruction", block=info.name, instruction=location.instruction
                ),
                hint=phrase("hint_block_has", count=len(code)),
            )
        return [location.instruction]
    if location.network is not None:
        found = [k for k, net in enumerate(info.networks) if net == location.network]
        if not found:
            raise MonitorError(
                "MON604",
                where=phrase("where_network", block=info.name, network=location.network),
                hint="",
            )
        return [found[0]]
    line = location.line
    hits = [k for k, value in enumerate(info.lines) if value == line and info.statement_start[k]]
    if not hits:
        later = sorted({v for v in info.lines if v is not None and line is not None and v > line})
        hint = phrase("hint_next_line", line=later[0]) if later else ""
        raise MonitorError(
            "MON604",
            where=phrase("where_line", file=info.file or info.name, line=line),
            hint=hint,
            next_line=later[0] if later else None,
        )
    if info.language != "scl":  # STL, and the generated STL line of a LAD/FBD element
        return hits[:1]
    return hits

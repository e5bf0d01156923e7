"""A block's variables as the rows of a DB editor: one row per member, nested by depth.

The compiler's layout (``Block.interface``, an instance DB's from its FB) becomes a flat list in
declaration order. STRUCT and UDT members (the IR already expands a UDT's members) follow their
parent one level deeper. Arrays of an elementary type are flattened: the array row comes first,
then one row per element (``Values[1]``, ``Grid[1,2]``, row-major, placed by the S7-300/400 rules:
BOOLs packed, BYTE and CHAR one byte, anything else word-aligned), up to
:data:`MAX_ELEMENTS` elements; a larger array, or an array of STRUCTs or UDTs, is one row. So every
elementary row's ``path`` is exactly what a watch table resolves after ``DB10.``.

``actual`` is the value the compiled DB holds (``Block.data``: its initial values with the
``BEGIN`` section applied), written as a STEP 7 constant (``TRUE``, ``-5``, ``1.5``,
``W#16#00FF``, ``T#2S``); ``initial`` is the declaration's text.
"""

from __future__ import annotations

import datetime
import math
import re
import struct
from collections.abc import Iterator, Mapping
from typing import Literal

from pydantic import BaseModel, Field

from nasaq.ir import Block, BlockKind, Program, Variable
from nasaq.ir.types import (
    ACCU_TYPES,
    ELEMENTARY_BITS,
    LONG_TYPES,
    NUMBER_TYPES,
    TYPE_ALIASES,
    array_shape,
)
from nasaq.workbench.tree import header_line, header_lines

Section = Literal["IN", "OUT", "IN_OUT", "STAT", "TEMP", "RETURN", "DATA"]
MAX_ELEMENTS = 256  # larger arrays stay one row: a DB editor lists, it does not dump memory

_STRING = re.compile(r"^STRING\s*(?:\[\s*(\d+)\s*\])?$", re.IGNORECASE)
_WATCHABLE = ACCU_TYPES | NUMBER_TYPES | LONG_TYPES  # what a watch table resolves to one value
_TEXT = re.compile(r"^W?STRING\s*\[\s*\d+\s*\]$")  # ... and strings (``monitor.long_values``)
_BY_REFERENCE = re.compile(r"^(?:ARRAY|W?STRING|STRUCT|UDT|DATE_AND_TIME$)")  # IN_OUT: a pointer
_EPOCH = datetime.date(1990, 1, 1)


class Member(BaseModel):
    path: str = Field(description="Dotted path from the DB: 'Motor.Speed', 'Values[1]'")
    name: str = Field(description="The last part of the path: 'Speed', 'Values[1]'")
    type: str = Field(description="As declared: 'INT', 'ARRAY[1..4] OF INT', 'STRUCT', 'UDT 5'")
    section: Section = Field(description="DATA for a shared DB's (or UDT's) variables")
    depth: int = Field(description="0 for the block's own variables, +1 per STRUCT/UDT/ARRAY")
    offset: str | None = Field(description="Byte.bit in the DB, '2.0'; null for TEMP/RETURN")
    initial: str | None = Field(description="The declared initial value as written, if any")
    actual: str | None = Field(
        description="The compiled DB's value of an elementary member (null for others)"
    )
    comment: str
    elementary: bool = Field(description="One value a watch table can show and modify")
    file: str | None = Field(default=None, description="File of the declaration, when known")
    line: int | None = Field(default=None, description="Line of the declaration, when known")


def block_members(
    block: Block, program: Program, texts: Mapping[str, str] | None = None
) -> list[Member]:
    """The rows of ``block``'s variables; ``texts`` (file name -> text) adds declaration lines."""
    owner = block
    interface = block.interface
    if block.instance_of is not None:
        fb = program.get(BlockKind.FB, block.instance_of)
        if fb is not None:
            owner = fb
            interface = interface or fb.interface
    data = block.data if block.kind is BlockKind.DB else b""
    text = (texts or {}).get(owner.file)
    lines = _Lines(
        owner.file, text, header_line(owner, header_lines(text)) if text is not None else None
    )
    rows: list[Member] = []
    for variable in interface:
        rows.extend(_rows(variable, variable.name, 0, data, lines))
    return rows


def _rows(
    variable: Variable, path: str, depth: int, data: bytes, lines: _Lines, outer: str = "DATA"
) -> Iterator[Member]:
    kind = _canonical(variable.type)
    section: Section = variable.section or outer  # type: ignore[assignment]
    located = section not in ("TEMP", "RETURN")
    if section == "IN_OUT" and _BY_REFERENCE.match(kind):
        data = b""  # the instance DB holds a pointer to the actual parameter, not its value
    initial = _initial_texts(variable.initial)
    file, line = lines.find(variable.name)
    yield Member(
        path=path,
        name=variable.name,
        type=variable.type,
        section=section,
        depth=depth,
        offset=_offset(variable.offset_bits) if located else None,
        initial=", ".join(initial) if initial else None,
        actual=_actual(kind, variable.offset_bits, variable.size_bits, data) if located else None,
        comment=variable.comment,
        elementary=located
        and (kind in _WATCHABLE or (_TEXT.match(kind) is not None and section != "IN_OUT")),
        file=file,
        line=line,
    )
    inner = _Lines(lines.file, None) if kind.startswith("UDT") else lines  # declared elsewhere
    for member in variable.members:
        yield from _rows(member, f"{path}.{member.name}", depth + 1, data, inner, section)
    shape = array_shape(variable.type)
    if shape is not None:
        for row in _elements(variable, shape, path, depth, data, initial, section):
            yield row.model_copy(update={"file": file, "line": line})


def _elements(
    array: Variable,
    shape: tuple[list[tuple[int, int]], str],
    path: str,
    depth: int,
    data: bytes,
    initial: list[str],
    section: Section,
) -> Iterator[Member]:
    located = section not in ("TEMP", "RETURN")
    dims, element = shape
    kind = _canonical(element)
    bits = ELEMENTARY_BITS.get(kind)
    count = math.prod(high - low + 1 for low, high in dims)
    if bits is None or kind not in _WATCHABLE or count > MAX_ELEMENTS or count <= 0:
        return
    stride = bits if bits <= 8 else (bits + 15) // 16 * 16
    for linear, indices in enumerate(_indices(dims)):
        label = f"{array.name}[{','.join(str(index) for index in indices)}]"
        offset = array.offset_bits + linear * stride
        yield Member(
            path=f"{path[: len(path) - len(array.name)]}{label}",
            name=label,
            type=element,
            section=section,
            depth=depth + 1,
            offset=_offset(offset) if located else None,
            initial=initial[linear] if linear < len(initial) else None,
            actual=_actual(kind, offset, bits, data) if located else None,
            comment="",
            elementary=located,
        )


def _indices(dims: list[tuple[int, int]]) -> Iterator[tuple[int, ...]]:
    if not dims:
        yield ()
        return
    (low, high), rest = dims[0], dims[1:]
    for index in range(low, high + 1):
        for tail in _indices(rest):
            yield (index, *tail)


class _Lines:
    """Finds declarations in the declaring file in order: ``name :`` after the last one found."""

    def __init__(self, file: str, text: str | None, start: int | None = None) -> None:
        self.file = file
        self.lines = text.splitlines() if text is not None else []
        self.cursor = (start or 1) - 1

    def find(self, name: str) -> tuple[str | None, int | None]:
        pattern = re.compile(rf"^\s*\"?{re.escape(name)}\"?\s*:(?!=)", re.IGNORECASE)
        for number in range(self.cursor, len(self.lines)):
            if pattern.match(self.lines[number]):
                self.cursor = number + 1
                return self.file, number + 1
        return None, None


def _initial_texts(initial: object) -> list[str]:
    """The initial value nodes as texts, repetitions (``3 (0)``) expanded."""
    if not isinstance(initial, list):
        return [] if initial is None else [str(initial)]
    texts: list[str] = []
    for node in initial:
        count = getattr(node, "count", None)
        values = getattr(node, "values", None)
        if isinstance(count, int) and isinstance(values, list):
            texts.extend(_initial_texts(values) * count)
        else:
            texts.append(str(getattr(node, "text", node)))
    return texts


def _canonical(type_text: str) -> str:
    upper = " ".join(type_text.strip().upper().split())
    return TYPE_ALIASES.get(upper, upper)


def _offset(bits: int) -> str:
    return f"{bits // 8}.{bits % 8}"


def _actual(kind: str, offset_bits: int, size_bits: int, data: bytes) -> str | None:
    """The compiled DB's value of an elementary member as a STEP 7 constant."""
    start = offset_bits // 8
    if kind.startswith("WSTRING"):  # WORD maximum, WORD length, UTF-16 (``lang.wide_text``)
        if start + 4 > len(data):
            return None
        room = int.from_bytes(data[start : start + 2], "big")
        length = min(int.from_bytes(data[start + 2 : start + 4], "big"), room)
        units = data[start + 4 : start + 4 + 2 * length]
        return "'" + units.decode("utf-16-be", errors="replace") + "'"
    string = _STRING.match(kind)
    if string is not None:
        if start + 2 > len(data):
            return None
        length = min(data[start + 1], data[start], len(data) - start - 2)
        return "'" + data[start + 2 : start + 2 + length].decode("latin-1") + "'"
    bits = ELEMENTARY_BITS.get(kind)
    if bits is None or start + max(1, bits // 8) > len(data):
        return None
    if bits == 1:
        return "TRUE" if data[start] >> (offset_bits % 8) & 1 else "FALSE"
    pattern = int.from_bytes(data[start : start + bits // 8], "big")
    return _constant(kind, pattern, bits)


def _constant(kind: str, pattern: int, bits: int) -> str:
    signed = pattern - (1 << bits) if pattern >> (bits - 1) & 1 else pattern
    if kind in ("INT", "DINT"):
        return str(signed) if kind == "INT" else f"L#{signed}"
    if kind == "REAL":
        return _real(pattern)
    if kind == "BYTE":
        return f"B#16#{pattern:02X}"
    if kind == "WORD":
        return f"W#16#{pattern:04X}"
    if kind == "DWORD":
        return f"DW#16#{pattern:08X}"
    if kind == "CHAR":
        return "'" + chr(pattern) + "'" if 32 <= pattern < 127 else f"B#16#{pattern:02X}"
    if kind == "WCHAR":  # a UTF-16 code unit (``lang.wide_text``)
        printable = chr(pattern).isprintable() and not 0xD800 <= pattern <= 0xDFFF
        return f"WCHAR#'{chr(pattern)}'" if printable else f"WCHAR#16#{pattern:04X}"
    if kind == "TIME":
        return "T#" + ("-" if signed < 0 else "") + _duration(abs(signed))
    if kind == "S5TIME":
        return "S5T#" + _duration(_s5time_ms(pattern))
    if kind == "DATE":
        return f"D#{_EPOCH + datetime.timedelta(days=pattern):%Y-%m-%d}"
    if kind == "TIME_OF_DAY":
        seconds, ms = divmod(pattern % 86_400_000, 1000)
        return f"TOD#{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}.{ms:03d}"
    if kind in NUMBER_TYPES:
        return str(pattern)
    return f"16#{pattern:0{max(1, bits // 4)}X}"


def _real(pattern: int) -> str:
    value: float = struct.unpack(">f", pattern.to_bytes(4, "big"))[0]
    if math.isnan(value) or math.isinf(value):
        return "NaN" if math.isnan(value) else ("+Inf" if value > 0 else "-Inf")
    text = f"{value:.7g}"
    return text if any(mark in text for mark in ".e") else f"{text}.0"


def _duration(ms: int) -> str:
    if ms == 0:
        return "0MS"
    parts = []
    for unit, size in (("D", 86_400_000), ("H", 3_600_000), ("M", 60_000), ("S", 1000)):
        if ms >= size:
            parts.append(f"{ms // size}{unit}")
            ms %= size
    if ms:
        parts.append(f"{ms}MS")
    return "".join(parts)


def _s5time_ms(pattern: int) -> int:
    digits = pattern & 0xFFF
    count = (digits >> 8 & 15) * 100 + (digits >> 4 & 15) * 10 + (digits & 15)
    return count * (10, 100, 1000, 10000)[pattern >> 12 & 3]

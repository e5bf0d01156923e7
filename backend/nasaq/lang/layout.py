"""Standard (non-optimized) S7-300/400 memory layout of variables, structures and instances.

Rules, as STEP 7 lays out DBs, instance DBs and the L stack:
- BOOLs are packed: each takes the next free bit; consecutive BOOLs share a byte.
- BYTE and CHAR (and the S7-1500's SINT and USINT) start on the next byte boundary.
- Every other type (WORD, INT, DINT, REAL, TIME, S5TIME, DATE, TOD, DT, STRING, ARRAY, STRUCT,
  UDT, FB multi-instance, POINTER, ANY; the S7-1500's UINT, UDINT and the 8-byte LINT, ULINT,
  LREAL, LWORD, LTIME as TIA lays out a standard block) starts on an even byte.
- STRUCT (and UDT, and FB instance) sizes are rounded up to an even number of bytes; a STRING
  or an ARRAY also occupies whole words, so whatever follows starts on an even byte again.
- ARRAY elements: BOOLs are packed bits, BYTE/CHAR one byte each, every other element starts on
  an even byte (its size rounded up to a word).
- STRING[n] takes n + 2 bytes (maximum length, current length, characters).
- An FB instance holds IN, then OUT, then IN_OUT, then STAT, each section starting on an even
  byte. An IN_OUT of a structured type (STRING, ARRAY, STRUCT, UDT, DT) holds a 6-byte DB
  pointer instead of the value.
- VAR_TEMP is laid out the same way in the block's L stack frame, starting at L 0.0.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from nasaq.ir import Variable
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
    is_reference,
    type_text,
)

SECTION_ORDER = ("IN", "OUT", "IN_OUT", "STAT")

# What a BlockType stands for: a UDT's structure, or an FB's instance sections in order.
Expansion = StructType | list[tuple[str, list[Field]]] | None


class RecursiveTypeError(ValueError):
    """A UDT or FB contains itself (directly or through other types)."""

    def __init__(self, block: BlockType) -> None:
        super().__init__(f"{block.kind} {block.number}")
        self.block = block


@dataclass(slots=True)
class Slot:
    """A placed variable: offsets in bits from the start of its area (DB, instance, L stack)."""

    name: str
    type: DataType
    offset_bits: int
    size_bits: int
    section: str = ""
    initial: object = None
    comment: str = ""
    by_reference: bool = False  # FB IN_OUT of a structured type: the slot holds a pointer
    members: list[Slot] = field(default_factory=list)
    # members by upper-case name, with the list they were indexed from
    _index: tuple[list[Slot], dict[str, Slot]] | None = field(
        default=None, repr=False, compare=False
    )

    def member(self, name: str) -> Slot | None:
        """The member called ``name`` (case-insensitive; the first, should two be)."""
        if self._index is None or self._index[0] is not self.members:
            by_name: dict[str, Slot] = {}
            for slot in self.members:
                by_name.setdefault(slot.name.upper(), slot)
            self._index = (self.members, by_name)
        return self._index[1].get(name.upper())


def _even(bits: int) -> int:
    return (bits + 15) // 16 * 16


def _byte(bits: int) -> int:
    return (bits + 7) // 8 * 8


def _is_bool(data_type: DataType) -> bool:
    return isinstance(data_type, Elementary) and data_type.name == "BOOL"


_BYTE_TYPES = frozenset({"BYTE", "CHAR", "SINT", "USINT"})


def _is_byte(data_type: DataType) -> bool:
    return isinstance(data_type, Elementary) and data_type.name in _BYTE_TYPES


class Layout:
    """Computes sizes and offsets; ``expand`` tells what a UDT or FB type contains."""

    def __init__(self, expand: Callable[[BlockType], Expansion]) -> None:
        self.expand = expand
        self._sizes: dict[BlockType, int] = {}
        self._busy: set[BlockType] = set()

    # ---- sizes ------------------------------------------------------------------------------

    def size_bits(self, data_type: DataType) -> int:
        if isinstance(data_type, Elementary):
            return data_type.bits
        if isinstance(data_type, StringType):
            return _even((data_type.length + 2) * data_type.char_bytes * 8)
        if isinstance(data_type, ArrayType):
            return _even(data_type.count * self.stride(data_type.element))
        if isinstance(data_type, StructType):
            return _even(self._place(data_type.fields, 0, "", expand=False)[1])
        return self._block_size(data_type)

    def stride(self, element: DataType) -> int:
        """Distance in bits between two array elements."""
        if _is_bool(element):
            return 1
        if _is_byte(element):
            return 8
        return _even(self.size_bits(element))

    def _block_size(self, block: BlockType) -> int:
        if block in self._sizes:
            return self._sizes[block]
        _slots, size = self._expand_block(block, 0, expand=False)
        self._sizes[block] = size
        return size

    def _expand_block(self, block: BlockType, start: int, expand: bool) -> tuple[list[Slot], int]:
        if block in self._busy:
            raise RecursiveTypeError(block)
        self._busy.add(block)
        try:
            found = self.expand(block)
            if found is None:
                return [], 0
            if isinstance(found, StructType):
                slots, end = self._place(found.fields, start, "", expand)
                return slots, _even(end - start)
            return self._instance(found, start, expand)
        finally:
            self._busy.discard(block)

    # ---- placement --------------------------------------------------------------------------

    def _align(self, cursor: int, data_type: DataType) -> int:
        if _is_bool(data_type):
            return cursor
        if _is_byte(data_type):
            return _byte(cursor)
        return _even(cursor)

    def _place(
        self, fields: tuple[Field, ...] | list[Field], start: int, section: str, expand: bool
    ) -> tuple[list[Slot], int]:
        slots: list[Slot] = []
        cursor = start
        for declared in fields:
            cursor = self._align(cursor, declared.type)
            slot = self._slot(declared, cursor, section, expand)
            slots.append(slot)
            cursor += slot.size_bits
        return slots, cursor

    def _slot(self, declared: Field, offset: int, section: str, expand: bool) -> Slot:
        data_type = declared.type
        slot = Slot(
            declared.name,
            data_type,
            offset,
            0,
            section,
            declared.initial,
            declared.comment,
        )
        if isinstance(data_type, StructType):
            members, end = self._place(data_type.fields, offset, "", expand)
            slot.size_bits = _even(end - offset)
            slot.members = members if expand else []
        elif isinstance(data_type, BlockType):
            members, size = self._expand_block(data_type, offset, expand)
            slot.size_bits = size
            slot.members = members if expand else []
        else:
            slot.size_bits = self.size_bits(data_type)
        return slot

    def place(self, fields: list[Field], start_bits: int = 0, section: str = "") -> list[Slot]:
        """Slots for ``fields`` laid out from ``start_bits`` (members expanded)."""
        return self._place(fields, start_bits, section, expand=True)[0]

    def end_bits(self, fields: list[Field], start_bits: int = 0) -> int:
        """Where the next variable could start after ``fields``, rounded to an even byte."""
        return _even(self._place(fields, start_bits, "", expand=False)[1])

    def _instance(
        self, sections: list[tuple[str, list[Field]]], start: int, expand: bool
    ) -> tuple[list[Slot], int]:
        slots: list[Slot] = []
        cursor = start
        for section in SECTION_ORDER:
            fields = [declared for name, group in sections if name == section for declared in group]
            if not fields:
                continue
            cursor = _even(cursor)
            for declared in fields:
                if section == "IN_OUT" and is_reference(declared.type):
                    cursor = _even(cursor)
                    slot = Slot(
                        declared.name, declared.type, cursor, 48, section, by_reference=True
                    )
                    slot.comment = declared.comment
                else:
                    cursor = self._align(cursor, declared.type)
                    slot = self._slot(declared, cursor, section, expand)
                slots.append(slot)
                cursor += slot.size_bits
        return slots, _even(cursor - start)

    def instance(self, sections: list[tuple[str, list[Field]]]) -> tuple[list[Slot], int]:
        """An FB's instance data: slots from offset 0 and the size in bits."""
        return self._instance(sections, 0, expand=True)

    def element(self, array: Slot, indices: list[int]) -> Slot | None:
        """The slot of ``array[indices]``; None when an index is out of bounds."""
        data_type = array.type
        if not isinstance(data_type, ArrayType) or len(indices) != len(data_type.dims):
            return None
        linear = 0
        for index, (low, high) in zip(indices, data_type.dims, strict=True):
            if not low <= index <= high:
                return None
            linear = linear * (high - low + 1) + (index - low)
        offset = array.offset_bits + linear * self.stride(data_type.element)
        name = f"{array.name}[{', '.join(str(i) for i in indices)}]"
        return self._slot(Field(name, data_type.element), offset, "", expand=True)


def variables(slots: list[Slot]) -> list[Variable]:
    """The IR view of placed slots (``Block.interface``)."""
    return [
        Variable(
            name=slot.name,
            type=type_text(slot.type),
            section=slot.section,
            offset_bits=slot.offset_bits,
            size_bits=slot.size_bits,
            initial=slot.initial,
            comment=slot.comment,
            members=variables(slot.members),
        )
        for slot in slots
    ]

"""S7-300/400 data types as the compilers see them (STL now, SCL later).

Elementary types have fixed sizes; STRING[n], ARRAY (any number of dimensions), STRUCT, UDTs
and FB/SFB instances (multi-instances) are built from them. UDT and FB types are referred to
by number (``BlockType``) and expanded through the program, so a UDT used in many places is
declared once, as in STEP 7.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.ir import Width
from nasaq.ir.types import ACCU_TYPES, ELEMENTARY_BITS, TYPE_ALIASES

# The sizes live with the IR, where the CPU reads them too.
ALIASES = TYPE_ALIASES
LOADABLE = ACCU_TYPES
# Parameter types an FB stores as a pointer when passed IN_OUT (and an FC always by reference).
REFERENCE_TYPES = ("STRING", "ARRAY", "STRUCT", "UDT", "DATE_AND_TIME")


@dataclass(frozen=True, slots=True)
class Elementary:
    name: str

    @property
    def bits(self) -> int:
        return ELEMENTARY_BITS[self.name]


@dataclass(frozen=True, slots=True)
class StringType:
    """STRING[n] (1-byte characters) or, ``wide``, WSTRING[n] (2-byte UTF-16 code units): the
    maximum and the current length, each one character wide, then n characters."""

    length: int = 254
    wide: bool = False

    @property
    def char_bytes(self) -> int:
        return 2 if self.wide else 1

    @property
    def name(self) -> str:
        return "WSTRING" if self.wide else "STRING"


@dataclass(frozen=True, slots=True)
class ArrayType:
    dims: tuple[tuple[int, int], ...]
    element: DataType

    @property
    def count(self) -> int:
        total = 1
        for low, high in self.dims:
            total *= high - low + 1
        return total


@dataclass(frozen=True, slots=True)
class Field:
    """A declared variable or struct member; ``initial`` keeps the declared initial value."""

    name: str
    type: DataType
    initial: object = None
    comment: str = ""


@dataclass(frozen=True, slots=True)
class StructType:
    fields: tuple[Field, ...]


@dataclass(frozen=True, slots=True)
class BlockType:
    """A UDT (``UDT 5``) or an FB/SFB instance (``FB 2`` as a multi-instance)."""

    kind: str  # "UDT", "FB" or "SFB"
    number: int


DataType = Elementary | StringType | ArrayType | StructType | BlockType


def elementary(name: str) -> Elementary | StringType | None:
    upper = ALIASES.get(name.upper(), name.upper())
    if upper == "STRING":
        return StringType()
    if upper == "WSTRING":
        return StringType(wide=True)
    return Elementary(upper) if upper in ELEMENTARY_BITS else None


_WIDTHS = {name: Width(ELEMENTARY_BITS[name]) for name in LOADABLE}


def width_of(data_type: DataType) -> Width | None:
    """The access width of a type that fits an accumulator, else None."""
    return _WIDTHS.get(data_type.name) if isinstance(data_type, Elementary) else None


def type_text(data_type: DataType) -> str:
    """The declaration as STEP 7 writes it: ``INT``, ``STRING[10]``, ``ARRAY[1..4] OF INT``."""
    if isinstance(data_type, Elementary):
        return data_type.name
    if isinstance(data_type, StringType):
        return f"{data_type.name}[{data_type.length}]"
    if isinstance(data_type, ArrayType):
        dims = ", ".join(f"{low}..{high}" for low, high in data_type.dims)
        return f"ARRAY[{dims}] OF {type_text(data_type.element)}"
    if isinstance(data_type, StructType):
        shown = getattr(data_type, "text", None)  # VARIANT, ARRAY[*] (``scl.descriptor``)
        return shown if isinstance(shown, str) else "STRUCT"
    return f"{data_type.kind} {data_type.number}"


def is_reference(data_type: DataType) -> bool:
    """Types passed by reference (a pointer) when they are FB IN_OUT or FC parameters."""
    if isinstance(data_type, Elementary):
        return data_type.name == "DATE_AND_TIME"
    return isinstance(data_type, StringType | ArrayType | StructType) or (
        isinstance(data_type, BlockType) and data_type.kind == "UDT"
    )

"""VARIANT and ``ARRAY[*]`` parameters (S7-1200/1500) as Nasaq represents them: a descriptor.

TIA Portal passes a VARIANT or an ``ARRAY[*]`` parameter as a pointer that knows the type of
what it points at; the user never sees its bytes. Nasaq lowers SCL to S7-300/400 STL, so the
pointer becomes a visible structure, the *descriptor*, an ANY pointer as STEP 7 builds it
followed by what TIA's pointer knows besides (70 bytes, big-endian as everything in S7):

======  ========  =========================================================================
byte    field     contents
======  ========  =========================================================================
0       ID        16#10, as in an ANY (S7 syntax id)
1       TYPE      ANY type code of the variable, or of its elements for an array (``CODES``);
                  a STRUCT or UDT is 16#02 BYTE as in STEP 7's ANY
2       COUNT     repetition factor of that type, as in an ANY (a structure: its bytes)
4       DB        DB number of the variable (0: not in a DB)
6       PTR       area-crossing pointer to the variable's first bit (16#84 DB, 16#87 the
                  caller's local data, 16#81/82/83 I/Q/M)
10      UDT       number of the UDT of the variable or of its elements (0: no UDT)
12      DIMS      0: no array, else its number of dimensions (at most ``MAX_DIMS``)
14      ELEMENTS  number of array elements (1 for a variable that is no array)
18      BYTES     size of the variable in bytes
22      BOUNDS    lower and upper bound of each dimension (DINT pairs, ``MAX_DIMS`` of them)
======  ========  =========================================================================

The caller builds the descriptor in a temporary before the call (``lower.variant``) and
passes it as STEP 7 passes a structure: an FC gets a DB pointer to it, an FB's IN copies
it into the instance, an FB's IN_OUT keeps a DB pointer to it. A VARIANT parameter passed on
to another VARIANT (or ``ARRAY[*]``) parameter is passed as it is.

``OpenArray`` and ``VariantParam`` are the descriptor's ``StructType`` (so layouts, the STL
interface and parameter passing see the structure) carrying the declared meaning (element
type and number of dimensions) for the checker and the code generator.
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
)

MAX_DIMS = 6  # TIA Portal: arrays have at most 6 dimensions

_E = Elementary
FIELDS: tuple[Field, ...] = (
    Field("ID", _E("BYTE")),
    Field("TYPE", _E("BYTE")),
    Field("COUNT", _E("WORD")),
    Field("DB", _E("WORD")),
    Field("PTR", _E("DWORD")),
    Field("UDT", _E("WORD")),
    Field("DIMS", _E("INT")),
    Field("ELEMENTS", _E("DINT")),
    Field("BYTES", _E("DINT")),
    Field("BOUNDS", ArrayType(((1, 2 * MAX_DIMS),), _E("DINT"))),
)
# Byte offsets of the fields (the layout above; STEP 7 aligns WORDs, all are even here).
OFFSETS = {"ID": 0, "TYPE": 1, "COUNT": 2, "DB": 4, "PTR": 6, "UDT": 10, "DIMS": 12}
OFFSETS |= {"ELEMENTS": 14, "BYTES": 18, "BOUNDS": 22}
SIZE = 22 + 8 * MAX_DIMS

# ANY type codes (STEP 7's, ``nasaq.cpu.pointers.ANY_TYPES``), and for the S7-1200/1500 types
# Nasaq's own numbers from 16#30 up (TIA's VARIANT knows them; its codes are not published).
CODES: dict[str, int] = {
    "BOOL": 0x01,
    "BYTE": 0x02,
    "CHAR": 0x03,
    "WORD": 0x04,
    "INT": 0x05,
    "DWORD": 0x06,
    "DINT": 0x07,
    "REAL": 0x08,
    "DATE": 0x09,
    "TIME_OF_DAY": 0x0A,
    "TIME": 0x0B,
    "S5TIME": 0x0C,
    "DATE_AND_TIME": 0x0E,
    "STRING": 0x13,
    "SINT": 0x30,
    "USINT": 0x31,
    "UINT": 0x32,
    "UDINT": 0x33,
    "LINT": 0x34,
    "ULINT": 0x35,
    "LREAL": 0x36,
    "LWORD": 0x37,
    "LTIME": 0x38,
    "WCHAR": 0x39,
    "WSTRING": 0x3A,
    "DTL": 0x3B,
}
STRUCTURE = 0x02  # a STRUCT or UDT: BYTEs, as STEP 7's ANY names it


@dataclass(frozen=True, slots=True)
class OpenArray(StructType):
    """``ARRAY[*, ...] OF element``: ``dims`` dimensions whose bounds come with the actual."""

    element: DataType
    dims: int

    @property
    def text(self) -> str:
        return describe(self)


@dataclass(frozen=True, slots=True)
class VariantParam(StructType):
    """A VARIANT parameter (IN, OUT or IN_OUT of an FC or FB)."""

    @property
    def text(self) -> str:
        return "VARIANT"


@dataclass(frozen=True, slots=True)
class DbAnyType(Elementary):
    """DB_ANY: the number of a data block, a UINT (TIA Portal converts it to and from
    UINT with ``DB_ANY_TO_UINT``/``UINT_TO_DB_ANY``)."""


DB_ANY = DbAnyType("UINT")


def open_array(element: DataType, dims: int) -> OpenArray:
    return OpenArray(FIELDS, element, dims)


VARIANT = VariantParam(FIELDS)


def is_descriptor(data_type: object) -> bool:
    return isinstance(data_type, OpenArray | VariantParam)


def type_code(data_type: DataType) -> int:
    """The descriptor's TYPE of a variable (of its elements for an array)."""
    if isinstance(data_type, ArrayType):
        data_type = data_type.element
    if isinstance(data_type, Elementary):
        return CODES.get(data_type.name, STRUCTURE)
    if isinstance(data_type, StringType):
        return CODES[data_type.name]
    return STRUCTURE


def udt_number(data_type: DataType) -> int:
    if isinstance(data_type, ArrayType):
        data_type = data_type.element
    if isinstance(data_type, BlockType) and data_type.kind == "UDT":
        return data_type.number
    return 0


def describe(data_type: DataType) -> str:
    """How messages name a descriptor type."""
    if isinstance(data_type, OpenArray):
        from nasaq.lang.types import type_text

        stars = ", ".join("*" for _ in range(data_type.dims))
        return f"ARRAY[{stars}] OF {type_text(data_type.element)}"
    return "VARIANT"

"""The IEC functions of STEP 7's Standard Library ("IEC Function Blocks"): the FCs that work on
STRING and DATE_AND_TIME values, with their numbers and interfaces as Siemens ships them
(System Software for S7-300/400, System and Standard Functions, chapter "IEC Functions").

Only the interface is here: the compilers use it (a CALL of ``"CONCAT"`` or ``FC 2`` is checked
against it, the SCL compiler calls these FCs for STRING and DATE_AND_TIME operations);
what the functions do belongs to the CPU (``nasaq.cpu.iec_library``).

Every parameter is an input; the result is RET_VAL. STRING parameters are ``STRING`` (254
characters), which takes a STRING of any length (an FC gets a pointer to it).

**Numbers.** A program that calls a library FC and does not define a block of that name gets the
library block added by the compiler (STEP 7: copied from the Standard Library into the block
folder). Its number is the library's own (CONCAT FC 2), or the one the symbol table gives the
name; when the program has its own block with that number, the library block takes the lowest
number from ``RELOCATED_BASE`` up that no block and no symbol uses (``nasaq.lang.stl.library``).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from nasaq.lang.types import DataType, Elementary, StringType

STRING = StringType(254)
DT = Elementary("DATE_AND_TIME")
INT = Elementary("INT")
DINT = Elementary("DINT")
REAL = Elementary("REAL")
TIME = Elementary("TIME")
BOOL = Elementary("BOOL")
DATE = Elementary("DATE")
TOD = Elementary("TIME_OF_DAY")

RELOCATED_BASE = 1000  # where a library FC goes when its number is the program's own block
FAMILY = "IEC"  # the FAMILY header property of the library blocks (as Siemens ships them)


@dataclass(frozen=True, slots=True)
class LibraryFunction:
    """``inputs``: (name, type) in interface order; ``result``: the type of RET_VAL;
    ``others``: (section ``OUT``/``IN_OUT``, name, type) after the inputs (TIA's VAL_STRG ...,
    ``nasaq.lang.text_instructions``; the IEC library's FCs have none)."""

    name: str
    number: int
    inputs: tuple[tuple[str, DataType], ...]
    result: DataType
    title: str
    others: tuple[tuple[str, str, DataType], ...] = ()


def _fc(
    number: int, name: str, title: str, result: DataType, *inputs: tuple[str, DataType]
) -> LibraryFunction:
    return LibraryFunction(name, number, inputs, result, title)


_STRING_COMPARISONS = [
    (10, "EQ_STRNG", "S1 = S2"),
    (13, "GE_STRNG", "S1 >= S2"),
    (15, "GT_STRNG", "S1 > S2"),
    (19, "LE_STRNG", "S1 <= S2"),
    (24, "LT_STRNG", "S1 < S2"),
    (29, "NE_STRNG", "S1 <> S2"),
]
_DT_COMPARISONS = [
    (9, "EQ_DT", "DT1 = DT2"),
    (12, "GE_DT", "DT1 >= DT2"),
    (14, "GT_DT", "DT1 > DT2"),
    (18, "LE_DT", "DT1 <= DT2"),
    (23, "LT_DT", "DT1 < DT2"),
    (28, "NE_DT", "DT1 <> DT2"),
]

_ALL = [
    _fc(1, "AD_DT_TM", "DATE_AND_TIME + TIME", DT, ("T", DT), ("D", TIME)),
    _fc(2, "CONCAT", "IN1 followed by IN2", STRING, ("IN1", STRING), ("IN2", STRING)),
    _fc(3, "D_TOD_DT", "DATE and TIME_OF_DAY to DATE_AND_TIME", DT, ("IN1", DATE), ("IN2", TOD)),
    _fc(
        4,
        "DELETE",
        "IN without L characters from P",
        STRING,
        ("IN", STRING),
        ("L", INT),
        ("P", INT),
    ),
    _fc(5, "DI_STRNG", "DINT to STRING", STRING, ("I", DINT)),
    _fc(6, "DT_DATE", "the DATE of a DATE_AND_TIME", DATE, ("IN", DT)),
    _fc(7, "DT_DAY", "the weekday of a DATE_AND_TIME (1 = Sunday)", INT, ("IN", DT)),
    _fc(8, "DT_TOD", "the TIME_OF_DAY of a DATE_AND_TIME", TOD, ("IN", DT)),
    _fc(11, "FIND", "the position of IN2 in IN1", INT, ("IN1", STRING), ("IN2", STRING)),
    _fc(16, "I_STRNG", "INT to STRING", STRING, ("I", INT)),
    _fc(
        17,
        "INSERT",
        "IN2 inserted into IN1 after P",
        STRING,
        ("IN1", STRING),
        ("IN2", STRING),
        ("P", INT),
    ),
    _fc(20, "LEFT", "the first L characters of IN", STRING, ("IN", STRING), ("L", INT)),
    _fc(21, "LEN", "the length of S", INT, ("S", STRING)),
    _fc(26, "MID", "L characters of IN from P", STRING, ("IN", STRING), ("L", INT), ("P", INT)),
    _fc(30, "R_STRNG", "REAL to STRING", STRING, ("IN", REAL)),
    _fc(
        31,
        "REPLACE",
        "L characters of IN1 from P replaced by IN2",
        STRING,
        ("IN1", STRING),
        ("IN2", STRING),
        ("L", INT),
        ("P", INT),
    ),
    _fc(32, "RIGHT", "the last L characters of IN", STRING, ("IN", STRING), ("L", INT)),
    _fc(34, "SB_DT_DT", "DATE_AND_TIME - DATE_AND_TIME", TIME, ("T1", DT), ("T2", DT)),
    _fc(35, "SB_DT_TM", "DATE_AND_TIME - TIME", DT, ("T", DT), ("D", TIME)),
    _fc(37, "STRNG_DI", "STRING to DINT", DINT, ("S", STRING)),
    _fc(38, "STRNG_I", "STRING to INT", INT, ("S", STRING)),
    _fc(39, "STRNG_R", "STRING to REAL", REAL, ("S", STRING)),
    *[
        _fc(n, name, title, BOOL, ("S1", STRING), ("S2", STRING))
        for n, name, title in _STRING_COMPARISONS
    ],
    *[_fc(n, name, title, BOOL, ("DT1", DT), ("DT2", DT)) for n, name, title in _DT_COMPARISONS],
]

# WSTRING (TIA, S7-1200/1500): the STRING functions and comparisons again, with WSTRING where
# they take or give a STRING, as hidden FCs ``LEN_WSTRING``, ``EQ_WSTRING`` ... (TIA Portal
# overloads the names; ``wide_variant`` picks these when an input is a WSTRING).
WSTRING = StringType(254, wide=True)
WIDE_BASE = 660
_WIDE_SOURCES = ("CONCAT", "DELETE", "FIND", "INSERT", "LEFT", "LEN", "MID", "REPLACE", "RIGHT")
WIDE: dict[str, str] = {
    **{name: f"{name}_WSTRING" for name in _WIDE_SOURCES},
    **{name: name.replace("_STRNG", "_WSTRING") for _n, name, _t in _STRING_COMPARISONS},
}


def _widened(source: LibraryFunction, number: int) -> LibraryFunction:
    def wide(data_type: DataType) -> DataType:
        return WSTRING if data_type == STRING else data_type

    inputs = tuple((name, wide(data_type)) for name, data_type in source.inputs)
    title = f"{source.title} (WSTRING)"
    return LibraryFunction(WIDE[source.name], number, inputs, wide(source.result), title)


_BY_NAME = {function.name: function for function in _ALL}
_ALL += [
    _widened(_BY_NAME[name], number)
    for number, name in enumerate(sorted(WIDE, key=WIDE.__getitem__), start=WIDE_BASE)
]
_ALL += [  # the conversions between the two (``nasaq.cpu.iec_library`` says how)
    _fc(675, "STRING_TO_WSTRING", "STRING to WSTRING", WSTRING, ("IN", STRING)),
    _fc(676, "WSTRING_TO_STRING", "WSTRING to STRING", STRING, ("IN", WSTRING)),
]
WIDE_FUNCTIONS = frozenset([*WIDE.values(), "STRING_TO_WSTRING", "WSTRING_TO_STRING"])

FUNCTIONS: dict[str, LibraryFunction] = {function.name: function for function in _ALL}
"""The library FCs by name (upper case)."""
BY_NUMBER: dict[int, LibraryFunction] = {function.number: function for function in _ALL}
"""The library FCs by their number in the Standard Library."""

# The functions S7-SCL calls for an operator on STRING (comparisons) and DATE_AND_TIME values.
STRING_COMPARE = {
    "=": "EQ_STRNG",
    "<>": "NE_STRNG",
    "<": "LT_STRNG",
    ">": "GT_STRNG",
    "<=": "LE_STRNG",
    ">=": "GE_STRNG",
}
DT_COMPARE = {"=": "EQ_DT", "<>": "NE_DT", "<": "LT_DT", ">": "GT_DT", "<=": "LE_DT", ">=": "GE_DT"}
DT_ARITHMETIC = {
    ("+", "TIME"): "AD_DT_TM",
    ("-", "TIME"): "SB_DT_TM",
    ("-", "DATE_AND_TIME"): "SB_DT_DT",
}


WSTRING_COMPARE = {op: WIDE[name] for op, name in STRING_COMPARE.items()}


def wide_variant(name: str, values: Iterable[object]) -> str:
    """``name``'s WSTRING version when one of the input types ``values`` is a WSTRING."""
    wide = WIDE.get(name)
    if wide is not None and any(isinstance(v, StringType) and v.wide for v in values):
        return wide
    return name


def function(name: str) -> LibraryFunction | None:
    return FUNCTIONS.get(name.upper())


def _with_long_library() -> None:
    """The hidden FCs of the S7-1200/1500 types (``nasaq.lang.long_library``) are library FCs
    too: added to the program when called, their bodies Python."""
    from nasaq.lang.character_arrays import functions as character_arrays
    from nasaq.lang.long_library import functions
    from nasaq.lang.number_text import functions as number_text
    from nasaq.lang.text_instructions import functions as text_instructions

    # and TIA's INT_TO_STRING ..., VAL_STRG, ATH ...
    for found in [*functions(), *number_text(), *text_instructions(), *character_arrays()]:
        FUNCTIONS[found.name] = found
        BY_NUMBER[found.number] = found


_with_long_library()

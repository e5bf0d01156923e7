"""What the checker knows about the value of an expression, and S7-SCL's conversion rules.

A value's type is a ``nasaq.lang.types`` type, or one of the markers below: ``ERROR`` (the
expression is wrong and was reported: nothing built on it is reported again), ``ANYTHING`` (a
value the checker cannot type yet, accepted everywhere), and untyped constants that take their
type from where they are used (``IntConst`` for ``5``, ``BitsConst`` for ``16#FF``, ``TimeConst``
for ``T#2s``, ``CharsConst`` for ``'A'``).

Implicit conversions (S7-SCL class A, seeds-003b §2.15) go one way, within one family:
BOOL → BYTE → WORD → DWORD, INT → DINT → REAL, CHAR → STRING. Everything else (class B: WORD ↔
INT, DINT → INT, REAL → INT ...) needs the explicit ``*_TO_*`` function.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache, lru_cache
from typing import Any

from nasaq.ir import BlockKind
from nasaq.lang import s7_1500_types as s7_1500
from nasaq.lang.types import ArrayType, BlockType, DataType, Elementary, StringType, type_text
from nasaq.lang.wide_text import WCHAR_CONVERSIONS


@dataclass(frozen=True, slots=True)
class Special:
    name: str


ERROR = Special("ERROR")
ANYTHING = Special("ANY")


@dataclass(frozen=True, slots=True)
class IntConst:
    """A decimal integer constant: INT when it fits, else DINT; also REAL, and BOOL for 0/1."""

    value: int


@dataclass(frozen=True, slots=True)
class BitsConst:
    """``16#FF``, ``2#0101``, ``8#17``: an integer constant written in another base (S7-SCL
    manual §9.1.3): in arithmetic and next to integers an INT (DINT when it does not fit), next
    to a bit string or in a logic operation the smallest bit string that holds it; assigned,
    any bit string or integer it fits (``integer_of``)."""

    value: int


def integer_of(value: BitsConst) -> str | None:
    """The integer type a based constant is in arithmetic: INT, else DINT; None beyond DINT."""
    if value.value <= RANGES["INT"][1]:
        return "INT"
    return "DINT" if value.value <= RANGES["DINT"][1] else None


@dataclass(frozen=True, slots=True)
class TimeConst:
    """``T#..``: a TIME, which may also be assigned to an S5TIME (rounded to its time base)."""

    ms: int


@dataclass(frozen=True, slots=True)
class CharsConst:
    """``'...'``: a CHAR when it has one character, else a STRING."""

    length: int


@dataclass(frozen=True, slots=True)
class DbRef:
    """A data block as an operand base (``DB10``, a DB's name, ``WORD_TO_BLOCK_DB(w)``);
    ``number`` None when only known at run time."""

    number: int | None


@dataclass(frozen=True, slots=True)
class BlockRef:
    """An FB or FC named as a callee."""

    kind: BlockKind
    number: int


Type = DataType | Special | IntConst | BitsConst | TimeConst | CharsConst | DbRef | BlockRef

BITS = ("BOOL", "BYTE", "WORD", "DWORD")
NUMBERS = ("INT", "DINT", "REAL")
INTEGERS = ("INT", "DINT")
TEXT = ("CHAR", "STRING")
RANGES = {"INT": (-(2**15), 2**15 - 1), "DINT": (-(2**31), 2**31 - 1)}
RANGES |= {name: s7_1500.INTEGER_RANGES[name] for name in s7_1500.NEW_INTEGERS}  # SINT ... ULINT
BIT_LIMITS = {"BOOL": 1, "BYTE": 0xFF, "WORD": 0xFFFF, "DWORD": 0xFFFFFFFF}
BIT_LIMITS["LWORD"] = s7_1500.LWORD_LIMIT
SHORT = {"TIME_OF_DAY": "TOD", "DATE_AND_TIME": "DT"}

# TIA Portal's conversions between BOOL, BYTE, WORD, DWORD, INT, DINT and CHAR that S7-SCL
# Classic lacks: integers from and to bit strings of another width (zero-filled from a bit
# string, the low bits kept into a narrower one, an INT sign-extended into a DWORD), BOOL as 0/1.
TIA_CONVERSIONS = (
    "BOOL_TO_INT",
    "BOOL_TO_DINT",
    "BYTE_TO_INT",
    "BYTE_TO_DINT",
    "WORD_TO_DINT",
    "DWORD_TO_INT",
    "INT_TO_BYTE",
    "INT_TO_DWORD",
    "DINT_TO_BYTE",
    "DINT_TO_WORD",
    "CHAR_TO_DINT",
    "DINT_TO_CHAR",
)
# The explicit conversion functions of S7-SCL (class A and class B, seeds-003b §2.15).
CONVERSIONS = frozenset(
    [
        "BOOL_TO_BYTE",
        "BOOL_TO_DWORD",
        "BOOL_TO_WORD",
        "BYTE_TO_DWORD",
        "BYTE_TO_WORD",
        "CHAR_TO_STRING",
        "DINT_TO_REAL",
        "INT_TO_DINT",
        "INT_TO_REAL",
        "WORD_TO_DWORD",
        "BYTE_TO_BOOL",
        "BYTE_TO_CHAR",
        "CHAR_TO_BYTE",
        "CHAR_TO_INT",
        "DATE_TO_DINT",
        "DINT_TO_DATE",
        "DINT_TO_DWORD",
        "DINT_TO_INT",
        "DINT_TO_TIME",
        "DINT_TO_TOD",
        "DWORD_TO_BOOL",
        "DWORD_TO_BYTE",
        "DWORD_TO_DINT",
        "DWORD_TO_REAL",
        "DWORD_TO_WORD",
        "INT_TO_CHAR",
        "INT_TO_WORD",
        "REAL_TO_DINT",
        "REAL_TO_DWORD",
        "REAL_TO_INT",
        "STRING_TO_CHAR",
        "TIME_TO_DINT",
        "TOD_TO_DINT",
        "WORD_TO_BOOL",
        "WORD_TO_BYTE",
        "WORD_TO_INT",
        "WORD_TO_BLOCK_DB",
        "BLOCK_DB_TO_WORD",
        # TIA Portal's further conversions in this family (every CPU family; the conversions
        # of the S7-1200/1500 types are the profile's, ``nasaq.lang.profiles``)
        *TIA_CONVERSIONS,
        *s7_1500.CONVERSIONS,  # those of the S7-1200/1500 types
        *WCHAR_CONVERSIONS,  # WCHAR's code unit (``nasaq.lang.wide_text``)
    ]
)
# Long type names the function names abbreviate.
LONG = {"TOD": "TIME_OF_DAY", "DT": "DATE_AND_TIME"}


def is_silent(value: Type) -> bool:
    """A type nothing is reported about (an error already reported, or not known)."""
    return isinstance(value, Special) or (isinstance(value, Elementary) and value.name == "UNKNOWN")


def scalar(value: Type) -> str | None:
    """The elementary type name a value has when it takes part in an operation."""
    if isinstance(value, Elementary):
        return value.name
    if isinstance(value, StringType):
        return value.name
    if isinstance(value, IntConst):
        low, high = RANGES["INT"]
        return "INT" if low <= value.value <= high else "DINT"
    if isinstance(value, BitsConst):
        for name in ("BYTE", "WORD", "DWORD"):
            if value.value <= BIT_LIMITS[name]:
                return name
        return "DWORD"
    if isinstance(value, TimeConst):
        return "TIME"
    if isinstance(value, CharsConst):
        return "CHAR" if value.length == 1 else "STRING"
    return None


def describe(value: Type) -> str:
    """How a message names the type of a value."""
    name = scalar(value)
    if isinstance(value, StringType):
        return type_text(value)
    if name is not None:
        return name
    if isinstance(value, DbRef):
        return "DB" if value.number is None else f"DB {value.number}"
    if isinstance(value, BlockRef):
        return f"{value.kind.value} {value.number}"
    if isinstance(value, Special):
        return value.name
    if isinstance(value, IntConst | BitsConst | TimeConst | CharsConst):
        return "?"  # pragma: no cover - scalar() names every constant
    return type_text(value)


def widens(source: str, target: str) -> bool:
    """Whether S7-SCL converts ``source`` to ``target`` silently (class A, or the same type)."""
    if source == target:
        return True
    for family in (BITS, NUMBERS):
        if source in family and target in family:
            return family.index(source) < family.index(target)
    return (source == "CHAR" and target == "STRING") or s7_1500.widens(source, target)


@cache  # a few dozen name pairs, asked for every operation
def wider(left: str, right: str) -> str | None:
    """The common type two operands are converted to, if there is one."""
    if widens(left, right):
        return right
    if widens(right, left):
        return left
    return s7_1500.common(left, right)  # INT with UINT: DINT (S7-1200/1500 types only)


def function_name(source: str, target: str) -> str | None:
    """The explicit conversion function from ``source`` to ``target``, if S7-SCL has one."""
    name = f"{SHORT.get(source, source)}_TO_{SHORT.get(target, target)}"
    return name if name in CONVERSIONS else None


@dataclass(slots=True)
class Verdict:
    """Whether a value may be stored in a variable: ``code`` None when it may. Verdicts are
    shared (``OK``, and those of ``assignable`` between elementary types): read, never change."""

    code: str | None = None
    params: dict[str, Any] = field(default_factory=dict)


OK = Verdict()


def assignable(value: Type, target: DataType) -> Verdict:
    """Whether ``value`` may be assigned (or passed) to a variable of type ``target``."""
    if type(target) is Elementary:
        if type(value) is Elementary:
            return _between(value.name, target.name)
        if type(value) is IntConst:
            return _constant_into(value.value, target.name)
    return _assignable(value, target)


@cache  # between two elementary types the verdict depends on their names only
def _between(source: str, goal: str) -> Verdict:
    return _assignable(Elementary(source), Elementary(goal))


@lru_cache(maxsize=4096)  # an integer constant into an elementary type: by value and name
def _constant_into(value: int, goal: str) -> Verdict:
    return _assignable(IntConst(value), Elementary(goal))


def _assignable(value: Type, target: DataType) -> Verdict:
    if is_silent(value) or is_silent(target) or isinstance(value, Special):
        return OK
    goal = scalar(target)
    if goal is None or isinstance(target, ArrayType | BlockType):
        if value == target:
            return OK
        return Verdict("SCL214", {"actual": describe(value), "expected": describe(target)})
    if isinstance(value, IntConst):
        found = _int_constant(value.value, goal)
        if found is not None:
            return found
    if isinstance(value, BitsConst):
        if (goal in BIT_LIMITS and goal != "BOOL") or goal in RANGES:
            limit = BIT_LIMITS.get(goal) or _BITS_INTO.get(goal) or RANGES[goal][1]
            if value.value <= limit:
                return OK
            return Verdict("SCL218", {"text": f"16#{value.value:X}", "type": goal, "hint": ""})
        if goal == "BOOL" and value.value in (0, 1):
            return OK
    if isinstance(value, TimeConst) and goal == "S5TIME":
        if 0 <= value.ms <= 9_990_000:
            return OK
        return Verdict("SCL218", {"text": f"{value.ms} ms", "type": "S5TIME", "hint": ""})
    if isinstance(value, CharsConst) and goal in ("WSTRING", "WCHAR"):  # 'abc' as TIA takes it
        if goal == "WCHAR" and value.length != 1:
            return Verdict("SCL214", {"actual": "STRING", "expected": "WCHAR"})
        return OK
    if goal == "WSTRING" and scalar(value) == "WCHAR":  # one character
        return OK
    if isinstance(value, CharsConst) and goal == "CHAR" and value.length != 1:
        return Verdict("SCL214", {"actual": "STRING", "expected": "CHAR"})
    source = scalar(value)
    if source is None:
        return Verdict("SCL214", {"actual": describe(value), "expected": describe(target)})
    if widens(source, goal):
        return OK
    function = function_name(source, goal)
    if function is not None:
        return Verdict("SCL213", {"actual": source, "expected": goal, "function": function})
    return Verdict("SCL214", {"actual": source, "expected": goal})


# A bit-string constant into a signed integer: its bit pattern (16#FFFF into an INT is -1).
_BITS_INTO = {"INT": 0xFFFF, "DINT": 0xFFFFFFFF, "SINT": 0xFF, "LINT": 2**64 - 1}


def _int_constant(value: int, goal: str) -> Verdict | None:
    if goal in RANGES:
        low, high = RANGES[goal]
        if low <= value <= high:
            return OK
        return Verdict("SCL218", {"text": str(value), "type": goal, "hint": ""})
    if goal in s7_1500.FLOATS:
        return OK
    if goal == "BOOL" and value in (0, 1):
        return OK  # `Q0.0 := 1;` (seeds-003b §2.6)
    if goal in BIT_LIMITS and goal != "BOOL":  # `w := 255;`: STEP 7 takes its bit pattern
        if 0 <= value <= BIT_LIMITS[goal]:
            return OK
        return Verdict("SCL218", {"text": str(value), "type": goal, "hint": ""})
    return None

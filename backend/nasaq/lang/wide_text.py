"""WSTRING and WCHAR, TIA Portal's Unicode text types (S7-1200/1500 only).

Layout (standard access, as TIA): a WSTRING[n] (n defaults to 254, at most 16382) is a WORD
with the maximum length n, a WORD with the current length, then n characters of 2 bytes each
(UTF-16 code units, big-endian); a WCHAR is one such 2-byte character. Nasaq builds them on
the STRING machinery with a character width (``nasaq.lang.types.StringType.wide``), so
declarations (every section, DBs, UDTs, FB instances), initial values, the header written at
start-up, assignments (constant, WSTRING, WCHAR) and their copies run as STRING's do;
comparisons and the text functions call hidden library FCs (``LEN_WSTRING`` ...,
``nasaq.lang.iec_library``); WCHAR is an elementary 16-bit type (``WCHAR_CONVERSIONS``).

Under a classic profile both names are ``SCL500``/``STL500`` (the types do not exist there).
What is not simulated yet for them is ``SCL800`` (``what`` says which operation).
"""

from __future__ import annotations

from nasaq.lang.number_text import WIDE_CONVERSIONS
from nasaq.lang.types import StringType

NAMES = ("WSTRING", "WCHAR")
LONGEST_WSTRING = 16382  # TIA Portal's limit
LONGEST_STRING = 254


def wide_text(name: str) -> str | None:
    """``WSTRING`` or ``WCHAR`` when ``name`` is one of them (any case), else None."""
    upper = name.upper()
    return upper if upper in NAMES else None


# WCHAR to and from the other character and whole-number types: its code unit, zero-extended
# (a code above 255 into a CHAR keeps its low byte, a number into a WCHAR its low word: *Nasaq*).
_CODES = ("CHAR", "BYTE", "USINT", "SINT", "INT", "DINT", "UINT", "UDINT", "WORD", "DWORD")
WCHAR_CONVERSIONS = frozenset(
    [f"WCHAR_TO_{name}" for name in _CODES] + [f"{name}_TO_WCHAR" for name in _CODES]
)


def wide_conversion(name: str) -> bool:
    """Whether ``name`` is a conversion to or from WCHAR or WSTRING."""
    source, middle, target = name.upper().partition("_TO_")
    return bool(middle) and (source in NAMES or target in NAMES)


def unsimulated_conversion(name: str) -> bool:
    """Whether ``name`` is a conversion to or from WCHAR/WSTRING Nasaq does not simulate yet
    (``WCHAR_TO_WSTRING``, ``LREAL_TO_WSTRING`` ...; STRING_TO_WSTRING, WSTRING_TO_STRING and
    the numbers' ``INT_TO_WSTRING`` ... are library FCs, ``nasaq.lang.number_text``)."""
    upper = name.upper()
    if not wide_conversion(upper) or upper in WCHAR_CONVERSIONS or upper in WIDE_CONVERSIONS:
        return False
    return upper not in ("STRING_TO_WSTRING", "WSTRING_TO_STRING")


def longest(data_type: StringType) -> int:
    """The largest maximum length a declaration of this kind of text may have."""
    return LONGEST_WSTRING if data_type.wide else LONGEST_STRING

"""TIA Portal's conversions between numbers and STRING (``INT_TO_STRING``, ``STRING_TO_REAL``
...) as hidden library FCs, one per source type: Nasaq lists them with the IEC library's
(``nasaq.lang.iec_library``), so the compilers add and call them as they do ``I_STRNG``; their
bodies are Python, beside I_STRNG's (``nasaq.cpu.iec_library``), in the format TIA's help gives
for SCL (the sign and the digits, no blanks, ``nasaq/cpu/COMPATIBILITY.md``).

INT, DINT and REAL have them under every profile (TIA Portal offers them for S7-300/400 too);
the S7-1200/1500 types' (``UINT_TO_STRING`` ...) and TIA's TIME conversions (``UDINT_TO_TIME``,
``TIME_TO_INT`` ...) need the S7-1500 profile (``S7_1500_ONLY``), as the WSTRING versions of
all of them (``INT_TO_WSTRING``, ``WSTRING_TO_REAL`` ...: the same text, as UTF-16).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.types import Elementary, StringType

if TYPE_CHECKING:
    from nasaq.lang.iec_library import LibraryFunction

BASE = 620  # up to 659 (the WSTRING FCs follow from 660)
CLASSIC = ("INT", "DINT", "REAL")
S7_1500_SOURCES = ("SINT", "USINT", "UINT", "UDINT", "LINT", "ULINT")
_TO_STRING = [*CLASSIC, *S7_1500_SOURCES]
_FROM_STRING = (*CLASSIC, *S7_1500_SOURCES)
# TIA's conversions of a TIME the S7-1200/1500 have (``TIME_TO_DINT`` is the classic one).
TIME_CONVERSIONS = {
    "UDINT_TO_TIME": ("UDINT", "TIME"),
    "TIME_TO_UDINT": ("TIME", "UDINT"),
    "TIME_TO_INT": ("TIME", "INT"),
    "TIME_TO_LINT": ("TIME", "LINT"),
    "TIME_TO_ULINT": ("TIME", "ULINT"),
    "INT_TO_TIME": ("INT", "TIME"),
    "UINT_TO_TIME": ("UINT", "TIME"),
    "TOD_TO_TIME": ("TIME_OF_DAY", "TIME"),
}
# The same conversions with WSTRING (S7-1200/1500 only): ``INT_TO_WSTRING``, ``WSTRING_TO_REAL``
# ... give and read the same text as the STRING ones, in UTF-16 code units (FC 677-694).
WIDE_BASE = 677
WIDE_NUMBERS = frozenset(
    [
        *(f"{kind}_TO_WSTRING" for kind in _TO_STRING),
        *(f"WSTRING_TO_{kind}" for kind in _FROM_STRING),
    ]
)
# One character to and from the texts of the other width (``WCHAR_TO_WSTRING``, ``WSTRING_TO_CHAR``
# ...), FC 938-943: (source, target)
CHARACTER_CONVERSIONS = {
    "CHAR_TO_WSTRING": ("CHAR", "WSTRING"),
    "WCHAR_TO_WSTRING": ("WCHAR", "WSTRING"),
    "WCHAR_TO_STRING": ("WCHAR", "STRING"),
    "WSTRING_TO_CHAR": ("WSTRING", "CHAR"),
    "WSTRING_TO_WCHAR": ("WSTRING", "WCHAR"),
    "STRING_TO_WCHAR": ("STRING", "WCHAR"),
}
CHARACTER_BASE = 938
WIDE_CONVERSIONS = WIDE_NUMBERS | CHARACTER_CONVERSIONS.keys()
S7_1500_ONLY = frozenset(
    [
        *(f"{kind}_TO_STRING" for kind in S7_1500_SOURCES),
        *(f"STRING_TO_{kind}" for kind in S7_1500_SOURCES),
        *TIME_CONVERSIONS,
        *WIDE_CONVERSIONS,
    ]
)


def functions() -> list[LibraryFunction]:
    """The conversion FCs, numbered from ``BASE``."""
    from nasaq.lang.iec_library import LibraryFunction

    text = StringType(254)
    made = [
        LibraryFunction(
            f"{kind}_TO_STRING", n, (("IN", Elementary(kind)),), text, f"{kind} to STRING"
        )
        for n, kind in enumerate(_TO_STRING, start=BASE)
    ]
    start = BASE + len(made)
    made += [
        LibraryFunction(
            f"STRING_TO_{kind}", n, (("IN", text),), Elementary(kind), f"STRING to {kind}"
        )
        for n, kind in enumerate(_FROM_STRING, start=start)
    ]
    start = BASE + len(made)
    made += [
        LibraryFunction(name, n, (("IN", Elementary(source)),), Elementary(target), name)
        for n, (name, (source, target)) in enumerate(TIME_CONVERSIONS.items(), start=start)
    ]
    wide = StringType(254, wide=True)
    made += [
        LibraryFunction(
            f"{kind}_TO_WSTRING", n, (("IN", Elementary(kind)),), wide, f"{kind} to WSTRING"
        )
        for n, kind in enumerate(_TO_STRING, start=WIDE_BASE)
    ]
    made += [
        LibraryFunction(
            f"WSTRING_TO_{kind}", n, (("IN", wide),), Elementary(kind), f"WSTRING to {kind}"
        )
        for n, kind in enumerate(_FROM_STRING, start=WIDE_BASE + len(_TO_STRING))
    ]
    texts = {"STRING": text, "WSTRING": wide}
    made += [
        LibraryFunction(
            name,
            n,
            (("IN", texts.get(source) or Elementary(source)),),
            texts.get(target) or Elementary(target),
            name,
        )
        for n, (name, (source, target)) in enumerate(
            CHARACTER_CONVERSIONS.items(), start=CHARACTER_BASE
        )
    ]
    return made

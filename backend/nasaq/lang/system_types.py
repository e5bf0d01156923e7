"""The system data types of TIA Portal that system block interfaces use (HW_HSC, TCON_IP_v4 ...)
and the one reader of the interfaces' type texts (``parse``).

The interfaces in ``nasaq.lang.system_blocks`` are lists of ``(section, name, type_text)``; a
type text is an elementary name, ``STRING[n]``, ``WSTRING[n]``, ``ARRAY[lo..hi] OF <text>``
(several dimensions separated by commas), ``VARIANT``, ``ANY``, the name of a system FB
(``IEC_TIMER`` stands for TON's layout: a member that is an instance) or the name of a
structured system data type registered in ``SYSTEM_TYPES`` (a ``StructType`` whose members may
themselves be such types). An elementary member may carry its initial value after ``:=``
(``"BOOL := TRUE"``, ``"REAL := 0.1"``), as the block's instance DB starts with it.
Every compiler and the CPU read the texts through ``parse``, so a system block has one layout
everywhere.

Other modules add their data types to ``SYSTEM_TYPES`` at the bottom of this file (one import
line each; they must not import ``system_blocks`` or this module at import time).
"""

from __future__ import annotations

import re
from functools import cache

from nasaq.lang import tia_iec
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
    elementary,
)

SYSTEM_TYPES: dict[str, StructType] = {}
# System data types that are another type under TIA's name (HW_HSC, a hardware identifier: WORD).
ALIASES: dict[str, str] = {}
# Instance types that stand for a system FB's layout (TIA's IEC_TIMER is TON's layout).
INSTANCE_TYPES: dict[str, int] = {"IEC_TIMER": 4, "IEC_COUNTER": 2}
INSTANCE_TYPES.update(tia_iec.INSTANCE_TYPES)  # (longs: IEC_DCOUNTER ..., IEC_LTIMER)

_STRING = re.compile(r"(W?STRING)\s*\[\s*(\d+)\s*\]$", re.IGNORECASE)
_ARRAY = re.compile(r"ARRAY\s*\[(.+?)\]\s*OF\s+(.+)$", re.IGNORECASE | re.DOTALL)
_BOUNDS = re.compile(r"\s*(-?\d+)\s*\.\.\s*(-?\d+)\s*$")
_OPAQUE = frozenset({"VARIANT", "ANY"})


def struct(*members: tuple[str, str]) -> StructType:
    """A system data type from ``(name, type_text)`` members, in declaration order."""
    return StructType(tuple(Field(name, parse(text)) for name, text in members))


def parse(type_text: str) -> DataType:
    """The data type a type text of a system block interface stands for (see the module doc).
    An unknown text is a programming error in the tables: ``ValueError``."""
    return _parse(type_text.partition(":=")[0].strip())


def initial(type_text: str) -> object:
    """The initial value a type text gives (``"BOOL := TRUE"``: True), None without one."""
    _text, assigned, value = type_text.partition(":=")
    if not assigned:
        return None
    value = value.strip()
    if value.upper() in ("TRUE", "FALSE"):
        return value.upper() == "TRUE"
    return float(value) if any(c in value for c in ".eE") else int(value, 0)


@cache  # the tables are fixed: each text is parsed once (the result is immutable)
def _parse(text: str) -> DataType:
    upper = text.upper()
    string = _STRING.match(text)
    if string is not None:
        return StringType(int(string.group(2)), string.group(1).upper() == "WSTRING")
    array = _ARRAY.match(text)
    if array is not None:
        dims = []
        for part in array.group(1).split(","):
            bounds = _BOUNDS.match(part)
            if bounds is None:
                raise ValueError(f"bad array bounds in system type {text!r}")
            dims.append((int(bounds.group(1)), int(bounds.group(2))))
        return ArrayType(tuple(dims), _parse(array.group(2).strip()))
    if upper in _OPAQUE:
        return Elementary(upper)
    found = elementary(text)
    if found is not None:
        return found
    alias = next((text for name, text in ALIASES.items() if name.upper() == upper), None)
    if alias is not None:
        return _parse(alias)
    registered = _registered(upper)
    if registered is not None:
        return registered
    number = INSTANCE_TYPES.get(upper)
    if number is None:
        number = _system_fb(upper)
    if number is not None:
        return BlockType("SFB", number)
    raise ValueError(f"unknown type {text!r} in a system block interface")


def _registered(upper: str) -> StructType | None:
    for name, found in SYSTEM_TYPES.items():
        if name.upper() == upper:
            return found
    return None


def _system_fb(upper: str) -> int | None:
    from nasaq.lang.system_blocks import SFB_NAMES  # (which may import the modules below)

    for number, name in SFB_NAMES.items():
        if name.upper() == upper:
            return number
    return None


def system_type(name: str) -> DataType | None:
    """The system data type ``name`` (any case) when it is registered here (a structure or an
    alias), else None."""
    upper = name.upper()
    if upper in _OPAQUE or not any(n.upper() == upper for n in (*SYSTEM_TYPES, *ALIASES)):
        return None
    return _parse(upper)


def fields(interface: list[tuple[str, str, str]]) -> list[tuple[str, list[Field]]]:
    """An interface's sections with their members, in order (for the layout of an instance)."""
    sections: dict[str, list[Field]] = {}
    for section, name, text in interface:
        sections.setdefault(section, []).append(Field(name, parse(text), initial(text)))
    return list(sections.items())


def system_fb_sections(number: int) -> list[tuple[str, list[Field]]] | None:
    """The instance sections of system FB ``number`` (None for an unknown number): what a
    layout's ``expand`` gives for ``BlockType("SFB", number)``."""
    from nasaq.lang.system_blocks import SFB_INTERFACES

    interface = SFB_INTERFACES.get(number)
    return None if interface is None else fields(interface)


# -- merge points: each module that brings system data types adds one line here --------------------
from nasaq.lang import tia_control  # noqa: E402  (sysfb: HW_HSC ..., PID_Compact's members)

SYSTEM_TYPES.update(tia_control.TYPES)
ALIASES.update(tia_control.ALIASES)
from nasaq.lang import tia_comm  # noqa: E402  (syscomm: TCON_IP_v4, TCON_Param, HW_ANY ...)

SYSTEM_TYPES.update(tia_comm.TYPES)
ALIASES.update(tia_comm.ALIASES)
from nasaq.lang import tia_filters  # noqa: E402  (filters: Filter_PT1's CycleTime ...)

SYSTEM_TYPES.update(tia_filters.TYPES)

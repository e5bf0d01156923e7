"""Which names a project file may have, and what language a name means.

A name is what the compiler reads by its suffix (``.awl``/``.stl`` STL, ``.scl`` SCL, ``.lad``
LAD and ``.fbd`` FBD in their text format, ``.graph`` S7-Graph, ``.sdf``, ``.asc``, ``.seq``,
``.csv`` symbol tables;
``.vat`` watch tables, ``cpu.properties`` and ``.plant`` plant files are project files the
compiler skips)
and also a plain file in an export, so it avoids what
any file system or zip tool refuses: path separators, control and reserved characters, Windows'
device names, a leading dot (hidden files) and a trailing dot or space (Windows drops them).
"""

from __future__ import annotations

import re
from typing import Literal

from nasaq.lang.limits import MAX_SOURCE_CHARS
from nasaq.lang.stl.compiler import (
    LAD_SUFFIXES,
    PLANT_SUFFIXES,
    SCL_SUFFIXES,
    STL_SUFFIXES,
    WATCH_TABLE_SUFFIXES,
)
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES

BlockLanguage = Literal["stl", "scl", "lad", "fbd", "graph"]
Language = Literal["stl", "scl", "lad", "fbd", "graph", "symbols", "watch", "cpu", "plant"]
GRAPH_SUFFIXES = (".graph",)  # nasaq.lang.graph.text.SUFFIXES: an S7-Graph FB, compiled to STL

MAX_NAME_CHARS = 128
MAX_TEXT_CHARS = MAX_SOURCE_CHARS  # the compiler refuses larger sources (STL111)
MAX_FILES = 500  # what one download into a simulated CPU accepts
SOURCE_SUFFIXES = (
    STL_SUFFIXES + SCL_SUFFIXES + LAD_SUFFIXES + GRAPH_SUFFIXES + SYMBOL_TABLE_SUFFIXES
)

_FORBIDDEN = re.compile(r'[\x00-\x1f\x7f/\\:*?"<>|]')
_DEVICES = re.compile(r"(CON|PRN|AUX|NUL|COM\d|LPT\d)", re.IGNORECASE)


def language_of(name: str) -> Language | None:
    """``stl``, ``scl``, ``lad``, ``fbd``, ``graph`` or ``symbols`` by the suffix, as the
    compiler decides; else None."""
    suffix = name[name.rfind(".") :].lower() if "." in name else ""
    if suffix in STL_SUFFIXES:
        return "stl"
    if suffix in SCL_SUFFIXES:
        return "scl"
    if suffix in LAD_SUFFIXES:
        return "lad" if suffix == ".lad" else "fbd"
    if suffix in GRAPH_SUFFIXES:
        return "graph"
    if suffix in SYMBOL_TABLE_SUFFIXES:
        return "symbols"
    if suffix in WATCH_TABLE_SUFFIXES:
        return "watch"  # nasaq.workbench.watch_table: no program, the compiler skips it
    if name.lower() == "cpu.properties":
        return "cpu"  # nasaq.workbench.cpu_properties: the one CPU properties file of a project
    if suffix in PLANT_SUFFIXES:
        return "plant"  # nasaq.plants.plant_file: the project's virtual plant (YAML)
    return None


def is_valid_name(name: str) -> bool:
    stem = name[: name.rfind(".")] if "." in name else name
    return (
        0 < len(name) <= MAX_NAME_CHARS
        and language_of(name) is not None
        and stem.strip() != ""
        and not name.startswith(".")
        and name == name.strip()
        and _FORBIDDEN.search(name) is None
        and _DEVICES.fullmatch(stem.split(".")[0]) is None
    )

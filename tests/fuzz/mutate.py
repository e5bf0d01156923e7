"""Mutations of real sources and the pathological inputs the issue lists.

The seeds are the repository's own sources (``examples/`` and the test corpora: STL, SCL and
LAD/FBD files under 8 KB, read in sorted order so a run is the same on every machine with the
same tree) and the grammar's random sentences (``grammar_gen``). A mutation works on tokens
(words, numbers, strings, comments, punctuation, line ends): delete, duplicate, swap, splice a
run of tokens from another seed, replace a number by a huge one, truncate. ``pathological``
builds the inputs a compiler must survive whatever its grammar: deep nesting of brackets,
parentheses, IF/FOR/WHILE/CASE, STRUCTs and LAD parallels, numbers of thousands of digits,
addresses and DB numbers past any CPU, huge array bounds, time literals out of range, nested and
unterminated comments, stray ``*)``, unterminated strings, BOM/CRLF/NUL/lone surrogates and very
long lines. Every choice comes from the caller's ``random.Random``.
"""

from __future__ import annotations

import random
import re
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUFFIXES = {"stl": (".awl",), "scl": (".scl",), "lad": (".lad", ".fbd")}
_SKIP = ("node_modules", ".output", ".reports", "fuzz")
_TOKEN = re.compile(
    r"\(\*.*?\*\)|//[^\n]*|'(?:[^'\n]|'')*'|\"[^\"\n]*\""
    r"|\d[\w#.:]*|[A-Za-z_#%][\w#.]*|\r?\n|[ \t]+|.",
    re.DOTALL,
)


@cache
def seeds(language: str) -> tuple[str, ...]:
    """The repository's sources of ``language`` under 8 KB, in path order."""
    found: list[Path] = []
    for top in ("examples", "tests"):
        for suffix in SUFFIXES[language]:
            for path in (ROOT / top).rglob(f"*{suffix}"):
                if any(part in _SKIP for part in path.parts) or path.stat().st_size > 8192:
                    continue
                found.append(path)
    return tuple(p.read_text(encoding="utf-8", errors="replace") for p in sorted(found))


def tokens(text: str) -> list[str]:
    return _TOKEN.findall(text)


HUGE_NUMBERS = (
    "9" * 5000,
    "1" + "0" * 4400,
    "16#" + "F" * 3000,
    "2#" + "1" * 9000,
    "8#" + "7" * 40,
    "1.0e999999",
    "1e-99999",
    "3.4e39",
    "-" + "9" * 700,
    "99999999999999999999999999",
    "4294967296",
    "65536",
    "2147483648",
    "L#" + "9" * 400,
    "B#16#" + "F" * 300,
    "W#16#1FFFF",
    "DW#16#" + "F" * 80,
    "P#" + "9" * 60 + ".0",
    "C#" + "9" * 30,
    "S5T#" + "9" * 30 + "S",
    "T#" + "9" * 500 + "D",
    "T#-24D_20H_31M_23S_649MS",
    "T#25D",
    "TIME#" + "9" * 40 + "MS",
    "D#99999-99-99",
    "D#2169-06-07",
    "DT#9999-12-31-99:99:99.999",
    "TOD#99:99:99.9999",
    "LT#" + "9" * 300 + "NS",
    "16#" + "F" * 200,
)
HUGE_ADDRESSES = (
    "M 99999999999.0",
    "M 1.9",
    "I 65536.0",
    "MW " + "9" * 400,
    "DB" + "9" * 30 + ".DBX 0.0",
    "DB65536.DBW 0",
    "DB0.DBB 0",
    "DB1.DBD " + "9" * 60,
    "T " + "9" * 40,
    "C 65536",
    "FC " + "9" * 50,
    "FB 4294967296",
    "DB " + "9" * 4000,
    "%MW" + "9" * 100,
    "PIW 99999999",
    "L " + "9" * 20 + ".7",
    "P#M 9999999999.7",
    "P#DB99999999.DBX 0.0 BYTE " + "9" * 40,
    "DBX " + "9" * 30 + ".0",
    "SFC " + "9" * 30,
)
STRANGE_TEXT = (
    "\ufeff",
    "\r\n",
    "\r",
    "\x00",
    "\ud800",
    "\udfff",
    "\x1a",
    "\u2028",
    "\u202e",
    "(*",
    "*)",
    "(* (* (* *)",
    "/*",
    "*/",
    "'",
    '"',
    "//",
    "{",
    "}",
    "END_",
    "BEGIN",
    "\t" * 50,
)


def mutate(text: str, rng: random.Random, donors: tuple[str, ...]) -> str:
    """``text`` with one to four token mutations."""
    parts = tokens(text)
    if not parts:
        parts = [""]
    for _ in range(rng.randint(1, 4)):
        what = rng.random()
        k = rng.randrange(len(parts))
        if what < 0.2:  # delete a run
            del parts[k : k + rng.randint(1, 6)]
        elif what < 0.35:  # duplicate a run
            run = parts[k : k + rng.randint(1, 12)]
            parts[k:k] = run * rng.randint(1, 3)
        elif what < 0.45 and len(parts) > 2:  # swap two tokens
            j = rng.randrange(len(parts))
            parts[k], parts[j] = parts[j], parts[k]
        elif what < 0.6 and donors:  # splice a run of another source
            donor = tokens(rng.choice(donors))
            if donor:
                start = rng.randrange(len(donor))
                parts[k:k] = donor[start : start + rng.randint(1, 40)]
        elif what < 0.7:  # a number becomes a huge or odd one
            numbers = [i for i, p in enumerate(parts) if p[:1].isdigit()]
            where = rng.choice(numbers) if numbers else k
            parts[where] = rng.choice(HUGE_NUMBERS)
        elif what < 0.78:  # an address beyond any CPU
            parts.insert(k, rng.choice(HUGE_ADDRESSES))
        elif what < 0.9:  # a character or marker that breaks lexers
            parts.insert(k, rng.choice(STRANGE_TEXT))
        elif what < 0.95:  # truncate
            del parts[k:]
        else:  # repeat a token many times (long line, long list)
            token = parts[k] or "x"  # at most 100 KB: size has its own limits and cases
            parts.insert(k, token * min(rng.randint(50, 3000), 1 + 100_000 // len(token)))
        if not parts:
            parts = [""]
    return "".join(parts)


def _nest(rng: random.Random, depth: int, open_: str, close: str, middle: str) -> str:
    return open_ * depth + middle + close * (depth if rng.random() < 0.8 else depth // 2)


def pathological(language: str, rng: random.Random, big: bool = False) -> str:
    """One of the inputs the issue names, shaped for ``language``; ``big`` takes sizes up to
    hundreds of KB (``make fuzz``), else up to tens (the bounded run's time budget)."""
    depth = rng.choice((50, 200, 1000, 3000) if big else (45, 70, 300))
    many = rng.choice((3000, 30000) if big else (300, 1000))
    kind = rng.randrange(12)
    if language == "stl":
        body = [
            lambda: "A(\n" * depth + "A I 0.0\n" + ")\n" * depth,
            lambda: "L " + rng.choice(HUGE_NUMBERS) + "\nT MW 10\n",
            lambda: "A " + rng.choice(HUGE_ADDRESSES) + "\n= Q 0.0\n",
            lambda: "L " + rng.choice(HUGE_ADDRESSES) + "\n",
            lambda: "CALL " + rng.choice(HUGE_ADDRESSES) + "\n",
            lambda: "OPN DB " + "9" * rng.choice((6, 11, 600)) + "\n",
            lambda: "A I 0.0\n" * many,
            lambda: "(*" * depth + "*)" * rng.randint(0, depth),
            lambda: "L '" + "x" * many + "\n",
            lambda: "A I 0.0 " + "// x" * many + "\n",
            lambda: "L P#" + "9" * 30 + ".0\n",
            lambda: "NETWORK\n" * many,
        ][kind]()
        if kind in (8, 11) or rng.random() < 0.3:
            return body
        head = "FUNCTION FC 1 : VOID\n"
        if rng.random() < 0.3:  # a deep STRUCT in the interface
            head += "VAR_TEMP\n" + "s : STRUCT\n" * depth + "x : INT;\n" + "END_STRUCT;\n" * depth
            head += "END_VAR\n"
        if rng.random() < 0.2:
            head += f"VAR_TEMP\n a : ARRAY[0..{rng.choice(HUGE_NUMBERS)}] OF INT;\nEND_VAR\n"
        return head + "BEGIN\nNETWORK\nTITLE =\n" + body + "END_FUNCTION\n"
    if language == "scl":
        inner = [
            lambda: "x := " + _nest(rng, depth, "(", ")", "1") + ";\n",
            lambda: "IF TRUE THEN\n" * depth + "x := 1;\n" + "END_IF;\n" * depth,
            lambda: "FOR i := 0 TO 1 DO\n" * depth + "x := 1;\n" + "END_FOR;\n" * depth,
            lambda: "WHILE FALSE DO\n" * depth + "x := 1;\n" + "END_WHILE;\n" * depth,
            lambda: "CASE x OF 1:\n" * depth + "x := 1;\n" + "END_CASE;\n" * depth,
            lambda: "x := " + rng.choice(HUGE_NUMBERS) + ";\n",
            lambda: "x := " + "-" * depth + "1;\n",
            lambda: "x := " + " + ".join(["1"] * depth) + ";\n",
            lambda: "x := " + "NOT " * depth + "TRUE;\n",
            lambda: "x := a" + "[0]" * depth + ";\n",
            lambda: "*)" * (rng.choice((4000, 16384)) if big else many),
            lambda: "x := 1;\n" * many,
        ][kind]()
        decl = "VAR_TEMP\n x : INT;\n i : INT;\n"
        if rng.random() < 0.3:
            decl += " s : " + "STRUCT a : " * depth + "INT;" + " END_STRUCT;" * depth + "\n"
        if rng.random() < 0.3:
            decl += f" a : ARRAY[0..{rng.choice(HUGE_NUMBERS)}] OF INT;\n"
        if rng.random() < 0.2:
            decl += f" t : TIME := {rng.choice(HUGE_NUMBERS)};\n"
        if rng.random() < 0.2:
            return (
                f"DATA_BLOCK DB {rng.choice(('1', '9' * 400))}\nSTRUCT\n"
                + decl.split("\n", 1)[1]
                + "END_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
            )
        return "FUNCTION FC1 : VOID\n" + decl + "END_VAR\nBEGIN\n" + inner + "END_FUNCTION\n"
    # LAD
    parallel = (
        "PARALLEL BRANCH " * depth
        + "Contact(I 0.0)"
        + " END_BRANCH BRANCH Contact(I 0.1) END_BRANCH END_PARALLEL" * depth
    )
    body = [
        lambda: parallel,
        lambda: "Contact(" + rng.choice(HUGE_ADDRESSES) + ")",
        lambda: "Contact(I 0.0) " * many,
        lambda: "Box(MOVE, IN := " + rng.choice(HUGE_NUMBERS) + ", OUT => MW 10)",
        lambda: "(*" * depth,
        lambda: "Box(AND, IN1 := RUNG " * depth + "Contact(I 0.0)" + " END_RUNG)" * depth,
        lambda: "Contact('abc",
        lambda: "Contact(I 0.0) \x00 Coil(Q 0.0)",
        lambda: "NOT " * depth + "Contact(I 0.0)",
        lambda: "Box(ADD_I, IN1 := " + "9" * 4000 + ", IN2 := 1, OUT => MW 2)",
        lambda: "Coil(" + rng.choice(HUGE_ADDRESSES) + ")",
        lambda: "Box(FC " + "9" * 50 + ")",
    ][kind]()
    return (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG\n"
        + body
        + " Coil(Q 0.0)\nEND_RUNG\nEND_ORGANIZATION_BLOCK\n"
    )

"""What a terminal's match may start with (``nasaq.lang.scl.first_chars``) may say too much but
never too little: every match found in sample texts starts with a character it allows, and the
character after the first is one its second-character test lets through. The fast lexer tries
a terminal only where these allow it, so a miss here would be a token Lark sees and it does not.
"""

from __future__ import annotations

import random
import re

import pytest

from nasaq.lang.scl.first_chars import (
    ALPHABET,
    NON_ASCII,
    OTHER,
    SPACE,
    WORD,
    Shapes,
    char_class,
)
from nasaq.lang.scl.grammar import build_parser

GRAMMAR_TERMINALS = build_parser().terminals
TERMINALS = {terminal.name: terminal.pattern.to_regexp() for terminal in GRAMMAR_TERMINALS}
# The keywords and punctuation as written (and in lower case): samples of the string terminals.
WORDS = [
    case(terminal.pattern.value)
    for terminal in GRAMMAR_TERMINALS
    if terminal.pattern.type == "str"
    for case in (str.upper, str.lower)
] + ["END_REGION", "end_region x"]  # a keyword written as a regular expression (its title)
PIECES = [
    *"abcmMpPiIqQtTdDxXwWbBeE_019#%$'\"[](){}.,:;=<>+-*/& \t\r\n",
    *["ä", "ß", "K", "ſ", "ı", "\u00a0", "\u2028", "€", "²"],
    *["16#", "2#", "T#", "INT#", "DB", "DBX", "PIW", "END_IF", "NAME", "VAR_TEMP", "REGION", "(*"],
    *["*)", "/*", "*/", "//", "1.5", "e3", "-", " [", " :", " 1.2", ":=", "=>", "..", "**"],
    *["AUTHOR :", "name:", "KNOW_HOW_PROTECT", "read_only", "VAR_INPUT CONSTANT", "REGION x"],
    *["%X3", "%w1", "#k..", '"K",', "END_REGION t", "%IW", ":P", "%qb"],
]


def _kind(char: str) -> str:
    """The member of ``ALPHABET`` that stands for ``char``."""
    if char.isascii():
        return char
    if re.match(r"\s", char):
        return SPACE
    return WORD if re.match(r"\w", char) else OTHER


def _samples(count: int) -> list[str]:
    rng = random.Random(7)
    found = ["".join(rng.choices(PIECES, k=rng.randint(1, 6))) for _ in range(count)]
    return found + [word + rng.choice(PIECES) for word in WORDS for _ in range(3)]


@pytest.mark.parametrize("name", sorted(TERMINALS))
def test_matches_start_as_the_analysis_allows(name: str) -> None:
    shapes = Shapes(0)
    pattern = re.compile(TERMINALS[name])
    first = shapes.first(name, TERMINALS[name])
    matched = 0
    for text in _samples(6000):
        found = pattern.match(text)
        if found is None or not found.group():
            continue
        matched += 1
        assert _kind(text[0]) in first, (name, text)
        second = shapes.second(name, TERMINALS[name], frozenset({_kind(text[0])}))
        if second is not None:  # the text must go on with a character it allows
            assert len(text) > 1, (name, text)
            assert _kind(text[1]) in second, (name, text)
    if name not in ("ERROR", "BLOCK_COMMENT", "C_COMMENT"):
        assert matched, name  # the samples reach every terminal


def test_known_answers() -> None:
    shapes = Shapes(0)
    assert shapes.first("WS", TERMINALS["WS"]) == frozenset(" \t\n\r\x0b\x0c\x1c\x1d\x1e\x1f") | {
        SPACE
    }
    assert "_" in shapes.first("IDENT", TERMINALS["IDENT"])
    assert shapes.first("IDENT", TERMINALS["IDENT"]).isdisjoint(" \t\n" + SPACE)
    after_c = shapes.second("ADDR", TERMINALS["ADDR"], frozenset("Cc"))
    assert after_c is not None
    assert set("0123456789 \t") <= after_c
    assert after_c.isdisjoint("abcoO_#")
    after_m = shapes.second("AREA", TERMINALS["AREA"], frozenset("M"))  # M(?=[ \t]*\[) ...
    assert after_m is not None
    assert "[" in after_m
    assert "y" not in after_m
    assert shapes.second("IDENT", TERMINALS["IDENT"], frozenset("x")) is None  # "x" alone


def test_character_classes_hold_what_they_stand_for() -> None:
    rng = random.Random(3)
    samples = [*map(chr, range(128)), "ä", "K", "\u00a0", "\u2028", "€", "²", "\U0001f600"]
    for _ in range(200):
        chars = rng.sample(list(ALPHABET), rng.randint(1, 12))
        pattern = re.compile(char_class(chars))
        for char in samples:
            wide = any(member in NON_ASCII for member in chars)
            expected = _kind(char) in chars or (not char.isascii() and wide)
            assert bool(pattern.fullmatch(char)) == expected, (chars, char)

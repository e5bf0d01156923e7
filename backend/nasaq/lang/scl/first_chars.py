"""What a match of a regular expression may start with, for the fast lexer
(``nasaq.lang.scl.lexer``): it tries only the terminals that may start with the next character,
and skips whitespace without looking for the terminals that cannot start with a blank.

The answer is read from the expression as ``re`` parses it, for each ASCII character and three
classes of all others (white space, word characters, the rest: what ``\\s``, ``\\w`` and case
folding tell apart). It may say "may" where no match does (anything unusual: "may"), never the
reverse, so the lexer built on it makes Lark's choices.
"""

from __future__ import annotations

import importlib
import re
from functools import cache
from typing import Any

# The non-ASCII classes (strings no character is).
SPACE, WORD, OTHER = "\x80 ", "\x80w", "\x80."
NON_ASCII = (SPACE, WORD, OTHER)
ALPHABET: tuple[str, ...] = (*map(chr, range(128)), *NON_ASCII)
Starts = frozenset[str]
ANY: Starts = frozenset(ALPHABET)

_sre: Any = importlib.import_module("re._parser")  # the parser of ``re``: no public API
_ASCII_CATEGORIES = {
    _sre.CATEGORY_DIGIT: r"\d",
    _sre.CATEGORY_NOT_DIGIT: r"\D",
    _sre.CATEGORY_SPACE: r"\s",
    _sre.CATEGORY_NOT_SPACE: r"\S",
    _sre.CATEGORY_WORD: r"\w",
    _sre.CATEGORY_NOT_WORD: r"\W",
}
# The non-ASCII classes a category meets (non-ASCII digits are word characters).
_WIDE_CATEGORIES = {
    _sre.CATEGORY_DIGIT: {WORD},
    _sre.CATEGORY_NOT_DIGIT: set(NON_ASCII),
    _sre.CATEGORY_SPACE: {SPACE},
    _sre.CATEGORY_NOT_SPACE: {WORD, OTHER},
    _sre.CATEGORY_WORD: {WORD},
    _sre.CATEGORY_NOT_WORD: {SPACE, OTHER},
}
_REPEATS = (_sre.MAX_REPEAT, _sre.MIN_REPEAT, _sre.POSSESSIVE_REPEAT)
_ZERO_WIDTH = (_sre.AT, _sre.ASSERT, _sre.ASSERT_NOT)
_SINGLE = (_sre.LITERAL, _sre.IN, _sre.ANY, _sre.NOT_LITERAL)  # one character each


def _wide(char: str) -> str:
    """The class of a non-ASCII character."""
    if re.match(r"\s", char):
        return SPACE
    return WORD if re.match(r"\w", char) else OTHER


@cache
def _literal(code: int, flags: int) -> Starts:
    char = chr(code)
    found = {char} if code < 128 else {_wide(char)}
    if flags & re.IGNORECASE:  # ``re`` itself says which ASCII characters match (``İ``: ``i``)
        case = flags & (re.IGNORECASE | re.ASCII)
        found |= {each for each in ALPHABET[:128] if re.fullmatch(re.escape(char), each, case)}
        if char.isalpha() or code >= 128:  # ``k`` also matches the Kelvin sign, a letter
            found.add(WORD)
    return frozenset(found)


def _in_ascii(items: list[tuple[Any, Any]], flags: int, char: str) -> bool:
    """Whether the character class ``[...]`` may match the ASCII ``char``."""
    ignore = flags & re.IGNORECASE
    negate = bool(items) and items[0][0] is _sre.NEGATE
    if ignore and negate:
        return True
    candidates = {char, char.lower(), char.upper()} if ignore else {char}
    hit = False
    for op, arg in items:
        if op is _sre.LITERAL and not (ignore and arg > 127):
            hit = hit or chr(arg) in candidates
        elif op is _sre.RANGE and not (ignore and arg[1] > 127):
            hit = hit or any(arg[0] <= ord(each) <= arg[1] for each in candidates)
        elif op is _sre.CATEGORY and arg in _ASCII_CATEGORIES:
            pattern = _ASCII_CATEGORIES[arg]
            hit = hit or any(re.fullmatch(pattern, each, flags & re.ASCII) for each in candidates)
        elif op is not _sre.NEGATE:
            return True
    return hit != negate


def _in_wide(items: list[tuple[Any, Any]], flags: int) -> set[str]:
    """The non-ASCII classes the character class ``[...]`` may match."""
    if items and items[0][0] is _sre.NEGATE:
        return set(NON_ASCII)
    found: set[str] = set()
    for op, arg in items:
        if op is _sre.LITERAL:
            found |= _literal(arg, flags) & set(NON_ASCII)
        elif op is _sre.RANGE and arg[1] < 128:
            low, high = arg
            letters = any(chr(code).isalpha() for code in range(low, high + 1))
            found |= {WORD} if flags & re.IGNORECASE and letters else set()
        elif op is _sre.CATEGORY and arg in _WIDE_CATEGORIES and not flags & re.ASCII:
            found |= _WIDE_CATEGORIES[arg]
        else:  # a range beyond ASCII, the ASCII-only categories' complements ...
            return set(NON_ASCII)
    return found


_IN_CACHE: dict[tuple[str, int], Starts] = {}  # the same classes recur in many terminals


def _in(items: list[tuple[Any, Any]], flags: int) -> Starts:
    key = (repr(items), flags)
    found = _IN_CACHE.get(key)
    if found is None:
        ascii_chars = {char for char in ALPHABET[:128] if _in_ascii(items, flags, char)}
        found = _IN_CACHE[key] = frozenset(ascii_chars | _in_wide(items, flags))
    return found


def _first(items: list[tuple[Any, Any]], flags: int) -> tuple[Starts, bool]:
    """What a sequence may start with, and whether it may match the empty text."""
    starts: set[str] = set()
    for op, arg in items:
        found, empty = _item(op, arg, flags)
        starts |= found
        if not empty:
            return frozenset(starts), False
    return frozenset(starts), True


def _item(op: Any, arg: Any, flags: int) -> tuple[Starts, bool]:
    if op is _sre.LITERAL:
        return _literal(arg, flags), False
    if op is _sre.IN:
        return _in(arg, flags), False
    if op is _sre.SUBPATTERN:
        _group, add, remove, items = arg
        return _first(items, (flags | add) & ~remove)
    if op is _sre.BRANCH:
        results = [_first(items, flags) for items in arg[1]]
        starts: set[str] = set()
        for found, _ in results:
            starts |= found
        return frozenset(starts), any(empty for _, empty in results)
    if op in _REPEATS:
        low, _high, items = arg
        found, empty = _first(items, flags)
        return found, empty or low == 0
    if op is _sre.ATOMIC_GROUP:
        return _first(arg, flags)
    if op in _ZERO_WIDTH:
        return frozenset(), True
    if op is _sre.ANY or op is _sre.NOT_LITERAL:  # ``.``, ``[^x]``: one character
        return ANY, False
    return ANY, True  # anything else (a back reference ...): it may


def _next(
    items: list[tuple[Any, Any]], flags: int, then: tuple[Starts, bool]
) -> tuple[Starts, bool]:
    """What the text may have at the start of ``items`` (``then``: after them), and whether
    it may end there; a lookahead ``(?=...)`` narrows what follows it (``AREA``'s ``M`` then
    ``(?=[ \\t]*\\[)``)."""
    found: set[str] = set()
    for index, (op, arg) in enumerate(items):
        if op is _sre.ASSERT and arg[0] == 1:
            ahead, empty = _first(arg[1], flags)
            rest, may_end = _next(items[index + 1 :], flags, then)
            if empty:
                return frozenset(found | rest), may_end
            return frozenset(found | (rest & ahead)), False
        chars, empty = _item(op, arg, flags)
        found |= chars
        if not empty:
            return frozenset(found), False
    return frozenset(found | then[0]), then[1]


def _follow(
    items: list[tuple[Any, Any]], flags: int, chars: Starts, then: tuple[Starts, bool]
) -> tuple[Starts, bool]:
    """What the text may have right after a first character of ``chars`` that ``items`` take
    (``then``: what it may have after them), and whether it may end there."""
    found: set[str] = set()
    may_end = False
    for index, (op, arg) in enumerate(items):
        after = _next(items[index + 1 :], flags, then)
        next_chars, ends = _follow_item(op, arg, flags, chars, after)
        found |= next_chars
        may_end = may_end or ends
        if not _item(op, arg, flags)[1]:  # it takes a character: the first is its
            break
    return frozenset(found), may_end


def _follow_item(
    op: Any, arg: Any, flags: int, chars: Starts, then: tuple[Starts, bool]
) -> tuple[Starts, bool]:
    if op in _SINGLE:
        return then if _item(op, arg, flags)[0] & chars else (frozenset(), False)
    if op is _sre.SUBPATTERN:
        _group, add, remove, items = arg
        return _follow(items, (flags | add) & ~remove, chars, then)
    if op is _sre.BRANCH:
        found: set[str] = set()
        may_end = False
        for items in arg[1]:
            next_chars, ends = _follow(items, flags, chars, then)
            found |= next_chars
            may_end = may_end or ends
        return frozenset(found), may_end
    if op in _REPEATS:
        _low, high, items = arg
        again = _first(items, flags)[0] if high > 1 else frozenset()
        return _follow(items, flags, chars, (again | then[0], then[1]))
    if op is _sre.ATOMIC_GROUP:
        return _follow(arg, flags, chars, then)
    if op in _ZERO_WIDTH:
        return frozenset(), False
    return ANY, True  # anything else: anything may follow


def second_chars(parsed: Any, chars: Starts) -> Starts | None:
    """What the text may have right after a first character of ``chars`` where the parsed
    expression matches; None where it may also end there."""
    found, may_end = _follow(list(parsed), parsed.state.flags, chars, (ANY, True))
    return None if may_end else found


def first_chars(parsed: Any) -> Starts:
    """The members of ``ALPHABET`` a match of the parsed expression may start with."""
    found, empty = _first(list(parsed), parsed.state.flags)
    return ANY if empty else found


class Shapes:
    """What the matches of a grammar's terminals may start with, worked out once each."""

    def __init__(self, flags: int) -> None:
        self.flags = flags
        self.parsed: dict[str, Any] = {}
        self.firsts: dict[str, Starts] = {}
        self.seconds: dict[tuple[str, Starts], Starts | None] = {}

    def _parse(self, name: str, regexp: str) -> Any:
        if name not in self.parsed:
            self.parsed[name] = _sre.parse(regexp, self.flags)
        return self.parsed[name]

    def first(self, name: str, regexp: str) -> Starts:
        if name not in self.firsts:
            self.firsts[name] = first_chars(self._parse(name, regexp))
        return self.firsts[name]

    def tests_first(self, name: str, regexp: str) -> bool:
        """Whether the compiled expression starts with a test of one character that an
        alternation makes before trying it (a literal or a class, without case folding)."""
        parsed = self._parse(name, regexp)
        items = list(parsed)
        if not items or parsed.state.flags & re.IGNORECASE:
            return False
        return items[0][0] in (_sre.LITERAL, _sre.IN)

    def second(self, name: str, regexp: str, chars: Starts) -> Starts | None:
        """What may follow a first character of ``chars`` (None: the match may end there;
        nothing: it cannot start so)."""
        key = (name, chars)
        if key not in self.seconds:
            self.seconds[key] = second_chars(self._parse(name, regexp), chars)
        return self.seconds[key]


def char_class(chars: list[str]) -> str:
    """A regular-expression class of ``chars`` (any non-ASCII class: all non-ASCII characters,
    as the complement of the ASCII ones left out: a wide range makes ``re`` compile slowly)."""
    if not any(char in NON_ASCII for char in chars):
        return f"[{''.join(re.escape(char) for char in chars)}]"
    others = [chr(code) for code in range(128) if chr(code) not in chars]
    return f"[^{''.join(re.escape(char) for char in others)}]"

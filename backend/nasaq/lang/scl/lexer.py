"""The contextual lexer of the fast parse (``nasaq.lang.scl.lalr``): one regular-expression match
per token, and no ``Token`` for punctuation that no rule keeps.

Lark's contextual lexer matches one terminal per step, whitespace and comments too, and tries the
state's terminals one after the other. A ``Scanner`` makes the same choice as the state's Lark
scanner at every position (the same terminals in the same order) in one match:

- the ignored terminals are skipped first (possessively). The skip is exact: an ignored
  terminal is skipped only where no terminal Lark tries before it matches (``(?!...)``), as
  Lark's alternation takes the first that matches (a header value may begin with a blank);
- then only the terminals that may start with the next character are tried (a lookahead on
  the character selects them; each keeps Lark's order). An empty group after each terminal
  tells which matched: an alternative that starts with a plain character (``;``) is then
  dismissed by ``re`` on that character, without running a lookahead.

What a terminal may start with is read from its parsed regular expression, erring towards "it
may" (``nasaq.lang.scl.first_chars``). Where the fast parse cannot be sure to give what Lark
gives (no terminal matches, a reserved word read as a name, a line break Lark would not count),
it raises ``FastPathError`` and the source is parsed again by the recovering driver, which
reports the problem.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from operator import itemgetter
from sys import intern

from lark.lexer import BasicLexer, ContextualLexer, TerminalDef, UnlessCallback

from nasaq.lang.scl.first_chars import ALPHABET, NON_ASCII, Shapes, Starts, char_class


class FastPathError(Exception):
    """The fast parse cannot reproduce Lark here: the recovering driver parses the source."""


# A terminal's group in a scanner: (the terminal; for a name, the kinds its text may make it;
# whether the parser keeps the token; whether Lark counts line breaks in it).
Group = tuple[str, "Words | None", bool, bool]


@dataclass(frozen=True, slots=True)
class Scanner:
    """What one parser state's lexer needs per token."""

    # Skips ignored text (group 1), then matches one terminal, followed by its empty group.
    match: Callable[[str, int], re.Match[str] | None]
    rest: re.Pattern[str]  # ignored text (to check that it runs to the end of the source)
    groups: list[Group | None]  # by the number of the terminal's group (``lastindex``)


class Words(dict[str, str]):
    """The kind a name's text makes it, by the text as written: Lark's ``UnlessCallback`` (a
    name that spells a keyword of the state is that keyword) and the parse driver's retyping of
    reserved words (then a syntax error: ``""``). Each text is worked out once
    (``__missing__``) and remembered, up to ``LIMIT`` of them: the names of a program repeat,
    and a look-up is cheaper than upper-casing the text."""

    LIMIT = 10_000

    def __init__(self, kind: str, unless: UnlessCallback | None, reserved: frozenset[str]):
        super().__init__()
        self.kind = intern(kind)
        self.unless = unless
        self.reserved = reserved
        self.upper: dict[str, str] = dict.fromkeys(reserved, "")  # for ASCII text (``ascii``)
        self.ascii = True
        for terminal in unless.scanner.terminals if unless is not None else []:
            pattern = terminal.pattern
            if pattern.flags != {"i"} or not pattern.value.isascii():
                self.ascii = False  # not a case-insensitive ASCII word: match as Lark does
            self.upper[pattern.value.upper()] = intern(terminal.name)

    def __missing__(self, value: str) -> str:
        kind = self.kind_of(value)
        if len(self) < self.LIMIT:
            self[value] = kind
        return kind

    def kind_of(self, value: str) -> str:
        """The kind ``value`` is (``""``: a reserved word)."""
        if self.ascii and value.isascii():
            return self.upper.get(value.upper(), self.kind)
        found = self.unless.scanner.fullmatch(value) if self.unless is not None else None
        if found is not None:
            return intern(str(found))
        return "" if value.upper() in self.reserved else self.kind


class FastToken:
    """A token of the fast parse: what the AST builder reads of Lark's ``Token`` (its kind,
    text and position) in a plain object, cheaper to make than a ``Token`` (a ``str`` copy of
    the text with eight fields)."""

    __slots__ = ("column", "end_column", "end_line", "line", "type", "value")

    type: str
    value: str
    line: int
    column: int
    end_line: int
    end_column: int


# ---- scanners --------------------------------------------------------------------------------


def _skip(terminals: list[TerminalDef], ignored: frozenset[str], shapes: Shapes) -> str:
    """The ignored terminals, each where no terminal Lark tries before it matches."""
    skips: list[str] = []
    before: list[TerminalDef] = []
    for terminal in terminals:
        regexp = terminal.pattern.to_regexp()
        if terminal.name not in ignored:
            before.append(terminal)
            continue
        starts = shapes.first(terminal.name, regexp)
        rivals = [
            f"(?:{rival.pattern.to_regexp()})"
            for rival in before
            if shapes.first(rival.name, rival.pattern.to_regexp()) & starts
        ]
        guard = f"(?=(?:{regexp}))(?!{'|'.join(rivals)})" if rivals else ""
        skips.append(f"{guard}(?:{regexp})")
    return f"(?:{'|'.join(skips)})*+" if skips else ""


# A terminal tried before others is skipped on the text's second character where that rules it
# out cheaply; not where names and numbers may go on (the test would rarely fail).
_WORDY = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789")


def _guard(terminal: TerminalDef, chars: Starts, shapes: Shapes) -> str | None:
    """A test of the second character for ``terminal`` after a first one of ``chars``, where
    worthwhile (or ``""``); None where it cannot match there."""
    regexp = terminal.pattern.to_regexp()
    second = shapes.second(terminal.name, regexp, chars)
    if second is None or second >= _WORDY:
        return ""
    if not second:
        return None
    return f"(?=[\\s\\S]{char_class(sorted(second))})"


def _alone(terminal: TerminalDef, chars: Starts, shapes: Shapes) -> bool:
    """Whether ``terminal`` is the only one tried at ``chars``, starts with no other character
    and starts with a test of one character that ``re`` makes before trying an alternative
    (``;``): then it needs no lookahead to be tried only there."""
    regexp = terminal.pattern.to_regexp()
    return shapes.first(terminal.name, regexp) == chars and shapes.tests_first(
        terminal.name, regexp
    )


def _dispatch(kept: list[TerminalDef], shapes: Shapes) -> tuple[str, dict[str, str]]:
    """The alternation of ``kept`` per first character, and which group is which terminal."""
    starts = [
        (terminal, shapes.first(terminal.name, terminal.pattern.to_regexp())) for terminal in kept
    ]
    classes: dict[tuple[TerminalDef, ...], list[str]] = {}
    for chars in [*([char] for char in ALPHABET[:128]), list(NON_ASCII)]:
        candidates = tuple(terminal for terminal, first in starts if not first.isdisjoint(chars))
        if candidates:
            classes.setdefault(candidates, []).extend(chars)
    parts: list[tuple[int, str]] = []
    kinds: dict[str, str] = {}
    for candidates, chars in classes.items():
        groups: list[str] = []
        for index, terminal in enumerate(candidates):
            last = index == len(candidates) - 1  # tried last: no test saves time
            guard = "" if last else _guard(terminal, frozenset(chars), shapes)
            if guard is not None:
                group = f"t{len(kinds)}"
                kinds[group] = terminal.name
                groups.append(f"{guard}(?:{terminal.pattern.to_regexp()})(?P<{group}>)")
        if len(candidates) == 1 and _alone(candidates[0], frozenset(chars), shapes):
            parts.append((0, groups[0]))  # its first character is the test
        elif groups:
            parts.append((_rank(chars), f"(?={char_class(chars)})(?:{'|'.join(groups)})"))
    parts.sort(key=itemgetter(0))  # the classes are disjoint: any order gives the same match
    return "|".join(part for _, part in parts) or "(?!)", kinds


def _rank(chars: list[str]) -> int:
    """Where a class of first characters goes in the alternation: after the alternatives ``re``
    dismisses on their first character, the names (the commonest tokens), then numbers, then
    the rest."""
    if any(char.isascii() and char.isalpha() for char in chars):
        return 1
    return 2 if any(char.isdigit() for char in chars) else 3


def _words(
    lexer: BasicLexer, kept: list[TerminalDef], reserved: Mapping[str, frozenset[str]]
) -> dict[str, Words]:
    words: dict[str, Words] = {}
    for terminal in kept:
        name = terminal.name
        callback = lexer.callback.get(name)
        if callback is not None and not isinstance(callback, UnlessCallback):
            raise FastPathError(f"a lexer callback on {name}")
        if callback is not None or name in reserved:
            words[name] = Words(name, callback, reserved.get(name, frozenset()))
    return words


def _scanner(
    lexer: BasicLexer,
    shapes: Shapes,
    reserved: Mapping[str, frozenset[str]],
    dropped: frozenset[str],
) -> Scanner:
    terminals: list[TerminalDef] = lexer.scanner.terminals  # builds Lark's scanner first
    ignored = lexer.ignore_types
    if any(name in ignored for name in lexer.callback):
        raise FastPathError("an ignored terminal has a lexer callback")
    if not ignored <= lexer.newline_types:
        raise FastPathError("an ignored terminal Lark counts no line breaks in")
    if lexer.g_regex_flags != shapes.flags:
        raise FastPathError("lexers with different flags")
    kept = [terminal for terminal in terminals if terminal.name not in ignored]
    skip = _skip(terminals, ignored, shapes)
    dispatch, kinds = _dispatch(kept, shapes)
    words = _words(lexer, kept, reserved)
    pattern = re.compile(f"({skip})(?:{dispatch})", lexer.g_regex_flags)
    groups: list[Group | None] = [None] * (pattern.groups + 1)  # a terminal's own groups: None
    for group, kind in kinds.items():
        info = (intern(kind), words.get(kind), kind not in dropped, kind in lexer.newline_types)
        groups[pattern.groupindex[group]] = info
    return Scanner(match=pattern.match, rest=re.compile(skip, lexer.g_regex_flags), groups=groups)


def line_breaks(text: str) -> list[int]:
    """The offsets of the line breaks in ``text``, and one past its end (Lark counts ``\\n``)."""
    found = [match.start() for match in re.finditer("\n", text)]
    found.append(len(text) + 1)
    return found


class FastLexer:
    """The scanners of a parser's states, made on first use (most states never lex), and once
    per parser. ``reserved``: per terminal, the words the parse driver would turn into keywords
    (which makes them syntax errors); ``dropped``: the terminals no rule keeps."""

    def __init__(
        self,
        contextual: ContextualLexer,
        reserved: Mapping[str, frozenset[str]],
        dropped: frozenset[str],
    ):
        self.lexers: dict[int, BasicLexer] = contextual.lexers  # type: ignore[assignment]
        self.reserved = reserved
        self.dropped = dropped
        self.shapes = Shapes(contextual.root_lexer.g_regex_flags)  # type: ignore[attr-defined]
        self.by_lexer: dict[int, Scanner] = {}
        self.by_state: list[Scanner | None] = [None] * (max(self.lexers, default=-1) + 1)

    def scanner(self, state: int) -> Scanner:
        lexer = self.lexers[state]
        found = self.by_lexer.get(id(lexer))
        if found is None:
            found = _scanner(lexer, self.shapes, self.reserved, self.dropped)
            self.by_lexer[id(lexer)] = found
        self.by_state[state] = found
        return found

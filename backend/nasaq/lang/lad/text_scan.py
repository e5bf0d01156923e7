"""A cursor over LAD/FBD text for the recursive-descent reader (``text_parse``).

The format mixes keywords with operands kept exactly as written (``I 0.1``, ``B#(1,2)``,
``"Motor".speed``), so the reader does not split the text into tokens first: it asks the
scanner for the next word, a punctuation mark, the rest of a line or a raw operand, and the
scanner skips blanks and comments (``//`` and ``(* *)``) in between. Positions are 1-based
line/column pairs; every problem the scanner meets becomes a diagnostic, never an exception.
"""

from __future__ import annotations

import bisect
import re
from dataclasses import dataclass, field
from typing import Any

from nasaq.diagnostics import Diagnostic, Span, render

_WORD = re.compile(r"[A-Za-z_]\w*")
_SKIPPABLE = re.compile(r"(?:\s+|//[^\n]*|\(\*[\s\S]*?\*\))*")
_PUNCTUATION = (":=", "=>", "(", ")", ",", ":", "=")


@dataclass(frozen=True, slots=True)
class Pos:
    line: int
    column: int


@dataclass
class Scanner:
    text: str
    file: str
    pos: int = 0
    diagnostics: list[Diagnostic] = field(default_factory=list)
    network: int | None = None
    truncated: bool = False
    ended: bool = False
    # The structure words of a format that embeds LAD text (the Graph format's END_CONDITION,
    # STEP ...): while reading LAD there, an element, operand or recovery ends before them.
    host_words: frozenset[str] = frozenset()
    _lines: list[int] = field(default_factory=list)
    _peeked: re.Match[str] | None = None  # the last peeked word: ``word`` takes it

    def __post_init__(self) -> None:
        self._lines = [0] + [m.end() for m in re.finditer(r"\n", self.text)]

    # ---- positions and problems -----------------------------------------------------------
    def where(self, offset: int | None = None) -> Pos:
        at = self.pos if offset is None else offset
        line = bisect.bisect_right(self._lines, at)
        return Pos(line, at - self._lines[line - 1] + 1)

    def report(self, code: str, at: Pos | int | None = None, **params: Any) -> None:
        """Adds a diagnostic; none after an unclosed ``(*`` and only one at the end of the
        file: the others would be consequences of the first."""
        if self.truncated:
            return
        if at is None and self.pos >= len(self.text):
            if self.ended:  # the end of the file was already reported as missing something
                return
            self.ended = True
        spot = at if isinstance(at, Pos) else self.where(at)
        span = Span(file=self.file, line=spot.line, column=spot.column, network=self.network)
        self.diagnostics.append(render(code, span, **params))

    # ---- skipping -------------------------------------------------------------------------
    def skip(self) -> None:
        """Skips blanks and comments; an unclosed ``(*`` is reported and ends the text."""
        text = self.text
        pos = self.pos
        if pos < len(text) and not text[pos].isspace() and text[pos] not in "/(":
            return  # the common case: already at a word or a mark
        skipped = _SKIPPABLE.match(text, pos)
        self.pos = pos = skipped.end() if skipped else pos
        if text.startswith("(*", pos):  # a closed one would have been skipped
            self.report("LAD126")
            self.truncated = True
            self.pos = len(text)

    def at_end(self) -> bool:
        self.skip()
        return self.pos >= len(self.text)

    # ---- reading --------------------------------------------------------------------------
    def peek_word(self) -> str | None:
        """The next word in upper case (keywords are case-insensitive), not consumed."""
        self.skip()
        found = self._peeked = _WORD.match(self.text, self.pos)
        return found.group().upper() if found else None

    def word(self) -> str:
        """Consumes the next word as written (the caller has peeked it)."""
        self.skip()
        found = self._peeked
        if found is None or found.start() != self.pos:
            found = _WORD.match(self.text, self.pos)
        assert found is not None
        self.pos = found.end()
        return found.group()

    def take(self, mark: str) -> bool:
        """Consumes ``mark`` (``(``, ``:=`` ...) when it comes next."""
        self.skip()
        if self.text.startswith(mark, self.pos):
            self.pos += len(mark)
            return True
        return False

    def looking_at(self, mark: str) -> bool:
        self.skip()
        return self.text.startswith(mark, self.pos)

    def found(self) -> str:
        """What comes next, for a message: a word, a mark, a short run of text, or the end."""
        self.skip()
        if self.pos >= len(self.text):
            return "the end of the file"
        word = _WORD.match(self.text, self.pos)
        if word:
            return f"'{word.group()}'"
        for mark in _PUNCTUATION:
            if self.text.startswith(mark, self.pos):
                return f"'{mark}'"
        run = re.match(r"[^\s,()]{1,20}", self.text[self.pos :])
        return f"'{run.group() if run else self.text[self.pos]}'"

    def line_text(self) -> str:
        """The rest of the current line, stripped (a TITLE or COMMENT text)."""
        end = self.text.find("\n", self.pos)
        end = len(self.text) if end < 0 else end
        value = self.text[self.pos : end]
        self.pos = end
        return value.strip()

    def operand(self, keywords: frozenset[str] = frozenset()) -> str:
        """An operand as written, up to the ``,`` or ``)`` that ends it, the end of the line,
        ``:=``/``=>`` (a pin) or a word of ``keywords`` after a blank (a forgotten ``)``);
        ``(...)``, ``[...]`` and quoted text are taken whole, comments dropped."""
        self.skip()
        text = self.text
        parts: list[str] = []
        depth = 0
        start = self.pos
        while self.pos < len(text):
            char = text[self.pos]
            if char == "\n" or (depth == 0 and char in ",)"):
                break
            if depth == 0 and text.startswith((":=", "=>"), self.pos):  # a pin, not an operand
                break
            if depth == 0 and char in " \t" and self.pos > start:
                word = _WORD.match(text, self.pos + 1)
                if word and (
                    word.group().upper() in keywords or word.group().upper() in self.host_words
                ):
                    break
            if text.startswith("//", self.pos) or text.startswith("(*", self.pos):
                parts.append(text[start : self.pos])
                self.skip()
                start = self.pos
                continue
            if char in "\"'":
                close = text.find(char, self.pos + 1)
                newline = text.find("\n", self.pos + 1)
                if close < 0 or (0 <= newline < close):
                    self.report("LAD127")  # then read on as if the quote were not there
                    self.pos += 1
                    continue
                self.pos = close + 1
                continue
            if char in "([":
                depth += 1
            elif char in ")]":
                depth = max(depth - 1, 0)
            self.pos += 1
        parts.append(text[start : self.pos])
        return "".join(parts).strip()

    def skip_line(self) -> None:
        end = self.text.find("\n", self.pos)
        self.pos = len(self.text) if end < 0 else end

    def skip_to(self, stops: frozenset[str]) -> None:
        """Recovery: drops text up to the next word in ``stops`` standing outside parentheses
        (a newline closes any parenthesis left open)."""
        text = self.text
        depth = 0
        while True:
            before = self.pos
            self.skip()
            if "\n" in text[before : self.pos]:
                depth = 0
            if self.pos >= len(text):
                return
            word = _WORD.match(text, self.pos)
            if word:
                upper = word.group().upper()
                if depth == 0 and (upper in stops or upper in self.host_words):
                    return
                self.pos = word.end()
                continue
            char = text[self.pos]
            if char in "\"'":
                close = text.find(char, self.pos + 1)
                newline = text.find("\n", self.pos + 1)
                self.pos = self.pos + 1 if close < 0 or 0 <= newline < close else close + 1
                continue
            if char == "(":
                depth += 1
            elif char == ")":
                depth = max(depth - 1, 0)
            self.pos += 1

"""Reads one action row of a step: ``[event] qualifier[C] operand [, time] [@id];`` and the
``// comment`` after its ``;``.

The C suffix is glued (``NC``) or a separate ``C`` followed by something that is not a digit,
a comma or an ``@`` (so ``CS C 1, C#26`` is the counter C 1 with its preset). A row whose
operand holds ``:=`` outside parentheses is an assignment (``N #A := #A + 1``): the operand is
the whole assignment, its blanks collapsed and one blank either side of ``:=``. A CALL's operand
is the rest of the row (``FB 2, DB 2``). Other operands and times are kept as written (``(* *)``
comments dropped). Which event goes with which qualifier is the checker's business: any
combination reads. A broken row is reported and skipped up to its ``;`` (or the end of its
line when the ``;`` is missing), so reading goes on with the next row.

Speed: a row of plain text (no quotes, brackets, comments, ``@`` or ``/`` before its ``;``) is
split by one regular expression (``_quick``), which gives what the general reading gives for
it; any other row, and any row the quick way has a doubt about, takes the general way.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import cast

from nasaq.lang.graph.model import Action, Event, Qualifier
from nasaq.lang.graph.text_words import EVENTS, QUALIFIERS, ROW_STOPS
from nasaq.lang.lad.text_scan import Scanner

_WORD = re.compile(r"[A-Za-z_]\w*")
_NAME = re.compile(r"[A-Za-z_]\w*\Z")
_BLANKS = re.compile(r"[ \t]*")
# What can end a row or needs a closer look while looking for its end.
_ROW_MARK = re.compile(r"[;\n\"'()\[\]]|//|[ \t]+(?=[A-Za-z_])")
_MARK = re.compile(r"[\"'()\[\],@]|:=")
# A plain row after blanks: [event] qualifier, then up to its ';' nothing that needs a closer
# look; then its // comment, if any.
_PLAIN_ROW = re.compile(
    r"\s*(?:([A-Za-z]\d)[ \t]+)?([A-Za-z]+)[ \t]+([^;\n\"'()\[\]@/]*);(?:[ \t]*//([^\n]*))?"
)
_BLANK_WORD = re.compile(r"[ \t]([A-Za-z_]\w*)")  # a word after a blank: may end a row
_BLANK_RUN = re.compile(r"[ \t]+")
_QUOTED = re.compile(r"\"[^\"]*\"?|'[^']*'?")
# What ``_qualifier`` makes of each word it accepts.
_QUALIFIERS = {f"{word}C": (word, True) for word in QUALIFIERS} | {
    word: (word, False) for word in QUALIFIERS
}


@dataclass(slots=True)
class Row:
    """The parts of a row as read; ``Action`` is built once its number is known."""

    event: str | None
    qualifier: str
    interlock: bool
    operand: str
    time: str | None
    id: str
    comment: str = ""

    def action(self, number: int) -> Action:
        """The row as the ``number``-th action of its step."""
        return Action(
            id=self.id or f"a{number}",
            event=cast("Event | None", self.event),
            qualifier=cast("Qualifier", self.qualifier),
            interlock=self.interlock,
            operand=self.operand,
            time=self.time,
            comment=self.comment,
        )


def read_row(scan: Scanner) -> Row | None:
    """The row at the scanner (which stands on its first character); None when it is broken
    (reported). The scanner ends after the row's ``;`` and its ``//`` comment."""
    text = scan.text
    start = scan.pos
    row: Row | None
    end, closed = _row_end(scan, start)
    if closed is None:  # an unclosed quote or comment, reported: the row is lost
        row = None
        closed = False
    else:
        row = _parts(scan, start, end)
        if not closed:
            scan.report("GRA123", end, found=_found(text, end))
    scan.pos = end + 1 if closed else end
    if scan.pos == start:  # never stay on the same text
        scan.pos += 1
    spot = _skip_blanks(text, scan.pos, len(text))
    if text.startswith("//", spot):
        stop = text.find("\n", spot)
        stop = len(text) if stop < 0 else stop
        if row is not None:
            row.comment = text[spot + 2 : stop].strip()
        scan.pos = stop
    return row


def plain_row(text: str, pos: int, number: int) -> tuple[Action, int, int] | None:
    """The plain row after blanks at ``pos`` as ``read_row`` reads it (no diagnostic), as the
    ``number``-th action of its step, with where it starts and where reading goes on; None when
    the next row is not plain or has something to report (``read_row`` reads it then)."""
    plain = _PLAIN_ROW.match(text, pos)
    if plain is None:
        return None
    event, written, body, comment = plain.groups()
    pos = plain.start(3)
    end = plain.end(3)  # the ';'
    # The words after a blank: the qualifier (checked below) and those of the body.
    for word in _BLANK_WORD.findall(text, pos - 1, end):
        if word.upper() in ROW_STOPS:  # the row ends before it (its ';' is missing)
            return None
    if event is not None:
        event = event.upper()
        if event not in EVENTS:
            return None
    split = _QUALIFIERS.get(written.upper())
    if split is None:
        return None
    qualifier, interlock = split
    if not interlock and body[:1] in ("C", "c"):  # the C suffix as a word of its own
        suffix = _WORD.match(text, pos, end)
        if suffix and suffix.group().upper() == "C":
            after = _skip_blanks(text, suffix.end(), end)
            if suffix.end() < after < end and not (text[after].isdigit() or text[after] in ",@"):
                interlock = True
                body = text[after:end]
    time: str | None = None
    assignment = body.find(":=")
    if assignment >= 0:
        operand = f"{_collapse(body[:assignment])} := {_collapse(body[assignment + 2 :])}"
    elif qualifier == "CALL":
        operand = body.strip()
    elif (comma := body.find(",")) >= 0:
        if body.find(",", comma + 1) >= 0:
            return None
        operand = body[:comma].strip()
        time = body[comma + 1 :].strip()
        if not time:
            return None
    else:
        operand = body.strip()
    if not operand or operand.startswith(":="):
        return None
    action = Action(
        id=f"a{number}",
        event=cast("Event | None", event),
        qualifier=cast("Qualifier", qualifier),
        interlock=interlock,
        operand=operand,
        time=time,
        comment=comment.strip() if comment else "",
    )
    return action, plain.start(1 if event else 2), plain.end()


def _row_end(scan: Scanner, start: int) -> tuple[int, bool | None]:
    """Where the row ends: its ``;`` (True) or, when that is missing, the end of the line, a
    ``//`` comment or a Graph word after a blank (False); None after an unclosed quote or
    ``(*`` (reported)."""
    text = scan.text
    pos = start
    depth = 0
    while True:
        mark = _ROW_MARK.search(text, pos)
        if mark is None:
            return len(text), False
        found = mark.group()
        at = mark.start()
        if found == ";":
            return at, True
        if found in ("\n", "//"):
            return at, False
        if found == "(" and text.startswith("(*", at):
            close = text.find("*)", at + 2)
            if close < 0:
                scan.report("LAD126", at)
                scan.truncated = True  # as the scanner does: the rest is the comment
                return len(text), None
            pos = close + 2
        elif found in "\"'":
            close = text.find(found, at + 1)
            newline = text.find("\n", at + 1)
            if close < 0 or 0 <= newline < close:
                scan.report("LAD127", at)
                return (len(text) if newline < 0 else newline), None
            pos = close + 1
        elif found in "([":
            depth += 1
            pos = at + 1
        elif found in ")]":
            depth = max(depth - 1, 0)
            pos = at + 1
        else:  # blanks before a word
            word = _WORD.match(text, mark.end())
            assert word is not None
            if depth == 0 and at > start and word.group().upper() in ROW_STOPS:
                return at, False
            pos = word.end()


def _parts(scan: Scanner, start: int, end: int) -> Row | None:
    text = scan.text
    word = _WORD.match(text, start, end)
    event: str | None = None
    if word and word.group().upper() in EVENTS:
        event = word.group().upper()
        word = _WORD.match(text, _skip_blanks(text, word.end(), end), end)
    if word is None:
        at = _skip_blanks(text, start if event is None else start + 2, end)
        scan.report("GRA121", at, found=_found(text, at, end))
        return None
    written = word.group()
    split = _qualifier(written.upper())
    if split is None:
        scan.report("GRA121", word.start(), found=f"'{written}'")
        return None
    qualifier, interlock = split
    pos = _skip_blanks(text, word.end(), end)
    if not interlock:
        suffix = _WORD.match(text, pos, end)
        if suffix and suffix.group().upper() == "C":
            after = _skip_blanks(text, suffix.end(), end)
            if suffix.end() < after < end and not (text[after].isdigit() or text[after] in ",@"):
                interlock = True
                pos = after
    body = _without_comments(text[pos:end])
    marks = _top_level(body)
    row_id = ""
    at_sign = next((index for index, mark in marks if mark == "@"), None)
    if at_sign is not None:
        given = body[at_sign + 1 :].strip()
        if _NAME.match(given):
            row_id = given
        else:
            scan.report("GRA127", pos + at_sign, found=f"'@{given}'")
        body = body[:at_sign]
        marks = [(index, mark) for index, mark in marks if index < at_sign]
    time: str | None = None
    assignment = next((index for index, mark in marks if mark == ":="), None)
    if assignment is not None:
        operand = f"{_collapse(body[:assignment])} := {_collapse(body[assignment + 2 :])}"
    elif qualifier == "CALL":
        operand = body.strip()
    else:
        commas = [index for index, mark in marks if mark == ","]
        operand = body[: commas[0]].strip() if commas else body.strip()
        if len(commas) > 1:
            extra = body[commas[1] :].strip()
            scan.report("GRA124", pos + commas[1], found=f"'{extra[:20]}'")
            return None
        if commas:
            time = body[commas[0] + 1 :].strip()
            if not time:
                scan.report("GRA125", pos + commas[0], qualifier=written)
                return None
    if not operand or operand.startswith(":="):
        scan.report("GRA122", word.start(), qualifier=written)
        return None
    return Row(event, qualifier, interlock, operand, time, row_id)


def _qualifier(word: str) -> tuple[str, bool] | None:
    """``N`` → (N, False), ``NC`` → (N, True); None when ``word`` is no qualifier."""
    if word in QUALIFIERS:
        return word, False
    if word.endswith("C") and word[:-1] in QUALIFIERS:
        return word[:-1], True
    return None


def _skip_blanks(text: str, pos: int, end: int) -> int:
    blank = _BLANKS.match(text, pos, end)
    return blank.end() if blank else pos


def _found(text: str, pos: int, end: int | None = None) -> str:
    """What stands at ``pos``, for a message."""
    stop = len(text) if end is None else end
    if pos >= len(text):
        return "the end of the file"
    if pos >= stop or text[pos] == "\n":
        return "the end of the line"
    run = re.match(r"\S{1,20}", text[pos:stop])
    return f"'{run.group() if run else text[pos]}'"


def _without_comments(text: str) -> str:
    """``text`` without its ``(* *)`` comments (quoted text kept whole)."""
    if "(*" not in text:
        return text
    parts: list[str] = []
    pos = 0
    start = 0
    while pos < len(text):
        char = text[pos]
        if char in "\"'":
            close = text.find(char, pos + 1)
            pos = len(text) if close < 0 else close + 1
            continue
        if text.startswith("(*", pos):
            close = text.find("*)", pos + 2)
            parts.append(text[start:pos])
            pos = len(text) if close < 0 else close + 2
            start = pos
            continue
        pos += 1
    parts.append(text[start:])
    return " ".join(parts)


def _top_level(text: str) -> list[tuple[int, str]]:
    """Where ``,``, ``:=`` and ``@`` stand outside quotes, parentheses and brackets."""
    marks: list[tuple[int, str]] = []
    depth = 0
    pos = 0
    while True:
        mark = _MARK.search(text, pos)
        if mark is None:
            return marks
        found = mark.group()
        pos = mark.end()
        if found in "\"'":
            close = text.find(found, pos)
            pos = len(text) if close < 0 else close + 1
        elif found in "([":
            depth += 1
        elif found in ")]":
            depth = max(depth - 1, 0)
        elif depth == 0:
            marks.append((mark.start(), found))


def _collapse(text: str) -> str:
    """Runs of blanks outside quotes made one blank, the ends stripped."""
    parts: list[str] = []
    pos = 0
    for quoted in _QUOTED.finditer(text):
        parts.append(_BLANK_RUN.sub(" ", text[pos : quoted.start()]))
        parts.append(quoted.group())
        pos = quoted.end()
    parts.append(_BLANK_RUN.sub(" ", text[pos:]))
    return "".join(parts).strip()

"""Watch and force tables (STEP 7's variable tables, "VAT") as project files: ``<name>.vat``.

The file is plain UTF-8 text, one row per line, so it exports, diffs and merges like a source::

    // Nasaq watch table: operand | format | modify value | force value // comment
    MW10         | DEC     | 5                    // set point
    "Motor"      | BOOL
    I 0.0        | BOOL    |          | TRUE      // start button, forced on
    T1           | S5TIME
    // a comment line of its own, as STEP 7 allows between rows

- Columns are separated by ``|``; trailing empty columns may be left out. ``//`` starts the
  row's comment. Both are literal inside double quotes (``"Symbol"``) and single quotes
  (``'A'``), so a symbol keeps its quotes in the operand column (a project-wide rename replaces
  the quoted ``"Name"`` tokens).
- Operand: an absolute address (``MW10``, ``I 0.0``, ``PIW256``, ``T1``, ``C5``,
  ``DB1.DBW2``), a symbol in double quotes, optionally followed by a member path
  (``"Tank".level``, ``"Line".cells[2]``), or a DB variable path (``DB1.level``).
- Format: empty (the default for the operand's type) or one of :data:`FORMATS`; STEP 7's
  names ``SIMATIC_TIME``, ``FLOATING_POINT``, ``CHARACTER`` and ``C#`` are read as ``S5TIME``,
  ``REAL``, ``CHAR`` and ``COUNTER``.
- Modify and force values are kept as typed (``5``, ``16#FF``, ``S5T#2S``, ``C#5``, ``TRUE``):
  the table stores them; sending them to the CPU is an online action of the watch table, as
  STEP 7's "Modify"/"Force" buttons send the VAT's values. The force column is the value a Force
  of the row applies; whether a force is active is the CPU's state, not the file's.
- Comment lines at the top, before the first row, are the file's header and are kept as they
  are; a line that is only ``// text`` further down is a comment row.

Reading recovers: a broken line gives one diagnostic (WAT8xx, with its line and column) and is
kept verbatim, so saving the table again loses nothing a user wrote; the good lines load.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from nasaq.diagnostics.catalogue import render
from nasaq.diagnostics.model import Diagnostic, Span
from nasaq.lang.stl.compiler import WATCH_TABLE_SUFFIXES

SUFFIX = WATCH_TABLE_SUFFIXES[0]
HEADER = "// Nasaq watch table: operand | format | modify value | force value // comment"
FORMATS = ("BOOL", "BIN", "HEX", "DEC", "REAL", "CHAR", "TIME", "S5TIME", "COUNTER")
_ALIASES = {
    "SIMATIC_TIME": "S5TIME",
    "FLOATING_POINT": "REAL",
    "CHARACTER": "CHAR",
    "C#": "COUNTER",
}
MAX_COLUMNS = 4
# Widths a row pads its operand and format to: row-local, so one long operand does not
# reflow every other line of a diff.
_OPERAND_WIDTH = 12
_FORMAT_WIDTH = 7
_VALUE_WIDTH = 8

_IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
_QUOTED = r'"[^"]+"'
_INDEX = r"\[\s*-?\d+(?:\s*,\s*-?\d+)*\s*\]"
_ABSOLUTE = re.compile(
    r"(?:P?[IQEA][BWD]?|[IQEAM][BWDX]?|[TCZ]|L[BWDX]?)\s?\d+(?:\.\d+)?", re.IGNORECASE
)
_DB_ABSOLUTE = re.compile(r"DB\d+\.DB[XBWD]\s?\d+(?:\.\d+)?", re.IGNORECASE)
_PATH = re.compile(rf"(?:{_QUOTED}|{_IDENT})(?:\.(?:{_IDENT}|{_QUOTED})|{_INDEX})*")


def is_operand(text: str) -> bool:
    """Whether ``text`` has the shape of something a watch row can name (whether it exists is
    the symbol table's and the CPU's to say)."""
    return any(pattern.fullmatch(text) for pattern in (_ABSOLUTE, _DB_ABSOLUTE, _PATH))


def format_of(text: str) -> str | None:
    """The canonical format name of ``text`` (any letter case, STEP 7 aliases); None if none."""
    upper = text.strip().upper()
    upper = _ALIASES.get(upper, upper)
    return upper if upper in FORMATS else None


@dataclass(frozen=True, slots=True)
class WatchRow:
    """A row: an operand with its format and values, or (operand empty) a comment line."""

    operand: str
    format: str | None = None
    modify: str = ""
    force: str = ""
    comment: str = ""


@dataclass(frozen=True, slots=True)
class BrokenLine:
    """A line that does not read as a row, kept as it was written."""

    text: str


Line = WatchRow | BrokenLine


@dataclass(slots=True)
class WatchTable:
    header: list[str] = field(default_factory=lambda: [HEADER])
    lines: list[Line] = field(default_factory=list)
    # (1-based line number of each entry of ``lines``, as read)
    line_numbers: list[int] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def rows(self) -> list[WatchRow]:
        return [line for line in self.lines if isinstance(line, WatchRow)]


class _LineError(ValueError):
    def __init__(self, code: str, column: int, **params: object) -> None:
        super().__init__(code)
        self.code = code
        self.column = column
        self.params = params


def _split(text: str) -> tuple[list[tuple[int, str]], str | None]:
    """The ``|`` columns of a line (each with its 1-based start column) and its ``//`` comment;
    separators inside quotes count as text."""
    columns: list[tuple[int, str]] = []
    start = 0
    quote: str | None = None
    quote_at = 0
    index = 0
    while index < len(text):
        char = text[index]
        if quote is not None:
            if char == quote:
                quote = None
        elif char in "\"'":
            quote, quote_at = char, index
        elif char == "|":
            columns.append((start + 1, text[start:index]))
            start = index + 1
        elif text.startswith("//", index):
            columns.append((start + 1, text[start:index]))
            return columns, text[index + 2 :].strip()
        index += 1
    if quote is not None:
        raise _LineError("WAT803", quote_at + 1)
    columns.append((start + 1, text[start:]))
    return columns, None


def _row(text: str) -> WatchRow | None:
    """The row a line holds; None for a blank line. Raises _LineError for a broken one."""
    columns, comment = _split(text)
    cells = [cell.strip() for _, cell in columns]
    if not any(cells):
        return None if comment is None else WatchRow("", comment=comment)
    if len(cells) > MAX_COLUMNS:
        raise _LineError("WAT804", columns[MAX_COLUMNS][0], count=len(cells), limit=MAX_COLUMNS)
    cells += [""] * (MAX_COLUMNS - len(cells))
    operand, format_text, modify, force = cells
    if not operand:
        raise _LineError("WAT805", 1)
    if not is_operand(operand):
        raise _LineError("WAT801", _column(columns, 0), operand=operand)
    chosen = format_of(format_text) if format_text else None
    if format_text and chosen is None:
        raise _LineError("WAT802", _column(columns, 1), format=format_text)
    return WatchRow(operand, chosen, modify, force, comment or "")


def _column(columns: list[tuple[int, str]], index: int) -> int:
    start, cell = columns[index]
    return start + len(cell) - len(cell.lstrip())


def parse(text: str, file: str | None = None) -> WatchTable:
    """Reads a table, recovering at every line: good rows load, each broken line gives one
    diagnostic and stays in the table verbatim."""
    table = WatchTable(header=[])
    in_header = True
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.rstrip()
        if in_header and line.lstrip().startswith("//"):
            table.header.append(line)
            continue
        in_header = False
        try:
            row = _row(line)
        except _LineError as error:
            where = Span(file=file, line=number, column=error.column)
            table.diagnostics.append(render(error.code, where, **error.params))
            table.lines.append(BrokenLine(line))
            table.line_numbers.append(number)
            continue
        if row is not None:
            table.lines.append(row)
            table.line_numbers.append(number)
    if not table.header:
        table.header = [HEADER]
    return table


def print_row(row: WatchRow) -> str:
    """One row as a line; trailing empty columns are left out."""
    if not row.operand:
        return f"// {row.comment}".rstrip()
    cells = [row.operand, row.format or "", row.modify, row.force]
    while len(cells) > 1 and not cells[-1]:
        cells.pop()
    widths = (_OPERAND_WIDTH, _FORMAT_WIDTH, _VALUE_WIDTH, _VALUE_WIDTH)
    text = " | ".join(cell.ljust(width) for cell, width in zip(cells, widths, strict=False))
    if row.comment:
        return f"{text.rstrip()}  // {row.comment}"
    return text.rstrip()


def print_table(table: WatchTable) -> str:
    """The file text of ``table``: its header, then one line per row (broken lines as read)."""
    lines = list(table.header or [HEADER])
    for line in table.lines:
        lines.append(line.text if isinstance(line, BrokenLine) else print_row(line))
    return "\n".join(lines) + "\n"

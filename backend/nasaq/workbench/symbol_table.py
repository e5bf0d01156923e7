"""A symbol table file as the rows of an editor, checked, and written back in any STEP 7 format.

Reading splits a file with the compiler's own readers (``nasaq.lang.stl.symbols``), so the editor
shows exactly what the compiler will read, but keeps every row, also those the compiler refuses,
with a problem beside it. Writing produces text those readers give back unchanged:
``read_rows(name, write_rows(name, rows)) == rows`` for rows as :func:`cleaned` leaves them
(fields stripped, no control characters: none of the formats can hold a line break or a tab in a
field).

The formats (see the reader's module for how each is read):

- ``.sdf``: ``"name","address","type","comment"``, each field padded with spaces to the STEP 7
  widths, as the SIMATIC Manager exports it;
- ``.asc``: ``126,`` then fixed columns (name 24, address 12, type 10, comment 80): a longer field
  cannot be written (:class:`TableError` API124);
- ``.seq``: ``126``, then the four fields, tab-separated;
- ``.csv``: a ``name,address,type,comment`` header, then comma-separated, quoted where needed.

In the project a table is text like every source. A download (:func:`export_bytes`) is what
STEP 7 reads: Windows-1252 with CRLF line ends; a character that code page lacks is refused
(API125) rather than replaced, so no symbol silently changes its name.
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Iterable
from typing import Any, Literal

from pydantic import BaseModel, Field

from nasaq.diagnostics import Diagnostic, render
from nasaq.ir.types import ELEMENTARY_BITS, TYPE_ALIASES
from nasaq.lang.stl.addresses import AddressError, Parsed, parse_address
from nasaq.lang.stl.symbol_fit import misfit
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES, _rows_asc, _rows_csv, _rows_seq

Format = Literal["sdf", "asc", "seq", "csv"]
FORMATS: tuple[Format, ...] = ("sdf", "asc", "seq", "csv")
ENCODING = "cp1252"  # what STEP 7 writes and reads
WIDTHS = {"name": 24, "address": 12, "type": 10, "comment": 80}  # the .asc columns
Column = Literal["name", "address", "type", "comment"]
FIELDS: tuple[Column, ...] = ("name", "address", "type", "comment")
MEDIA_TYPES: dict[Format, str] = {
    "sdf": "text/plain",
    "asc": "text/plain",
    "seq": "text/tab-separated-values",
    "csv": "text/csv",
}

_CONTROL = re.compile(r"[\x00-\x1f\x7f]")
_BLOCK_TYPE = re.compile(r"^(OB|FB|FC|SFB|SFC|DB|UDT|VAT)\s*(\d+)$")
_OTHER_TYPES = frozenset({"POINTER", "ANY", "BLOCK_FB", "BLOCK_FC", "BLOCK_DB", "BLOCK_SDB"})


class SymbolRow(BaseModel):
    name: str = ""
    address: str = ""
    type: str = ""
    comment: str = ""


class RowProblem(BaseModel):
    row: int = Field(description="0-based index of the row in the list")
    field: Column
    problem: Diagnostic


class TableError(ValueError):
    """A table that cannot be written or read: ``code`` and ``params`` for the API's answer."""

    def __init__(self, code: str, **params: Any) -> None:
        super().__init__(render(code, **params).message)
        self.code = code
        self.params = params


def format_of(name: str) -> Format | None:
    suffix = name[name.rfind(".") :].lower() if "." in name else ""
    return suffix[1:] if suffix in SYMBOL_TABLE_SUFFIXES else None  # type: ignore[return-value]


def cleaned(row: SymbolRow) -> SymbolRow:
    """What a file can hold: fields stripped, control characters as spaces, type upper case."""
    fields = {key: _CONTROL.sub(" ", getattr(row, key)).strip() for key in FIELDS}
    fields["type"] = fields["type"].upper()
    return SymbolRow(**fields)


def read_rows(name: str, text: str) -> list[SymbolRow]:
    """Every row the file has (blank lines skipped), as the compiler's reader splits it."""
    kind = format_of(name)
    reader = {"asc": _rows_asc, "seq": _rows_seq}.get(kind or "csv", _rows_csv)
    rows = []
    for _line, cells in reader(text.lstrip("\ufeff")):
        if not any(cells):
            continue
        padded = [*cells[:4], "", "", "", ""][:4]
        rows.append(cleaned(SymbolRow(**dict(zip(FIELDS, padded, strict=True)))))
    return rows


def write_rows(name: str, rows: Iterable[SymbolRow]) -> str:
    """The file text in the format ``name``'s suffix says; line ends ``\\n``."""
    kind = format_of(name) or "csv"
    items = [cleaned(row) for row in rows]
    items = [row for row in items if any(getattr(row, key) for key in FIELDS)]
    if kind == "asc":
        return "".join(_asc_line(number, row) for number, row in enumerate(items))
    if kind == "seq":
        return "".join(
            f"126\t{row.name}\t{row.address}\t{row.type}\t{row.comment}\n" for row in items
        )
    out = io.StringIO()
    if kind == "csv":
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(FIELDS)
        writer.writerows([row.name, row.address, row.type, row.comment] for row in items)
    else:
        writer = csv.writer(out, lineterminator="\n", quoting=csv.QUOTE_ALL)
        writer.writerows([getattr(row, key).ljust(WIDTHS[key]) for key in FIELDS] for row in items)
    return out.getvalue()


def _asc_line(number: int, row: SymbolRow) -> str:
    for key in FIELDS:
        value = getattr(row, key)
        if len(value) > WIDTHS[key]:
            raise TableError(
                "API124", row=number + 1, field=key, length=len(value), limit=WIDTHS[key]
            )
    fields = "".join(getattr(row, key).ljust(WIDTHS[key]) for key in FIELDS)
    return f"126,{fields}".rstrip() + "\n"


def export_bytes(kind: Format, rows: Iterable[SymbolRow]) -> bytes:
    """A download STEP 7 reads: Windows-1252, CRLF. TableError API125/API124 if it cannot."""
    items = list(rows)
    for number, row in enumerate(items):
        for key in FIELDS:
            for char in getattr(cleaned(row), key):
                try:
                    char.encode(ENCODING)
                except UnicodeEncodeError:
                    raise TableError("API125", row=number + 1, field=key, char=char) from None
    text = write_rows(f"export.{kind}", items)
    return text.replace("\n", "\r\n").encode(ENCODING)


def decode_upload(name: str, data: bytes) -> str:
    """An uploaded table's text: UTF-8 (with or without BOM) if it is that, else Windows-1252."""
    if b"\x00" in data:
        raise TableError("API126", name=name, reason="it is a binary file, not text")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode(ENCODING, errors="replace")


def merged(old: list[SymbolRow], new: list[SymbolRow]) -> list[SymbolRow]:
    """``old`` with ``new`` laid over it: a row of the same name (any case) is replaced in place,
    the others are appended in their order."""
    result = list(old)
    where = {row.name.casefold(): place for place, row in enumerate(result) if row.name}
    for row in new:
        place = where.get(row.name.casefold()) if row.name else None
        if place is None:
            where[row.name.casefold()] = len(result)
            result.append(row)
        else:
            result[place] = row
    return result


def problems(rows: list[SymbolRow], kind: Format | None = None) -> list[RowProblem]:
    """What is wrong with each row: its address, name (missing, duplicate), type (unknown, or
    not fitting the address: SYT002); for ``asc``
    also fields too long for its columns. Rows are numbered from 1 in the messages."""
    found: list[RowProblem] = []
    names: dict[str, int] = {}
    addresses: dict[str, tuple[int, str]] = {}

    def add(place: int, column: Column, code: str, **params: Any) -> None:
        problem = render(code, row=place + 1, **params)
        found.append(RowProblem(row=place, field=column, problem=problem))

    for place, row in enumerate(rows):
        if not any(getattr(row, key).strip() for key in FIELDS):
            continue
        address = " ".join(row.address.split())
        parsed: Parsed | None = None
        try:
            parsed = parse_address(address)
        except AddressError as error:
            reason = str(error) if address else "it is empty (e.g. I 0.0, MW 10, DB 1, FB 10)"
            add(place, "address", "API120", address=row.address, reason=reason)
        else:
            key = f"{parsed.kind}:{parsed.area}:{parsed.block}:{parsed.db}:{parsed.byte}:"
            key += f"{parsed.bit}:{parsed.width}:{parsed.number}"
            if key in addresses:
                first, other = addresses[key]
                add(place, "address", "API122", address=address, other=other, first=first + 1)
            else:
                addresses[key] = (place, row.name)
        if not row.name.strip():
            add(place, "name", "API129", address=address or "?")
        elif (first_name := names.setdefault(row.name.strip().casefold(), place)) != place:
            add(place, "name", "API121", name=row.name.strip(), first=first_name + 1)
        if row.type.strip() and not known_type(row.type):
            add(place, "type", "API123", type=row.type.strip())
        elif parsed is not None and (allowed := misfit(parsed, row.type)) is not None:
            add(place, "type", "SYT002", type=row.type.strip(), address=address, allowed=allowed)
        if kind == "asc":
            for field in FIELDS:
                value = getattr(row, field).strip()
                if len(value) > WIDTHS[field]:
                    add(place, field, "API124", field=field, length=len(value), limit=WIDTHS[field])
    return found


def known_type(text: str) -> bool:
    """A type a STEP 7 symbol may have: elementary, TIMER/COUNTER, or a block's (``FB 10``)."""
    upper = " ".join(text.upper().split())
    upper = TYPE_ALIASES.get(upper, upper)
    return upper in ELEMENTARY_BITS or upper in _OTHER_TYPES or _BLOCK_TYPE.match(upper) is not None

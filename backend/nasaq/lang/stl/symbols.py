"""Symbol tables: STEP 7 exports (``.sdf``, ``.asc``, ``.seq``) and a plain CSV.

- ``.csv``: ``name,address,type,comment`` (``;`` works as separator too; a first line whose
  first field is ``name`` or ``symbol`` is a header);
- ``.sdf`` (System Data Format): the same four fields, quoted and space-padded;
- ``.asc``: ``126,`` then fixed columns: name 24, address 12, type 10, comment 80 characters;
- ``.seq``: tab-separated, optionally led by the record code ``126``.
Addresses may use either mnemonic set (``E 0.0`` or ``I 0.0``, ``Z 1`` or ``C 1``).
Symbol names are matched without regard to case, as STEP 7 does.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic
from nasaq.lang.stl.addresses import AddressError, Parsed, parse_address
from nasaq.lang.stl.ast import Loc
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.symbol_fit import misfit
from nasaq.lang.system_blocks import SFB_NAMES, SFC_NAMES

SYMBOL_TABLE_SUFFIXES = (".sdf", ".asc", ".seq", ".csv")
SYSTEM_FILE = "<system blocks>"


@dataclass(frozen=True, slots=True)
class Symbol:
    name: str
    address: str  # as written, normalised spacing ("MW 10")
    parsed: Parsed
    type: str
    comment: str
    file: str
    line: int


@dataclass(slots=True)
class SymbolTable:
    symbols: dict[str, Symbol] = field(default_factory=dict)  # casefolded name -> symbol
    _blocks: dict[tuple[str, int], Symbol] = field(default_factory=dict, repr=False)
    _indexed: int = field(default=-1, repr=False)

    def get(self, name: str) -> Symbol | None:
        return self.symbols.get(name.casefold())

    def lookup(self, name: str) -> Symbol | None:
        """``get``, else the system block STEP 7 and TIA Portal know by that name (``TON`` is
        SFB 4) where no symbol of the program defines it."""
        return self.symbols.get(name.casefold()) or self.system(name)

    @staticmethod
    def system(name: str) -> Symbol | None:
        return _SYSTEM_SYMBOLS.get(name.casefold())

    def block_symbol(self, kind: str, number: int) -> Symbol | None:
        """The symbol naming a block (``"Main"`` for OB 1), if any (the first, should two)."""
        if self._indexed != len(self.symbols):  # index the symbols read so far (only ever added)
            self._blocks = {}
            for symbol in self.symbols.values():
                parsed = symbol.parsed
                if parsed.kind == "block" and parsed.block is not None:
                    self._blocks.setdefault((parsed.block.value, parsed.number), symbol)
            self._indexed = len(self.symbols)
        return self._blocks.get((str(kind), number))


def _rows_csv(text: str) -> list[tuple[int, list[str]]]:
    first = text.split("\n", 1)[0]
    delimiter = ";" if first.count(";") > first.count(",") else ","
    rows = []
    for number, row in enumerate(csv.reader(io.StringIO(text), delimiter=delimiter), start=1):
        cells = [cell.strip() for cell in row]
        if number == 1 and cells and cells[0].lower() in ("name", "symbol"):
            continue
        rows.append((number, cells))
    return rows


def _rows_asc(text: str) -> list[tuple[int, list[str]]]:
    rows = []
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        body = line[4:] if line[:4].strip(",").isdigit() and line[3:4] == "," else line
        cells = [body[0:24], body[24:36], body[36:46], body[46:126]]
        rows.append((number, [cell.strip() for cell in cells]))
    return rows


def _rows_seq(text: str) -> list[tuple[int, list[str]]]:
    rows = []
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        cells = [cell.strip() for cell in line.split("\t")]
        if cells and cells[0].isdigit() and len(cells) > 3:
            cells = cells[1:]
        rows.append((number, cells))
    return rows


def read_symbol_table(file: str, text: str, table: SymbolTable) -> list[Diagnostic]:
    """Adds the symbols of one file to ``table``; problems carry the file's line. A line that
    cannot be read is a warning (ignored); a type that does not fit its address is an error."""
    suffix = file.lower().rsplit(".", 1)[-1]
    reader = {"asc": _rows_asc, "seq": _rows_seq}.get(suffix, _rows_csv)
    diagnostics: list[Diagnostic] = []
    for number, cells in reader(text):
        where = Loc(number, 1, number, 1)
        if len(cells) < 2 or not cells[0] or not cells[1]:
            if any(cells):
                diagnostics.append(
                    problem(
                        "STL225", file, where, file=file, line=number, reason="no name or address"
                    )
                )
            continue
        name, address = cells[0], " ".join(cells[1].split())
        try:
            parsed = parse_address(address)
        except AddressError as error:
            diagnostics.append(
                problem("STL225", file, where, file=file, line=number, reason=str(error))
            )
            continue
        symbol = Symbol(
            name,
            address,
            parsed,
            cells[2].upper() if len(cells) > 2 else "",
            cells[3] if len(cells) > 3 else "",
            file,
            number,
        )
        allowed = misfit(parsed, symbol.type)
        if allowed is not None:
            # An error, but the symbol stays defined: its uses are not also reported as undefined.
            diagnostics.append(
                problem(
                    "SYT001",
                    file,
                    where,
                    file=file,
                    line=number,
                    name=name,
                    type=symbol.type,
                    address=address,
                    allowed=allowed,
                )
            )
        key = name.casefold()
        if key in table.symbols:
            first = table.symbols[key]
            diagnostics.append(problem("STL232", file, where, name=name, address=first.address))
            continue
        table.symbols[key] = symbol
    return diagnostics


def _system_symbol(kind: str, number: int, name: str) -> Symbol:
    address = f"{kind} {number}"
    return Symbol(name, address, parse_address(address), kind, "", SYSTEM_FILE, 0)


# The system blocks by their standard names (STEP 7's standard library symbols, TIA Portal's
# instruction names): a source may name them without a symbol table.
_SYSTEM_SYMBOLS: dict[str, Symbol] = {
    **{name.casefold(): _system_symbol("SFB", n, name) for n, name in SFB_NAMES.items()},
    **{name.casefold(): _system_symbol("SFC", n, name) for n, name in SFC_NAMES.items()},
}

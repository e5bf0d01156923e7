"""Symbol table rows: reading with the compiler's readers, checking, and writing every format so
that reading it back gives the same rows (and the compiler reads the same symbols)."""

from __future__ import annotations

import random
import string

import pytest

from nasaq.lang.stl.symbols import SymbolTable, read_symbol_table
from nasaq.workbench.symbol_table import (
    FORMATS,
    Format,
    SymbolRow,
    TableError,
    cleaned,
    decode_upload,
    export_bytes,
    known_type,
    merged,
    problems,
    read_rows,
    write_rows,
)

ROWS = [
    SymbolRow(name="Start", address="I 0.0", type="BOOL", comment="start button, NO"),
    SymbolRow(name="Level", address="MD 10", type="REAL", comment='level in % ("filtered")'),
    SymbolRow(name="LevelData", address="DB 10", type="FB 10", comment=""),
    SymbolRow(name="Flow; main", address="IW 64", type="INT", comment="a, b, c"),
]
_ADDRESSES = ["I 0.0", "Q 4.1", "MW 10", "MD 20", "DB 1", "FB 10", "T 5", "C 2", "IW 64"]


def _random_rows(rng: random.Random, kind: Format) -> list[SymbolRow]:
    letters = string.ascii_letters + string.digits + " _-.,'\"%/()éßü"
    if kind != "sdf":  # an .sdf has no header: its first line decides the separator
        letters += ";"

    def text(limit: int) -> str:
        return "".join(rng.choice(letters) for _ in range(rng.randint(0, limit)))

    rows = []
    for _ in range(rng.randint(1, 12)):
        name = text(24).strip() or "X"
        if name.casefold() in ("name", "symbol"):
            name += "1"
        rows.append(
            cleaned(
                SymbolRow(
                    name=name,
                    address=rng.choice(_ADDRESSES),
                    type=rng.choice(["BOOL", "INT", "", "REAL", "FB 10"]),
                    comment=text(80),
                )
            )
        )
    return rows


@pytest.mark.parametrize("kind", FORMATS)
def test_written_rows_read_back_unchanged(kind: Format) -> None:
    """The round trip property, over fixed and random rows in every format."""
    name = f"symbols.{kind}"
    assert read_rows(name, write_rows(name, ROWS)) == ROWS
    rng = random.Random(kind)
    for _ in range(300):
        rows = _random_rows(rng, kind)
        assert read_rows(name, write_rows(name, rows)) == rows


@pytest.mark.parametrize("kind", FORMATS)
def test_the_compiler_reads_the_written_symbols(kind: Format) -> None:
    name = f"symbols.{kind}"
    symbol_table = SymbolTable()
    assert read_symbol_table(name, write_rows(name, ROWS), symbol_table) == []
    level = symbol_table.get("level")
    assert level is not None
    assert (level.address, level.type, level.comment) == ("MD 10", "REAL", ROWS[1].comment)
    assert len(symbol_table.symbols) == len(ROWS)


def test_formats_have_the_step7_layout() -> None:
    asc = write_rows("s.asc", ROWS[:1]).splitlines()[0]
    assert asc.startswith("126,Start" + " " * 19 + "I 0.0" + " " * 7 + "BOOL")
    assert asc[4 + 46 :] == "start button, NO"
    sdf = write_rows("s.sdf", ROWS[:1]).splitlines()[0]
    assert sdf.startswith('"Start                   ","I 0.0       ","BOOL      ","start')
    assert write_rows("s.seq", ROWS[:1]) == "126\tStart\tI 0.0\tBOOL\tstart button, NO\n"
    assert write_rows("s.csv", ROWS[:1]).splitlines()[0] == "name,address,type,comment"


def test_asc_refuses_fields_wider_than_its_columns() -> None:
    long_name = SymbolRow(name="N" * 25, address="M 0.0", type="BOOL")
    with pytest.raises(TableError) as caught:
        write_rows("s.asc", [long_name])
    assert caught.value.code == "API124"
    assert [p.problem.code for p in problems([long_name], "asc")] == ["API124"]
    assert problems([long_name], "sdf") == []


def test_problems_name_the_row_field_and_code() -> None:
    rows = [
        SymbolRow(name="A", address="I 0.0", type="BOOL"),
        SymbolRow(name="a", address="E 0.0", type="BOOL"),  # same name and address (German)
        SymbolRow(name="B", address="X 9", type="BOOL"),
        SymbolRow(name="", address="M 1.0", type="FLOAT"),
        SymbolRow(),  # empty rows are no problem
    ]
    found = [(p.row, p.field, p.problem.code) for p in problems(rows)]
    assert found == [
        (1, "address", "API122"),
        (1, "name", "API121"),
        (2, "address", "API120"),
        (3, "name", "API129"),
        (3, "type", "API123"),
    ]
    duplicate = problems(rows)[1].problem
    assert duplicate.params == {"row": 2, "name": "a", "first": 1}
    assert duplicate.severity == "error"
    assert problems(rows)[0].problem.severity == "warning"


def test_known_types() -> None:
    for good in ("BOOL", "int", "S5TIME", "TOD", "TIMER", "COUNTER", "FB 10", "UDT5", "OB 1"):
        assert known_type(good), good
    for bad in ("FLOAT", "FB", "STRING", "DB x"):
        assert not known_type(bad), bad


def test_export_is_windows_1252_with_crlf_and_refuses_other_characters() -> None:
    rows = [SymbolRow(name="Füller", address="Q 4.0", type="BOOL", comment="Straße")]
    data = export_bytes("seq", rows)
    assert data == "126\tFüller\tQ 4.0\tBOOL\tStraße\r\n".encode("cp1252")
    with pytest.raises(TableError) as caught:
        export_bytes("sdf", [SymbolRow(name="مضخة", address="Q 4.0", type="BOOL")])
    assert caught.value.code == "API125"
    assert caught.value.params == {"row": 1, "field": "name", "char": "م"}


def test_uploads_decode_as_utf8_or_windows_1252() -> None:
    assert decode_upload("a.sdf", "Füller".encode()) == "Füller"
    assert decode_upload("a.sdf", "\ufeffFüller".encode()) == "Füller"
    assert decode_upload("a.sdf", "Füller".encode("cp1252")) == "Füller"
    with pytest.raises(TableError):
        decode_upload("a.sdf", b"\x00\x01binary")


def test_merge_replaces_by_name_and_appends_the_rest() -> None:
    old = [SymbolRow(name="A", address="I 0.0"), SymbolRow(name="B", address="I 0.1")]
    new = [SymbolRow(name="b", address="I 0.2"), SymbolRow(name="C", address="I 0.3")]
    assert merged(old, new) == [old[0], new[0], new[1]]


def test_cleaning_removes_what_no_format_holds() -> None:
    row = cleaned(SymbolRow(name=" Tab\there ", address="i 0.0", type=" bool", comment="a\nb"))
    assert row == SymbolRow(name="Tab here", address="i 0.0", type="BOOL", comment="a b")

"""The watch table file format (nasaq.workbench.watch_table): round trip, recovery, codes."""

from nasaq.lang.stl.compiler import SourceFile, compile_sources
from nasaq.workbench.names import is_valid_name, language_of
from nasaq.workbench.watch_table import (
    HEADER,
    BrokenLine,
    WatchRow,
    WatchTable,
    format_of,
    is_operand,
    parse,
    print_table,
)

GOOD = f"""{HEADER}
MW10         | DEC     | 5  // set point
"Motor"      | BOOL
I 0.0        | BOOL    |          | TRUE  // start button
T1           | S5TIME  | S5T#1S850MS
C5           | COUNTER | C#5
"Tank".level | REAL
DB1.DBW2     | HEX     | 16#00FF
"a | b"      | CHAR    | '|'  // quotes keep | and // as text: "x // y"
// a comment line between rows
"""


def test_a_table_reads_its_rows_and_prints_back_the_same_text() -> None:
    table = parse(GOOD, "Tank.vat")
    assert table.diagnostics == []
    assert table.rows[0] == WatchRow("MW10", "DEC", "5", "", "set point")
    assert table.rows[1] == WatchRow('"Motor"', "BOOL")
    assert table.rows[2] == WatchRow("I 0.0", "BOOL", "", "TRUE", "start button")
    assert table.rows[3] == WatchRow("T1", "S5TIME", "S5T#1S850MS")
    assert table.rows[7].operand == '"a | b"'
    assert table.rows[7].modify == "'|'"
    assert table.rows[7].comment == 'quotes keep | and // as text: "x // y"'
    assert table.rows[8] == WatchRow("", comment="a comment line between rows")
    again = parse(print_table(table))
    assert again.lines == table.lines
    assert print_table(again) == print_table(table)


def test_printing_a_table_made_in_the_ui_reads_back() -> None:
    table = WatchTable(
        lines=[
            WatchRow("QW4", "BIN", force="2#1010"),
            WatchRow('"Pump"', comment="main pump"),
        ]
    )
    text = print_table(table)
    assert text.splitlines() == [
        HEADER,
        "QW4          | BIN     |          | 2#1010",
        '"Pump"  // main pump',
    ]
    assert parse(text).lines == table.lines


def test_broken_lines_give_one_located_error_each_and_the_good_lines_load() -> None:
    lines = [
        HEADER,
        "MW10 | DEC",
        "MW12 | DECIMALS",
        '"Motor | BOOL',
        "M 0.0 0.1 | BOOL",
        "MW14 | DEC | 1 | 2 | 3",
        " | HEX | 5",
        "QW4 | HEX",
    ]
    text = "\n".join(lines)
    table = parse(text, "Broken.vat")
    assert [row.operand for row in table.rows] == ["MW10", "QW4"]
    found = [(d.code, d.span.line if d.span else None) for d in table.diagnostics]
    assert found == [
        ("WAT802", 3),
        ("WAT803", 4),
        ("WAT801", 5),
        ("WAT804", 6),
        ("WAT805", 7),
    ]
    unknown = table.diagnostics[0]
    assert unknown.params == {"format": "DECIMALS"}
    assert unknown.span is not None
    assert (unknown.span.file, unknown.span.column) == (
        "Broken.vat",
        8,
    )
    assert table.diagnostics[1].span is not None
    assert table.diagnostics[1].span.column == 1
    assert table.diagnostics[3].params == {"count": 5, "limit": 4}
    # Nothing a user wrote is lost: a save writes the broken lines back as they were.
    printed = print_table(table).splitlines()
    for broken in lines[2:7]:
        assert broken in printed
    assert isinstance(table.lines[1], BrokenLine)


def test_operands_and_formats() -> None:
    for good in (
        "MW10",
        "I 0.0",
        "PIW256",
        "T1",
        "C 5",
        "DB1.DBX0.1",
        '"Motor"',
        "DB1.level",
    ):
        assert is_operand(good), good
    assert is_operand('"Line".cells[2].speed')
    for bad in ("M 0.0 0.1", "MW10)", '"Motor', "12", ""):
        assert not is_operand(bad), bad
    assert format_of("simatic_time") == "S5TIME"
    assert format_of("C#") == "COUNTER"
    assert format_of("dec") == "DEC"
    assert format_of("DECIMAL") is None


def test_header_comments_are_kept_and_a_file_without_one_gets_the_standard_header() -> None:
    mine = "// my checks\n// second line\nMW10 | DEC\n"
    assert print_table(parse(mine)).splitlines()[:2] == [
        "// my checks",
        "// second line",
    ]
    assert print_table(parse("MW10\n")) == f"{HEADER}\nMW10\n"
    assert parse("").rows == []


def test_a_watch_table_is_a_project_file_the_compiler_skips() -> None:
    assert is_valid_name("VAT_1.vat")
    assert language_of("Tank check.VAT") == "watch"
    program = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      NOP 0;\nEND_ORGANIZATION_BLOCK\n"
    result = compile_sources([SourceFile("OB1.awl", program), SourceFile("VAT_1.vat", GOOD)])
    assert [d.code for d in result.diagnostics if d.severity.value == "error"] == []

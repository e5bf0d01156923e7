"""Symbol tables in the STEP 7 export formats and plain CSV."""

from __future__ import annotations

from nasaq.lang.stl.symbols import SymbolTable, read_symbol_table

ASC = (
    "126,Motor_On                M 0.0       BOOL      the motor\n"
    "126,Main                    OB 1        OB 1                \n"
    "126,Counter1                Z 10        COUNTER             \n"
)


def _read(name: str, text: str) -> SymbolTable:
    table = SymbolTable()
    assert read_symbol_table(name, text, table) == []
    return table


def test_asc_fixed_columns() -> None:
    table = _read("s.asc", ASC)
    motor = table.get("motor_on")
    assert motor is not None
    assert motor.address == "M 0.0"
    assert motor.type == "BOOL"
    assert motor.comment == "the motor"
    assert table.block_symbol("OB", 1) is not None
    counter = table.get("Counter1")
    assert counter is not None
    assert counter.parsed.kind == "counter"


def test_sdf_quoted_fields() -> None:
    table = _read("s.sdf", '"Motor_On            ","M       0.0","BOOL      ","x"\n')
    found = table.get("Motor_On")
    assert found is not None
    assert found.address == "M 0.0"


def test_seq_tabs() -> None:
    table = _read("s.seq", "126\tStart\tE 0.0\tBOOL\tstart button\n")
    found = table.get("Start")
    assert found is not None
    assert found.parsed.language == "de"


def test_csv_with_header_and_semicolons() -> None:
    table = _read("s.csv", "name;address;type;comment\nValve;Q 4.0;BOOL;\n")
    assert table.get("valve") is not None


def test_bad_lines_are_warnings() -> None:
    table = SymbolTable()
    problems = read_symbol_table("s.csv", "A,XY 3,BOOL,\nB,M 0.0,BOOL,\nB,M 0.1,BOOL,\n", table)
    assert [item.code for item in problems] == ["STL225", "STL232"]
    found = table.get("B")
    assert found is not None
    assert found.address == "M 0.0"

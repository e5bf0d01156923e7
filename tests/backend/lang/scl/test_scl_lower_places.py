"""Where SCL variables live (``lower/places.py``): matrix rows, areas next to variables of the
same name, DBs chosen at run time, names that look like addresses."""

from __future__ import annotations

from scl_run import build, ob1, read

from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.scl.ast import Address, Assign, Name
from nasaq.lang.scl.parse import parse_source


def test_a_vector_assigned_to_a_row_of_a_matrix_fills_that_row_only() -> None:
    cpu = build(
        ob1(
            "FOR k := 1 TO 3 DO FOR j := 1 TO 3 DO m[k, j] := 0; END_FOR; END_FOR;\n"
            "v[1] := 11; v[2] := 12; v[3] := 13;\n"
            "m[2] := v;\n"
            "FOR k := 1 TO 3 DO\n"
            "  FOR j := 1 TO 3 DO MW[(k - 1) * 6 + (j - 1) * 2] := INT_TO_WORD(m[k, j]);"
            " END_FOR;\n"
            "END_FOR;",
            "m : ARRAY[1..3, 1..3] OF INT; v : ARRAY[1..3] OF INT; k, j : INT;",
        )
    )
    assert [read(cpu, f"MW{2 * n}") for n in range(9)] == [0, 0, 0, 11, 12, 13, 0, 0, 0]


def test_an_input_bit_indexed_by_a_variable_called_i_reads_the_input_area() -> None:
    source = ob1("i := 2; k := 3;\nM0.0 := I[i, k];", "i : INT; k : INT;")
    cpu = build(source)
    assert read(cpu, "M0.0") == 0
    bit = parse_address("I2.3")
    assert isinstance(bit, Direct)
    cpu.set_input(bit, 1)
    cpu.run(1)
    assert read(cpu, "M0.0") == 1


def test_a_data_block_chosen_at_run_time_by_word_to_block_db() -> None:
    db = "DATA_BLOCK DB7\nSTRUCT a : WORD := W#16#1234; b : WORD := W#16#5678; END_STRUCT\n"
    db += "BEGIN\nEND_DATA_BLOCK\n"
    body = "n := W#16#0007; k := 2;\nMW0 := WORD_TO_BLOCK_DB(n).DW[k];\n"
    body += "MW2 := WORD_TO_BLOCK_DB(n).DW0;"
    cpu = build(db + ob1(body, "n : WORD; k : INT;"))
    assert read(cpu, "MW0") == 0x5678
    assert read(cpu, "MW2") == 0x1234


def test_an_area_letter_and_a_number_without_a_bit_is_a_name() -> None:
    source = "FUNCTION FC1 : VOID\nVAR_TEMP m1 : INT; END_VAR\nBEGIN\n"
    source += "m1 := 5; M1.0 := TRUE;\nEND_FUNCTION\n"
    block = parse_source("x.scl", source).source.blocks[0]
    first, second = block.code
    assert isinstance(first, Assign)
    assert isinstance(second, Assign)
    assert first.target == Name("m1")
    assert second.target == Address("M1.0")
    cpu = build(ob1("m1 := 40 / 8;\nMW4 := INT_TO_WORD(m1);", "m1 : INT;"))
    assert read(cpu, "MW4") == 5

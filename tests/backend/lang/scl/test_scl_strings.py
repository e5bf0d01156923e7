"""STRING values compiled by the SCL lowering (``lower/strings.py``, ``lower/references.py``) and
run on the CPU: assignments from constants, variables and CHARs into any place, comparisons, and
the IEC library's string functions called from SCL (``CALL "CONCAT"``)."""

from __future__ import annotations

from scl_run import build, ob1, read

from nasaq.cpu import Cpu
from nasaq.headless.addresses import parse_address
from nasaq.ir import BlockKind, Direct
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block


def text(cpu: Cpu, db: int, byte: int) -> tuple[int, str]:
    """(maximum length, characters) of the STRING at ``byte`` of DB ``db``."""
    data = cpu.db_bytes(db)
    assert data is not None
    return data[byte], data[byte + 2 : byte + 2 + data[byte + 1]].decode("latin-1")


TEXTS = """DATA_BLOCK Texts
STRUCT
  a : STRING[10] := 'Motor';
  b : STRING[4];
  arr : ARRAY[1..3] OF STRING[6];
  n : INT;
  c : CHAR;
  flags : ARRAY[0..7] OF BOOL;
END_STRUCT
BEGIN
END_DATA_BLOCK
"""
# Texts (DB1): a 0, b 12, arr[k] 18 + 8 (k - 1), n 42, c 44, flags 46


# ---- assignments --------------------------------------------------------------------------------


def test_constants_into_strings_keep_the_maximum_length_and_are_cut_to_it() -> None:
    source = (
        TEXTS
        + """FUNCTION_BLOCK FB1
CONST
  greeting := 'Pump on';
END_CONST
VAR
  s : STRING[5];
  t : STRING[20] := 'Valve';
  u : STRING[8] := 'full';
END_VAR
  s := greeting;        // 'Pump ' (cut to 5)
  t := '$41$4E';        // 'AN'
  u := '';
  Texts.b := 'abcdef';  // 'abcd'
END_FUNCTION_BLOCK
"""
        + ob1("FB1.DB2();")
    )
    cpu = build(source)
    assert text(cpu, 2, 0) == (5, "Pump ")
    assert text(cpu, 2, 8) == (20, "AN")
    assert text(cpu, 2, 30) == (8, "")
    assert text(cpu, 1, 12) == (4, "abcd")


def test_string_variables_copy_between_any_places() -> None:
    source = (
        TEXTS
        + """FUNCTION_BLOCK FB1
VAR
  rec : STRUCT
    name : STRING[8];
    tag : STRING[3];
  END_STRUCT;
  k : INT;
END_VAR
VAR_TEMP
  local : STRING[12];
END_VAR
  local := Texts.a;             // DB -> L
  rec.name := local;            // L -> instance (a structure member)
  rec.tag := rec.name;          // 'Mot'
  FOR k := 1 TO 3 DO            // variable index as the target
    Texts.arr[k] := rec.tag;
  END_FOR;
  k := 2;
  Texts.arr[k] := 'xy';
  Texts.b := Texts.arr[k];      // variable index as the source
  Texts.arr[3] := Texts.arr[3]; // a string onto itself
END_FUNCTION_BLOCK
"""
        + ob1("FB1.DB2();")
    )
    cpu = build(source)
    assert text(cpu, 2, 0) == (8, "Motor")
    assert text(cpu, 2, 10) == (3, "Mot")
    assert [text(cpu, 1, 18 + 8 * k) for k in range(3)] == [(6, "Mot"), (6, "xy"), (6, "Mot")]
    assert text(cpu, 1, 12) == (4, "xy")


def test_fc_parameters_and_return_value_pass_strings_by_pointer() -> None:
    source = (
        TEXTS
        + """FUNCTION Shout : STRING[12]
VAR_INPUT
  s : STRING;
END_VAR
VAR_IN_OUT
  io : STRING;
END_VAR
VAR_OUTPUT
  o : STRING[8];
END_VAR
  Shout := CONCAT(IN1 := s, IN2 := '!');
  o := io;
  io := 'abcdefghij';   // the actual's maximum length (its byte 0) cuts it
END_FUNCTION
"""
        + ob1(
            "io := 'in';\n"
            "k := 2;\n"
            "Texts.arr[k] := 'ab';\n"
            "s := Shout(s := Texts.arr[k], io := io, o := o);\n"
            "MW10 := INT_TO_WORD(LEN(s));\n"
            "MW12 := INT_TO_WORD(LEN(o));\n"
            "MW14 := INT_TO_WORD(LEN(io));\n"
            "Texts.b := s;",
            "k : INT; s : STRING[20]; o : STRING[8]; io : STRING[5];",
        )
    )
    cpu = build(source)
    assert [read(cpu, word) for word in ("MW10", "MW12", "MW14")] == [3, 2, 5]
    assert text(cpu, 1, 12) == (4, "ab!")


def test_an_fb_in_out_string_is_reached_through_its_pointer() -> None:
    source = (
        TEXTS
        + """FUNCTION_BLOCK Keeper
VAR_IN_OUT
  ref : STRING[6];
END_VAR
VAR
  copy : STRING[6];
  k : INT;
END_VAR
  copy := ref;
  ref := 'keep';
  k := LEN(ref);
END_FUNCTION_BLOCK
"""
        + ob1("Keeper.DB5(ref := Texts.arr[1]);\nMW0 := INT_TO_WORD(DB5.k);")
    )
    cpu = build(source)
    assert text(cpu, 1, 18) == (6, "keep")
    assert text(cpu, 5, 6) == (6, "")  # the empty string that was there before
    assert read(cpu, "MW0") == 4


def test_a_char_becomes_a_one_character_string_and_back() -> None:
    source = TEXTS + ob1(
        "c := 'Q';\n"
        "Texts.b := c;\n"
        "Texts.arr[1] := CHAR_TO_STRING(c);\n"
        "Texts.c := STRING_TO_CHAR(Texts.a);",
        "c : CHAR;",
    )
    cpu = build(source)
    assert text(cpu, 1, 12) == (4, "Q")
    assert text(cpu, 1, 18) == (6, "Q")
    assert read(cpu, "DB1.DBB44") == ord("M")


def test_string_temporaries_get_their_maximum_length_at_the_start() -> None:
    # in OB1 the first 20 bytes of the L stack hold the start information: a STRING there
    # would have garbage as its maximum length without S7-SCL's initialisation
    source = TEXTS + ob1(
        "t := CONCAT(IN1 := Texts.a, IN2 := 'way');\n"
        "Texts.arr[1] := t;\n"
        "MW0 := INT_TO_WORD(LEN(t));",
        "t : STRING[6];",
    )
    cpu = build(source)
    assert read(cpu, "MW0") == 6
    assert text(cpu, 1, 18) == (6, "Motorw")


# ---- comparisons --------------------------------------------------------------------------------


def test_comparisons_call_the_library_and_order_by_character_code() -> None:
    source = TEXTS + ob1(
        "k := 2;\n"
        "Texts.arr[k] := 'ab';\n"
        "Texts.c := 'Z';\n"
        "Texts.arr[3] := Texts.c;\n"
        "Texts.flags[0] := Texts.a = 'Motor';\n"
        "Texts.flags[1] := Texts.a < 'Motorway';\n"  # a prefix is smaller
        "Texts.flags[2] := Texts.a > 'Mo';\n"
        "Texts.flags[3] := 'motor' > Texts.a;\n"  # 'm' 16#6D > 'M' 16#4D
        "Texts.flags[4] := Texts.arr[k] <> 'ab';\n"
        "Texts.flags[5] := Texts.c = Texts.arr[3];\n"  # a CHAR with a STRING
        "Texts.flags[6] := Texts.a <= Texts.b OR Texts.b >= 'x';\n"  # '' >= 'x' FALSE
        "IF Texts.arr[k] = 'ab' AND NOT (Texts.a = Texts.b) THEN Texts.flags[7] := TRUE; END_IF;",
        "k : INT;",
    )
    cpu = build(source)
    assert read(cpu, "DB1.DBB46") & 0xFF == 0b10101111


def test_a_search_in_an_array_of_strings_with_exit() -> None:
    source = """FUNCTION_BLOCK FB1
VAR
  I : INT;
  IDWORD : ARRAY[1..50] OF STRING;
END_VAR
  FOR I := 1 TO 50 BY 2 DO
    IF IDWORD[I] = 'KEY' THEN
      M0.0 := true;
      EXIT;
    END_IF;
  END_FOR;
END_FUNCTION_BLOCK
""" + ob1("FB1.DB1();")
    cpu = build(source)
    assert (read(cpu, "M0.0"), read(cpu, "DB1.DBW0")) == (0, 51)
    start = 2 + 256 * 4  # IDWORD[5]
    for offset, value in enumerate(b"\xfe\x03KEY"):
        cpu.write(parse_address(f"DB1.DBB{start + offset}"), value)  # type: ignore[arg-type]
    cpu.run(1)
    assert (read(cpu, "M0.0"), read(cpu, "DB1.DBW0")) == (1, 5)


# ---- library functions --------------------------------------------------------------------------


def test_nested_string_functions_use_hidden_string_temporaries() -> None:
    source = TEXTS + ob1(
        "no := 12;\n"
        "Texts.arr[1] := CONCAT(IN1 := 'M', IN2 := RIGHT(L := 2, IN := I_STRNG(no)));\n"
        "Texts.n := FIND(IN1 := Texts.a, IN2 := 'tor') * 10 + LEN(S := Texts.arr[1]);\n"
        "Texts.b := MID(IN := Texts.a, L := 3, P := 2);\n"
        "Texts.arr[2] := INSERT(IN1 := Texts.b, IN2 := DELETE(IN := 'xyz', L := 1, P := 2),"
        " P := 1);\n"
        "Texts.arr[3] := REPLACE(IN1 := Texts.a, IN2 := LEFT(IN := 'AB', L := 1), L := 4,"
        " P := 2);",
        "no : INT;",
    )
    cpu = build(source)
    assert text(cpu, 1, 18) == (6, "M12")
    assert read(cpu, "DB1.DBW42") == 33
    assert text(cpu, 1, 12) == (4, "oto")
    assert text(cpu, 1, 26) == (6, "oxzto")
    assert text(cpu, 1, 34) == (6, "MA")


def test_eno_after_a_string_function_is_its_br() -> None:
    source = TEXTS + ob1(
        "Texts.b := CONCAT(IN1 := 'ab', IN2 := 'cd');\n"
        "M0.0 := ENO;\n"
        "Texts.b := CONCAT(IN1 := 'ab', IN2 := 'cde');\n"  # cut to 4: BR 0
        "M0.1 := ENO;\n"
        "Texts.n := STRNG_I(S := '12x');\n"  # no conversion: BR 0
        "M0.2 := ENO;\n"
        "CONCAT(IN1 := 'a', IN2 := 'b');"  # a function value dropped
    )
    cpu = build(source)
    assert [read(cpu, bit) for bit in ("M0.0", "M0.1", "M0.2")] == [1, 0, 0]
    assert text(cpu, 1, 12) == (4, "abcd")


def test_a_program_with_its_own_fc2_gets_concat_elsewhere() -> None:
    source = """FUNCTION FC2 : INT
  FC2 := 5;
END_FUNCTION
""" + ob1(
        "MW0 := INT_TO_WORD(FC2());\n"
        "s := CONCAT(IN1 := 'ab', IN2 := 'c');\n"
        "MW2 := INT_TO_WORD(LEN(s));",
        "s : STRING[8];",
    )
    result = compile_sources([SourceFile("prog.scl", source)])
    assert not [d for d in result.diagnostics if d.severity == "error"]
    assert result.program.blocks[(BlockKind.FC, 1000)].name == "CONCAT"
    assert result.program.blocks[(BlockKind.FC, 21)].name == "LEN"
    cpu = build(source)
    assert (read(cpu, "MW0"), read(cpu, "MW2")) == (5, 3)


def test_a_block_called_like_a_library_function_is_the_programs_own() -> None:
    source = """FUNCTION CONCAT : INT
VAR_INPUT
  IN1 : INT;
  IN2 : INT;
END_VAR
  CONCAT := IN1 * IN2;
END_FUNCTION
""" + ob1("MW0 := INT_TO_WORD(CONCAT(IN1 := 6, IN2 := 7));")
    cpu = build(source)
    assert read(cpu, "MW0") == 42


def test_generated_stl_with_library_calls_compiles_back_to_the_same_behaviour() -> None:
    source = TEXTS + ob1(
        "k := WORD_TO_INT(MW20);\n"
        "Texts.arr[k] := CONCAT(IN1 := Texts.a, IN2 := I_STRNG(k));\n"
        "M0.0 := Texts.arr[k] > 'Motor+1';",
        "k : INT;",
    )
    result = compile_sources([SourceFile("prog.scl", source)])
    printed = "\n".join(format_block(block) for _file, block in result.generated)
    assert 'CALL "CONCAT"' in printed
    assert 'CALL "GT_STRNG"' in printed
    again = compile_sources([SourceFile("prog.awl", printed)])
    assert not [d for d in again.diagnostics if d.severity == "error"]
    found = []
    for program in (result.program, again.program):
        cpu = Cpu(program, cycle_ms=10)
        cpu.start()
        word = parse_address("MW20")
        assert isinstance(word, Direct)
        cpu.write(word, 3)
        cpu.run(1)
        found.append((text(cpu, 1, 34), read(cpu, "M0.0")))
    assert found[0] == found[1] == ((6, "Motor+"), 0)


def test_library_calls_are_checked_against_their_interfaces() -> None:
    source = ob1(
        "s := CONCAT(IN1 := 'a');\n"
        "s := LEFT(IN := 'a', L := 'x');\n"
        "n := LEN(Q := s);\n"
        "s := I_STRNG(n);\n"  # one input: its name may be left out
        "n := STRNG_I(s, s);",
        "s : STRING[4]; n : INT;",
    )
    result = compile_sources([SourceFile("prog.scl", source)])
    found = sorted((d.code, d.span.line) for d in result.diagnostics if d.span is not None)
    assert found == [("SCL213", 7), ("SCL223", 8), ("SCL227", 6), ("SCL229", 10)]


def test_fb_string_inputs_and_outputs_copy_what_fits() -> None:
    source = """FUNCTION_BLOCK FB1
VAR_INPUT
  s : STRING[4];
END_VAR
VAR_OUTPUT
  o : STRING[10];
END_VAR
VAR
  n : INT;
END_VAR
  n := LEN(s);
  o := CONCAT(IN1 := s, IN2 := '-out');
END_FUNCTION_BLOCK
""" + ob1(
        "a := 'abcdefgh';\n"
        "FB1.DB1(s := a, o => b);\n"  # 'abcd' in, 'abcd-out' out into a STRING[3]
        "MW0 := INT_TO_WORD(DB1.n);\n"
        "MW2 := INT_TO_WORD(LEN(b));\n"
        "k := 2;\n"
        "arr[k] := 'xy';\n"
        "FB1.DB1(s := arr[k]);\n"
        "MW4 := INT_TO_WORD(DB1.n);",
        "a : STRING[20]; b : STRING[3]; k : INT; arr : ARRAY[1..2] OF STRING[12];",
    )
    cpu = build(source)
    assert [read(cpu, word) for word in ("MW0", "MW2", "MW4")] == [4, 3, 2]
    assert text(cpu, 1, 0) == (4, "xy")  # the instance's maximum length stays 4
    assert text(cpu, 1, 6) == (10, "xy-out")

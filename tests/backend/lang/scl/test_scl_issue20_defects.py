"""Issue 20's defects on the SCL side: BOOL constants as actual parameters (were STL107), a
STRING input an FC passes on (arrived empty), parameters named like addresses (did not parse),
and the range of TIME. The self-checking program ``tests/selfcheck/defects/call_arguments.scl``
runs the first two on the CPU as well."""

from __future__ import annotations

from scl_run import build, read

from nasaq.lang.scl import ast
from nasaq.lang.scl.parse import parse_source
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl import ast as stl

BOOL_CONSTANTS = """
FUNCTION "H" : INT
VAR_INPUT
  a : BOOL;
  b : BOOL;
END_VAR
BEGIN
  "H" := 0;
  IF a THEN "H" := 1; END_IF;
  IF b THEN "H" := "H" + 2; END_IF;
END_FUNCTION

FUNCTION_BLOCK FB1
VAR
  t : TON;
END_VAR
BEGIN
  t(IN := TRUE, PT := T#10MS);
  M0.0 := t.Q;
  MW10 := INT_TO_WORD("H"(a := FALSE, b := TRUE));
  MW12 := INT_TO_WORD("H"(a := TRUE, b := FALSE));
END_FUNCTION_BLOCK

DATA_BLOCK DB1 FB1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB1();
  SFB4.DB2(IN := TRUE, PT := T#20MS);
  M0.1 := DB2.Q;
END_ORGANIZATION_BLOCK
"""


def test_bool_constants_are_actual_parameters_of_fcs_fbs_and_timers() -> None:
    result = compile_sources([SourceFile("prog.scl", BOOL_CONSTANTS)])
    assert [d.code for d in result.diagnostics] == []
    cpu = build(BOOL_CONSTANTS)
    assert read(cpu, "MW10") == 2
    assert read(cpu, "MW12") == 1
    assert read(cpu, "M0.0") == 0  # the timers started in scan 1
    cpu.run(1)
    assert (read(cpu, "M0.0"), read(cpu, "M0.1")) == (1, 0)  # 10 ms later: TON 10 ms is done
    cpu.run(1)
    assert read(cpu, "M0.1") == 1


def test_a_bool_constant_becomes_the_stl_constant() -> None:
    result = compile_sources([SourceFile("prog.scl", BOOL_CONSTANTS)])
    calls = [
        arg
        for _file, block in result.generated
        for item in block.code
        if isinstance(item, stl.InstrNode) and item.args
        for arg in item.args
    ]
    written = {(arg.name.upper(), getattr(arg.value, "name", None)) for arg in calls}
    assert {("IN", "TRUE"), ("A", "FALSE"), ("B", "TRUE"), ("A", "TRUE")} <= written


STRING_PASSED_ON = """
DATA_BLOCK DB5
STRUCT
  direct : STRING[20];
  passed : STRING[20];
  deep : STRING[20];
  length : INT;
END_STRUCT
BEGIN
END_DATA_BLOCK

FUNCTION "Inner" : VOID
VAR_INPUT
  s : STRING;
END_VAR
BEGIN
  DB5.passed := s;
  DB5.length := LEN(s);
END_FUNCTION

FUNCTION "Outer" : VOID
VAR_INPUT
  s : STRING;
END_VAR
BEGIN
  DB5.direct := s;
  "Inner"(s := s);
END_FUNCTION

FUNCTION "Twice" : VOID
VAR_INPUT
  s : STRING;
END_VAR
BEGIN
  "Outer"(s := s);
  DB5.deep := DB5.passed;
END_FUNCTION

ORGANIZATION_BLOCK OB1
VAR_TEMP
  text : STRING[12];
END_VAR
BEGIN
  text := 'from a temp';
  "Twice"(s := text);
  "Outer"(s := 'hello');
END_ORGANIZATION_BLOCK
"""


def _string(cpu: object, byte: int) -> str:
    length = read(cpu, f"DB5.DBB{byte + 1}")  # type: ignore[arg-type]
    return bytes(read(cpu, f"DB5.DBB{byte + 2 + k}") for k in range(length)).decode()  # type: ignore[arg-type]


def test_an_fc_passes_its_string_input_on_whole() -> None:
    cpu = build(STRING_PASSED_ON)
    assert _string(cpu, 0) == "hello"  # stored directly
    assert _string(cpu, 22) == "hello"  # stored by the FC it was passed on to (was empty)
    assert read(cpu, "DB5.DBW66") == 5
    assert _string(cpu, 44) == "from a temp"  # passed on twice, from OB 1's temporary


ADDRESS_NAMES = """
FUNCTION "F" : INT
VAR_INPUT
  i1 : INT;
  M1 : BOOL;
  T1 : INT;
  Q0 : INT;
  C2 : INT;
END_VAR
BEGIN
  "F" := #i1 + #T1 + #Q0 + #C2;
  IF #M1 THEN "F" := -#i1; END_IF;
END_FUNCTION

FUNCTION_BLOCK FB2
VAR_INPUT
  i1 : INT;
END_VAR
VAR_OUTPUT
  M1 : INT;
  Q0 : BOOL;
END_VAR
BEGIN
  #M1 := #i1 * 2;
  #Q0 := TRUE;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB3
VAR
  inst : FB2;
  x : INT;
  q : BOOL;
END_VAR
BEGIN
  inst(i1 := 4, M1 => x, Q0 => q);
  MW20 := INT_TO_WORD(x + inst.M1);
  M22.0 := q;
END_FUNCTION_BLOCK

DATA_BLOCK DB3 FB3
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  MW10 := INT_TO_WORD("F"(i1 := 5, M1 := FALSE, T1 := 1, Q0 := 2, C2 := 3));
  MW12 := INT_TO_WORD("F"(i1 := 5, M1 := TRUE, T1 := 0, Q0 := 0, C2 := 0));
  FB3.DB3();
END_ORGANIZATION_BLOCK
"""


def test_parameters_named_like_addresses_parse_as_names() -> None:
    parsed = parse_source(
        "prog.scl",
        '"F"(i1 := 5, T1 := x, Q0 => y, M1 => #z);\n'.join(
            ["ORGANIZATION_BLOCK OB1\nBEGIN\n", "END_ORGANIZATION_BLOCK\n"]
        ),
    )
    assert parsed.diagnostics == []
    statement = parsed.source.blocks[0].code[0]
    assert isinstance(statement, ast.CallStmt)
    args = [(arg.name, arg.output) for arg in statement.call.args]
    assert args == [("i1", False), ("T1", False), ("Q0", True), ("M1", True)]


def test_parameters_named_like_addresses_are_passed() -> None:
    cpu = build(ADDRESS_NAMES)
    assert read(cpu, "MW10") == 11
    assert read(cpu, "MW12") == -5
    assert read(cpu, "MW20") == 16
    assert read(cpu, "M22.0") == 1


def test_an_address_is_no_parameter_name() -> None:
    source = """
FUNCTION_BLOCK FB2
VAR_INPUT
  i1 : INT;
END_VAR
BEGIN
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB3
VAR
  inst : FB2;
END_VAR
BEGIN
  inst(%M1.0 := 1);
  inst(T 1 := 1);
END_FUNCTION_BLOCK
"""
    result = compile_sources([SourceFile("prog.scl", source)])
    found = [(d.code, d.span.line if d.span else 0) for d in result.diagnostics]
    assert found == [("SCL223", 14), ("SCL223", 15)]


TIME_LIMITS = """
ORGANIZATION_BLOCK OB1
VAR_TEMP
  t : TIME;
END_VAR
BEGIN
  t := T#-24D_20H_31M_23S_648MS;
  MD0 := DINT_TO_DWORD(TIME_TO_DINT(t));
  MD4 := DINT_TO_DWORD(TIME_TO_DINT(T#24D_20H_31M_23S_647MS));
  MD8 := DINT_TO_DWORD(TIME_TO_DINT(TIME#-24d20h31m23s648ms));
END_ORGANIZATION_BLOCK
"""


def test_the_least_and_greatest_time_are_in_range() -> None:
    cpu = build(TIME_LIMITS)
    assert read(cpu, "MD0") == -(2**31)
    assert read(cpu, "MD4") == 2**31 - 1
    assert read(cpu, "MD8") == -(2**31)


def test_one_millisecond_beyond_time_is_out_of_range() -> None:
    source = """
ORGANIZATION_BLOCK OB1
VAR_TEMP
  t : TIME;
END_VAR
BEGIN
  t := T#-24D_20H_31M_23S_649MS;
  t := T#24D_20H_31M_23S_648MS;
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("prog.scl", source)])
    found = [(d.code, d.span.line if d.span else 0) for d in result.diagnostics]
    assert found == [("SCL218", 7), ("SCL218", 8)]


MEMBERS_LIKE_ADDRESSES = """
TYPE "Pair"
STRUCT
  i1 : INT;
  T1 : INT;
END_STRUCT
END_TYPE

DATA_BLOCK "Data"
STRUCT
  M1 : INT;
  T1 : INT;
  pair : "Pair";
END_STRUCT
BEGIN
  M1 := 3;
  T1 := 4;
  pair.T1 := 5;
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  MW0 := INT_TO_WORD("Data".M1 + "Data".T1 + "Data".pair.T1);
END_ORGANIZATION_BLOCK
"""


def test_db_members_named_like_addresses_take_their_initial_values() -> None:
    """TIA writes a DB's assignment section with bare member names: ``T1 := 4;`` is the member
    T1 there, not timer T1 (only members can be assigned in a DB)."""
    cpu = build(MEMBERS_LIKE_ADDRESSES)
    assert read(cpu, "MW0") == 12

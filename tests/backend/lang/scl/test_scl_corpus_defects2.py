"""Issue 20, second round: constructs of real TIA Portal / STEP 7 sources that Nasaq refused
with its own faults (SCL301, SCL101 ...). Each program here is written for its construct."""

from __future__ import annotations

from scl_run import build, read

from nasaq.lang.scl import ast
from nasaq.lang.scl.parse import parse_source
from nasaq.lang.stl import SourceFile, compile_sources

SYMBOLS = (
    "126,Counts                  DB    200   DB    200 counting data\n"
    "126,Runner                  DB    201   FB    201 instance of an FB without source\n"
)

UNKNOWN_DB = """
ORGANIZATION_BLOCK OB1
VAR_TEMP
  t : INT;
END_VAR
BEGIN
  "Counts".cnt := "Counts".cnt + 1;
  Runner.Reset := TRUE;
  t := DB200.cnt;
END_ORGANIZATION_BLOCK
"""


def codes(source: str, *more: SourceFile, profile: str = "S7-1500") -> list[str]:
    result = compile_sources([SourceFile("prog.scl", source), *more], profile=profile)
    return [d.code for d in result.diagnostics]


def test_a_db_known_only_from_the_symbol_table_is_named_not_left_out() -> None:
    """STEP 7 and TIA refuse members of a DB that does not exist; Nasaq says which DB lacks
    its source (SCL923 with the DB as ``block``) instead of SCL301 "cannot compile yet"."""
    result = compile_sources(
        [SourceFile("prog.scl", UNKNOWN_DB), SourceFile("Symbols.asc", SYMBOLS)],
        profile="S7-1500",
    )
    found = [(d.code, d.params.get("block"), d.params.get("name")) for d in result.diagnostics]
    assert found == [
        ("SCL923", '"Counts" (DB 200)', "cnt"),
        ("SCL923", '"Counts" (DB 200)', "cnt"),
        ("SCL923", '"Runner" (DB 201)', "Reset"),
        ("SCL923", "DB 200", "cnt"),
    ]


INDIRECT_IO = """
FUNCTION_BLOCK FB1
VAR
  adr : INT := 10;
  w : WORD;
END_VAR
BEGIN
  %MB(#adr + 1) := 7;
  %MW(#adr + 10) := %MW(#adr + 10) OR 16#0101;
  %MX(#adr + 40, 3) := TRUE;
  %QW(#adr - 6):P := 16#1234;
  w := %IW(#adr - 10):P;
  %MW30 := %IW0:P;
  %MW40 := #w;
END_FUNCTION_BLOCK

DATA_BLOCK DB1 FB1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB1();
END_ORGANIZATION_BLOCK
"""


def test_tia_indirect_and_peripheral_io_access_runs_on_both_profiles() -> None:
    """TIA writes STEP 7's ``MB[i]`` as ``%MB(#i)`` and ``PIW[i]`` as ``%IW(#i):P``."""
    for profile in ("S7-300", "S7-1500"):
        cpu = build(INDIRECT_IO, profile=profile, scans=2)
        assert read(cpu, "MB11") == 7
        assert read(cpu, "MW20") == 0x0101  # OR-ed twice: still the same bits
        assert read(cpu, "MB50") == 8  # M50.3
        assert read(cpu, "MW40") == 0  # PIW0: no module answers in the simulator
        assert read(cpu, "QW4") == 0  # PQW4 goes to the module, not the process image


def test_tia_indirect_access_parses_to_the_classic_indexed_address() -> None:
    source = parse_source("p.scl", INDIRECT_IO).source
    code = source.blocks[0].code
    targets = [stmt.target for stmt in code if isinstance(stmt, ast.Assign)]
    values = [stmt.value for stmt in code if isinstance(stmt, ast.Assign)]
    areas = [t.area for t in targets if isinstance(t, ast.IndexedAddress)]
    assert areas == ["MB", "MW", "MX", "PQW"]
    assert ast.Address("PIW0") in values
    assert any(isinstance(v, ast.IndexedAddress) and v.area == "PIW" for v in values)


def test_a_peripheral_suffix_on_a_memory_or_bit_area_is_named() -> None:
    head = "FUNCTION_BLOCK FB1\nVAR\n i : INT;\n b : BYTE;\n x : BOOL;\nEND_VAR\nBEGIN\n"
    source = head + "#b := %MB(#i):P;\n#x := %IX(#i):P;\nEND_FUNCTION_BLOCK\n"
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    assert [(d.code, d.params.get("area")) for d in result.diagnostics] == [
        ("SCL924", "MB"),
        ("SCL924", "IX"),
    ]


KEYWORD_MEMBERS = """
TYPE "Recipe"
VERSION : 0.1
   STRUCT
      Type : INT;
      Return : INT;
   END_STRUCT;
END_TYPE

FUNCTION_BLOCK FB1
VAR
  r : "Recipe";
END_VAR
BEGIN
  #r.Type := 5;
  #r.Return := #r.Type + 1;
  %MW10 := INT_TO_WORD(#r.Return);
END_FUNCTION_BLOCK

DATA_BLOCK DB1 FB1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB1();
END_ORGANIZATION_BLOCK
"""


def test_members_named_type_and_return_as_tia_exports_them() -> None:
    cpu = build(KEYWORD_MEMBERS, profile="S7-1500")
    assert read(cpu, "MW10") == 6


START_INFORMATION = """
ORGANIZATION_BLOCK "Diagnostic error interrupt"
{ S7_Optimized_Access := 'TRUE' }
BEGIN
  %MW10 := #LADDR;
  %MW12 := #IO_state;
  %M14.0 := #MultiError;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Main"
{ S7_Optimized_Access := 'TRUE' }
VAR_TEMP
  k : INT;
END_VAR
BEGIN
  #k := 3;
  %M0.0 := #Initial_Call;
  %M0.1 := NOT #Remanence;
  %MW2 := INT_TO_WORD(#k);
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Rack or station failure"
{ S7_Optimized_Access := 'TRUE' }
VAR_INPUT
  LADDR : HW_IO;
  Event_Class : Byte;
  Fault_ID : Byte;
END_VAR
BEGIN
  %MB20 := #Fault_ID;
END_ORGANIZATION_BLOCK
"""


def test_optimized_obs_have_their_events_start_information() -> None:
    """TIA declares an optimized OB's event inputs itself (``#LADDR`` in a diagnostic error
    interrupt, ``#Initial_Call`` in Main); the simulator has no hardware events: 0/FALSE."""
    cpu = build(START_INFORMATION, profile="S7-1500", scans=2)
    assert read(cpu, "M0.0") == 0
    assert read(cpu, "M0.1") == 1
    assert read(cpu, "MW2") == 3


def test_a_standard_ob_keeps_the_classic_start_information_only() -> None:
    source = START_INFORMATION.replace("'TRUE'", "'FALSE'")
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    assert {(d.code, d.params.get("name")) for d in result.diagnostics} == {
        ("SCL201", "#LADDR"),
        ("SCL201", "#IO_state"),
        ("SCL201", "#MultiError"),
        ("SCL201", "#Initial_Call"),
        ("SCL201", "#Remanence"),
    }


JUMP_IN_CASE = """
FUNCTION_BLOCK FB1
VAR
  step : INT := 1;
  sub : INT := 1;
  n : INT;
END_VAR
BEGIN
  CASE #step OF
    1:
      #n := 1;
      CASE #sub OF
        1:
          GOTO Skip;
      END_CASE;
      #n := 2;
    Skip:
      #n := #n + 10;
    2:
      #n := 20;
  END_CASE;
  %MW10 := INT_TO_WORD(#n);
END_FUNCTION_BLOCK

DATA_BLOCK DB1 FB1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB1();
END_ORGANIZATION_BLOCK
"""


def test_a_goto_target_inside_a_case_branch_is_a_jump_label() -> None:
    """``Skip:`` in a CASE branch is a named constant's branch unless a GOTO names it (TIA)."""
    cpu = build(JUMP_IN_CASE, profile="S7-1500")
    assert read(cpu, "MW10") == 11
    without_goto = JUMP_IN_CASE.replace("GOTO Skip;", "#n := 5;")
    assert codes(without_goto) == ["SCL201"]  # Skip is then a constant nobody declares


def test_an_unnumbered_optimized_ob_needs_the_s7_1500_profile() -> None:
    """TIA numbers an OB with any other name from 123 (a further program-cycle OB); its
    optimized source says it is for the S7-1200/1500 family."""
    source = "ORGANIZATION_BLOCK \"Dosing\"\n{ S7_Optimized_Access := 'TRUE' }\nBEGIN\n"
    source += "  %M0.0 := TRUE;\nEND_ORGANIZATION_BLOCK\n"
    assert codes(source, profile="S7-300") == ["SCL500"]
    assert codes(source) == []
    plain = source.replace("{ S7_Optimized_Access := 'TRUE' }\n", "")
    assert codes(plain, profile="S7-300") == ["SCL205"]


QUOTED_CALLEE = """
FUNCTION_BLOCK FB1
VAR
  Lookup : STRING[20];
END_VAR
BEGIN
  #Lookup := "Lookup"(Key := 'A');
END_FUNCTION_BLOCK
"""


def test_a_quoted_callee_is_a_global_block_not_a_local_of_that_name() -> None:
    result = compile_sources([SourceFile("prog.scl", QUOTED_CALLEE)], profile="S7-1500")
    found = [(d.code, d.params.get("name")) for d in result.diagnostics]
    assert found == [("SCL201", '"Lookup"')]


CHARACTERS = """
FUNCTION_BLOCK FB1
VAR
  s : STRING[8] := 'a1B2';
  w : WSTRING[4] := WSTRING#'xy';
  i : INT;
  n : INT;
  c : CHAR;
END_VAR
BEGIN
  #n := 0;
  FOR #i := 1 TO 4 DO
    IF #s[#i] >= '0' & #s[#i] <= '9' THEN
      #n := #n + 1;
    END_IF;
  END_FOR;
  #s[1] := 'Z';
  #c := #s[3];
  %MB0 := CHAR_TO_BYTE(#s[1]);
  %MB1 := CHAR_TO_BYTE(#c);
  %MW2 := INT_TO_WORD(#n);
  %MW4 := WCHAR_TO_WORD(#w[2]);
END_FUNCTION_BLOCK

DATA_BLOCK DB1 FB1
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  FB1.DB1();
END_ORGANIZATION_BLOCK
"""


def test_a_character_of_a_string_is_indexed_as_in_tia() -> None:
    """``#s[i]`` is the i-th character (S7-1200/1500), read and written, constant or variable
    index; a WSTRING's is a WCHAR."""
    cpu = build(CHARACTERS, profile="S7-1500")
    assert read(cpu, "MB0") == ord("Z")
    assert read(cpu, "MB1") == ord("B")
    assert read(cpu, "MW2") == 2  # the digits of 'a1B2'
    assert read(cpu, "MW4") == ord("y")


def test_a_character_of_a_string_needs_the_s7_1500_profile() -> None:
    found = set(
        codes(
            CHARACTERS.replace("  w : WSTRING[4] := WSTRING#'xy';\n", "").replace(
                "  %MW4 := WCHAR_TO_WORD(#w[2]);\n", ""
            ),
            profile="S7-300",
        )
    )
    assert found == {"SCL500"}


PASSED_CHARACTERS = """
FUNCTION "First" : CHAR
VAR_INPUT
  s : STRING[8];
END_VAR
VAR_IN_OUT
  t : STRING[8];
END_VAR
BEGIN
  "First" := #s[1];
  #t[2] := #s[2];
END_FUNCTION

FUNCTION_BLOCK FB2
VAR_IN_OUT
  u : STRING[8];
END_VAR
BEGIN
  #u[1] := 'k';
END_FUNCTION_BLOCK

DATA_BLOCK DB2 FB2
BEGIN
END_DATA_BLOCK

DATA_BLOCK "Txt"
   VAR
      a : STRING[8] := 'pqrs';
      b : STRING[8] := 'wxyz';
   END_VAR
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  %MB0 := CHAR_TO_BYTE("First"(s := "Txt".a, t := "Txt".b));
  FB2.DB2(u := "Txt".a);
  %MB1 := CHAR_TO_BYTE("Txt".b[2]);
  %MB2 := CHAR_TO_BYTE("Txt".a[1]);
END_ORGANIZATION_BLOCK
"""


def test_characters_of_string_parameters_and_db_members() -> None:
    cpu = build(PASSED_CHARACTERS, profile="S7-1500")
    assert [chr(read(cpu, f"MB{k}")) for k in range(3)] == ["p", "q", "k"]


def test_a_constant_character_index_outside_the_string_is_named() -> None:
    body = "c := s[5];\nc := s[0];\n"
    head = "FUNCTION_BLOCK FB1\nVAR\n s : STRING[4];\n c : CHAR;\nEND_VAR\nBEGIN\n"
    assert codes(head + body + "END_FUNCTION_BLOCK\n") == ["SCL249", "SCL249"]


def test_stl_calling_a_cp_instruction_is_named_as_not_simulated() -> None:
    """``CALL PNIO_RECV (...)``: the CP 343-1 instruction, written bare as TIA writes
    instructions: STL920 says Nasaq does not simulate it (was STL205 "not defined")."""
    source = "FUNCTION FC1 : VOID\nBEGIN\nNETWORK\nTITLE =\n"
    source += "      CALL PNIO_RECV (CPLADDR := 320, LEN := 10);\nEND_FUNCTION\n"
    result = compile_sources([SourceFile("prog.awl", source)])
    assert [(d.code, d.params.get("name")) for d in result.diagnostics] == [("STL920", "PNIO_RECV")]

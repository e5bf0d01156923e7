"""STL sources as STEP 7 Classic (V5.x) "Generate source" writes them (``nasaq.lang.stl``,
"Accepted export forms"): German or English mnemonics, symbolic block names with or without a
symbol table, ``TITLE =`` without text, tabs and ``//`` comments after declarations, a CALL's
parameter list opened on the CALL line, multi-instances, ``L P##x``, UDTs repeated in every
source that uses them, STEP 7's OB symbols; compiled and run on the CPU. The sources are written
for these tests."""

from __future__ import annotations

import re

from cpu_run import read, real, run
from stl_helpers import codes

from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.stl import CompileResult, SourceFile, compile_sources


def compile_classic(*sources: SourceFile) -> CompileResult:
    return compile_sources(list(sources))


def as_generated(text: str) -> str:
    """STEP 7 Classic ends every statement and DB value line with ``; `` (a blank after it)."""
    return re.sub(r";$", "; ", text, flags=re.MULTILINE)


def names(result: CompileResult) -> dict[str, str]:
    blocks = result.program.blocks.values()
    return {block.name: f"{block.kind.value} {block.number}" for block in blocks if block.name}


RECIPE = """\
TYPE "Recipe"
VERSION : 0.1


  STRUCT \t
   Amount : INT ;\t//how much
   Heat : BOOL ;\t
  END_STRUCT ;\t
END_TYPE
"""

STATION = (
    RECIPE
    + """
DATA_BLOCK "Recipes"
TITLE =
VERSION : 0.1


  STRUCT \t
   First : "Recipe";\t
   Count : INT  := 3;\t
   Tab : ARRAY  [1 .. 4 ] OF BYTE ;\t
  END_STRUCT ;\t
BEGIN
   First.Amount := 12;
   Count := 4;
   Tab[1] := B#16#7;
END_DATA_BLOCK

FUNCTION_BLOCK "Pump"
TITLE =Pump control
//Starts and stops the pump
AUTHOR : Tester
FAMILY : Plant
NAME : PUMP
VERSION : 1.0


VAR_INPUT
  Start : BOOL ;\t
  Stop : BOOL ;\t
END_VAR
VAR_OUTPUT
  Running : BOOL ;\t
END_VAR
VAR
  Starts : INT ;\t
  Edge : BOOL ;\t
END_VAR
VAR_TEMP
  Where : DWORD ;\t
END_VAR
BEGIN
NETWORK
TITLE =Latch

      U(    ;
      O     #Start;
      O     #Running;
      )     ;
      UN    #Stop;
      =     #Running;
NETWORK
TITLE =

      U     #Start;
      FP    #Edge;
      SPBN  M001;
      L     #Starts;
      +     1;
      T     #Starts;
M001: NOP   0;
NETWORK
TITLE =

      L     P##Starts;
      T     #Where;
END_FUNCTION_BLOCK

FUNCTION_BLOCK "Station"
TITLE =
VERSION : 0.1


VAR
  P1 : "Pump";\t
  P2 : "Pump";\t
END_VAR
BEGIN
NETWORK
TITLE =

      CALL #P1 (
           Start                    := E      0.0,
           Stop                     := E      0.1,
           Running                  := A      4.0);
NETWORK
TITLE =

      CALL #P2 (
           Start                    := E      0.2,
           Stop                     := E      0.3,
           Running                  := A      4.1);
      L     #P1.Starts;
      T     MW    26;
END_FUNCTION_BLOCK

DATA_BLOCK "StationDB"
TITLE =
VERSION : 0.1

"Station"
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "CYCL_EXC"
TITLE = "Main Program Sweep (Cycle)"
VERSION : 0.1


VAR_TEMP
  OB1_EV_CLASS : BYTE ;\t//Bits 0-3 = 1 (Coming event), Bits 4-7 = 1 (Event class 1)
  OB1_SCAN_1 : BYTE ;\t//1 (Cold restart scan 1 of OB 1), 3 (Scan 2-n of OB 1)
  OB1_PRIORITY : BYTE ;\t//Priority of OB Execution
  OB1_OB_NUMBR : BYTE ;\t//1 (Organization block 1, OB1)
  OB1_RESERVED_1 : BYTE ;\t//Reserved for system
  OB1_RESERVED_2 : BYTE ;\t//Reserved for system
  OB1_PREV_CYCLE : INT ;\t//Cycle time of previous OB1 scan (milliseconds)
  OB1_MIN_CYCLE : INT ;\t//Minimum cycle time of OB1 (milliseconds)
  OB1_MAX_CYCLE : INT ;\t//Maximum cycle time of OB1 (milliseconds)
  OB1_DATE_TIME : DATE_AND_TIME ;\t//Date and time OB1 started
END_VAR
BEGIN
NETWORK
TITLE =

      CALL "Station" , "StationDB" ;

NETWORK
TITLE =copy

      L     "Recipes".First.Amount;
      T     MW    20;
      L     "Recipes".Count;
      T     MW    22;
      AUF   "Recipes";
      L     DBB    6;
      T     MB    24;
END_ORGANIZATION_BLOCK
"""
)


def test_a_classic_export_with_german_mnemonics_runs_its_multi_instances_and_db() -> None:
    result = compile_classic(SourceFile("Station.AWL", as_generated(STATION)))
    assert names(result) == {
        "Recipe": "UDT 1",
        "Recipes": "DB 1",
        "Pump": "FB 1",
        "Station": "FB 2",
        "StationDB": "DB 2",
        "CYCL_EXC": "OB 1",  # STEP 7's symbol of OB 1
    }
    cpu = run(result, scans=2)
    assert read(cpu, "MW 20") == 12  # "Recipes".First.Amount from BEGIN
    assert read(cpu, "MW 22") == 4
    assert read(cpu, "MB 24") == 7  # DBB 6 of "Recipes": Tab[1]
    start = parse_address("I 0.0")
    assert isinstance(start, Direct)
    cpu.set_input(start, 1)
    cpu.run(2)
    assert read(cpu, "Q 4.0") == 1  # the first pump runs (E 0.0), the second does not
    assert read(cpu, "Q 4.1") == 0
    assert read(cpu, "MW 26") == 1  # one rising edge of Start counted in P1's instance data


def test_a_symbol_table_gives_the_numbers_and_the_mnemonics_may_be_english() -> None:
    table = SourceFile(
        "Symbols.sdf",
        '"Pump","FB    7","FB    7",""\r\n"Line","DB   30","FB    7",""\r\n',
    )
    text = """\
FUNCTION_BLOCK "Pump"
TITLE =
VERSION : 0.1

VAR_INPUT
  Start : BOOL ;\t
END_VAR
BEGIN
NETWORK
TITLE =

      A     #Start;
      =     Q      4.2;
END_FUNCTION_BLOCK

DATA_BLOCK "Line"
TITLE =
VERSION : 0.1
 FB 7
BEGIN
   Start := TRUE;
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
TITLE =
VERSION : 0.1

BEGIN
NETWORK
TITLE =

      CALL "Pump" , "Line" ;
      L     db30.dbb0;
      T     mb 40;
END_ORGANIZATION_BLOCK
"""
    result = compile_classic(table, SourceFile("Pump.awl", as_generated(text)))
    assert names(result) == {"Pump": "FB 7", "Line": "DB 30"}
    cpu = run(result)
    assert read(cpu, "Q 4.2") == 1  # Start := TRUE from the instance DB's values
    assert read(cpu, "MB 40") == 1


def test_a_udt_repeated_in_every_source_that_uses_it_is_one_udt() -> None:
    first = SourceFile("DB10.AWL", RECIPE.replace('"Recipe"', "UDT 5") + DB_OF_UDT.format(db=10))
    second = SourceFile("DB11.AWL", RECIPE.replace('"Recipe"', "UDT 5") + DB_OF_UDT.format(db=11))
    result = compile_classic(first, second)
    assert result.ok, result.diagnostics
    changed = SourceFile(
        "DB12.AWL",
        RECIPE.replace('"Recipe"', "UDT 5").replace("Heat : BOOL", "Heat : INT")
        + DB_OF_UDT.format(db=12),
    )
    different = compile_classic(first, changed)
    assert [(d.code, d.span.file if d.span else "") for d in different.diagnostics] == [
        ("STL215", "DB12.AWL")
    ]


DB_OF_UDT = """
DATA_BLOCK DB {db}
TITLE =
VERSION : 0.1

  STRUCT \t
   Item : UDT 5;\t
  END_STRUCT ;\t
BEGIN
   Item.Amount := 1;
END_DATA_BLOCK
"""


def test_obs_named_by_step7_symbols_or_their_descriptions_get_their_numbers() -> None:
    text = "".join(
        f'ORGANIZATION_BLOCK "{name}"\nTITLE =\nVERSION : 0.1\n\nBEGIN\nNETWORK\nTITLE =\n\n'
        "      NOP   0; \nEND_ORGANIZATION_BLOCK\n\n"
        for name in (
            "Cycle Execution",
            "Cyclic Interrupt 5",
            "COMPLETE RESTART",
            "Time of Day Interrupt 2",
        )
    )
    result = compile_classic(SourceFile("obs.awl", text))
    assert result.ok, result.diagnostics
    assert names(result) == {
        "Cycle Execution": "OB 1",
        "Cyclic Interrupt 5": "OB 35",
        "COMPLETE RESTART": "OB 100",
        "Time of Day Interrupt 2": "OB 12",
    }


def test_a_call_of_an_unknown_block_name_still_says_which_symbol() -> None:
    text = 'ORGANIZATION_BLOCK OB 1\nBEGIN\n      CALL "Nowhere" ;\nEND_ORGANIZATION_BLOCK\n'
    assert codes(compile_classic(SourceFile("ob1.awl", text))) == [("STL205", 3, 12)]


def test_scale_and_unscale_of_the_standard_library_are_added_where_called() -> None:
    text = """\
ORGANIZATION_BLOCK OB 1
TITLE =
VERSION : 0.1

BEGIN
NETWORK
TITLE =

      CALL SCALE (
           IN                       := 13824,
           HI_LIM                   := 1.000000e+002,
           LO_LIM                   := 0.000000e+000,
           BIPOLAR                  := FALSE,
           RET_VAL                  := MW    10,
           OUT                      := MD    20);
      CALL "SCALE" (
           IN                       := 30000,
           HI_LIM                   := 1.000000e+002,
           LO_LIM                   := 0.000000e+000,
           BIPOLAR                  := TRUE,
           RET_VAL                  := MW    12,
           OUT                      := MD    24);
      CALL UNSCALE (
           IN                       := 2.500000e+001,
           HI_LIM                   := 1.000000e+002,
           LO_LIM                   := 0.000000e+000,
           BIPOLAR                  := TRUE,
           RET_VAL                  := MW    14,
           OUT                      := MW    16);
END_ORGANIZATION_BLOCK

FUNCTION FC 105 : VOID
TITLE =the program's own FC 105: SCALE moves aside
BEGIN
NETWORK
TITLE =

      NOP   0;
END_FUNCTION
"""
    result = compile_classic(SourceFile("scale.awl", text))
    assert names(result) == {"SCALE": "FC 1000", "UNSCALE": "FC 106"}
    cpu = run(result)
    assert read(cpu, "MW 10") == 0
    assert real(cpu, "MD 20") == 50.0  # half of 27648 is half of 0..100
    assert read(cpu, "MW 12") == 8  # beyond 27648: HI_LIM and W#16#0008
    assert real(cpu, "MD 24") == 100.0
    assert read(cpu, "MW 14") == 0
    assert read(cpu, "MW 16") == -13824  # a quarter of 0..100 on -27648..27648


def test_local_names_written_without_their_hash_sign() -> None:
    text = """\
function_block fb40
know_how_protect
var_input
position1:int;
end_var
var_output
high:bool;
end_var
begin
network
l position1;
l 1500;
>i;
= high;
end_function_block
data_block db41
fb40
begin
position1 := 2000;
end_data_block
organization_block ob1
begin
call fb40, db41;
a db41.dbx2.0;
= m 5.0;
end_organization_block
"""
    cpu = run(compile_classic(SourceFile("lower.awl", text)))
    assert read(cpu, "M 5.0") == 1

"""STL sources as TIA Portal's "Generate source from blocks" writes them (``nasaq.lang.stl``,
"Accepted export forms"): symbolic block names numbered as TIA numbers them, OBs by event,
block and member attributes, TIA type spellings, ``%`` addresses, quoted names, a CALL's
parameters on the lines after it, ``VAR CONSTANT``, the S7-1500 data type choice of IEC timers;
compiled and run on the CPU. The sources are written for these tests."""

from __future__ import annotations

import re

from cpu_run import read, real, run
from stl_helpers import codes

from nasaq.ir import BlockKind
from nasaq.lang.stl import CompileResult, SourceFile, compile_sources
from nasaq.lang.stl.format import format_source
from nasaq.lang.stl.parse import parse_source


def compile_tia(text: str, *extra: SourceFile, profile: str = "S7-300") -> CompileResult:
    return compile_sources([SourceFile("export.awl", text), *extra], profile=profile)


def names(result: CompileResult) -> dict[str, str]:
    blocks = result.program.blocks.values()
    return {block.name: f"{block.kind.value} {block.number}" for block in blocks if block.name}


def as_exported(text: str) -> bytes:
    """What TIA writes to disk: a UTF-8 BOM, CRLF line ends, no newline after the last line,
    a blank after ``TITLE =``, section keywords and a parameter's comma."""
    text = re.sub(r"^(TITLE =|\s*VAR\w*|\s*STRUCT|.* ,)$", r"\1 ", text, flags=re.MULTILINE)
    return b"\xef\xbb\xbf" + text.rstrip("\n").replace("\n", "\r\n").encode("utf-8")


PLANT = """\
FUNCTION_BLOCK "Valve"
{ S7_Optimized_Access := 'FALSE' }
AUTHOR : Tester
FAMILY : Plant
NAME : Valve
VERSION : 0.1
   VAR_INPUT
      Open : Bool;
      Close { S7_SetPoint := 'True'} : Bool;
      Limit {ExternalAccessible := 'False'; ExternalVisible := 'False'} : Int := 100;
   END_VAR

   VAR_OUTPUT
      IsOpen : Bool;
      Count : Int;
   END_VAR

   VAR
      Steps : Array[0..3] of Int;
      Info : Struct
         Ready : Bool;
         Level : Real;
      END_STRUCT;
      Label : String[20];
      Delay : S5Time := S5T#2S;
      Span : Time := T#1S;
      Mask : Word := 16#00FF;
   END_VAR

   VAR_TEMP
      Tmp : Int;
   END_VAR


BEGIN
NETWORK
TITLE = Open logic
// opens when asked, until closed
      A     #Open;
      O     #IsOpen;
      AN    #Close;
      =     #IsOpen;
NETWORK
TITLE =
      L     #Count;
      L     1;
      +I    ;
      T     #Count;
      T     #Steps[1];

END_FUNCTION_BLOCK

FUNCTION_BLOCK "Line"
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1
   VAR_INPUT
      Go : Bool;
   END_VAR

   VAR
      First : "Valve";
      Second : "Valve";
   END_VAR


BEGIN
NETWORK
TITLE = Two valves
      CALL #First
      (  Open                        := #Go ,
         Close                       := %I0.1
      );

      CALL #Second
      // the second valve never closes
      (  Open                        := %I0.2 ,
         Close                       := FALSE
      );
      A     #First.IsOpen;
      =     %Q4.0;
END_FUNCTION_BLOCK

DATA_BLOCK "Settings"
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1
NON_RETAIN
   STRUCT
      Speed : Int := 5;
      Enable : Bool := TRUE;
      Table : Array[1..3] of Int;
   END_STRUCT;


BEGIN
   Speed := 7;
   Table[2] := 9;

END_DATA_BLOCK

DATA_BLOCK "Line_DB"
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1
NON_RETAIN
"Line"

BEGIN

END_DATA_BLOCK

FUNCTION "Scale" : Void
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1
   VAR_INPUT
      Raw : Int;
   END_VAR

   VAR_OUTPUT
      Out : Real;
   END_VAR


BEGIN
NETWORK
TITLE =
      L     #Raw;
      ITD   ;
      DTR   ;
      T     #Out;
END_FUNCTION

ORGANIZATION_BLOCK "Main"
TITLE = "Main Program Sweep (Cycle)"
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1

   VAR_TEMP
      OB1_EV_CLASS : Byte;
      OB1_SCAN_1 : Byte;
      OB1_PRIORITY : Byte;
      OB1_OB_NUMBR : Byte;
      OB1_RESERVED_1 : Byte;
      OB1_RESERVED_2 : Byte;
      OB1_PREV_CYCLE : Int;
      OB1_MIN_CYCLE : Int;
      OB1_MAX_CYCLE : Int;
      OB1_DATE_TIME : Date_And_Time;
      Scaled : Real;
   END_VAR


BEGIN
NETWORK
TITLE =
      CALL "Line" , "Line_DB"
      (  Go                          := TRUE
      );
NETWORK
TITLE =
      CALL "Scale"
      (  Raw                         := "Settings".Speed ,
         Out                         := #Scaled
      );
      L     "Settings".Table[2];
      T     %MW20;
      L     #Scaled;
      T     %MD30;
      L     "Line_DB".Second.Count;
      T     %MW24;
END_ORGANIZATION_BLOCK
"""


def test_a_tia_export_compiles_with_its_blocks_numbered_as_tia_numbers_them() -> None:
    result = compile_tia(PLANT)
    assert result.ok, result.diagnostics
    assert names(result) == {
        "Valve": "FB 1",
        "Line": "FB 2",
        "Settings": "DB 1",
        "Line_DB": "DB 2",
        "Scale": "FC 1",
        "Main": "OB 1",
    }
    line_db = result.program.get(BlockKind.DB, 2)
    assert line_db is not None
    assert line_db.instance_of == 2
    valve = result.program.get(BlockKind.FB, 1)
    assert valve is not None
    assert valve.attributes["S7_Optimized_Access"] == "FALSE"
    assert valve.attributes["VERSION"] == "0.1"


def test_a_tia_export_with_bom_and_crlf_runs_its_multi_instances_and_db() -> None:
    result = compile_sources([SourceFile("Plant.awl", as_exported(PLANT))])
    cpu = run(result, scans=3)
    assert read(cpu, "MW 20") == 9  # "Settings".Table[2] from the DB's BEGIN section
    assert real(cpu, "MD 30") == 7.0  # "Scale" of "Settings".Speed (7, not its default 5)
    assert read(cpu, "MW 24") == 3  # the second multi-instance counted every scan
    assert read(cpu, "Q 4.0") == 1  # the first valve opened (Go = TRUE, %I0.1 not closing)


def test_percent_addresses_are_the_addresses_without_percent() -> None:
    with_percent = compile_tia(
        'ORGANIZATION_BLOCK "Main"\nBEGIN\n  A %I0.0;\n  = %Q4.1;\n  L %MW2;\n  T %DB1.DBW0;\n'
        "  OPN %DB1;\n  L %DBW2;\n  T %MD10;\nEND_ORGANIZATION_BLOCK\n"
        'DATA_BLOCK "D"\nSTRUCT\n  a : Int;\n  b : Int;\nEND_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n'
    )
    plain = compile_tia(
        "ORGANIZATION_BLOCK OB 1\nBEGIN\n  A I 0.0;\n  = Q 4.1;\n  L MW 2;\n  T DB1.DBW 0;\n"
        "  OPN DB 1;\n  L DBW 2;\n  T MD 10;\nEND_ORGANIZATION_BLOCK\n"
        "DATA_BLOCK DB 1\nSTRUCT\n  a : INT;\n  b : INT;\nEND_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
    )
    assert with_percent.ok, with_percent.diagnostics
    assert plain.ok, plain.diagnostics
    first = with_percent.program.get(BlockKind.OB, 1)
    second = plain.program.get(BlockKind.OB, 1)
    assert first is not None
    assert second is not None
    assert [(i.op, i.operand) for i in first.code] == [(i.op, i.operand) for i in second.code]


def test_obs_are_numbered_by_their_event_and_unknown_ones_are_refused_on_s7_300() -> None:
    text = "".join(
        f'ORGANIZATION_BLOCK "{name}"\nBEGIN\n  NOP 0;\nEND_ORGANIZATION_BLOCK\n'
        for name in ("Startup", "Cyclic interrupt", "Main", "Programming error")
    )
    result = compile_tia(text)
    assert result.ok, result.diagnostics
    assert names(result) == {
        "Startup": "OB 100",
        "Cyclic interrupt": "OB 35",
        "Main": "OB 1",
        "Programming error": "OB 121",
    }
    refused = compile_tia(
        'ORGANIZATION_BLOCK "Conveyor"\nBEGIN\n  NOP 0;\nEND_ORGANIZATION_BLOCK\n'
    )
    assert codes(refused) == [("STL600", 1, 1)]  # one message, no "undefined symbol" after it
    assert '"Conveyor"' in refused.diagnostics[0].message
    modern = compile_tia(
        'ORGANIZATION_BLOCK "Conveyor"\nBEGIN\n  NOP 0;\nEND_ORGANIZATION_BLOCK\n',
        profile="S7-1500",
    )
    assert modern.ok
    assert names(modern) == {"Conveyor": "OB 123"}
    servo = compile_tia('ORGANIZATION_BLOCK "MC-Servo"\nBEGIN\n  NOP 0;\nEND_ORGANIZATION_BLOCK\n')
    assert codes(servo) == [("STL500", 1, 1)]


def test_a_symbol_table_number_wins_and_numbering_skips_the_numbers_in_use() -> None:
    table = SourceFile("tags.csv", "name,address\nValve,FB 1\nOther,FC 1\n")
    text = (
        'FUNCTION_BLOCK "Pump"\nBEGIN\n  NOP 0;\nEND_FUNCTION_BLOCK\n'
        'FUNCTION_BLOCK "Valve"\nBEGIN\n  NOP 0;\nEND_FUNCTION_BLOCK\n'
        "FUNCTION_BLOCK FB 2\nBEGIN\n  NOP 0;\nEND_FUNCTION_BLOCK\n"
        'FUNCTION "Calc" : Void\nBEGIN\n  NOP 0;\nEND_FUNCTION\n'
    )
    result = compile_tia(text, table)
    assert result.ok, result.diagnostics
    assert names(result)["Valve"] == "FB 1"  # the table's number
    assert names(result)["Pump"] == "FB 3"  # 1 is the table's, 2 is written in the source
    assert names(result)["Calc"] == "FC 2"  # FC 1 belongs to "Other" of the table


def test_an_undefined_instance_db_of_a_call_is_created_as_step7_does() -> None:
    text = (
        'FUNCTION_BLOCK "Count"\nVAR\n  n : Int;\nEND_VAR\nBEGIN\n  L #n;\n  + 1;\n  T #n;\n'
        "  T %MW4;\nEND_FUNCTION_BLOCK\n"
        'ORGANIZATION_BLOCK "Main"\nBEGIN\n  CALL "Count", "Count_DB";\nEND_ORGANIZATION_BLOCK\n'
    )
    result = compile_tia(text)
    assert [d.code for d in result.diagnostics] == ["STL229"]  # a warning: DB 1 is created
    assert names(result)["Count_DB"] == "DB 1"
    assert read(run(result, scans=4), "MW 4") == 4


def test_iec_timers_by_their_names_and_tia_data_type_choice() -> None:
    text = """\
FUNCTION_BLOCK "Delays"
{ S7_Optimized_Access := 'TRUE' }
   VAR_INPUT
      Go : Bool;
   END_VAR
   VAR
      Wait {InstructionName := 'TON'; LibVersion := '1.0'} : TON;
   END_VAR
BEGIN
NETWORK
TITLE =
      CALL #Wait
      {time_type := 'Time'}
      (  IN                          := #Go ,
         PT                          := T#50MS ,
         Q                           := %Q0.0
      );
      CALL TP , "Pulse_DB"
      {time_type := 'Time'}
      (  IN                          := #Go ,
         PT                          := T#1S ,
         Q                           := %Q0.1
      );
END_FUNCTION_BLOCK
ORGANIZATION_BLOCK "Main"
BEGIN
      CALL "Delays", "Delays_DB"
      (Go := TRUE);
END_ORGANIZATION_BLOCK
"""
    modern = compile_tia(text, profile="S7-1500")
    assert {d.code for d in modern.diagnostics} == {"STL229"}  # Pulse_DB and Delays_DB created
    cpu = run(modern, scans=10, profile="S7-1500")
    assert read(cpu, "Q 0.0") == 1
    assert read(cpu, "Q 0.1") == 1
    classic = compile_tia(text)
    assert [code for code, _, _ in codes(classic) if code != "STL229"] == [
        "STL500",  # the optimized block
        "STL500",  # {time_type := 'Time'}: S7-1200/1500 only
        "STL500",
    ]
    long_time = text.replace("'Time'}\n      (  IN", "'LTime'}\n      (  IN", 1)
    assert ("STL602", 12, 7) in codes(compile_tia(long_time, profile="S7-1500"))


def test_local_constants_are_their_values() -> None:
    text = """\
FUNCTION "Limits" : Void
   VAR CONSTANT
      Top : Int := 250;
      Big : DInt := L#100000;
   END_VAR
BEGIN
      L     #Top;
      T     %MW40;
      L     #Big;
      T     %MD42;
END_FUNCTION
ORGANIZATION_BLOCK "Main"
BEGIN
      CALL "Limits";
END_ORGANIZATION_BLOCK
"""
    cpu = run(compile_tia(text))
    assert read(cpu, "MW 40") == 250
    assert read(cpu, "MD 42") == 100000
    written = compile_tia(text.replace("T     %MW40;", "T     #Top;"))
    assert [code for code, _, _ in codes(written)] == ["STL204"]  # a constant is not written
    no_value = compile_tia(text.replace("Top : Int := 250;", "Top : Int;"))
    assert [code for code, _, _ in codes(no_value)] == ["STL601"]


def test_quoted_names_in_declarations_operands_parameters_and_db_values() -> None:
    text = """\
FUNCTION_BLOCK "Belt"
   VAR_INPUT
      "Start Button" : Bool;
      "Speed-Set" : Int := 5;
   END_VAR
BEGIN
      A     #"Start Button";
      =     %M1.0;
      L     #"Speed-Set";
      T     %MW2;
END_FUNCTION_BLOCK
DATA_BLOCK "Belt DB"
"Belt"
BEGIN
   "Speed-Set" := 7;
END_DATA_BLOCK
ORGANIZATION_BLOCK "Main"
BEGIN
      CALL "Belt" , "Belt DB"
      (  "Start Button"              := TRUE
      );
END_ORGANIZATION_BLOCK
"""
    cpu = run(compile_tia(text))
    assert read(cpu, "M 1.0") == 1
    assert read(cpu, "MW 2") == 7
    parsed = parse_source("belt.awl", text)
    printed = format_source(parsed.source)
    assert '#"Start Button"' in printed
    assert '"Speed-Set" := 7;' in printed
    again = parse_source("again.awl", printed)
    assert again.diagnostics == []


def test_a_missing_udt_is_reported_once_not_at_every_use() -> None:
    text = """\
FUNCTION "Check" : Void
   VAR_TEMP
      Item : "Missing type";
   END_VAR
BEGIN
      A     #Item.Ready;
      =     %M0.0;
      L     "Store".Slot.Count;
      T     %MW2;
END_FUNCTION
DATA_BLOCK "Store"
   STRUCT
      Slot : "Missing type";
   END_STRUCT;
BEGIN
   Slot.Count := 3;
END_DATA_BLOCK
"""
    found = [(code, line) for code, line, _ in codes(compile_tia(text))]
    assert found == [("STL205", 3), ("STL205", 13)]


def test_long_jump_labels_are_an_s7_1500_thing() -> None:
    text = 'FUNCTION "F" : Void\nBEGIN\n  JU Label_0;\nLabel_0: NOP 0;\nEND_FUNCTION\n'
    assert compile_tia(text, profile="S7-1500").ok
    assert [code for code, _, _ in codes(compile_tia(text))] == ["STL209"]


def test_the_instance_db_of_a_system_fb_written_by_its_name() -> None:
    text = """\
DATA_BLOCK "Wait_DB"
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1
NON_RETAIN
TON

BEGIN
   PT := T#30MS;

END_DATA_BLOCK
ORGANIZATION_BLOCK "Main"
BEGIN
      CALL TON , "Wait_DB"
      (  IN                          := TRUE ,
         Q                           := %M7.0
      );
      L     "Wait_DB".PT;
      T     %MD8;
END_ORGANIZATION_BLOCK
"""
    result = compile_tia(text)
    assert names(result) == {"Wait_DB": "DB 1", "Main": "OB 1"}
    wait_db = result.program.get(BlockKind.DB, 1)
    assert wait_db is not None
    assert wait_db.attributes["instance_of"] == "SFB 4"
    cpu = run(result, scans=6)
    assert read(cpu, "MD 8") == 30  # the DB's actual value of PT, in ms
    assert read(cpu, "M 7.0") == 1

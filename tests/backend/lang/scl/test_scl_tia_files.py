"""Sources as TIA Portal's "Generate source from blocks" writes them: ``.udt`` and ``.db`` files,
blocks named only symbolically and numbered as TIA numbers them (OBs by their event,
``nasaq.lang.tia_names``), optimized blocks (``nasaq.lang.scl.optimized``), attributes on
blocks and members, BOM, CRLF, ``END_REGION title``. Parse, bind, check, lower and run."""

from __future__ import annotations

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import parse_address, signed
from nasaq.ir import BlockKind, Direct
from nasaq.lang.scl import ast, parse_source
from nasaq.lang.scl.bind import SclIndex
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.compiler import SCL_SUFFIXES
from nasaq.lang.tia_names import ob_event, ob_number
from nasaq.workbench.names import language_of

# ---- sources in TIA Portal's exported form (written for these tests) -------------------------

UDT = (
    '\ufeffTYPE "Tf_Valve"\r\n'
    "TITLE = Valve record\r\n"
    "AUTHOR : Nasaq\r\n"
    "FAMILY : Tests\r\n"
    "VERSION : 0.1\r\n"
    "   STRUCT\r\n"
    "      opening { ExternalAccessible := 'False'; ExternalVisible := 'False';"
    " ExternalWritable := 'False'} : Int;   // percent\r\n"
    "      open : Bool;\r\n"
    "      history : Array[0..3] of Int;\r\n"
    "      timing : Struct\r\n"
    "         delay : Time := T#2S;\r\n"
    "         retries { S7_SetPoint := 'True'} : Int := 3;\r\n"
    "      END_STRUCT;\r\n"
    "   END_STRUCT;\r\n"
    "\r\n"
    "END_TYPE"  # no line break at the end
)

DB = """DATA_BLOCK "Tf_Plant"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      valve : "Tf_Valve";
      valves : Array[1..3] of "Tf_Valve";
      level { S7_SetPoint := 'True'} : Int := 40;
      name : String[10];
   END_VAR


BEGIN
   // the values TIA writes after BEGIN
   valve.opening := 25;
   valves[2].history[1] := -7;
   name := 'tank';

END_DATA_BLOCK
"""

FB = """FUNCTION_BLOCK "Tf_Filler"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      step : Int;
   END_VAR

   VAR_OUTPUT
      full : Bool;
   END_VAR

   VAR
      amount { ExternalAccessible := 'False'} : Int;
      limit : Int := 100;
   END_VAR


BEGIN
    REGION Fill
        #amount := #amount + #step;
    END_REGION Fill
    REGION Report the level
        #full := #amount >= #limit;
    END_REGION Report the level
END_FUNCTION_BLOCK
"""

INSTANCE = """DATA_BLOCK "Tf_Filler_DB"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
"Tf_Filler"

BEGIN
   limit := 60;

END_DATA_BLOCK
"""

PROGRAM = """ORGANIZATION_BLOCK "Startup"
TITLE = "Complete Restart"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1

BEGIN
    "Tf_Plant".level := "Tf_Plant".level + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Main"
TITLE = "Main Program Sweep (Cycle)"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1

BEGIN
    "Tf_Filler_DB"(step := 20);
    %M0.0 := "Tf_Filler_DB".full;
    %MW2 := INT_TO_WORD("Tf_Plant".level);
    %MW4 := INT_TO_WORD("Tf_Plant".valve.opening);
    %MW6 := INT_TO_WORD("Tf_Plant".valves[2].history[1]);
    %MW8 := INT_TO_WORD("Tf_Plant".valve.timing.retries);
END_ORGANIZATION_BLOCK
"""

FILES = {
    "Tf_Valve.udt": UDT,
    "Tf_Plant.db": DB,
    "Tf_Filler.scl": FB,
    "Tf_Filler_DB.db": INSTANCE,
    "Program.scl": PROGRAM,
}


def _codes(text: str, profile: str = "S7-1500") -> list[tuple[str, int, int]]:
    result = compile_sources([SourceFile("t.scl", text)], profile=profile)
    return [(d.code, d.span.line or 0, d.span.column or 0) for d in result.diagnostics]


def _read(cpu: Cpu, text: str) -> int:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return signed(cpu.read(address), address.width)


# ---- files -----------------------------------------------------------------------------------


def test_db_and_udt_files_are_scl_sources() -> None:
    assert {".db", ".udt"} <= set(SCL_SUFFIXES)
    assert language_of("Recipe.DB") == "scl"
    assert language_of("Valve.udt") == "scl"


def test_the_exported_files_parse_without_a_diagnostic() -> None:
    for name, text in FILES.items():
        result = parse_source(name, text)
        assert result.diagnostics == [], (name, [d.message for d in result.diagnostics])
    udt = parse_source("Tf_Valve.udt", UDT).source.blocks[0]
    assert (udt.kind, udt.name.text, udt.title) == ("TYPE", "Tf_Valve", "Valve record")
    assert udt.props == {"AUTHOR": "Nasaq", "FAMILY": "Tests", "VERSION": "0.1"}
    struct = udt.sources[0]
    assert isinstance(struct, ast.StructType)
    first = struct.members[0]
    assert isinstance(first, ast.VarDecl)
    assert [(a.name, a.value) for a in first.names[0].attributes] == [
        ("ExternalAccessible", "False"),
        ("ExternalVisible", "False"),
        ("ExternalWritable", "False"),
    ]
    db = parse_source("Tf_Plant.db", DB).source.blocks[0]
    assert [(a.name, a.value) for a in db.attributes] == [("S7_Optimized_Access", "TRUE")]
    assert db.flags == ["NON_RETAIN"]
    assert len(db.code) == 3  # the three values after BEGIN; the comment is no statement
    instance = parse_source("Tf_Filler_DB.db", INSTANCE).source.blocks[0]
    assert instance.sources == [ast.BlockName("Tf_Filler", quoted=True)]


def test_bom_crlf_and_a_missing_last_line_break_change_nothing() -> None:
    plain = UDT.removeprefix("\ufeff").replace("\r\n", "\n") + "\n"
    assert parse_source("a.udt", UDT).source.blocks == parse_source("b.udt", plain).source.blocks


# ---- END_REGION title ------------------------------------------------------------------------


def test_end_region_takes_the_title_again() -> None:
    block = parse_source("f.scl", FB).source.blocks[0]
    assert [type(item) for item in block.code] == [ast.Region, ast.Region]
    regions = [item for item in block.code if isinstance(item, ast.Region)]
    assert [region.title for region in regions] == ["Fill", "Report the level"]
    assert parse_source("f.scl", FB, fast=False).source == parse_source("f.scl", FB).source


@pytest.mark.parametrize(
    "tail",
    ["", " Fill", " Fill ;", " Type handling // a comment", "  Function call (* c *)", ";"],
)
def test_end_region_forms(tail: str) -> None:
    text = f"FUNCTION FC1 : VOID\nBEGIN\nREGION Fill\n  x := 1;\nEND_REGION{tail}\nEND_FUNCTION\n"
    for fast in (True, False):
        result = parse_source("f.scl", text, fast=fast)
        assert result.diagnostics == [], [d.message for d in result.diagnostics]
        assert isinstance(result.source.blocks[0].code[0], ast.Region)


def test_a_stray_end_region_title_opens_no_phantom_block() -> None:
    """Words of the title that are keywords (``Type``, ``Function``) are no block heads, and
    the statement after the stray END_REGION is kept."""
    text = (
        'FUNCTION "F" : VOID\nBEGIN\n  x := 1;\n  END_REGION Type handling\n  y := 2;\n'
        "END_FUNCTION\nFUNCTION_BLOCK FB1\nBEGIN\nEND_FUNCTION_BLOCK\n"
    )
    for fast in (True, False):
        result = parse_source("f.scl", text, fast=fast)
        assert [(d.code, d.span.line, d.span.column) for d in result.diagnostics] == [
            ("SCL101", 4, 3)
        ]
        blocks = result.source.blocks
        assert [(b.kind, b.name.text) for b in blocks] == [
            ("FUNCTION", "F"),
            ("FUNCTION_BLOCK", "FB1"),
        ]
        last = blocks[0].code[-1]
        assert isinstance(last, ast.Assign)
        assert last.target == ast.Name("y")


# ---- OBs by their event, and TIA's numbering -------------------------------------------------


@pytest.mark.parametrize(
    ("profile", "names", "numbers"),
    [
        (
            "S7-1500",
            ["Main", "Startup", "Cyclic interrupt", "Cyclic interrupt_1"],
            [1, 100, 30, 31],
        ),
        ("S7-300", ["Main", "Startup", "Cyclic interrupt", "Cyclic interrupt_1"], [1, 100, 35, 30]),
        ("S7-1500", ["Time of day", "Time delay interrupt", "Hardware interrupt"], [10, 20, 40]),
        ("S7-1500", ["Time error interrupt", "Diagnostic error interrupt"], [80, 82]),
        ("S7-1500", ["Pull or plug of modules", "Rack or station failure"], [83, 86]),
        ("S7-400", ["Programming error", "I/O access error", "program cycle"], [121, 122, 1]),
        ("S7-1500", ["Main", "Main_1", "Conveyor", "CYC_INT5"], [1, 123, 124, 35]),
        ("S7-300", ["COMPLETE RESTART", "CYC_INT2", "PROG_ERR"], [100, 32, 121]),
        # written without blanks, with an "ob" prefix, or with the number as TIA lists it
        ("S7-300", ["CyclicInterrupt", "RackOrStationFailure", "Main [OB1]"], [35, 86, 1]),
        ("S7-1500", ["obCyclicInterrupt", "DiagnosticErrorInterrupt", "PID"], [30, 82, 123]),
    ],
)
def test_obs_are_numbered_by_their_event(
    profile: str, names: list[str], numbers: list[int]
) -> None:
    text = "".join(f'ORGANIZATION_BLOCK "{n}"\nBEGIN\nEND_ORGANIZATION_BLOCK\n' for n in names)
    index = SclIndex(profile=profile)
    index.add_sources([parse_source("a.scl", text).source])
    assert index.diagnostics == []
    assert [index.named(name).number for name in names] == numbers  # type: ignore[union-attr]


def test_an_absolute_or_symbol_number_wins_and_is_skipped() -> None:
    text = (
        'ORGANIZATION_BLOCK "Cyclic interrupt"\nBEGIN\nEND_ORGANIZATION_BLOCK\n'
        "ORGANIZATION_BLOCK OB30\nBEGIN\nEND_ORGANIZATION_BLOCK\n"
    )
    index = SclIndex(profile="S7-1500")
    index.add_sources([parse_source("a.scl", text).source])
    assert index.get(BlockKind.OB, 30) is not None
    assert index.named("Cyclic interrupt").number == 31  # type: ignore[union-attr]


def test_ob_numbers_that_do_not_exist() -> None:
    text = "".join(
        f'ORGANIZATION_BLOCK "{n}"\nBEGIN\nEND_ORGANIZATION_BLOCK\n'
        for n in ("Startup", "Startup_1", "Conveyor")
    )
    index = SclIndex(profile="S7-300")
    index.add_sources([parse_source("a.scl", text).source])
    assert [(d.code, d.span.line) for d in index.diagnostics] == [("SCL602", 4), ("SCL205", 7)]
    assert "(100)" in index.diagnostics[0].message
    # the same OBs on an S7-1500: further OBs from 123
    index = SclIndex(profile="S7-1500")
    index.add_sources([parse_source("a.scl", text).source])
    assert index.diagnostics == []
    assert [b.number for b in index if b.kind is BlockKind.OB] == [100, 123, 124]


def test_the_event_table() -> None:
    assert ob_event("cyclic INTERRUPT_3") is not None
    assert ob_event("Cyclic interrupts") is None
    taken = set(range(30, 39))
    assert ob_number("Cyclic interrupt", taken, "S7-300") is None
    assert ob_number("Cyclic interrupt", taken, "S7-1500") == 123


def test_fbs_fcs_and_dbs_take_the_first_free_number() -> None:
    result = compile_sources([SourceFile(n, t) for n, t in FILES.items()], profile="S7-1500")
    assert [d.code for d in result.diagnostics] == []
    names = {(b.kind, b.number): b.name for b in result.program.blocks.values()}
    assert names[(BlockKind.DB, 1)] == "Tf_Plant"
    assert names[(BlockKind.DB, 2)] == "Tf_Filler_DB"
    assert names[(BlockKind.FB, 1)] == "Tf_Filler"
    assert names[(BlockKind.OB, 100)] == "Startup"
    assert names[(BlockKind.OB, 1)] == "Main"


# ---- optimized blocks ------------------------------------------------------------------------

OPTIMIZED = """DATA_BLOCK "Opt"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR
      a : Int;
      b : Bool;
   END_VAR
BEGIN
END_DATA_BLOCK
DATA_BLOCK "Std"
{ S7_Optimized_Access := 'FALSE' }
   VAR
      a : Int;
   END_VAR
BEGIN
END_DATA_BLOCK
FUNCTION_BLOCK "Fb"
{ S7_Optimized_Access := 'TRUE' }
   VAR x : Int; END_VAR
BEGIN
END_FUNCTION_BLOCK
DATA_BLOCK "FbInst"
"Fb"
BEGIN
END_DATA_BLOCK
FUNCTION "F" : Void
   VAR_TEMP i : Int; w : Word; END_VAR
BEGIN
   #w := DB1.DBW0;
   #w := %DB1.DBW0;
   #w := "Opt".DBW0;
   %M0.0 := "Opt".DBX2.0;
   #w := "Opt".DW[#i];
   #w := "FbInst".DBW0;
   #w := "Std".DBW0;
   #w := DB2.DW[#i];
   #i := "Opt".a;
END_FUNCTION
"""


def test_absolute_access_to_an_optimized_db_is_refused() -> None:
    assert _codes(OPTIMIZED) == [
        ("SCL600", 29, 14),
        ("SCL600", 30, 15),
        ("SCL600", 31, 16),
        ("SCL600", 32, 19),
        ("SCL600", 33, 16),
        ("SCL600", 34, 19),  # the instance DB of an optimized FB is optimized
    ]
    result = compile_sources([SourceFile("t.scl", OPTIMIZED)], profile="S7-1500")
    assert result.diagnostics[0].message == (
        'DB1.DBW0: "Opt" (DB 1) is an optimized block, whose data has no absolute addresses;'
        " reach its variables by name."
    )


def test_an_optimized_block_needs_the_s7_1500_profile() -> None:
    assert _codes(OPTIMIZED, "S7-300") == [("SCL500", 2, 3), ("SCL500", 18, 3)]
    result = compile_sources([SourceFile("t.scl", OPTIMIZED)], profile="S7-400")
    assert result.diagnostics[0].message == (
        "S7_Optimized_Access := 'TRUE' needs the S7-1200/1500 profile; this program is"
        " compiled for S7-400."
    )


def test_the_access_attribute_takes_true_or_false() -> None:
    text = (
        "DATA_BLOCK \"D\"\n{ S7_Optimized_Access := 'yes' }\nVAR a : Int; END_VAR\n"
        "BEGIN\nEND_DATA_BLOCK\n"
        "DATA_BLOCK \"E\"\n{ s7_optimized_access := 'true' }\nVAR a : Int; END_VAR\n"
        "BEGIN\nEND_DATA_BLOCK\n"
    )
    assert _codes(text) == [("SCL601", 2, 3)]


# ---- lowered and run -------------------------------------------------------------------------


def test_the_exported_program_runs_on_an_s7_1500() -> None:
    sources = [SourceFile(name, text.encode("utf-8")) for name, text in FILES.items()]
    result = compile_sources(sources, profile="S7-1500")
    assert result.ok, [d.message for d in result.diagnostics]
    cpu = Cpu(result.program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(2)
    assert cpu.mode == "RUN", cpu.stop_reason
    assert _read(cpu, "MW2") == 41  # 40 declared, plus one in the Startup OB (OB 100)
    assert _read(cpu, "MW4") == 25  # from the DB's BEGIN section
    assert _read(cpu, "MW6") == -7
    assert _read(cpu, "MW8") == 3  # the UDT's initial value
    assert _read(cpu, "M0.0") == 0  # 40 of the instance DB's limit 60
    cpu.run(1)
    assert _read(cpu, "M0.0") == 1  # 60: the limit from the instance DB's BEGIN section


def test_a_standard_tia_db_keeps_its_absolute_addresses() -> None:
    text = (
        "DATA_BLOCK \"S\"\n{ S7_Optimized_Access := 'FALSE' }\nVERSION : 0.1\n"
        "VAR\n  a : Int;\n  b : Int;\nEND_VAR\nBEGIN\n  a := 11;\n  b := 22;\nEND_DATA_BLOCK\n"
        'ORGANIZATION_BLOCK "Main"\nBEGIN\n  %MW0 := DB1.DBW2;\n'
        '  %MW2 := "S".DBW0;\nEND_ORGANIZATION_BLOCK\n'
    )
    for profile in ("S7-300", "S7-1500"):
        result = compile_sources([SourceFile("s.scl", text)], profile=profile)
        assert result.ok, [d.message for d in result.diagnostics]
        cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=10)
        cpu.start()
        cpu.run(1)
        assert (_read(cpu, "MW0"), _read(cpu, "MW2")) == (22, 11)


def test_iec_type_colon_and_variables_named_like_keywords() -> None:
    """``TYPE "U" : STRUCT ... END_TYPE`` (IEC 61131-3, CODESYS) and TIA's bare ``Return : SInt``
    (its code writes ``#Return``)."""
    text = (
        'TYPE "Tf_Pair" :\nSTRUCT\n  a : Int;\n  b : Int;\nEND_STRUCT;\nEND_TYPE\n'
        "FUNCTION \"Tf_Sum\" : Void\n{ S7_Optimized_Access := 'TRUE' }\nVAR_INPUT\n"
        '  p : "Tf_Pair";\nEND_VAR\nVAR_OUTPUT\n  Return : Int;\nEND_VAR\nBEGIN\n'
        "  #Return := #p.a + #p.b;\nEND_FUNCTION\n"
        'ORGANIZATION_BLOCK "Main"\nVAR_TEMP\n  p : "Tf_Pair";\n  r : Int;\nEND_VAR\nBEGIN\n'
        '  #p.a := 2;\n  #p.b := 5;\n  "Tf_Sum"(p := #p, Return => #r);\n'
        "  %MW0 := INT_TO_WORD(#r);\nEND_ORGANIZATION_BLOCK\n"
    )
    for fast in (True, False):
        assert parse_source("k.scl", text, fast=fast).diagnostics == []
    result = compile_sources([SourceFile("k.scl", text)], profile="S7-1500")
    assert result.ok, [d.message for d in result.diagnostics]
    cpu = Cpu(result.program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert _read(cpu, "MW0") == 7


@pytest.mark.parametrize(
    ("comment", "statements"),
    [
        ("(* off:\n  (* the old step *)\n  x := 2;\n*)", 1),  # nested, as TIA reads it
        ("(* a (* b (* c (* d *) *) *) *)", 1),  # four levels
        ("(* unbalanced (* as in Classic *)", 1),  # ends at its first *)
        ("(* one *) x := 3; (* two *)", 2),
    ],
)
def test_block_comments_nest_as_in_tia(comment: str, statements: int) -> None:
    text = f"FUNCTION FC1 : VOID\nBEGIN\n  x := 1;\n  {comment}\nEND_FUNCTION\n"
    for fast in (True, False):
        result = parse_source("c.scl", text, fast=fast)
        assert result.diagnostics == [], [d.message for d in result.diagnostics]
        assert len(result.source.blocks[0].code) == statements


def test_a_function_block_called_main_is_an_fb() -> None:
    """Only an OB or a PROGRAM called Main is OB 1; a FUNCTION_BLOCK Main beside OB1 is FB 1."""
    text = (
        "FUNCTION_BLOCK Main\nVAR x : INT; END_VAR\nBEGIN\n  x := 1;\nEND_FUNCTION_BLOCK\n"
        "ORGANIZATION_BLOCK OB1\nBEGIN\n  Main.DB1();\nEND_ORGANIZATION_BLOCK\n"
    )
    index = SclIndex()
    index.add_sources([parse_source("m.scl", text).source])
    assert index.diagnostics == []
    assert index.named("Main").kind is BlockKind.FB  # type: ignore[union-attr]
    assert _codes(text, "S7-300") == []

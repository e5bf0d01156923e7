"""STL constants in TIA Portal's type notation (``L INT#5``, ``L UDINT#16#FFFF``) and STL's
access to the optimized DBs of SCL sources.

STL stays S7-300/400 (``nasaq.lang.stl``): the type names S7-300/400 have load what STEP 7's own
notation loads (``INT#5`` is ``5``, ``DINT#5`` is ``L#5``, ``WORD#16#FF`` is ``W#16#FF``,
``REAL#1.5`` is ``1.5``); the S7-1200/1500 ones (``UDINT#``, ``SINT#`` ...) need that profile
(STL500), and the 64-bit ones (``LREAL#``, ``LINT#`` ...) fit no accumulator (STL603). An
optimized DB has no absolute addresses: ``L DB10.DBW 0`` on it is STL604, by name it works."""

from __future__ import annotations

import pytest
from cpu_run import read, real, run
from stl_helpers import codes, compile_text, ob1

from nasaq.lang.stl import CompileResult, SourceFile, compile_sources


def loads(*pairs: tuple[str, str]) -> str:
    return ob1("\n".join(f"      L     {value};\n      T     {target};" for value, target in pairs))


def test_type_names_of_s7_300_load_what_steps_own_notation_loads() -> None:
    text = loads(
        ("INT#5", "MW 10"),
        ("INT#-1", "MD 12"),  # a 16-bit immediate, as L -1: 16#0000FFFF
        ("DINT#-1", "MD 16"),
        ("DINT#100_000", "MD 20"),
        ("REAL#1.5", "MD 24"),
        ("WORD#16#ABCD", "MW 28"),
        ("DWORD#16#8000_0001", "MD 30"),
        ("BYTE#2#1010", "MB 34"),
        ("INT#16#FFFF", "MW 36"),  # base notation is the bit pattern: -1
    )
    cpu = run(compile_text(text))
    assert read(cpu, "MW 10") == 5
    assert read(cpu, "MD 12") == 0xFFFF
    assert read(cpu, "MD 16") == -1
    assert read(cpu, "MD 20") == 100_000
    assert real(cpu, "MD 24") == 1.5
    assert read(cpu, "MW 28") & 0xFFFF == 0xABCD
    assert read(cpu, "MD 30") & 0xFFFFFFFF == 0x80000001
    assert read(cpu, "MB 34") == 10
    assert read(cpu, "MW 36") == -1


def test_the_same_program_in_steps_notation_gives_the_same_memory() -> None:
    typed = loads(("INT#-3", "MD 0"), ("DINT#-3", "MD 4"), ("WORD#16#F0", "MW 8"))
    classic = loads(("-3", "MD 0"), ("L#-3", "MD 4"), ("W#16#F0", "MW 8"))
    first, second = run(compile_text(typed)), run(compile_text(classic))
    for address in ("MD 0", "MD 4", "MW 8"):
        assert read(first, address) == read(second, address)


@pytest.mark.parametrize(
    ("constant", "column"), [("UDINT#16#FFFF", 13), ("SINT#-5", 13), ("LREAL#1.5", 13)]
)
def test_s7_1500_type_names_need_that_profile_under_s7_300(constant: str, column: int) -> None:
    result = compile_text(loads((constant, "MD 0")))
    assert codes(result) == [("STL500", 3, column)]
    assert constant.partition("#")[0] + "#" in result.diagnostics[0].message


def test_s7_1500_type_names_load_their_32_bit_value_under_s7_1500() -> None:
    text = loads(("UDINT#16#FFFF_FFFF", "MD 0"), ("UINT#65535", "MW 4"), ("SINT#-5", "MW 6"))
    result = compile_sources([SourceFile("test.awl", text)], profile="S7-1500")
    cpu = run(result, profile="S7-1500")
    assert read(cpu, "MD 0") == -1  # all 32 bits set
    assert read(cpu, "MW 4") & 0xFFFF == 65535
    assert read(cpu, "MW 6") == -5


@pytest.mark.parametrize("constant", ["LREAL#1.5", "LINT#5", "LWORD#16#1", "ULINT#7"])
def test_a_64_bit_constant_fits_no_accumulator(constant: str) -> None:
    result = compile_sources([SourceFile("test.awl", loads((constant, "MD 0")))], profile="S7-1500")
    assert codes(result) == [("STL603", 3, 13)]
    assert "64-bit" in result.diagnostics[0].message


@pytest.mark.parametrize("constant", ["INT#40000", "DINT#3000000000", "WORD#16#1_0000"])
def test_a_typed_constant_outside_its_type_is_out_of_range(constant: str) -> None:
    assert codes(compile_text(loads((constant, "MD 0")))) == [("STL214", 3, 13)]


OPTIMIZED = """\
DATA_BLOCK "OptDb"
{ S7_Optimized_Access := 'TRUE' }
   VAR
      x : Int;
      y : Real;
   END_VAR
BEGIN
   x := 7;
   y := 2.5;
END_DATA_BLOCK

DATA_BLOCK DB10
{ S7_Optimized_Access := 'TRUE' }
   VAR
      w : Int := 3;
   END_VAR
BEGIN
END_DATA_BLOCK

DATA_BLOCK "StdDb"
{ S7_Optimized_Access := 'FALSE' }
   VAR
      s : Int := 4;
   END_VAR
BEGIN
END_DATA_BLOCK

FUNCTION "Touch" : VOID
BEGIN
   "OptDb".x := "OptDb".x + 1;
   DB10.w := DB10.w + 1;
END_FUNCTION
"""


def compile_1500(stl: str) -> CompileResult:
    sources = [SourceFile("data.scl", OPTIMIZED), SourceFile("main.awl", stl)]
    return compile_sources(sources, profile="S7-1500")


def test_stl_reads_an_optimized_scl_db_by_name() -> None:
    stl = ob1(
        '      CALL  "Touch" ;\n      L     "OptDb".x;\n      T     MW 10;\n'
        '      L     "OptDb".y;\n      T     MD 12;\n      L     "StdDb".s;\n      T     MW 16;\n'
        "      L     DB10.w;\n      T     MW 18;"
    )
    result = compile_1500(stl)
    cpu = run(result, profile="S7-1500")
    assert read(cpu, "MW 10") == 8  # 7, and the SCL FC (absolute inside) added one
    assert real(cpu, "MD 12") == 2.5
    assert read(cpu, "MW 16") == 4
    assert read(cpu, "MW 18") == 4


def test_stl_addressing_an_optimized_db_absolutely_is_stl604() -> None:
    # DB 2 is "StdDb", a standard DB: its absolute addresses stay
    stl = ob1(
        "      L     DB10.DBW 0;\n      T     MW 10;\n      L     DB2.DBW 0;\n      T     MW 12;"
    )
    result = compile_1500(stl)
    assert [(d.code, d.span.file, d.span.line) for d in result.diagnostics] == [
        ("STL604", "main.awl", 3)
    ]
    assert "DB 10" in result.diagnostics[0].message


def test_an_optimized_db_of_an_stl_source_is_reached_by_name_only() -> None:
    text = """\
DATA_BLOCK "Recipe"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   STRUCT
      speed : Int;
   END_STRUCT;
BEGIN
   speed := 12;
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
      L     "Recipe".speed;
      T     MW 10;
      L     "Recipe".DBW 0;
      T     MW 12;
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("recipe.awl", text)], profile="S7-1500")
    assert codes(result) == [("STL604", 15, 13)]
    assert '"Recipe" (DB 1)' in result.diagnostics[0].message
    by_name = text.replace('      L     "Recipe".DBW 0;\n      T     MW 12;\n', "")
    cpu = run(
        compile_sources([SourceFile("recipe.awl", by_name)], profile="S7-1500"), profile="S7-1500"
    )
    assert read(cpu, "MW 10") == 12

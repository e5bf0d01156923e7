"""A block whose local data (VAR_TEMP) exceed the L stack the profile's CPU has per priority
class is STL605 when compiling (``nasaq.lang.stl.compiler.check_temp``): STEP 7 compiles it, but
the CPU could never call it. S7-300 2048 bytes, S7-400 16384, S7-1500 65536
(``nasaq.cpu.profile``)."""

from __future__ import annotations

import pytest
from cpu_run import read, run
from scl_run import build, ob1

from nasaq.cpu.profile import Profile
from nasaq.lang.stl import SourceFile, compile_sources

BIG = """\
FUNCTION "Big" : VOID
VAR_TEMP
  buffer : ARRAY[0..2000] OF INT;
END_VAR
BEGIN
  buffer[2000] := 5;
  MW10 := INT_TO_WORD(buffer[2000]);
END_FUNCTION
"""


def compiled(text: str, profile: str, name: str = "prog.scl") -> list[tuple[str, str, int]]:
    result = compile_sources([SourceFile(name, text)], profile=profile)
    return [(d.code, d.span.file, d.span.line) for d in result.diagnostics]


def test_an_scl_block_over_the_s7_300_l_stack_is_stl605() -> None:
    result = compile_sources([SourceFile("prog.scl", BIG + ob1('"Big"();'))], profile="S7-300")
    found = [d for d in result.diagnostics if d.severity == "error"]
    assert [(d.code, d.span.file, d.span.line) for d in found] == [("STL605", "prog.scl", 1)]
    message = found[0].message
    assert '"Big" (FC 1)' in message
    assert "4002 bytes" in message
    assert "2048 bytes" in message


@pytest.mark.parametrize("profile", ["S7-400", "S7-1500"])
def test_the_same_block_fits_the_larger_l_stacks_and_runs(profile: str) -> None:
    cpu = build(BIG + ob1('"Big"();'), profile=profile)
    assert read(cpu, "MW 10") == 5


def stl_fc(temp_bytes: int) -> str:
    return (
        "FUNCTION FC 2 : VOID\nVAR_TEMP\n"
        f"  area : ARRAY[1..{temp_bytes}] OF BYTE;\nEND_VAR\nBEGIN\n"
        "      L     7;\n      T     #area[1];\n      L     #area[1];\n      T     MW 20;\n"
        "END_FUNCTION\n"
        "ORGANIZATION_BLOCK OB 1\nBEGIN\n      CALL  FC 2;\nEND_ORGANIZATION_BLOCK\n"
    )


def test_an_stl_block_may_use_the_whole_l_stack_and_not_one_byte_more() -> None:
    limit = Profile("S7-300").lstack_bytes
    assert compiled(stl_fc(limit + 1), "S7-300", "fc.awl") == [("STL605", "fc.awl", 1)]
    assert compiled(stl_fc(limit), "S7-300", "fc.awl") == []


def test_an_stl_block_within_the_l_stack_runs() -> None:
    """The check is per block; calls nested past the L stack together are the CPU's (SIM509)."""
    limit = Profile("S7-300").lstack_bytes
    result = compile_sources([SourceFile("fc.awl", stl_fc(limit - 20))], profile="S7-300")
    cpu = run(result)
    assert read(cpu, "MW 20") == 7

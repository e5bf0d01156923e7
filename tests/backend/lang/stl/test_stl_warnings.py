"""A warning never changes what the instruction does: the operand stays as written."""

from nasaq.ir import BlockKind, Constant
from nasaq.lang.stl import SourceFile, compile_sources


def test_a_shift_count_above_the_step7_limit_warns_and_keeps_its_count() -> None:
    source = "ORGANIZATION_BLOCK OB 1\nBEGIN\nL MW 0;\nSLW 16;\nT MW 0;\nEND_ORGANIZATION_BLOCK\n"
    result = compile_sources([SourceFile("OB1.awl", source)])
    assert result.ok
    assert [d.code for d in result.diagnostics] == ["STL237"]
    block = result.program.get(BlockKind.OB, 1)
    assert block is not None
    shift = block.code[1]
    assert shift.op == "SLW"
    assert isinstance(shift.operand, Constant)
    assert shift.operand.value == 16

"""Instructions, calls and jumps written again, in one block or in another: the compiler
lowers each only once (``lower``: by mnemonic and operand, shared between blocks when no local
variable is involved; ``calls``: whole calls), and must give the IR and the diagnostics it gives
when it lowers every one."""

from __future__ import annotations

import dataclasses

import pytest
from stl_helpers import block, code_of, codes, compile_text, ob1

from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    CallInfo,
    Constant,
    ConstType,
    Direct,
    Instruction,
    LabelRef,
    Origin,
    Width,
)

FC = "FUNCTION FC {number} : VOID\nVAR_TEMP\n{temps}END_VAR\nBEGIN\n{body}\nEND_FUNCTION\n"


def fc(number: int, body: str, temps: str = "") -> str:
    return FC.format(number=number, temps=temps, body=body)


def test_an_instruction_that_reports_reports_at_every_use_in_every_block() -> None:
    body = "A MW 10\nL 1\nA MW 10\nL 1"
    result = compile_text(fc(1, body) + fc(2, body))
    assert codes(result) == [
        ("STL204", 5, 3),
        ("STL204", 7, 3),
        ("STL204", 14, 3),
        ("STL204", 16, 3),
    ]
    assert [item.operand for item in code_of(result, "FC", 2)] == [None, _int(1), None, _int(1)]


def test_local_variables_are_lowered_in_their_own_block() -> None:
    first = fc(1, "L #x\nT #x\nL P##x", temps="  x : INT;\n")
    second = fc(2, "L #x\nT #x\nL P##x", temps="  a : DINT;\n  x : INT;\n")
    result = compile_text(first + second)
    assert result.ok, result.diagnostics
    assert [item.operand for item in code_of(result, "FC", 1)][:2] == [
        Direct(Area.L, Width.WORD, 0)
    ] * 2
    assert [item.operand for item in code_of(result, "FC", 2)][:2] == [
        Direct(Area.L, Width.WORD, 4)
    ] * 2
    pointers = [code_of(result, "FC", number)[2].operand for number in (1, 2)]
    assert [item.pattern for item in pointers if isinstance(item, Constant)] == [
        0x86000000,
        0x86000020,
    ]


def test_jumps_written_again_resolve_in_their_own_block() -> None:
    body = "JU M001\nM001: NOP 0\nJC M001\nJU M002"
    result = compile_text(fc(1, body) + fc(2, body) + fc(3, "JU M001\nJU M001"))
    assert codes(result) == [
        ("STL207", 8, 4),
        ("STL207", 17, 4),
        ("STL219", 23, 4),
        ("STL219", 24, 4),
    ]
    assert code_of(result, "FC", 2)[2].operand == LabelRef("M001")
    assert block(result, "FC", 2).labels == {"M001": 1}


def test_brackets_written_again_are_checked_at_every_use() -> None:
    result = compile_text(ob1(")\nA(\nA I 0.0\n)\n)\nA(\nA(\nA(\nA(\nA(\nA(\nA(\nA(\nA(\n)"))
    unclosed = [("STL238", line, 1) for line in range(8, 16)]
    assert codes(result) == [("STL239", 3, 1), ("STL239", 7, 1), *unclosed, ("STL240", 15, 1)]


def test_calls_written_again_give_the_same_call_and_report_again() -> None:
    callee = "FUNCTION FC 5 : VOID\nVAR_INPUT\n  a : INT;\nEND_VAR\nBEGIN\nNOP 0\nEND_FUNCTION\n"
    good = "CALL FC 5 (a := MW 2);\n"
    bad = "CALL FC 5 (a := MD 4);\n"
    result = compile_text(callee + ob1(good + good + bad + bad))
    assert [code for code, _line, _column in codes(result)] == ["STL210", "STL210"]
    calls = [item.call for item in code_of(result)]
    expected = CallInfo(
        BlockRef(BlockKind.FC, 5), None, (CallArg("a", Direct(Area.M, Width.WORD, 2)),)
    )
    assert calls == [
        expected,
        expected,
        CallInfo(BlockRef(BlockKind.FC, 5), None, ()),
        CallInfo(BlockRef(BlockKind.FC, 5), None, ()),
    ]


def test_an_instance_db_that_no_source_defines_is_reported_once() -> None:
    callee = (
        "FUNCTION_BLOCK FB 1\nVAR_INPUT\n  a : INT;\nEND_VAR\nBEGIN\nNOP 0\nEND_FUNCTION_BLOCK\n"
    )
    call = "CALL FB 1, DB 9 (a := MW 2);\n"
    result = compile_text(callee + ob1(call * 3) + fc(2, call))
    assert codes(result) == [("STL229", 10, 1)]
    assert result.program.get(BlockKind.DB, 9) is not None


def test_a_library_call_is_found_whatever_the_case_of_call() -> None:
    db = "DATA_BLOCK DB 1\nSTRUCT\n  s : STRING[4];\nEND_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
    call = "cAlL \"CONCAT\" (IN1 := 'ab', IN2 := 'cd', RET_VAL := DB1.s);"
    result = compile_text(db + ob1(call))
    assert not result.diagnostics
    assert result.program.symbols["CONCAT"] == "FC 2"


def test_the_lowering_makes_instructions_field_by_field() -> None:
    """``CodeLowerer.lower`` builds an instruction written before field by field (faster than
    the class call): a new field of ``Instruction`` must be set there too."""
    names = [item.name for item in dataclasses.fields(Instruction)]
    assert names == ["op", "operand", "origin", "operand2", "label", "call"]
    result = compile_text(ob1("L MW 2\nL MW 2"))
    first, second = code_of(result)
    assert second == dataclasses.replace(first, origin=second.origin)


def test_fast_init_keeps_what_dataclass_makes() -> None:
    origin = Origin("a.awl", 3, 7)
    assert (origin.network, origin.element) == (None, None)
    assert origin == Origin(file="a.awl", line=3, column=7, network=None)
    assert hash(origin) == hash(Origin("a.awl", 3, 7))
    assert repr(origin) == "Origin(file='a.awl', line=3, column=7, network=None, element=None)"
    assert dataclasses.replace(origin, line=4) == Origin("a.awl", 4, 7)
    with pytest.raises(dataclasses.FrozenInstanceError):
        origin.line = 5  # type: ignore[misc]
    with pytest.raises(TypeError):
        Direct(Area.M, Width.BIT)  # type: ignore[call-arg]
    assert Direct(Area.DB, Width.WORD, 2, db=5) == Direct(Area.DB, Width.WORD, 2, 0, 5)


def _int(value: int) -> Constant:
    return Constant(ConstType.INT, value, value, str(value))

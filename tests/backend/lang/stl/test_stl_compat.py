# ruff: noqa: E501  (test sources are easier to read on one line)
"""What STEP 7 accepts beyond the basics, and the awlsim extensions accepted with test
instructions: header orders, DT#/string actual parameters, memory-indirect block parameters,
ANY actuals, awlsim's ``P#DB42.member``, STRING indexing and negative system block numbers."""

from __future__ import annotations

from stl_helpers import block, code_of, codes, compile_text, ob1

from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    Constant,
    ConstType,
    Direct,
    MemoryIndirect,
    ParamRef,
    Width,
)
from nasaq.lang.stl import SourceFile, ast
from nasaq.lang.stl.parse import parse_source


def args_of(text: str, **options: bool) -> tuple[CallArg, ...]:
    result = compile_text(text, **options)  # type: ignore[arg-type]
    assert result.ok, result.diagnostics
    calls = [item.call for item in code_of(result) if item.call is not None]
    assert calls
    assert calls[0] is not None
    return calls[0].args


def error_codes(text: str, *extra: SourceFile, **options: bool) -> set[str]:
    return {code for code, _, _ in codes(compile_text(text, *extra, **options))}  # type: ignore[arg-type]


# ---- block headers -------------------------------------------------------------------------


def test_db_headers_may_follow_the_instance_fb_or_the_structure() -> None:
    text = (
        "FUNCTION_BLOCK FB 1\nVAR\n  a : INT;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION_BLOCK\n"
        "DATA_BLOCK DB 2\n  FB 1\n  TITLE = after the FB\n  AUTHOR : me\n  { S7_m_c := 'true' }\n  KNOW_HOW_PROTECT\nBEGIN\nEND_DATA_BLOCK\n"
        "DATA_BLOCK DB 3\nTITLE = before\n  STRUCT\n    x : INT;\n  END_STRUCT;\nVERSION : 0.1\nBEGIN\nEND_DATA_BLOCK\n"
    )
    parsed = parse_source("h.awl", text)
    assert parsed.diagnostics == []
    db2 = parsed.source.blocks[1]
    assert [type(item).__name__ for item in db2.head] == [
        "TitleNode",
        "HeaderPropNode",
        "AttributesNode",
        "FlagNode",
    ]
    result = compile_text(text)
    assert result.ok, result.diagnostics
    assert block(result, "DB", 2).title == "after the FB"
    assert block(result, "DB", 2).know_how_protect
    assert block(result, "DB", 3).attributes["VERSION"] == "0.1"


def test_code_block_headers_in_any_order() -> None:
    text = (
        "FUNCTION FC 1 : VOID\n  VAR_INPUT\n    a : INT;\n  END_VAR\n  TITLE = late title\n"
        "  { attribute1 := 'value 1'; attribute2 := 'value 2' }\n  NAME : late\n  STANDARD\n"
        "BEGIN\n  NOP 0\nEND_FUNCTION\n"
    )
    result = compile_text(text)
    assert result.ok, result.diagnostics
    fc = block(result, "FC", 1)
    assert fc.title == "late title"
    assert fc.attributes["attribute2"] == "value 2"
    assert fc.attributes["NAME"] == "late"


def test_a_call_spanning_lines_outside_any_block() -> None:
    result = compile_text("  CALL SFC 46 (\n    X := 1\n  )\n  NOP 0\n")
    assert result.ok, result.diagnostics
    (call, nop) = code_of(result)
    assert call.call is not None
    assert call.call.args[0].name == "X"
    assert nop.op == "NOP"


# ---- awlsim's own system blocks --------------------------------------------------------------


def test_negative_system_blocks_are_awlsim_test_blocks() -> None:
    text = ob1("  CALL SFC -3 (\n    SHUTDOWN_TYPE := 1\n  )")
    (call,) = code_of(compile_text(text, test_ops=True))
    assert call.call is not None
    assert call.call.block == BlockRef(BlockKind.SFC, -3)
    assert call.call.args == (CallArg("SHUTDOWN_TYPE", Constant(ConstType.INT, 1, 1, "1")),)
    assert codes(compile_text(text)) == [("STL218", 3, 8)]
    instance = "DATA_BLOCK DB 3\n  SFB -1\nBEGIN\nEND_DATA_BLOCK\n"
    assert compile_text(instance, test_ops=True).ok
    assert error_codes(instance) == {"STL218"}
    assert error_codes(ob1("  CALL MW -2")) == {"STL205"}  # only SFC/SFB take a sign


def test_negative_system_blocks_in_a_symbol_table() -> None:
    table = SourceFile("s.asc", "126,__CLKRST                SFC -4      SFC -4\n")
    text = ob1('  CALL "__CLKRST"')
    result = compile_text(text, table, test_ops=True)
    assert result.ok, result.diagnostics
    (call,) = code_of(result)
    assert call.call is not None
    assert call.call.block == BlockRef(BlockKind.SFC, -4)
    assert error_codes(text, table) == {"STL218"}


# ---- DATE_AND_TIME and STRING constants ------------------------------------------------------

_DT_BLOCKS = (
    "FUNCTION FC 1 : VOID\nVAR_INPUT\n  dt : DATE_AND_TIME;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"
    "FUNCTION_BLOCK FB 1\nVAR_INPUT\n  dt : DATE_AND_TIME;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION_BLOCK\n"
    "DATA_BLOCK DB 1\n  FB 1\nBEGIN\n  dt := DT#1990-1-1-0:0:0.0;\nEND_DATA_BLOCK\n"
    "DATA_BLOCK DB 2\n  STRUCT\n    dt : DATE_AND_TIME := DT#1998-02-03-16:17:20.211;\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
)


def test_date_and_time_constants_as_actual_parameters_and_db_values() -> None:
    moment = Constant(
        ConstType.DATE_AND_TIME,
        0x9802031617202113,
        0x9802031617202113,
        "DT#1998-02-03-16:17:20.211",
    )
    text = _DT_BLOCKS + ob1(
        "  CALL FC 1 (dt := DT#1998-02-03-16:17:20.211)\n  CALL FB 1, DB 1 (dt := DT#1998-02-03-16:17:20.211)"
    )
    result = compile_text(text)
    assert result.ok, result.diagnostics
    calls = [item.call for item in code_of(result) if item.call is not None]
    assert [call.args for call in calls] == [(CallArg("dt", moment),), (CallArg("dt", moment),)]
    assert block(result, "DB", 1).data.hex() == "9001010000000002"
    assert block(result, "DB", 2).data.hex() == "9802031617202113"


def test_date_and_time_constants_are_no_accumulator_values() -> None:
    assert codes(compile_text(ob1("  L DT#1990-1-1-0:0:0"))) == [("STL107", 3, 5)]
    assert codes(compile_text(ob1("  __ASSERT== MD 0, DT#1990-1-1-0:0:0"), test_ops=True)) == [
        ("STL107", 3, 20)
    ]
    wrong = (
        _DT_BLOCKS
        + "FUNCTION FC 2 : VOID\nVAR_INPUT\n  i : INT;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"
    )
    assert error_codes(wrong + ob1("  CALL FC 2 (i := DT#1990-1-1-0:0:0)")) == {"STL210"}


def test_string_constants_as_string_parameters() -> None:
    fc = (
        "FUNCTION FC 1 : VOID\nVAR_INPUT\n  s : STRING[6];\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"
    )
    args = args_of(fc + ob1("  CALL FC 1 (s := 'aabbcc')"))
    assert args == (CallArg("s", Constant(ConstType.STRING, 0x616162626363, 6, "'aabbcc'")),)
    args = args_of(fc + ob1("  CALL FC 1 (s := 'ab')"))
    assert args == (CallArg("s", Constant(ConstType.STRING, 0x6162, 2, "'ab'")),)
    assert error_codes(fc + ob1("  CALL FC 1 (s := 'aabbccd')")) == {"STL210"}
    assert codes(compile_text(ob1("  L 'ABCDE'"))) == [("STL107", 3, 5)]


# ---- block parameters ------------------------------------------------------------------------


def test_block_timer_and_counter_parameters_take_memory_indirect_actuals() -> None:
    fb = (
        "FUNCTION_BLOCK FB 2\nVAR_INPUT\n  d : BLOCK_DB;\n  f : BLOCK_FC;\n  b : BLOCK_FB;\n  t : TIMER;\n  c : COUNTER;\n"
        "END_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION_BLOCK\n"
    )
    args = args_of(
        fb
        + ob1(
            "  CALL FB 2, DB 2 (d := DB [MW 14], f := FC [MW 12], b := FB [MW 12], t := T [MW 2], c := Z [MW 4])"
        )
    )
    pointer = Direct(Area.M, Width.WORD, 14)
    assert args[0] == CallArg("d", MemoryIndirect(None, None, pointer, "DB"))
    assert [arg.value.target for arg in args if isinstance(arg.value, MemoryIndirect)] == [
        "DB",
        "FC",
        "FB",
        "T",
        "C",
    ]
    assert error_codes(fb + ob1("  CALL FB 2, DB 2 (d := FC [MW 14])")) == {"STL210", "STL229"}


# ---- ANY parameters and awlsim's pointers to DB variables ------------------------------------

_DB100 = (
    "DATA_BLOCK DB 100\n  STRUCT\n    v1 : INT;\n    v2 : ARRAY[1 .. 6] OF STRUCT\n      a : INT;\n      b : INT;\n    END_STRUCT;\n"
    "    v3 : ARRAY[1 .. 4] OF STRUCT\n      a1 : INT;\n    END_STRUCT;\n    v4 : ARRAY[1 .. 8] OF BYTE;\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
)
_ANY_FC = "FUNCTION FC 1 : VOID\nVAR_INPUT\n  p : ANY;\n  q : ANY;\n  r : ANY;\n  s : ANY;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"


def test_declared_variables_reach_an_any_parameter_with_their_type() -> None:
    table = SourceFile("s.csv", "Level,MW 20,INT\nData,DB 100\n")
    text = (
        _DB100
        + _ANY_FC
        + ob1(
            '  CALL FC 1 (p := DB100.v2[2].b, q := "Level", r := "Data".v4, s := M 1.0)\n'
            "  CALL FC 1 (p := DB100.v3, q := DB100.v2[1], r := MW 2, s := #t)"
        )
    )
    result = compile_text(
        text.replace("BEGIN\n  CALL", "VAR_TEMP\n  t : INT;\nEND_VAR\nBEGIN\n  CALL"), table
    )
    assert result.ok, result.diagnostics
    first, second = [item.call for item in code_of(result) if item.call is not None]
    assert [arg.value for arg in first.args] == [
        Constant(ConstType.POINTER, 0x84000040, 64, "P#DB100.DBX 8.0 INT 1"),
        Constant(ConstType.POINTER, 0x830000A0, 160, "P#M 20.0 INT 1"),
        Constant(ConstType.POINTER, 0x84000110, 272, "P#DB100.DBX 34.0 BYTE 8"),
        Direct(Area.M, Width.BIT, 1, 0),
    ]
    assert [arg.value for arg in second.args] == [
        Constant(ConstType.POINTER, 0x840000D0, 208, "P#DB100.DBX 26.0 BYTE 8"),  # STRUCTs: bytes
        Constant(ConstType.POINTER, 0x84000010, 16, "P#DB100.DBX 2.0 BYTE 4"),
        Direct(Area.M, Width.WORD, 2, 0),
        # a temporary: the caller's local data (V, as the callee sees it), with its type
        Constant(ConstType.POINTER, 0x87000000, 0, "P#V 0.0 INT 1"),
    ]


def test_awlsim_pointers_to_db_variables() -> None:
    table = SourceFile("s.csv", "Data,DB 100\n")
    body = '  L P#DB100.v2[2].b\n  L P#"Data".v1\n  CALL FC 1 (p := P#DB100.v2[2].b, q := P#DB100.v3, r := P#DB100.v4, s := P#DB100.v1)'
    result = compile_text(_DB100 + _ANY_FC + ob1(body), table, test_ops=True)
    assert result.ok, result.diagnostics
    first, second, call = code_of(result)
    assert first.operand == Constant(ConstType.POINTER, 0x84000040, 64, "P#DB100.DBX 8.0")
    assert second.operand == Constant(ConstType.POINTER, 0x84000000, 0, "P#DB100.DBX 0.0")
    assert call.call is not None
    assert [arg.value.text for arg in call.call.args if isinstance(arg.value, Constant)] == [
        "P#DB100.DBX 8.0 INT 1",
        "P#DB100.DBX 26.0 DWORD 2",  # awlsim: an array of STRUCTs as its widest units
        "P#DB100.DBX 34.0 BYTE 8",  # an array of BYTEs: its elements
        "P#DB100.DBX 0.0 INT 1",
    ]
    assert codes(compile_text(_DB100 + ob1("  L P#DB100.v1"))) == [("STL107", 17, 5)]
    assert error_codes(_DB100 + ob1("  L P#DB100.nothing"), test_ops=True) == {"STL216"}
    # the STEP 7 forms stay what they were
    (load,) = code_of(compile_text(ob1("  L P#DB100.DBX 2.0")))
    assert load.operand == Constant(ConstType.POINTER, 0x84000010, 16, "P#DB100.DBX 2.0")


def test_the_awlsim_pointer_token() -> None:
    text = ob1(
        '  L P#DB42.ARR1[1, 2].V1\n  L P#"Data".x.y\n  L P#DB50.DBX 10.0 DWORD 8\n  L P#DB1.DBX1.0'
    )
    (block_node,) = parse_source("p.awl", text).source.blocks
    loaded = [item.operands[0] for item in block_node.code if isinstance(item, ast.InstrNode)]
    assert [(node.kind, node.text) for node in loaded if isinstance(node, ast.LiteralNode)] == [
        ("POINTER", "P#DB42.ARR1[1, 2].V1"),
        ("POINTER", 'P#"Data".x.y'),
        ("POINTER", "P#DB50.DBX 10.0 DWORD 8"),
        ("POINTER", "P#DB1.DBX1.0"),
    ]


def test_db_members_named_like_addresses() -> None:
    db = "DATA_BLOCK DB 5\n  STRUCT\n    A1 : INT;\n    v2 : ARRAY[1..2] OF INT;\n    T1 : INT;\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
    table = SourceFile("s.csv", "Data,DB 5\n")
    result = compile_text(
        db + ob1('  L "Data".A1\n  L DB5.v2[2]\n  L "Data".T1\n  L "Data".DBW 2\n  L DB5.DBW 4'),
        table,
    )
    assert result.ok, result.diagnostics
    assert [item.operand for item in code_of(result)] == [
        Direct(Area.DB, Width.WORD, 0, 0, 5),
        Direct(Area.DB, Width.WORD, 4, 0, 5),
        Direct(Area.DB, Width.WORD, 6, 0, 5),
        Direct(Area.DB, Width.WORD, 2, 0, 5),
        Direct(Area.DB, Width.WORD, 4, 0, 5),
    ]
    assert error_codes(db + ob1('  L "Data".M2'), table) == {"STL216"}


# ---- STRING characters ------------------------------------------------------------------------


def test_string_characters_by_index_with_test_instructions() -> None:
    db = "DATA_BLOCK DB 100\n  STRUCT\n    n : INT;\n    s : STRING[4] := 'ab';\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
    fc = "FUNCTION FC 1 : VOID\nVAR_INPUT\n  t : STRING;\nEND_VAR\nVAR_TEMP\n  u : STRING[3];\nEND_VAR\nBEGIN\n  L #t[3]\n  L #u[1]\nEND_FUNCTION\n"
    result = compile_text(db + fc + ob1("  L DB100.s[1]\n  T DB100.s[4]"), test_ops=True)
    assert result.ok, result.diagnostics
    assert [item.operand for item in code_of(result)] == [
        Direct(Area.DB, Width.BYTE, 4, 0, 100),
        Direct(Area.DB, Width.BYTE, 7, 0, 100),
    ]
    assert [item.operand for item in code_of(result, "FC", 1)] == [
        ParamRef(0, "t", Width.BYTE, 32),
        Direct(Area.L, Width.BYTE, 2),
    ]
    assert codes(compile_text(db + ob1("  L DB100.s[1]"))) == [("STL235", 10, 5)]
    assert codes(compile_text(db + ob1("  L DB100.s[5]"), test_ops=True)) == [("STL217", 10, 5)]
    assert codes(compile_text(db + ob1("  L DB100.s[1, 1]"), test_ops=True)) == [("STL217", 10, 5)]


# ---- data block values -----------------------------------------------------------------------


def test_initial_values_inside_each_struct_element_of_an_array() -> None:
    text = (
        "DATA_BLOCK DB 1\n  STRUCT\n    arr : ARRAY[1 .. 2] OF STRUCT\n      a : INT := 1031;\n"
        "      b : ARRAY[1 .. 2] OF INT := 1, 2;\n      s : STRING[2] := 'x';\n    END_STRUCT;\n  END_STRUCT;\n"
        "BEGIN\n  arr[2].a := 1032;\nEND_DATA_BLOCK\n"
    )
    result = compile_text(text)
    assert result.ok, result.diagnostics
    element = "04070001000202017800"
    assert block(result, "DB", 1).data.hex() == element + element.replace("0407", "0408", 1)

# ruff: noqa: E501  (test sources are easier to read on one line)
"""Parse → lower: each construct becomes the IR the contract in nasaq.ir prescribes."""

from __future__ import annotations

from stl_helpers import block, code_of, codes, compile_text, ob1

from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    Constant,
    ConstType,
    CounterRef,
    Direct,
    LabelRef,
    MemoryIndirect,
    MultiInstance,
    ParamRef,
    Register,
    RegisterIndirect,
    StatusCondition,
    TimerRef,
    Width,
)
from nasaq.lang.stl import SourceFile


def ops(body: str, **options: bool) -> list[tuple[str, object]]:
    result = compile_text(ob1(body), **options)  # type: ignore[arg-type]
    assert result.ok, result.diagnostics
    return [(item.op, item.operand) for item in code_of(result)]


def test_bit_logic_nesting_and_status_conditions() -> None:
    assert ops(
        "A(\nO I 0.0\nO\nON M 1.1\n)\nX ==0\nXN OV\nA BR\n= Q 4.0\nSET\nNOT\nSAVE\nFP M 0.0"
    ) == [
        ("A(", None),
        ("O", Direct(Area.I, Width.BIT, 0, 0)),
        ("O", None),
        ("ON", Direct(Area.M, Width.BIT, 1, 1)),
        (")", None),
        ("X", StatusCondition.EQ0),
        ("XN", StatusCondition.OV),
        ("A", StatusCondition.BR),
        ("=", Direct(Area.Q, Width.BIT, 4, 0)),
        ("SET", None),
        ("NOT", None),
        ("SAVE", None),
        ("FP", Direct(Area.M, Width.BIT, 0, 0)),
    ]


def test_load_transfer_areas_sizes_registers_and_pointers() -> None:
    assert ops(
        "L PIW 256\nT PQW 256\nL DB5.DBW 2\nT DID 4\nL STW\nL DBNO\nL P#M10.0\nL T 3\nLC C 2"
    ) == [
        ("L", Direct(Area.PI, Width.WORD, 256)),
        ("T", Direct(Area.PQ, Width.WORD, 256)),
        ("L", Direct(Area.DB, Width.WORD, 2, 0, 5)),
        ("T", Direct(Area.DI, Width.DWORD, 4)),
        ("L", Register("STW")),
        ("L", Register("DBNO")),
        ("L", Constant(ConstType.POINTER, 0x83000050, 80, "P#M10.0")),
        ("L", TimerRef(3)),
        ("LC", CounterRef(2)),
    ]


def test_indirect_addressing() -> None:
    assert ops(
        "A I [MD 2]\nL DBW [AR2, P#4.0]\nL W [AR1, P#0.0]\nA [AR1, P#0.1]\nSP T [MW 4]\nOPN DB [MW 6]"
    ) == [
        ("A", MemoryIndirect(Width.BIT, Area.I, Direct(Area.M, Width.DWORD, 2))),
        ("L", RegisterIndirect(Width.WORD, Area.DB, 2, 32)),
        ("L", RegisterIndirect(Width.WORD, None, 1, 0)),
        ("A", RegisterIndirect(Width.BIT, None, 1, 1)),
        ("SP", MemoryIndirect(None, None, Direct(Area.M, Width.WORD, 4), "T")),
        ("OPN", MemoryIndirect(None, None, Direct(Area.M, Width.WORD, 6), "DB")),
    ]


def test_accumulator_arithmetic_word_logic_shifts_and_address_registers() -> None:
    result = ops(
        "INC 1\n+ 5\n+ L#5\nAW W#16#FF\nAW\nSLW 3\nRLDA\nLAR1 P#M10.0\nLAR1 MD 20\nLAR1 AR2\n+AR1 P#2.0\nTAR2 LD 0\nCAR"
    )
    assert [op for op, _ in result] == [
        "INC",
        "+",
        "+",
        "AW",
        "AW",
        "SLW",
        "RLDA",
        "LAR1",
        "LAR1",
        "LAR1",
        "+AR1",
        "TAR2",
        "CAR",
    ]
    assert result[9][1] == Register("AR2")
    assert result[8][1] == Direct(Area.M, Width.DWORD, 20)


def test_jumps_labels_and_networks() -> None:
    result = compile_text(
        ob1(
            "NETWORK\nTITLE = First\n// explains it\n  JC M001\n  NOP 0\nNETWORK\nM001: NOP 1\n  LOOP M001"
        )
    )
    assert result.ok, result.diagnostics
    ob = block(result)
    assert ob.labels == {"M001": 2}
    assert ob.code[0].operand == LabelRef("M001")
    assert [(net.title, net.first, net.comment) for net in ob.networks] == [
        ("First", 0, "explains it"),
        ("", 2, ""),
    ]
    assert ob.code[2].origin is not None
    assert ob.code[2].origin.network == 2


def test_german_and_international_sources_compile_to_the_same_ir() -> None:
    german = "U E 0.0\nUN A 4.1\nSPB M001\nL S5T#2S\nSE T 1\nSV T 2\nZV Z 3\nAUF DB 2\nUW W#16#F\nM001: BEB\nBEA"
    english = "A I 0.0\nAN Q 4.1\nJC M001\nL S5T#2S\nSD T 1\nSE T 2\nCU C 3\nOPN DB 2\nAW W#16#F\nM001: BEC\nBEU"
    de = compile_text(ob1(german))
    en = compile_text(ob1(english))
    assert de.ok, de.diagnostics
    assert en.ok, en.diagnostics
    strip = [(item.op, item.operand, item.label) for item in code_of(de)]
    assert strip == [(item.op, item.operand, item.label) for item in code_of(en)]
    assert [item.op for item in code_of(de)][4:6] == ["SD", "SE"]


def test_forced_mnemonics_reject_the_other_set() -> None:
    result = compile_text(ob1("U E 0.0\nA E 0.1"), mnemonics="en")
    assert codes(result) == [("STL201", 3, 1), ("STL220", 4, 3)]


def test_fb_locals_fc_params_temps_and_db_members() -> None:
    text = (
        'DATA_BLOCK "Data"\n  STRUCT\n    a : BOOL;\n    arr : ARRAY[1..3] OF INT;\n  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n'
        "FUNCTION_BLOCK FB 1\nVAR_INPUT\n  go : BOOL;\nEND_VAR\nVAR\n  n : INT;\n  tmr : TIMER;\nEND_VAR\n"
        'VAR_TEMP\n  t : DWORD;\nEND_VAR\nBEGIN\n  A #go\n  L #n\n  T #t\n  L "Data".arr[2]\n  SP #tmr\n'
        "END_FUNCTION_BLOCK\n"
        "FUNCTION FC 1 : INT\nVAR_INPUT\n  x : INT;\nEND_VAR\nBEGIN\n  L #x\n  T #RET_VAL\nEND_FUNCTION\n"
    )
    symbols = SourceFile("s.csv", "Data,DB 7,DB 7,\n")
    result = compile_text(text, symbols)
    assert result.ok, result.diagnostics
    assert [item.operand for item in code_of(result, "FB", 1)] == [
        RegisterIndirect(Width.BIT, Area.DI, 2, 0),
        RegisterIndirect(Width.WORD, Area.DI, 2, 16),
        Direct(Area.L, Width.DWORD, 0),
        Direct(Area.DB, Width.WORD, 4, 0, 7),
        MemoryIndirect(None, None, RegisterIndirect(Width.WORD, Area.DI, 2, 32), "T"),
    ]
    assert [item.operand for item in code_of(result, "FC", 1)] == [
        ParamRef(0, "x", Width.WORD),
        ParamRef(1, "RET_VAL", Width.WORD),
    ]
    fb = block(result, "FB", 1)
    assert [(var.name, var.section, var.offset_bits) for var in fb.interface] == [
        ("go", "IN", 0),
        ("n", "STAT", 16),
        ("tmr", "STAT", 32),
        ("t", "TEMP", 0),
    ]
    assert fb.temp_bytes == 4
    assert block(result, "FC", 1).return_type == "INT"


def test_calls_instances_and_multi_instances() -> None:
    text = (
        "FUNCTION_BLOCK FB 2\nVAR_INPUT\n  i : INT;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK FB 1\nVAR\n  w : WORD;\n  inner : FB 2;\nEND_VAR\nBEGIN\n  CALL #inner (i := 5)\n"
        "END_FUNCTION_BLOCK\n"
        "DATA_BLOCK DB 10 FB 1\nBEGIN\nEND_DATA_BLOCK\n"
        "FUNCTION FC 3 : VOID\nVAR_INPUT\n  a : BOOL;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"
        "ORGANIZATION_BLOCK OB 1\nBEGIN\n  CALL FB 1 , DB 10\n  CALL FC 3 (a := I 0.0)\n  UC FC 3\n"
        "  CALL SFC 46\nEND_ORGANIZATION_BLOCK\n"
    )
    result = compile_text(text)
    assert result.ok, result.diagnostics
    (call_inner,) = code_of(result, "FB", 1)
    assert call_inner.call is not None
    assert call_inner.call.block == BlockRef(BlockKind.FB, 2)
    assert call_inner.call.instance == MultiInstance(16, "inner")
    calls = [item.call for item in code_of(result) if item.call is not None]
    assert calls[0].instance == BlockRef(BlockKind.DB, 10)
    assert calls[1].args == (CallArg("a", Direct(Area.I, Width.BIT, 0, 0)),)
    assert calls[2].block == BlockRef(BlockKind.SFC, 46)
    assert block(result, "DB", 10).instance_of == 1
    assert len(block(result, "DB", 10).data) == 4


def test_editor_style_call_parameters() -> None:
    text = (
        "FUNCTION FC 1 : VOID\nVAR_INPUT\n  A1 : INT;\nEND_VAR\nBEGIN\n  NOP 0\nEND_FUNCTION\n"
        "ORGANIZATION_BLOCK OB 1\nBEGIN\n      CALL  FC     1\n       A1   :=MW 6\nEND_ORGANIZATION_BLOCK\n"
    )
    result = compile_text(text)
    assert result.ok, result.diagnostics
    (call,) = code_of(result)
    assert call.call is not None
    assert call.call.args == (CallArg("A1", Direct(Area.M, Width.WORD, 6)),)


def test_data_block_initial_and_actual_values() -> None:
    text = (
        "DATA_BLOCK DB 1\n  STRUCT\n    a : INT := 1;\n    b : BOOL := TRUE;\n    c : BOOL;\n"
        "    r : REAL := 1.5;\n    s : STRING[4] := 'ab';\n    arr : ARRAY[1..3] OF BYTE := 2 (B#16#7), B#16#9;\n"
        "  END_STRUCT;\nBEGIN\n  a := 300;\n  c := TRUE;\nEND_DATA_BLOCK\n"
    )
    result = compile_text(text)
    assert result.ok, result.diagnostics
    assert block(result, "DB", 1).data.hex() == "012c03003fc0000004026162000007070900"


def test_test_operations_need_test_mode() -> None:
    body = "__ASSERT== __ACCU 1, 5\n__ASSERT== __STW VKE, 1\n__STWRST\nL __CNST_PI"
    assert ops(body, test_ops=True)[0] == ("__ASSERT==", Register("ACCU1"))
    result = compile_text(ob1(body))
    assert {code for code, _, _ in codes(result)} == {"STL218"}
    (first, second, _, _) = code_of(compile_text(ob1(body), test_ops=True))
    assert first.operand2 == Constant(ConstType.INT, 5, 5, "5")
    assert second.operand == Register("STW.RLO")

"""TIA Portal's forms in SCL (issue 20), each parsed, checked, lowered and run on the CPU: the
function value written ``#Name``, IEC timers/counters/edge detectors as TIA declares and calls
them, CASE labels that are named constants, integer literals in base notation typed as integers,
an untyped constant into a bit string, absolute indexed DB access, multiple assignment and slice
access; and the refusals of what does not fit (``SCL500`` under a classic profile, SCL700-704).
"""

from __future__ import annotations

import pytest
from scl_run import build, ob1, read

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.scl import ast, parse_source
from nasaq.lang.scl.format import source as format_source
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block


def parse_ok(text: str) -> ast.SourceFile:
    result = parse_source("test.scl", text)
    assert result.diagnostics == [], [item.message for item in result.diagnostics]
    printed = format_source(result.source)
    again = parse_source("test.scl", printed)
    assert again.diagnostics == [], printed
    assert again.source == result.source, printed
    return result.source


def body(text: str, decls: str = "") -> list[ast.Stmt]:
    found = parse_ok(f"FUNCTION_BLOCK FB1\n{decls}BEGIN\n{text}\nEND_FUNCTION_BLOCK\n")
    return found.blocks[0].code


def problems(text: str, profile: str = "S7-300") -> list[tuple[str, int, int]]:
    result = compile_sources([SourceFile("prog.scl", text)], profile=profile)
    return [(d.code, d.span.line, d.span.column) for d in result.diagnostics if d.span]


def run(text: str, profile: str = "S7-300", scans: int = 1) -> Cpu:
    return build(text, profile=profile, scans=scans)


def unsigned(cpu: Cpu, text: str) -> int:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return cpu.read(address)


# ---- parse --------------------------------------------------------------------------------------


def test_multiple_assignment_parses_with_its_targets_in_order() -> None:
    [stmt] = body("a := b := c := 5;")
    assert stmt == ast.Assign(
        ast.Name("a"), ast.Literal("INTEGER", "5"), chain=[ast.Name("b"), ast.Name("c")]
    )
    steps = stmt.steps()
    assert [(s.target, s.value) for s in steps] == [
        (ast.Name("c"), ast.Literal("INTEGER", "5")),
        (ast.Name("b"), ast.Name("c")),
        (ast.Name("a"), ast.Name("b")),
    ]


def test_slices_parse_as_parts_of_their_base() -> None:
    [stmt] = body("#x.%X3 := w.%B1.%x7;")
    assert stmt == ast.Assign(
        ast.Slice(ast.Local("x"), "X", 3),
        ast.Slice(ast.Slice(ast.Name("w"), "B", 1), "X", 7),
    )
    [other] = body("d.%W1 := l.%D0;")
    assert other == ast.Assign(ast.Slice(ast.Name("d"), "W", 1), ast.Slice(ast.Name("l"), "D", 0))
    # a DB-relative address keeps its meaning after a dot
    [db] = body('x := "Data".%D1.1;')
    assert isinstance(db, ast.Assign)
    assert isinstance(db.value, ast.Member)


def test_case_labels_may_be_named_constants_in_every_spelling() -> None:
    [case] = body(
        'CASE i OF\n K1: x := 1;\n #K1..K2, "K3": x := 2;\n K4: x := 3; y := 4;\n'
        " K5, 7: ;\nELSE: x := 0;\nEND_CASE;"
    )
    assert isinstance(case, ast.Case)
    labels = [[(v.low, v.high) for v in branch.values] for branch in case.branches]
    assert labels == [
        [(ast.Name("K1"), None)],
        [(ast.Local("K1"), ast.Name("K2")), (ast.Symbol("K3"), None)],
        [(ast.Name("K4"), None)],
        [(ast.Name("K5"), None), (ast.Literal("INTEGER", "7"), None)],
    ]
    assert [len(branch.body) for branch in case.branches] == [1, 1, 2, 1]
    assert case.orelse is not None
    assert len(case.orelse) == 1


def test_jump_labels_outside_case_stay_labels() -> None:
    stmts = body(
        "GOTO l1;\nl1: x := 1;\nIF x = 1 THEN l2: x := 2; END_IF;", "LABEL l1, l2; END_LABEL\n"
    )
    assert isinstance(stmts[1], ast.Label)
    assert isinstance(stmts[3], ast.If)
    assert isinstance(stmts[3].branches[0].body[0], ast.Label)


# ---- check: refusals ----------------------------------------------------------------------------

FB_HEAD = (
    "FUNCTION_BLOCK FB1\nVAR w : WORD; d : DWORD; i : INT; b : BYTE; r : REAL; x : BOOL; END_VAR\n"
    "BEGIN\n"
)
FB_TAIL = "\nEND_FUNCTION_BLOCK\n"


@pytest.mark.parametrize(
    ("code", "profile", "expected"),
    [
        ("i := i := 1;", "S7-300", [("SCL500", 4, 1)]),
        ("i := i := 1;", "S7-1500", []),
        ("x := w.%X3;", "S7-300", [("SCL500", 4, 6)]),
        ("w.%B1 := b;", "S7-400", [("SCL500", 4, 1)]),
        ("x := w.%X16;", "S7-1500", [("SCL701", 4, 6)]),
        ("b := d.%B4;", "S7-1500", [("SCL701", 4, 6)]),
        ("w := b.%W0;", "S7-1500", [("SCL702", 4, 6)]),
        ("x := r.%X0;", "S7-1500", [("SCL702", 4, 6)]),
        ("b := w.%B1.%B0;", "S7-1500", []),
        ("w := 65535; b := 255; d := 4294967295;", "S7-300", []),
        ("b := 256;", "S7-300", [("SCL218", 4, 6)]),
        ("w := -1;", "S7-300", [("SCL218", 4, 6)]),
        ("x := 2;", "S7-300", [("SCL214", 4, 6)]),
        ("i := 16#10 + 2#1010; i := 16#FFFF; d := d AND 16#FF;", "S7-300", []),
        ("i := 16#10 * i - 8#7;", "S7-300", []),
        ("w := 16#10 + 2#1010;", "S7-300", [("SCL213", 4, 6)]),
    ],
)
def test_forms_are_checked(code: str, profile: str, expected: list[tuple[str, int, int]]) -> None:
    assert problems(FB_HEAD + code + FB_TAIL, profile) == expected


def test_a_case_label_that_is_a_variable_is_scl700() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nVAR i : INT; v : INT; END_VAR\nCONST K := 2; END_CONST\nBEGIN\n"
        'CASE i OF\n  K: i := 1;\n  v: i := 2;\n  "Tag": i := 3;\nEND_CASE;\nEND_FUNCTION_BLOCK\n'
    )
    found = compile_sources([SourceFile("prog.scl", text)]).diagnostics
    assert [(d.code, d.span.line, d.span.column) for d in found] == [
        ("SCL700", 7, 3),
        ("SCL201", 8, 3),  # a global constant Nasaq's symbol table cannot hold: not declared
    ]
    assert "v is not a constant" in found[0].message


def test_case_constants_take_part_in_the_overlap_test() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nVAR i : INT; END_VAR\nVAR CONSTANT LOW : INT := 1; HIGH : INT := 5; "
        "END_VAR\nBEGIN\nCASE i OF\n  #LOW..#HIGH: i := 1;\n  3: i := 2;\n  HIGH..LOW: i := 3;\n"
        "END_CASE;\nEND_FUNCTION_BLOCK\n"
    )
    assert problems(text) == [("SCL236", 7, 3), ("SCL248", 8, 3)]


def test_tia_instance_types_need_the_s7_1500_profile_and_trig_does_not() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nVAR t : TON_TIME; u : IEC_TIMER; c : CTU_INT; k : IEC_COUNTER;\n"
        "  e : R_TRIG; f : F_TRIG; END_VAR\nBEGIN\n#t(IN := TRUE, PT := T#1S);\n"
        "#e(CLK := #t.Q);\nEND_FUNCTION_BLOCK\n"
    )
    found = compile_sources([SourceFile("prog.scl", text)]).diagnostics
    assert [(d.code, d.span.line, d.span.column) for d in found] == [
        ("SCL500", 2, 9),
        ("SCL500", 2, 23),
        ("SCL500", 2, 38),
        ("SCL500", 2, 51),
    ]
    assert found[0].message.startswith("TON_TIME needs the S7-1200/1500 profile")
    assert problems(text, "S7-1500") == []


def test_tia_single_instance_calls_are_checked_against_the_instance() -> None:
    text = (
        'DATA_BLOCK "Timer" IEC_TIMER\nBEGIN\nEND_DATA_BLOCK\n'
        'DATA_BLOCK "Count" CTU_INT\nBEGIN\nEND_DATA_BLOCK\n'
        'DATA_BLOCK "Plain"\nSTRUCT a : INT; END_STRUCT\nBEGIN\nEND_DATA_BLOCK\n'
        "FUNCTION_BLOCK FB1\nVAR e : R_TRIG; END_VAR\nBEGIN\n"
        '"Timer".TP(IN := TRUE, PT := T#1S);\n'
        '"Timer".CTU(CU := TRUE, PV := 1);\n'
        '"Plain".TON(IN := TRUE, PT := T#1S);\n'
        '"Count".CTU(CU := TRUE, PV := 1, PT := T#1S);\n'
        "#e.F_TRIG(CLK := TRUE);\n"
        "END_FUNCTION_BLOCK\n"
    )
    found = compile_sources([SourceFile("prog.scl", text)], profile="S7-1500").diagnostics
    assert [(d.code, d.span.line, d.span.column) for d in found] == [
        ("SCL703", 15, 1),
        ("SCL704", 16, 1),
        ("SCL223", 17, 34),
        ("SCL703", 18, 1),
    ]
    assert found[0].message == '"Timer" cannot be called as CTU: it is an instance of TON.'


# ---- run ----------------------------------------------------------------------------------------


def test_the_function_value_written_with_hash_is_returned() -> None:
    cpu = run(
        'FUNCTION "Scale" : INT\nVAR_INPUT x : INT; END_VAR\nBEGIN\n'
        "  #Scale := #x * 3;\n  IF #x < 0 THEN\n    #Scale := 0;\n  END_IF;\nEND_FUNCTION\n"
        + ob1('MW0 := INT_TO_WORD("Scale"(x := 14));\nMW2 := INT_TO_WORD("Scale"(x := -1));')
    )
    assert (read(cpu, "MW0"), read(cpu, "MW2")) == (42, 0)


def test_an_fc_that_never_sets_its_value_is_still_reported() -> None:
    text = 'FUNCTION "F" : INT\nVAR_TEMP Other : INT; END_VAR\nBEGIN\n#Other := 1;\nEND_FUNCTION\n'
    assert [code for code, _l, _c in problems(text)] == ["SCL242"]


def test_based_literals_are_integers_and_constants_fill_bit_strings() -> None:
    cpu = run(
        ob1(
            "i := 16#10 + 2#1010 + 8#17; MW0 := INT_TO_WORD(i);\n"
            "i := 16#FFFF; MW2 := INT_TO_WORD(i);\n"
            "w := 255; MW4 := w; b := 200; MB6 := b; d := 70000; MD8 := d;\n"
            "w := w AND 16#0F; MW12 := w;",
            "i : INT; w : WORD; b : BYTE; d : DWORD;",
        )
    )
    assert read(cpu, "MW0") == 41
    assert read(cpu, "MW2") == -1
    assert (unsigned(cpu, "MW4"), unsigned(cpu, "MB6"), unsigned(cpu, "MD8")) == (255, 200, 70000)
    assert read(cpu, "MW12") == 15


def test_case_labels_that_are_constants_select_their_branch() -> None:
    cpu = run(
        'FUNCTION "Pick" : INT\nVAR_INPUT x : INT; END_VAR\n'
        "VAR CONSTANT LOW : INT := 3; HIGH : INT := 5; END_VAR\nCONST SEVEN := 7; END_CONST\n"
        "BEGIN\n  CASE #x OF\n    #LOW..#HIGH: #Pick := 1;\n    SEVEN: #Pick := 2;\n"
        "    8, 9: #Pick := 3;\n  ELSE #Pick := 0;\n  END_CASE;\nEND_FUNCTION\n"
        + ob1(
            "\n".join(
                f'MW{2 * n} := INT_TO_WORD("Pick"(x := {x}));'
                for n, x in enumerate([2, 3, 5, 6, 7, 9])
            )
        )
    )
    assert [read(cpu, f"MW{2 * n}") for n in range(6)] == [0, 1, 1, 0, 2, 3]


def test_indexed_db_access_with_run_time_indices() -> None:
    cpu = run(
        "DATA_BLOCK DB21\nSTRUCT a : ARRAY[0..15] OF BYTE; END_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
        + ob1(
            "FOR i := 0 TO 15 DO DB21.DB[i] := INT_TO_BYTE(i + 1); END_FOR;\n"
            "i := 4; j := 7;\n"
            "MW0 := DB21.DW[i - 2]; MD2 := DB21.DD[i]; MB6 := DB21.DB[i + 8];\n"
            "DB21.DX[i, j] := TRUE; M7.0 := DB21.DX[i, j]; M7.1 := DB21.DX[i, 6];\n"
            "DB21.DW[i * 2] := W#16#BEEF; MW8 := DB21.DW[8]; DB21.DD[12] := DW#16#01020304;\n"
            "MB10 := DB21.DB[15];",
            "i : INT; j : INT;",
        )
    )
    assert unsigned(cpu, "MW0") == 0x0304
    assert unsigned(cpu, "MD2") == 0x05060708
    assert unsigned(cpu, "MB6") == 13
    assert (unsigned(cpu, "M7.0"), unsigned(cpu, "M7.1")) == (1, 0)
    assert unsigned(cpu, "MW8") == 0xBEEF
    assert unsigned(cpu, "MB10") == 4


def test_multiple_assignment_converts_at_each_step() -> None:
    cpu = run(
        ob1(
            "i := j := 7; MW0 := INT_TO_WORD(i); MW2 := INT_TO_WORD(j);\n"
            "d := i := j + 1; MD4 := DINT_TO_DWORD(d); r := d := 100000; MD8 := DINT_TO_DWORD(d);"
            "\nM12.0 := x := TRUE;",
            "i : INT; j : INT; d : DINT; r : REAL; x : BOOL;",
        ),
        profile="S7-1500",
    )
    assert (read(cpu, "MW0"), read(cpu, "MW2"), read(cpu, "MD4")) == (7, 7, 8)
    assert (read(cpu, "MD8"), read(cpu, "M12.0")) == (100000, 1)


def test_slices_read_and_write_every_width() -> None:
    cpu = run(
        "FUNCTION_BLOCK FB1\n"
        "VAR w : WORD := W#16#1234; d : DWORD := DW#16#11223344; i : INT := -2;\n"
        "  a : ARRAY[0..3] OF WORD; k : INT := 2; END_VAR\nBEGIN\n"
        "MW0 := d.%W0; MW2 := d.%W1; MB4 := w.%B0; MB5 := w.%B1;\n"
        "M6.0 := w.%X2; M6.1 := w.%X3; M6.2 := i.%X0; M6.3 := i.%X15; M6.4 := w.%B1.%X4;\n"
        "IF d.%X2 AND NOT d.%X1 THEN M6.5 := TRUE; END_IF;\n"
        "w.%X15 := TRUE; w.%B0 := B#16#AA; w.%B0.%X0 := M6.0; MW8 := w;\n"
        "d.%B2 := 16#55; d.%W0 := 16#BEEF; MD10 := d;\n"
        "a[k].%X0 := TRUE; a[k].%B1 := 16#7F; MW14 := a[2];\n"
        "i.%X15 := FALSE; MW16 := INT_TO_WORD(i);\n"
        "END_FUNCTION_BLOCK\n" + ob1("FB1.DB1();"),
        profile="S7-1500",
    )
    assert (unsigned(cpu, "MW0"), unsigned(cpu, "MW2")) == (0x3344, 0x1122)
    assert (unsigned(cpu, "MB4"), unsigned(cpu, "MB5")) == (0x34, 0x12)
    bits = [unsigned(cpu, f"M6.{n}") for n in range(6)]
    assert bits == [1, 0, 0, 1, 1, 1]
    assert unsigned(cpu, "MW8") == 0x92AB
    assert unsigned(cpu, "MD10") == 0x1155BEEF
    assert unsigned(cpu, "MW14") == 0x7F01
    assert read(cpu, "MW16") == 0x7FFE


def test_iec_timers_as_tia_declares_them_run() -> None:
    text = (
        "DATA_BLOCK \"IEC_Timer_0_DB\"\n{ S7_Optimized_Access := 'TRUE' }\nIEC_TIMER\nBEGIN\n"
        'END_DATA_BLOCK\nDATA_BLOCK "IEC_Timer_1_DB" IEC_TIMER\nBEGIN\nEND_DATA_BLOCK\n'
        'FUNCTION_BLOCK "Delays"\nVAR\n  t1 : TON;\n'
        "  t2 {InstructionName := 'TON_TIME'; LibVersion := '1.0'} : TON_TIME;\n"
        "  t3 : IEC_TIMER;\n  p : TP_TIME;\nEND_VAR\nBEGIN\n"
        '  "IEC_Timer_0_DB".TON(IN := TRUE, PT := T#50MS);\n'
        '  "IEC_Timer_1_DB".TP(IN := TRUE, PT := T#20MS);\n'
        "  #t1(IN := TRUE, PT := T#30MS);\n  #t2(IN := TRUE, PT := T#200MS);\n"
        "  #t3.TON(IN := TRUE, PT := T#30MS);\n  #p(IN := TRUE, PT := T#20MS);\n"
        '  M0.0 := "IEC_Timer_0_DB".Q; M0.1 := #t1.Q; M0.2 := #t2.Q; M0.3 := #t3.Q;\n'
        '  M0.4 := #p.Q; M0.5 := "IEC_Timer_1_DB".Q; MD4 := DINT_TO_DWORD(TIME_TO_DINT(#t2.ET));\n'
        "END_FUNCTION_BLOCK\n" + ob1('"Delays".DB10();')
    )
    cpu = run(text, profile="S7-1500", scans=6)  # 6 calls: 50 ms after the first
    assert [unsigned(cpu, f"M0.{n}") for n in range(6)] == [1, 1, 0, 1, 0, 0]
    assert read(cpu, "MD4") == 50


def test_edge_detectors_and_counters_run_under_both_profiles() -> None:
    fb = (
        'FUNCTION_BLOCK "Edges"\nVAR e : R_TRIG; f : F_TRIG; c : CTU; clk : BOOL;\n'
        "  ups : INT; downs : INT; END_VAR\nBEGIN\n  #clk := NOT #clk;\n  #e(CLK := #clk);\n"
        "  #f(CLK := #clk);\n  IF #e.Q THEN #ups := #ups + 1; END_IF;\n"
        "  IF #f.Q THEN #downs := #downs + 1; END_IF;\n  #c(CU := #e.Q, PV := 3);\n"
        "  MW0 := INT_TO_WORD(#ups); MW2 := INT_TO_WORD(#downs); M4.0 := #c.Q;\n"
        "  MW6 := INT_TO_WORD(#c.CV);\nEND_FUNCTION_BLOCK\n" + ob1('"Edges".DB10();')
    )
    for profile in ("S7-300", "S7-1500"):
        cpu = run(fb, profile=profile, scans=7)  # 7 calls: CLK rises 4 times, falls 3 times
        assert [read(cpu, a) for a in ("MW0", "MW2", "M4.0", "MW6")] == [4, 3, 1, 4], profile


def test_a_counter_on_an_iec_counter_instance_reads_qu() -> None:
    text = (
        'DATA_BLOCK "IEC_Counter_0_DB" IEC_COUNTER\nBEGIN\nEND_DATA_BLOCK\n'
        'DATA_BLOCK "Down_DB" IEC_COUNTER\nBEGIN\nEND_DATA_BLOCK\n'
        + ob1(
            "M0.1 := NOT M0.1;\n"
            '"IEC_Counter_0_DB".CTU(CU := M0.1, R := FALSE, PV := 3, Q => M1.0);\n'
            'MW2 := INT_TO_WORD("IEC_Counter_0_DB".CV); M1.1 := "IEC_Counter_0_DB".QU;\n'
            '"Down_DB".CTD(CD := M0.1, LOAD := FALSE, PV := 0, Q => M1.2);'
        )
    )
    cpu = run(text, profile="S7-1500", scans=5)  # 5 calls: 3 rising edges
    assert (read(cpu, "MW2"), read(cpu, "M1.0"), read(cpu, "M1.1"), read(cpu, "M1.2")) == (
        3,
        1,
        1,
        1,
    )


def test_r_trig_is_a_system_block_stl_calls_too() -> None:
    stl = (
        'DATA_BLOCK DB 5\n "R_TRIG"\nBEGIN\nEND_DATA_BLOCK\n\nORGANIZATION_BLOCK OB 1\nBEGIN\n'
        '      CALL "R_TRIG" , DB 5 (\n           CLK := I 0.0,\n           Q := M 0.0);\n'
        "END_ORGANIZATION_BLOCK\n"
    )
    result = compile_sources([SourceFile("prog.awl", stl)])
    assert [d.code for d in result.diagnostics if d.severity == "error"] == []
    cpu = Cpu(result.program, cycle_ms=10)
    cpu.start()
    address = parse_address("I0.0")
    assert isinstance(address, Direct)
    cpu.set_input(address, 1)
    cpu.run(1)
    assert unsigned(cpu, "M0.0") == 1
    cpu.run(1)
    assert unsigned(cpu, "M0.0") == 0


def test_the_generated_stl_compiles_again_to_the_same_behaviour() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nVAR w : WORD := W#16#00F0; e : R_TRIG; n : INT; END_VAR\nBEGIN\n"
        "w.%X0 := NOT w.%X4; w.%B1 := w.%B0; #e(CLK := TRUE); IF #e.Q THEN n := n + 1; END_IF;\n"
        "MW0 := w; MW2 := INT_TO_WORD(n);\nEND_FUNCTION_BLOCK\n" + ob1("FB1.DB1();")
    )
    first = compile_sources([SourceFile("prog.scl", text)], profile="S7-1500")
    printed = "\n".join(format_block(block) for _file, block in first.generated)
    result = compile_sources([SourceFile("prog.awl", printed)], profile="S7-1500")
    assert [d.code for d in result.diagnostics if d.severity == "error"] == [], printed
    cpu = Cpu(result.program, profile=Profile("S7-1500"), cycle_ms=10)
    cpu.start()
    cpu.run(2)
    assert (unsigned(cpu, "MW0"), read(cpu, "MW2")) == (0xF0F0, 1)


# ---- what the corpus measurement found (briefs: corpus-findings) --------------------------------


def test_quoted_parameter_names_are_the_parameters() -> None:
    cpu = run(
        'FUNCTION_BLOCK "Motor"\nVAR_INPUT speed : INT; END_VAR\n'
        "VAR_OUTPUT doubled : INT; END_VAR\nBEGIN\n  #doubled := #speed * 2;\nEND_FUNCTION_BLOCK\n"
        + ob1('"Motor".DB5("speed" := 21, "doubled" => i); MW0 := INT_TO_WORD(i);', "i : INT;")
    )
    assert read(cpu, "MW0") == 42
    [stmt] = body('"Motor"("speed" := 1, "Return" => y);')
    assert isinstance(stmt, ast.CallStmt)
    assert [(arg.name, arg.output) for arg in stmt.call.args] == [
        ("speed", False),
        ("Return", True),
    ]


def test_untyped_constants_compare_with_bit_strings() -> None:
    cpu = run(
        ob1(
            "w := W#16#00F0; x := TRUE; d := DW#16#0;\n"
            "M0.0 := w <> 0; M0.1 := d = 0; M0.2 := x = 1; M0.3 := (w AND 255) = 16#F0;\n"
            "MW2 := w AND 15; M0.4 := w > 100;",
            "w : WORD; d : DWORD; x : BOOL;",
        )
    )
    assert [read(cpu, f"M0.{n}") for n in range(5)] == [1, 1, 1, 1, 1]
    assert read(cpu, "MW2") == 0


def test_tia_jump_labels_need_no_label_section() -> None:
    cpu = run(
        'FUNCTION "Jumps" : INT\nVAR_TEMP n : INT; END_VAR\nBEGIN\n  #n := 0;\nAgain:\n'
        "  #n := #n + 1;\n  IF #n < 5 THEN\n    GOTO Again;\n  END_IF;\n  #Jumps := #n;\n"
        "END_FUNCTION\n" + ob1('MW0 := INT_TO_WORD("Jumps"());')
    )
    assert read(cpu, "MW0") == 5
    # with a LABEL section (STEP 7 Classic) every label must be declared there
    classic = (
        "FUNCTION_BLOCK FB1\nLABEL Here; END_LABEL\nBEGIN\n  Here: ;\n  There: ;\n"
        "END_FUNCTION_BLOCK\n"
    )
    assert problems(classic) == [("SCL238", 5, 3)]


def test_a_standard_function_named_like_a_tia_local_is_the_function() -> None:
    cpu = run(
        'FUNCTION "Root" : INT\nVAR_TEMP sqrt : REAL; END_VAR\nBEGIN\n'
        "  #sqrt := SQRT(16.0);\n  #Root := REAL_TO_INT(#sqrt);\nEND_FUNCTION\n"
        + ob1('MW0 := INT_TO_WORD("Root"());')
    )
    assert read(cpu, "MW0") == 4


def test_a_tia_call_on_an_undeclared_db_makes_it_the_instance() -> None:
    cpu = run(ob1("DB99.TON(IN := TRUE, PT := T#20MS);\nM0.0 := DB99.Q;"), scans=3)
    assert read(cpu, "M0.0") == 1  # as SFB4.DB99(...) creates DB 99


def test_compound_assignments_run_on_s7_1500_only() -> None:
    program = ob1(
        "i := 10; i += 5; i -= 1; i *= 2 + 1; i /= 6; MW0 := INT_TO_WORD(i);\n"
        "r := 1.5; r *= 4.0; MD2 := DINT_TO_DWORD(REAL_TO_DINT(r));",
        "i : INT; r : REAL;",
    )
    cpu = run(program, profile="S7-1500")
    assert (read(cpu, "MW0"), read(cpu, "MD2")) == (7, 6)  # (10 + 5 - 1) * 3 / 6
    assert problems(program)[:1] == [("SCL500", 6, 10)]
    [stmt] = body("a *= b + c;")
    assert stmt == ast.Assign(
        ast.Name("a"),
        ast.Binary("*", ast.Name("a"), ast.Binary("+", ast.Name("b"), ast.Name("c"))),
        op="*",
    )


def test_a_quoted_local_is_the_local() -> None:
    [stmt] = body('#"raw value" := #"raw value" + 1;')
    assert stmt == ast.Assign(
        ast.Local("raw value"),
        ast.Binary("+", ast.Local("raw value"), ast.Literal("INTEGER", "1")),
    )
    cpu = run(
        'FUNCTION "F" : INT\nVAR_INPUT "raw value" : INT; END_VAR\nBEGIN\n'
        '  #F := #"raw value" * 2;\nEND_FUNCTION\n'
        + ob1('MW0 := INT_TO_WORD("F"("raw value" := 8));')
    )
    assert read(cpu, "MW0") == 16

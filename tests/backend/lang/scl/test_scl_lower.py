"""SCL compiled to STL and run on the CPU: each construct computes what S7-SCL computes.

Programs are compiled with ``compile_sources`` (the same path as ``nasaq run``), started (OB100,
then RUN) and scanned; results are read from M, Q and DB memory.
"""

from __future__ import annotations

import math

import pytest
from scl_run import build, ob1, read, real

from nasaq.cpu import Cpu
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct, Origin
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block

# ---- expressions ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("expression", "expected"),
    [
        ("7 + 5 * 3", 22),
        ("(7 + 5) * 3", 36),
        ("17 DIV 5", 3),
        ("17 MOD 5", 2),
        ("-17 MOD 5", -2),
        ("-17 / 5", -3),
        ("a - b - c", 100 - 30 - 7),
        ("a - (b - c)", 100 - (30 - 7)),
        ("-a + b", -70),
        ("a * b DIV c", 3000 // 7),
        ("WORD_TO_INT(INT_TO_WORD(a) AND 16#00F0)", 100 & 0xF0),
        ("ABS(b - a)", 70),
        ("MAX(IN1 := b, IN2 := a, IN3 := c)", 100),
        ("MIN(IN1 := b, IN2 := a, IN3 := c)", 7),
        ("LIMIT(MN := 10, IN := c, MX := 20)", 10),
        ("LIMIT(MN := 10, IN := a, MX := 20)", 20),
        ("SEL(G := a > b, IN0 := b, IN1 := c)", 7),
        ("WORD_BCD_TO_INT(16#0123)", 123),
        ("WORD_TO_INT(INT_TO_BCD_WORD(456))", 0x456),
    ],
)
def test_integer_expressions(expression: str, expected: int) -> None:
    cpu = build(
        ob1(
            f"a := 100; b := 30; c := 7;\nMW10 := INT_TO_WORD({expression});",
            "a : INT; b : INT; c : INT;",
        )
    )
    assert read(cpu, "MW10") == expected


def test_dint_and_real_arithmetic_with_implicit_widening() -> None:
    cpu = build(
        ob1(
            """i := 300; d := 100000; r := 2.5;
d := d * i + 7;           // INT widened to DINT
MD20 := DINT_TO_DWORD(d);
r := r * i + d;           // INT and DINT widened to REAL
MD24 := REAL_TO_DWORD(r);
MD28 := REAL_TO_DWORD(SQRT(16.0) + SIN(0.0) + LOG(1000.0) + EXPD(2) + 2 ** 10);
MD32 := DINT_TO_DWORD(ROUND(2.5) + TRUNC(-3.7) + REAL_TO_DINT(7.6));""",
            "i : INT; d : DINT; r : REAL;",
        )
    )
    assert read(cpu, "MD20") == 100000 * 300 + 7
    assert real(cpu, "MD24") == pytest.approx(2.5 * 300 + 30000007, rel=1e-6)
    assert real(cpu, "MD28") == pytest.approx(4 + 0 + 3 + 100 + 1024, rel=1e-5)
    # RND rounds half to even: 2.5 -> 2; TRUNC(-3.7) -> -3; 7.6 -> 8
    assert read(cpu, "MD32") == 2 - 3 + 8


@pytest.mark.parametrize(
    ("call", "expected"),
    [
        ("ROL(IN := BYTE#2#1101_0011, N := 5)", 0b0111_1010),
        ("ROR(IN := BYTE#2#1101_0011, N := 2)", 0b1111_0100),
        ("SHL(IN := BYTE#2#1101_0011, N := 3)", 0b1001_1000),
        ("SHR(IN := BYTE#2#1101_0011, N := 2)", 0b0011_0100),
    ],
)
def test_shifts_and_rotations_of_a_byte(call: str, expected: int) -> None:
    cpu = build(ob1(f"MB10 := {call};"))
    assert read(cpu, "MB10") & 0xFF == expected


def test_word_rotation_and_shift_count_from_a_variable() -> None:
    cpu = build(
        ob1(
            "n := 4; MW10 := ROL(IN := W#16#F00D, N := n); MW12 := SHR(IN := W#16#F00D, N := n);",
            "n : INT;",
        )
    )
    assert read(cpu, "MW10") & 0xFFFF == 0x00DF
    assert read(cpu, "MW12") & 0xFFFF == 0x0F00


# ---- conditions -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("inputs", "expected"),
    [((0, 0, 0), 0), ((1, 0, 0), 1), ((1, 1, 0), 0), ((0, 0, 1), 1), ((1, 1, 1), 1)],
)
def test_and_binds_before_or_and_not_applies_to_its_operand(
    inputs: tuple[int, int, int], expected: int
) -> None:
    cpu = build(ob1("Q4.0 := I0.0 AND NOT I0.1 OR I0.2 AND (WORD_TO_INT(MW10) < 5);"))
    for bit, value in enumerate(inputs):
        cpu.set_input(Direct(parse_address("I0.0").area, 1, 0, bit), value)  # type: ignore[union-attr]
    cpu.run(1)
    assert read(cpu, "Q4.0") == expected


def test_xor_comparisons_and_boolean_equality() -> None:
    cpu = build(
        ob1(
            """a := 5; b := 7;
M0.0 := a < b XOR a = 5;
M0.1 := (a < b) = (b > a);
M0.2 := NOT (a <> 5);
M0.3 := TRUE AND a >= 5;""",
            "a : INT; b : INT;",
        )
    )
    assert [read(cpu, f"M0.{bit}") for bit in range(4)] == [0, 1, 1, 1]


# ---- statements -----------------------------------------------------------------------------


def test_if_elsif_else_and_case_with_lists_and_ranges() -> None:
    source = ob1(
        """n := WORD_TO_INT(MW0);
IF n < 0 THEN MW2 := 16#FFFF; ELSIF n = 0 THEN MW2 := 16#0; ELSE MW2 := 16#1; END_IF;
CASE n OF
  0: MW4 := INT_TO_WORD(100);
  1, 3, 5: MW4 := INT_TO_WORD(101);
  6..9, 20: MW4 := INT_TO_WORD(102);
ELSE MW4 := INT_TO_WORD(103);
END_CASE;""",
        "n : INT;",
    )
    cpu = build(source)
    for value, sign, case in [(0, 0, 100), (3, 1, 101), (7, 1, 102), (20, 1, 102), (-4, -1, 103)]:
        cpu.write(parse_address("MW0"), value & 0xFFFF)  # type: ignore[arg-type]
        cpu.run(1)
        assert read(cpu, "MW2") == sign
        assert read(cpu, "MW4") == case


def test_loops_exit_continue_and_goto() -> None:
    source = ob1(
        """s := 0;
FOR i := 10 TO 1 BY -3 DO s := s + i; END_FOR;       // 10 + 7 + 4 + 1
MW0 := INT_TO_WORD(s);
s := 0; i := 0;
WHILE TRUE DO
  i := i + 1;
  IF i MOD 2 = 0 THEN CONTINUE; END_IF;
  IF i > 9 THEN EXIT; END_IF;
  s := s + i;                                      // 1 + 3 + 5 + 7 + 9
END_WHILE;
MW2 := INT_TO_WORD(s);
i := 0;
REPEAT i := i + 5; UNTIL i >= 23 END_REPEAT;
MW4 := INT_TO_WORD(i);
step := 2; s := 0;
FOR i := 1 TO 10 BY step DO s := s + 1; END_FOR;   // 1, 3, 5, 7, 9
MW6 := INT_TO_WORD(s);
GOTO skip;
MW8 := 16#FFFF;
skip: MW10 := 16#0001;""",
        "s : INT; i : INT; step : INT;",
    ).replace("BEGIN", "LABEL skip; END_LABEL\nBEGIN")
    cpu = build(source)
    assert [read(cpu, f"MW{n}") for n in (0, 2, 4, 6, 8, 10)] == [22, 25, 25, 5, 0, 1]


# ---- blocks, calls, data --------------------------------------------------------------------

FC_AND_FB = """
FUNCTION Scale : REAL
VAR_INPUT raw : INT; low : REAL; high : REAL; END_VAR
BEGIN
  Scale := low + (high - low) * raw / 27648.0;
END_FUNCTION

FUNCTION_BLOCK Average
VAR_INPUT sample : REAL; END_VAR
VAR_OUTPUT mean : REAL; END_VAR
VAR history : ARRAY[1..4] OF REAL; next : INT := 1; k : INT; END_VAR
BEGIN
  history[next] := sample;
  next := next MOD 4 + 1;
  mean := 0.0;
  FOR k := 1 TO 4 DO mean := mean + history[k] / 4; END_FOR;
END_FUNCTION_BLOCK

DATA_BLOCK Filter Average
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK Main
VAR_TEMP value : REAL; END_VAR
BEGIN
  value := Scale(raw := WORD_TO_INT(PIW256), low := 0.0, high := 100.0);
  Average.Filter(sample := value);
  MD20 := REAL_TO_DWORD(Filter.mean);
  MD24 := REAL_TO_DWORD(value);
END_ORGANIZATION_BLOCK
"""


def test_fc_with_return_value_and_fb_with_instance_db_and_static_array() -> None:
    cpu = build(FC_AND_FB.replace("PIW256", "MW0"))
    cpu.write(parse_address("MW0"), 13824)  # type: ignore[arg-type]
    cpu.run(1)
    assert real(cpu, "MD24") == pytest.approx(50.0)
    assert real(cpu, "MD20") == pytest.approx(12.5)  # one sample of four
    cpu.run(3)
    assert real(cpu, "MD20") == pytest.approx(50.0)


def test_multi_instances_en_eno_and_ok_flag() -> None:
    source = """
FUNCTION_BLOCK Pulses
VAR_INPUT up : BOOL; END_VAR
VAR_OUTPUT count : INT; END_VAR
VAR edge : BOOL; END_VAR
BEGIN
  IF up AND NOT edge THEN count := count + 1; END_IF;
  edge := up;
END_FUNCTION_BLOCK

FUNCTION Divide : INT
VAR_INPUT a : INT; b : INT; END_VAR
BEGIN
  IF b = 0 THEN OK := FALSE; Divide := 0; RETURN; END_IF;
  Divide := a / b;
END_FUNCTION

FUNCTION_BLOCK Station
VAR left : Pulses; right : Pulses; END_VAR
BEGIN
  left(up := I0.0);
  right(up := I0.1);
  MW10 := INT_TO_WORD(left.count);
  MW12 := INT_TO_WORD(right.count);
  MW14 := INT_TO_WORD(Divide(a := 10, b := WORD_TO_INT(MW0), ENO => M1.0));
  MW16 := INT_TO_WORD(Divide(EN := I0.2, a := 9, b := 3));
END_FUNCTION_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  Station.DB5();
END_ORGANIZATION_BLOCK
"""
    cpu = build(source)
    i0 = parse_address("I0.0")
    i1 = parse_address("I0.1")
    i2 = parse_address("I0.2")
    for _ in range(3):
        cpu.set_input(i0, 1)  # type: ignore[arg-type]
        cpu.run(1)
        cpu.set_input(i0, 0)  # type: ignore[arg-type]
        cpu.run(1)
    cpu.set_input(i1, 1)  # type: ignore[arg-type]
    cpu.run(2)
    assert read(cpu, "MW10") == 3
    assert read(cpu, "MW12") == 1
    assert read(cpu, "MW14") == 0
    assert read(cpu, "M1.0") == 0
    cpu.write(parse_address("MW0"), 5)  # type: ignore[arg-type]
    cpu.set_input(i2, 1)  # type: ignore[arg-type]
    cpu.run(1)
    assert read(cpu, "MW14") == 2
    assert read(cpu, "M1.0") == 1
    assert read(cpu, "MW16") == 3


def test_s5_timer_and_counter_functions() -> None:
    source = ob1(
        """value := S_ODT(T_NO := T1, S := I0.0, TV := T#200ms, Q => Q4.0, BI => binary);
MW10 := S5TIME_TO_WORD_FAKE;
bcd := S_CU(C_NO := C2, CU := I0.1, S := I0.2, PV := 16#0005, R := I0.3, Q => Q4.1, CV => MW14);
MW16 := bcd;""",
        "value : S5TIME; binary : WORD; bcd : WORD;",
    ).replace("MW10 := S5TIME_TO_WORD_FAKE;\n", "")
    cpu = build(source)
    i = {name: parse_address(f"I0.{bit}") for bit, name in enumerate(["s", "cu", "set", "r"])}
    cpu.set_input(i["s"], 1)  # type: ignore[arg-type]
    cpu.run(10)
    assert read(cpu, "Q4.0") == 0
    cpu.run(12)
    assert read(cpu, "Q4.0") == 1
    cpu.set_input(i["set"], 1)  # type: ignore[arg-type]
    cpu.run(1)
    for _ in range(2):
        cpu.set_input(i["cu"], 1)  # type: ignore[arg-type]
        cpu.run(1)
        cpu.set_input(i["cu"], 0)  # type: ignore[arg-type]
        cpu.run(1)
    assert read(cpu, "MW14") == 7
    assert read(cpu, "MW16") == 0x0007  # BCD
    assert read(cpu, "Q4.1") == 1


def test_struct_copy_constant_and_variable_indices_and_db_access() -> None:
    source = """
TYPE Point
STRUCT x : INT; y : INT; on : BOOL; END_STRUCT
END_TYPE

DATA_BLOCK Store
STRUCT
  points : ARRAY[1..3] OF Point;
  words : ARRAY[0..9] OF WORD;
END_STRUCT
BEGIN
  points[2].x := 42;
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
VAR_TEMP p : Point; k : INT; END_VAR
BEGIN
  p := Store.points[2];
  p.y := p.x + 1;
  p.on := TRUE;
  Store.points[3] := p;
  FOR k := 0 TO 9 DO Store.words[k] := INT_TO_WORD(k * k); END_FOR;
  k := 4;
  MW10 := Store.words[k];
  MW12 := DB1.DW[k + 2];
  MW[14] := INT_TO_WORD(Store.points[3].y);
  M[16, 3] := Store.points[3].on;
END_ORGANIZATION_BLOCK
"""
    cpu = build(source)
    assert read(cpu, "MW10") == 16
    assert read(cpu, "MW12") == 42  # DBW 6: a Point takes 6 bytes, points[2].x is at byte 6
    assert read(cpu, "MW14") == 43
    assert read(cpu, "M16.3") == 1


# ---- the source map and --emit stl ----------------------------------------------------------


def test_every_generated_instruction_knows_its_scl_line() -> None:
    source = ob1("a := 1;\nIF a > 0 THEN\n  MW0 := 16#0005;\nEND_IF;", "a : INT;")
    result = compile_sources([SourceFile("map.scl", source)])
    block = result.program.blocks[next(iter(result.program.blocks))]
    origins = [instruction.origin for instruction in block.code]
    assert all(isinstance(origin, Origin) and origin.file == "map.scl" for origin in origins)
    lines = {origin.line for origin in origins if origin is not None}
    assert {6, 7, 8} <= lines  # the assignment, the IF, the assignment in the IF


def test_generated_stl_compiles_back_to_the_same_behaviour() -> None:
    result = compile_sources([SourceFile("prog.scl", FC_AND_FB.replace("PIW256", "MW0"))])
    text = "\n".join(format_block(block) for _file, block in result.generated)
    again = compile_sources([SourceFile("prog.awl", text)])
    assert not [d for d in again.diagnostics if d.severity == "error"]
    values = []
    for program in (result.program, again.program):
        cpu = Cpu(program, cycle_ms=10)
        cpu.start()
        cpu.write(parse_address("MW0"), 2765)  # type: ignore[arg-type]
        cpu.run(2)
        values.append(real(cpu, "MD20"))
    # two samples of 100 * 2765 / 27648 in a mean over four
    assert values[0] == values[1] == pytest.approx(2 * 100 * 2765 / 27648 / 4, rel=1e-5)
    assert not math.isnan(values[0])

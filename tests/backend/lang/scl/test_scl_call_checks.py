"""The SCL call checks (rule ``call_parameters``, callee resolution in ``typecheck.callee``): each
mistake at a call gives exactly one diagnostic, snapshotted as (code, line, column), and the
correct forms of FC, FB, multi-instance, IEC SFB and S5 timer/counter calls give none."""

from __future__ import annotations

import pytest

from nasaq.lang.scl import check_sources, parse_source
from nasaq.lang.stl.symbols import SymbolTable, read_symbol_table

HEAD = """FUNCTION_BLOCK Motor
VAR_INPUT start : BOOL; speed : INT; END_VAR
VAR_OUTPUT running : BOOL; END_VAR
VAR_IN_OUT text : STRING[10]; buffer : ARRAY[1..3] OF INT; count : INT; END_VAR
BEGIN
  running := start;
END_FUNCTION_BLOCK
FUNCTION Calc : INT
VAR_INPUT a : INT; b : REAL; END_VAR
VAR_OUTPUT ok : BOOL; END_VAR
BEGIN
  Calc := a;
  ok := b > 0.0;
END_FUNCTION
FUNCTION Square : INT
VAR_INPUT v : INT; END_VAR
BEGIN
  Square := v * v;
END_FUNCTION
FUNCTION Swap : VOID
VAR_IN_OUT x, y : INT; END_VAR
VAR_TEMP h : INT; END_VAR
BEGIN
  h := x;
  x := y;
  y := h;
END_FUNCTION
FUNCTION_BLOCK Valve
VAR_INPUT open : BOOL; END_VAR
BEGIN
END_FUNCTION_BLOCK
DATA_BLOCK MotorData Motor
BEGIN
END_DATA_BLOCK
DATA_BLOCK Values
STRUCT n : INT; END_STRUCT
BEGIN
END_DATA_BLOCK
FUNCTION_BLOCK User
VAR_INPUT inp : INT; END_VAR
VAR
  m : Motor; t : TON; cnt : CTU; k : INT; x : BOOL; s : STRING[10]; s4 : STRING[4];
  buf : ARRAY[1..3] OF INT; w : WORD; r : REAL; d : DINT; tm : TIME; s5 : S5TIME;
END_VAR
BEGIN
"""
TAIL = "\nEND_FUNCTION_BLOCK\n"
L = HEAD.count("\n") + 1  # the line of the statement under test; it starts in column 3
# Blocks: Motor FB 1, Calc FC 1, Square FC 2, Swap FC 3, Valve FB 2, MotorData DB 1 (of FB 1),
# Values DB 2, User FB 3. The symbol table knows blocks that no source declares.
SYMBOLS = (
    "Pump,FB 20,FB 20,\nPumpData,DB 20,FB 20,\nSTP,SFC 46,SFC 46,\n"
    "MotorSym,DB 30,FB 1,\nStart button,I 0.0,BOOL,\n"
)

CASES: list[tuple[str, list[tuple[str, int, int]]]] = [
    # FB calls: multi-instance, instance DB, FB.DB (created if no DATA_BLOCK declares it)
    ("m(start := TRUE, speed := 5, text := s, buffer := buf, count := k);", []),
    ("m(text := s, buffer := buf);", []),
    ("m(running => x, text := s4, buffer := buf);", []),
    ("m(running := x, text := s, buffer := buf);", []),  # S7-SCL Classic: := for an output
    ('m(start := "Start button", text := s, buffer := buf, EN := x, ENO => x);', []),
    ("Motor.MotorData(start := x, text := s, buffer := buf);", []),
    ("FB1.DB1(text := s, buffer := buf); MotorData(text := s, buffer := buf);", []),
    ('"MotorData"(text := s, buffer := buf); x := MotorData.running;', []),
    ("Motor.DB5(text := s, buffer := buf); x := DB5.running AND MotorSym.running;", []),
    ("Valve.DB6(open := x); Valve.DB6(open := NOT x);", []),
    # IEC timers and counters as multi-instances (SFB interfaces), and as SFB with a DB
    ("t(IN := x, PT := T#5s, Q => x, ET => tm); cnt(CU := x, R := FALSE, PV := 10, CV => k);", []),
    ("SFB4.DB8(IN := x, PT := tm); x := t.Q OR DB8.Q;", []),
    # FC calls: every parameter, a single input without its name, EN/ENO
    ("k := Calc(a := 1, b := 2.5, ok => x);", []),
    ("k := Calc(a := k, b := k, ok => x, EN := x, ENO => x);", []),
    ("k := Square(k) + Square(v := 2); Swap(x := k, y := buf[2]);", []),
    ("r := SQRT(k) + LN(2.0); k := WORD_TO_INT(w); s := CONCAT(IN1 := s, IN2 := 'a');", []),
    # S5 timers and counters (Classic outputs with :=)
    ("s5 := S_ODT(T_NO := T1, S := x, TV := T#1s);", []),
    ("s5 := S_PEXT(T_NO := k, S := x, TV := w, R := x, BI => w, Q => x);", []),
    ("w := S_CU(C_NO := C1, CU := x, S := x, PV := 16#10, R := FALSE, Q := x, CV := w);", []),
    ("w := S_CUD(C_NO := C2, CU := x, CD := x); w := S_CD(C_NO := k, CD := x);", []),
    # blocks only the symbol table knows: their interface is unknown, nothing is checked
    ('Pump.PumpData(anything := 1); "Pump"."PumpData"(); STP(); SFC46(); SFB77.DB9();', []),
    # unknown parameter name (and no "missing" report for the misspelt one)
    ("m(stort := TRUE, text := s, buffer := buf);", [("SCL223", L, 5)]),
    ("k := Calc(a := 1, bb := 2.0, ok => x);", [("SCL223", L, 21)]),
    ("w := S_CU(C_NO := C1, CD := x);", [("SCL223", L, 25)]),
    ("t(IN := x, PV := 5);", [("SCL223", L, 14)]),
    # direction: => to an input or in/out
    ("m(start => x, text := s, buffer := buf);", [("SCL224", L, 5)]),
    ("m(text => s, buffer := buf);", [("SCL224", L, 5)]),
    ("k := Square(v := k, EN => x);", [("SCL224", L, 23)]),
    # input types, as assignments
    ("m(speed := w, text := s, buffer := buf);", [("SCL213", L, 14)]),
    ("m(speed := 40000, text := s, buffer := buf);", [("SCL218", L, 14)]),
    ("m(start := k, text := s, buffer := buf);", [("SCL214", L, 14)]),
    ("t(IN := x, PT := 5);", [("SCL214", L, 20)]),
    ("cnt(CU := x, PV := w);", [("SCL213", L, 22)]),
    ("s5 := S_ODT(T_NO := T1, S := x, TV := 5);", [("SCL214", L, 41)]),
    ("s5 := S_ODT(T_NO := r, S := x);", [("SCL214", L, 23)]),
    ("k := Calc(a := r, b := 1.0, ok => x);", [("SCL213", L, 18)]),
    # output types: the output is assigned to the actual parameter
    ("m(running => k, text := s, buffer := buf);", [("SCL214", L, 16)]),
    ("t(IN := x, PT := T#1s, Q => r);", [("SCL214", L, 31)]),
    ("w := S_CU(C_NO := C1, CU := x, CV => k);", [("SCL214", L, 40)]),
    # in/out: the same type
    ("m(text := s, buffer := buf, count := d);", [("SCL225", L, 40)]),
    ("m(text := s, buffer := w);", [("SCL225", L, 26)]),
    ("Swap(x := k, y := r);", [("SCL225", L, 21)]),
    # a counter's preset is BCD: a decimal constant is a warning (the book's E67 writes one)
    ("w := S_CU(C_NO := C1, CU := x, PV := 100);", [("SCL247", L, 40)]),
    ("w := S_CU(C_NO := C1, CU := x, PV := 1000);", [("SCL213", L, 40)]),
    # outputs and in/outs need a variable
    ("m(text := s, buffer := buf, count := 5);", [("SCL226", L, 40)]),
    ("m(text := s, buffer := buf, count := k + 1);", [("SCL226", L, 40)]),
    ("m(text := 'abc', buffer := buf);", [("SCL226", L, 13)]),
    ("m(running := TRUE, text := s, buffer := buf);", [("SCL226", L, 16)]),
    ("Swap(x := k, y := 3);", [("SCL226", L, 21)]),
    ("k := Square(v := k, ENO := 1);", [("SCL226", L, 30)]),
    # a warning: the output still has to fit the input it writes
    ("m(running => inp, text := s, buffer := buf);", [("SCL214", L, 16), ("SCL215", L, 16)]),
    # missing parameters: all of an FC, the by-reference in/outs of an FB, T_NO/C_NO
    ("k := Calc(a := 1, b := 2.0);", [("SCL227", L, 8)]),
    ("k := Calc(a := 1);", [("SCL227", L, 8)]),
    ("Swap(x := k);", [("SCL227", L, 3)]),
    ("m(start := x);", [("SCL227", L, 3)]),
    ("s5 := S_ODT(S := x, TV := T#1s);", [("SCL227", L, 9)]),
    # a parameter twice, a value without a name
    ("m(start := x, start := x, text := s, buffer := buf);", [("SCL228", L, 17)]),
    ("k := Calc(a := 1, b := 2.0, ok => x, a := 2);", [("SCL228", L, 40)]),
    ("m(x);", [("SCL229", L, 5)]),
    ("k := Calc(k);", [("SCL229", L, 13)]),
    ("k := Square(2, 3);", [("SCL229", L, 15)]),
    ("k := Square(k, EN := x);", [("SCL229", L, 15)]),
    # the callee: FB without instance, unknown block, not a block, wrong instance DB
    ("Motor(text := s, buffer := buf);", [("SCL230", L, 3)]),
    ('"Pump"(x := 1);', [("SCL230", L, 3)]),
    ("FC9(a := 1);", [("SCL231", L, 3)]),
    ("FB9.DB9();", [("SCL231", L, 3)]),
    ("k(a := 1);", [("SCL232", L, 3)]),
    ("Values(n := 1);", [("SCL232", L, 3)]),
    ("Motor.Values(text := s, buffer := buf);", [("SCL233", L, 9)]),
    ("Valve.MotorData(open := x);", [("SCL233", L, 9)]),
    ("Motor.DB6(text := s, buffer := buf); Valve.DB6(open := x);", [("SCL233", L, 46)]),
    ("Motor.k(text := s);", [("SCL233", L, 9)]),
    ("Calc.DB7(a := 1, b := 1.0, ok => x);", [("SCL234", L, 3)]),
    # the members of a created instance DB have the FB's types
    ("Motor.DB5(text := s, buffer := buf); k := DB5.running;", [("SCL213", L, 45)]),
    ("Motor.DB5(text := s, buffer := buf); k := DB5.nothing;", [("SCL222", L, 49)]),
    ("k := MotorSym.running;", [("SCL213", L, 8)]),  # BOOL_TO_INT
    # an FB call is a statement: it has no value to use in an expression
    (
        "m(text := s, buffer := buf); x := m.running AND t.Q;"
        " k := Square(2) + Calc(a := 1, b := 2.0, ok => x);",
        [],
    ),
    ("x := m(text := s, buffer := buf);", [("SCL251", L, 8)]),
    ("IF m(text := s, buffer := buf) THEN k := 1; END_IF;", [("SCL251", L, 6)]),
    ("x := t(IN := x, PT := T#1s) OR x;", [("SCL251", L, 8)]),
    ("k := Motor.MotorData(text := s, buffer := buf) + 1;", [("SCL251", L, 8)]),
    ("x := MotorData(text := s, buffer := buf);", [("SCL251", L, 8)]),
    ("x := SFB4.DB8(IN := x, PT := tm);", [("SCL251", L, 8)]),
    ("x := Pump.PumpData();", [("SCL251", L, 8)]),
    ("k := Square(v := m(text := s, buffer := buf));", [("SCL251", L, 20)]),
    ("x := m(speed := w, text := s, buffer := buf);", [("SCL251", L, 8), ("SCL213", L, 19)]),
    ("x := Motor(text := s, buffer := buf);", [("SCL230", L, 8)]),
    ("x := Motor.Values(text := s, buffer := buf);", [("SCL233", L, 14)]),
    # outputs and in/outs write the FOR variable (a warning); inputs only read it
    ("FOR k := 1 TO 3 DO m(speed := k, text := s, buffer := buf); d := Square(k); END_FOR;", []),
    ("FOR k := 1 TO 3 DO Swap(x := k, y := buf[k]); END_FOR;", [("SCL250", L, 32)]),
    (
        "FOR k := 1 TO 3 DO cnt(CU := x, CV => k);"
        " m(text := s, buffer := buf, count := #k); END_FOR;",
        [("SCL250", L, 41), ("SCL250", L, 82)],
    ),
    ("FOR k := 1 TO 3 DO m(start => k, text := s, buffer := buf); END_FOR;", [("SCL224", L, 24)]),
    # an unknown name is reported once, and the call is not checked further
    ("m(start := zz, text := s, buffer := buf);", [("SCL201", L, 14)]),
    ("zz(a := 1);", [("SCL201", L, 3)]),
    ("Motor.Nowhere(text := s, buffer := buf);", [("SCL201", L, 9)]),
]

PROGRAMS = [(HEAD + "  " + body + TAIL, expected) for body, expected in CASES]


def _symbols() -> SymbolTable:
    table = SymbolTable()
    assert read_symbol_table("symbols.csv", SYMBOLS, table) == []
    return table


@pytest.mark.parametrize(("body", "expected"), CASES)
def test_call_snapshot(body: str, expected: list[tuple[str, int, int]]) -> None:
    parsed = parse_source("calls.scl", HEAD + "  " + body + TAIL)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source], _symbols())
    found = [(item.code, item.span.line, item.span.column) for item in diagnostics if item.span]
    assert found == expected, [item.message for item in diagnostics]


def test_call_messages_name_the_parameter_and_the_block() -> None:
    body = "m(stort := x, text := s, buffer := buf); k := Calc(a := 1); Motor(text := s);"
    parsed = parse_source("calls.scl", HEAD + "  " + body + TAIL)
    _index, diagnostics = check_sources([parsed.source], _symbols())
    assert [item.message for item in diagnostics] == [
        "FB 1 has no parameter stort.",
        "The call of FC 1 must supply b, ok.",
        "FB 1 is a function block: call it with an instance (FB.DB(...), an instance DB or a "
        "multi-instance).",
    ]


def test_an_fb_call_in_an_expression_names_the_block() -> None:
    body = "x := t(IN := x, PT := T#1s); x := Motor.DB5(text := s, buffer := buf);"
    parsed = parse_source("calls.scl", HEAD + "  " + body + TAIL)
    _index, diagnostics = check_sources([parsed.source], _symbols())
    tail = "which returns no value: call it as a statement of its own and read its outputs"
    tail += " afterwards."
    assert [item.message for item in diagnostics] == [
        f"t calls the function block TON, {tail}",
        f"Motor.DB5 calls the function block FB 1, {tail}",
    ]


def test_a_decimal_bcd_preset_is_a_warning() -> None:
    body = "w := S_CD(C_NO := C10, CD := TRUE, S := TRUE, PV := 100, R := FALSE, CV := w);"
    parsed = parse_source("calls.scl", HEAD + "  " + body + TAIL)
    _index, diagnostics = check_sources([parsed.source], _symbols())
    assert [(item.code, item.severity.value, item.message) for item in diagnostics] == [
        (
            "SCL247",
            "warning",
            "PV := 100 is the word W#16#0064, which the counter reads as BCD, not as 100: "
            "write PV := 16#100.",
        )
    ]


def test_created_instance_dbs_are_in_the_index() -> None:
    body = "Motor.DB5(text := s, buffer := buf); Valve.DB6(open := x);"
    parsed = parse_source("calls.scl", HEAD + "  " + body + TAIL)
    index, diagnostics = check_sources([parsed.source], _symbols())
    assert diagnostics == []
    assert {db: (fb.kind, fb.number) for db, fb in index.implicit_dbs.items()} == {
        5: ("FB", 1),
        6: ("FB", 2),
        30: ("FB", 1),  # MotorSym: a DB of type FB 1 in the symbol table
    }


def test_a_parameter_of_unknown_type_is_reported_once() -> None:
    text = (
        "FUNCTION F : VOID\nVAR_IN_OUT u : Nothing; END_VAR\nVAR_OUTPUT o : STRUCT a : INT;"
        " END_STRUCT; END_VAR\nBEGIN\nEND_FUNCTION\n"
        "FUNCTION_BLOCK FB1\nVAR k : INT; s : STRUCT b : INT; END_STRUCT; END_VAR\nBEGIN\n"
        "  F(u := k, o => s);\nEND_FUNCTION_BLOCK\n"
    )
    parsed = parse_source("calls.scl", text)
    assert parsed.diagnostics == []
    _index, diagnostics = check_sources([parsed.source])
    # the STRUCT output fits a STRUCT of the same layout (member names may differ, as in STEP 7)
    assert [(item.code, item.span.line) for item in diagnostics if item.span] == [("SCL202", 2)]

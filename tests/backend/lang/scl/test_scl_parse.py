"""The SCL parser builds the expected AST for each construct (AST snapshots: nodes compare
without their positions), gives every node a position, parses the book's complete examples
without a diagnostic, and formats every test program back to source that parses to the same
AST (round trip)."""

from __future__ import annotations

from pathlib import Path

import pytest

from nasaq.lang.scl import ast, parse_source
from nasaq.lang.scl.format import source as format_source

CORPUS = Path(__file__).parent / "corpus"

L = ast.Literal
N = ast.Name


def _int(text: str) -> ast.Literal:
    return L("INTEGER", text)


def parse_ok(text: str) -> ast.SourceFile:
    result = parse_source("test.scl", text)
    assert result.diagnostics == [], [item.message for item in result.diagnostics]
    return result.source


def code(body: str, decls: str = "") -> list[ast.Stmt]:
    found = parse_ok(f"FUNCTION_BLOCK FB1\n{decls}BEGIN\n{body}\nEND_FUNCTION_BLOCK\n")
    return found.blocks[0].code


def value(text: str) -> ast.Expr:
    [statement] = code(f"x := {text};")
    assert isinstance(statement, ast.Assign)
    return statement.value


# ---- expressions ----------------------------------------------------------------------------

EXPRESSIONS = [
    ("a OR b XOR c", ast.Binary("OR", N("a"), ast.Binary("XOR", N("b"), N("c")))),
    ("a XOR b AND c", ast.Binary("XOR", N("a"), ast.Binary("AND", N("b"), N("c")))),
    ("a & b = c", ast.Binary("&", N("a"), ast.Binary("=", N("b"), N("c")))),
    ("a = b < c", ast.Binary("=", N("a"), ast.Binary("<", N("b"), N("c")))),
    ("a < b + c", ast.Binary("<", N("a"), ast.Binary("+", N("b"), N("c")))),
    ("a + b * c", ast.Binary("+", N("a"), ast.Binary("*", N("b"), N("c")))),
    ("a - b - c", ast.Binary("-", ast.Binary("-", N("a"), N("b")), N("c"))),
    ("a MOD b DIV c", ast.Binary("DIV", ast.Binary("MOD", N("a"), N("b")), N("c"))),
    ("-a ** 2", ast.Unary("-", ast.Binary("**", N("a"), _int("2")))),
    ("a ** b ** c", ast.Binary("**", ast.Binary("**", N("a"), N("b")), N("c"))),
    ("NOT a AND b", ast.Binary("AND", ast.Unary("NOT", N("a")), N("b"))),
    ("not (a = 4)", ast.Unary("NOT", ast.Paren(ast.Binary("=", N("a"), _int("4"))))),
    (
        "c + (a * b) ** 3",
        ast.Binary(
            "+", N("c"), ast.Binary("**", ast.Paren(ast.Binary("*", N("a"), N("b"))), _int("3"))
        ),
    ),
    ("a * -b", ast.Binary("*", N("a"), ast.Unary("-", N("b")))),
    ("3 <= 4", ast.Binary("<=", _int("3"), _int("4"))),
]


@pytest.mark.parametrize(("text", "expected"), EXPRESSIONS)
def test_expressions_follow_the_s7_scl_precedence(text: str, expected: ast.Expr) -> None:
    assert value(text) == expected


LITERALS = [
    ("32_767", "INTEGER"),
    ("1.5", "REAL"),
    ("4e2", "REAL"),
    ("TRUE", "BOOL"),
    ("false", "BOOL"),
    ("'Address$41'", "STRING"),
    ("16#FF", "TYPED"),
    ("2#1101_0011", "TYPED"),
    ("INT#5", "TYPED"),
    ("int#-32768", "TYPED"),
    ("W#16#FFFF", "TYPED"),
    ("DW#16#FFFF_FFFF", "TYPED"),
    ("B#(25, 25)", "TYPED"),
    ("T#2s", "TYPED"),
    ("T#1H_20M_10S_30MS", "TYPED"),
    ("TIME#-24d20h31m23s647ms", "TYPED"),
    ("S5T#1h30m10s", "TYPED"),
    ("D#1990-01-01", "TYPED"),
    ("TOD#23:59:59.999", "TYPED"),
    ("DT#95-01-01-12:12:12.2", "TYPED"),
    ("DATE_AND_TIME#1995-01-01-12:12:12.2", "TYPED"),
    ("REAL#2e4", "TYPED"),
    ("BOOL#TRUE", "TYPED"),
    ("Byte#'a'", "TYPED"),
]


@pytest.mark.parametrize(("text", "kind"), LITERALS)
def test_literals_keep_their_text_and_kind(text: str, kind: str) -> None:
    expected = text.upper() if kind == "BOOL" else text
    assert value(text) == L(kind, expected)


ACCESSES = [
    ("M0.0", ast.Address("M0.0")),
    ("%M10.1", ast.Address("%M10.1")),
    ("I 1.1", ast.Address("I1.1")),
    ("MW10", ast.Address("MW10")),
    ("PIW252", ast.Address("PIW252")),
    ("MW[i]", ast.IndexedAddress("MW", [N("i")])),
    ("I[i, k]", ast.IndexedAddress("I", [N("i"), N("k")])),
    ("PIW[252 + i]", ast.IndexedAddress("PIW", [ast.Binary("+", _int("252"), N("i"))])),
    ("DB10.DW2", ast.Member(ast.Address("DB10"), ast.Address("DW2"))),
    ("db1.dbx0.0", ast.Member(ast.Address("db1"), ast.Address("dbx0.0"))),
    ('"New data".D1.1', ast.Member(ast.Symbol("New data"), ast.Address("D1.1"))),
    ("DB11.DW[n]", ast.Member(ast.Address("DB11"), ast.IndexedAddress("DW", [N("n")]))),
    (
        "WORD_TO_BLOCK_DB(w).DW[i]",
        ast.Member(
            ast.Call(N("WORD_TO_BLOCK_DB"), [ast.Arg(None, N("w"))]),
            ast.IndexedAddress("DW", [N("i")]),
        ),
    ),
    ("#count", ast.Local("count")),
    ('"Global".member', ast.Member(ast.Symbol("Global"), N("member"))),
    (
        "a.b[1, 2].c",
        ast.Member(ast.Index(ast.Member(N("a"), N("b")), [_int("1"), _int("2")]), N("c")),
    ),
    ("Messagetexts.HW[unit]", ast.Index(ast.Member(N("Messagetexts"), N("HW")), [N("unit")])),
]


@pytest.mark.parametrize(("text", "expected"), ACCESSES)
def test_absolute_symbolic_and_structured_access(text: str, expected: ast.Expr) -> None:
    assert value(text) == expected


# ---- statements -----------------------------------------------------------------------------


def test_if_elsif_else() -> None:
    [found] = code("IF a THEN x := 1; ELSIF b THEN ; ELSE x := 2; END_IF;")
    assert found == ast.If(
        [
            ast.IfBranch(N("a"), [ast.Assign(N("x"), _int("1"))]),
            ast.IfBranch(N("b"), [ast.Empty()]),
        ],
        [ast.Assign(N("x"), _int("2"))],
    )
    [plain] = code("if a then end_if;")
    assert plain == ast.If([ast.IfBranch(N("a"), [])], None)


def test_case_with_lists_ranges_negative_values_and_else() -> None:
    [found] = code("CASE s OF 1, 3..9: x := 1; -5..-1: ; ELSE: x := 0; END_CASE;")
    assert found == ast.Case(
        N("s"),
        [
            ast.CaseBranch(
                [ast.CaseValue(_int("1")), ast.CaseValue(_int("3"), _int("9"))],
                [ast.Assign(N("x"), _int("1"))],
            ),
            ast.CaseBranch([ast.CaseValue(_int("-5"), _int("-1"))], [ast.Empty()]),
        ],
        [ast.Assign(N("x"), _int("0"))],
    )
    [without] = code("CASE s OF 1: x := 1; ELSE x := 2; END_CASE;")
    assert isinstance(without, ast.Case)
    assert without.orelse == [ast.Assign(N("x"), _int("2"))]


def test_loops_and_jumps() -> None:
    found = code(
        "FOR i := 100 TO 1 BY -2 DO EXIT; END_FOR;\n"
        "FOR i := 1 TO n DO CONTINUE; END_FOR;\n"
        "WHILE a DO RETURN; END_WHILE;\n"
        "REPEAT GOTO lab; UNTIL a END_REPEAT;\n"
        "lab: ;",
        "LABEL lab; END_LABEL\n",
    )
    assert found == [
        ast.For(N("i"), _int("100"), _int("1"), ast.Unary("-", _int("2")), [ast.Exit()]),
        ast.For(N("i"), _int("1"), N("n"), None, [ast.Continue()]),
        ast.While(N("a"), [ast.Return()]),
        ast.Repeat([ast.Goto("lab")], N("a")),
        ast.Label("lab"),
        ast.Empty(),
    ]


def test_calls_with_formal_parameters_instances_and_en_eno() -> None:
    found = code(
        "FB17.DB10(FINALVAL := 10, IQ1 := v);\n"
        "#inst(x := 1, y => out);\n"
        '"Block"();\n'
        "inst(EN := I0.0, ENO => ok1);\n"
        "r := FC1(x1 := 2.1) + I_STRNG(no);"
    )
    assert found == [
        ast.CallStmt(
            ast.Call(
                ast.Member(ast.Address("FB17"), ast.Address("DB10")),
                [ast.Arg("FINALVAL", _int("10")), ast.Arg("IQ1", N("v"))],
            )
        ),
        ast.CallStmt(
            ast.Call(ast.Local("inst"), [ast.Arg("x", _int("1")), ast.Arg("y", N("out"), True)])
        ),
        ast.CallStmt(ast.Call(ast.Symbol("Block"), [])),
        ast.CallStmt(
            ast.Call(
                N("inst"), [ast.Arg("EN", ast.Address("I0.0")), ast.Arg("ENO", N("ok1"), True)]
            )
        ),
        ast.Assign(
            N("r"),
            ast.Binary(
                "+",
                ast.Call(ast.Address("FC1"), [ast.Arg("x1", L("REAL", "2.1"))]),
                ast.Call(N("I_STRNG"), [ast.Arg(None, N("no"))]),
            ),
        ),
    ]


def test_region() -> None:
    [found] = code("REGION Part 1: inputs\n  a := 1;\nEND_REGION")
    assert found == ast.Region("Part 1: inputs", [ast.Assign(N("a"), _int("1"))])


# ---- blocks, declarations, types ------------------------------------------------------------


def test_function_with_return_type_header_and_sections() -> None:
    text = (
        "FUNCTION FC1 : REAL\n"
        "{ S7_blockview := 'big' }\n"
        "TITLE = 'Distance'\n"
        "VERSION : '3.1'\n"
        "AUTHOR : myCompany\n"
        "KNOW_HOW_PROTECT\n"
        "VAR_INPUT\n"
        "  x1, x2 {S7_server := 'alarm_archiv'; S7_a_type := 'ar_send'} : REAL := 1.0;\n"
        "END_VAR\n"
        "CONST LIMIT := 7; END_CONST\n"
        "LABEL lab1, lab2; END_LABEL\n"
        "BEGIN\n"
        "  FC1 := x1;\n"
        "END_FUNCTION\n"
    )
    [block] = parse_ok(text).blocks
    assert block.kind == "FUNCTION"
    assert block.name == ast.BlockName("FC1", absolute=True)
    assert block.return_type == ast.NamedType("REAL")
    assert block.attributes == [ast.Attribute("S7_blockview", "big")]
    assert block.title == "Distance"
    assert block.props == {"VERSION": "3.1", "AUTHOR": "myCompany"}
    assert block.flags == ["KNOW_HOW_PROTECT"]
    attributes = [ast.Attribute("S7_server", "alarm_archiv"), ast.Attribute("S7_a_type", "ar_send")]
    assert block.sections == [
        ast.VarSection(
            "VAR_INPUT",
            [
                ast.VarDecl(
                    [ast.DeclName("x1"), ast.DeclName("x2", attributes=attributes)],
                    ast.NamedType("REAL"),
                    [L("REAL", "1.0")],
                )
            ],
        ),
        ast.ConstSection([ast.ConstDecl("LIMIT", _int("7"))]),
        ast.LabelSection(["lab1", "lab2"]),
    ]
    assert block.begin
    assert block.code == [ast.Assign(ast.Address("FC1"), N("x1"))]


def test_types() -> None:
    text = (
        "FUNCTION_BLOCK FB1\nVAR\n"
        "  a : ARRAY[1..3, 0..LIMIT] OF STRUCT r : REAL; END_STRUCT;\n"
        "  s : STRING[34];\n"
        '  u : "Point";\n'
        "  v : UDT1;\n"
        "  w : ARRAY[*] OF INT;\n"
        "  t : TIMER;\n"
        "  init : ARRAY[1..12] OF REAL := 0.0, 10(100.0), 1.0;\n"
        "END_VAR\nVAR RETAIN\n  k : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n"
    )
    [block] = parse_ok(text).blocks
    first, second = block.sections
    assert isinstance(first, ast.VarSection)
    types = [decl.type for decl in first.decls if isinstance(decl, ast.VarDecl)]
    assert types == [
        ast.ArrayType(
            [ast.Dim(_int("1"), _int("3")), ast.Dim(_int("0"), N("LIMIT"))],
            ast.StructType([ast.VarDecl([ast.DeclName("r")], ast.NamedType("REAL"))]),
        ),
        ast.NamedType("STRING", length=_int("34")),
        ast.NamedType("Point", quoted=True),
        ast.NamedType("UDT1"),
        ast.ArrayType([ast.Dim(None, None)], ast.NamedType("INT")),
        ast.NamedType("TIMER"),
        ast.ArrayType([ast.Dim(_int("1"), _int("12"))], ast.NamedType("REAL")),
    ]
    last = first.decls[-1]
    assert isinstance(last, ast.VarDecl)
    assert last.init == [
        L("REAL", "0.0"),
        ast.InitRepeat("10", [L("REAL", "100.0")]),
        L("REAL", "1.0"),
    ]
    assert second == ast.VarSection(
        "VAR", [ast.VarDecl([ast.DeclName("k")], ast.NamedType("INT"))], "RETAIN"
    )


def test_data_blocks_and_udts() -> None:
    text = (
        "TYPE UDT1 STRUCT a : INT; END_STRUCT; END_TYPE\n"
        "DATA_BLOCK DB10 STRUCT v : ARRAY[1..3] OF INT := 3(0); END_STRUCT; "
        "BEGIN v[1] := 5; END_DATA_BLOCK\n"
        "DATA_BLOCK DB11 FB17 BEGIN END_DATA_BLOCK\n"
        'DATA_BLOCK "Inst" NON_RETAIN "Motor" BEGIN END_DATA_BLOCK\n'
    )
    udt, shared, instance, tia = parse_ok(text).blocks
    assert udt.kind == "TYPE"
    assert udt.sources == [ast.StructType([ast.VarDecl([ast.DeclName("a")], ast.NamedType("INT"))])]
    assert shared.code == [ast.Assign(ast.Index(N("v"), [_int("1")]), _int("5"))]
    assert instance.sources == [ast.BlockName("FB17", absolute=True)]
    assert tia.name == ast.BlockName("Inst", quoted=True)
    assert tia.flags == ["NON_RETAIN"]
    assert tia.sources == [ast.BlockName("Motor", quoted=True)]


def test_code_without_begin_and_pragmas() -> None:
    text = (
        "{SCL_CreateDebugInfo := 'y'}\nORGANIZATION_BLOCK CYCLE\n"
        "VAR_TEMP t : INT; END_VAR;\nx := 1;\nEND_ORGANIZATION_BLOCK\n"
    )
    found = parse_ok(text)
    assert found.pragmas == [ast.Attribute("SCL_CreateDebugInfo", "y")]
    [block] = found.blocks
    assert not block.begin
    assert block.code == [ast.Assign(N("x"), _int("1"))]


def test_keywords_are_case_insensitive_and_comments_are_skipped() -> None:
    text = (
        "function_block fb1 (* block\n comment *)\n"
        "var_temp a : int; End_Var // line comment\n"
        "begin a := 1; /* tia */ end_function_block\n"
    )
    [block] = parse_ok(text).blocks
    assert block.kind == "FUNCTION_BLOCK"
    assert block.code == [ast.Assign(N("a"), _int("1"))]


def test_every_node_has_a_position() -> None:
    text = (
        "FUNCTION FC1 : INT\nVAR_INPUT a : INT; END_VAR\nBEGIN\n"
        "  IF a > 1 THEN\n    FC1 := a * 2;\n  END_IF;\nEND_FUNCTION\n"
    )
    [block] = parse_ok(text).blocks
    assert (block.loc.line, block.loc.column) == (1, 1)
    assert (block.end.line, block.end.column) == (7, 1)
    [statement] = block.code
    assert isinstance(statement, ast.If)
    assert (statement.loc.line, statement.loc.column, statement.loc.end_line) == (4, 3, 6)
    [assign] = statement.branches[0].body
    assert isinstance(assign, ast.Assign)
    assert (assign.loc.line, assign.loc.column) == (5, 5)
    assert isinstance(assign.value, ast.Binary)
    assert (assign.value.right.loc.line, assign.value.right.loc.column) == (5, 16)


# ---- the book's complete examples and the round trip ----------------------------------------


def test_the_complete_examples_of_the_course_parse_without_diagnostics() -> None:
    e72 = parse_ok((CORPUS / "e72_textgenerator.scl").read_text("utf-8"))
    assert [block.name.text for block in e72.blocks] == ["Messagetexts", "Textgenerator", "OB1"]
    x10 = parse_ok((CORPUS / "x10_measured_values.scl").read_text("utf-8"))
    assert [block.name.text for block in x10.blocks] == ["SQUARE", "EVALUATE", "RECORD", "CYCLE"]
    assert [block.kind for block in x10.blocks] == [
        "FUNCTION",
        "FUNCTION_BLOCK",
        "FUNCTION_BLOCK",
        "ORGANIZATION_BLOCK",
    ]


def _programs() -> list[tuple[str, str]]:
    programs = [(path.name, path.read_text("utf-8")) for path in sorted(CORPUS.glob("*.scl"))]
    programs += [
        (f"expr{n}", f"FUNCTION FC1 : VOID\nx := {text};\nEND_FUNCTION\n")
        for n, (text, _) in enumerate(EXPRESSIONS + ACCESSES)
    ]
    return programs


@pytest.mark.parametrize(("name", "text"), _programs())
def test_format_and_parse_again_gives_the_same_ast(name: str, text: str) -> None:
    first = parse_ok(text)
    printed = format_source(first)
    second = parse_ok(printed)
    assert second == first, name
    assert format_source(second) == printed


def test_a_tia_portal_export() -> None:
    found = parse_ok((CORPUS / "tia_portal.scl").read_text("utf-8"))
    udt, data, motor, main = found.blocks
    assert (udt.kind, udt.name) == ("TYPE", ast.BlockName("Recipe", quoted=True))
    assert data.flags == ["NON_RETAIN"]
    assert data.code == [ast.Assign(N("count"), _int("5"))]
    constant = motor.sections[-1]
    assert isinstance(constant, ast.VarSection)
    assert (constant.kind, constant.modifier) == ("VAR", "CONSTANT")
    [region] = motor.code
    assert isinstance(region, ast.Region)
    assert region.title == "Start"
    assert main.title == "Main Program Sweep (Cycle)"
    assert main.props == {"VERSION": "0.1"}

"""AST → STL text (``nasaq.lang.stl.format``): every STL source of the repository prints back to
text that parses to the same AST, each node kind prints in the STEP 7 export layout, a trailing
comment per instruction, and the speed of a large source.

The round trip compares ``structure()`` dumps, not the nodes: every node carries a ``loc`` (a
named tuple, so dataclass equality compares it) and the printed text puts nodes on other lines
and columns than the original. Declaration comments are not parsed into the AST but attached
from the ``//`` comments of the name's line (as the compiler does), so both sides get them
attached the same way before comparing.

"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path
from typing import Any

import pytest

from nasaq.lang.stl import ast
from nasaq.lang.stl.bench import mixed_program
from nasaq.lang.stl.format import (
    format_block,
    format_code,
    format_instruction,
    format_operand,
    format_source,
    format_type,
    format_values,
)
from nasaq.lang.stl.parse import ParseResult, parse_source

ROOT = Path(__file__).resolve().parents[4]
REPOSITORY_SOURCES = sorted(
    path
    for folder in ("tests/scenarios", "tests/corpus", "tests/backend/lang/stl/corpus")
    for path in (ROOT / folder).rglob("*")
    if path.suffix.lower() == ".awl"
)
_NO_LOC = ast.Loc(0, 0, 0, 0)


# ---- helpers --------------------------------------------------------------------------------


def structure(node: Any) -> Any:
    """A node as nested tuples, lists and dicts, without its positions (``loc``, ``end``)."""
    if dataclasses.is_dataclass(node) and not isinstance(node, type):
        fields = dataclasses.fields(node)
        return (
            type(node).__name__,
            *(
                (item.name, structure(getattr(node, item.name)))
                for item in fields
                if item.name not in ("loc", "end")
            ),
        )
    if isinstance(node, list):
        return [structure(item) for item in node]
    if isinstance(node, dict):
        return {key: structure(value) for key, value in node.items()}
    return node


def attach_comments(result: ParseResult) -> None:
    """Gives each declaration the ``//`` comment of its name's line (``compiler`` does this)."""

    def walk(decls: list[ast.VarDeclNode]) -> None:
        for decl in decls:
            decl.comment = result.comments.get(decl.loc.line, "")
            kind: ast.TypeNode = decl.type
            while isinstance(kind, ast.ArrayTypeNode):
                kind = kind.element
            if isinstance(kind, ast.StructTypeNode):
                walk(kind.members)

    for block in result.source.blocks:
        for item in block.head:
            if isinstance(item, ast.VarSectionNode):
                walk(item.decls)
        if isinstance(block.db_body, ast.StructTypeNode):
            walk(block.db_body.members)


def decode(data: bytes) -> str:
    """Like the compiler: UTF-8, else Windows-1252 (STEP 7 and awlsim write 8-bit files)."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors="replace")


def parse_clean(text: str, name: str = "test.awl") -> ParseResult:
    result = parse_source(name, text)
    assert result.diagnostics == [], (result.diagnostics, text)
    attach_comments(result)
    return result


def round_trip(text: str, name: str = "test.awl") -> str:
    """Parses ``text``, prints it, parses the print: same structure, and printing is stable."""
    first = parse_clean(text, name)
    printed = format_source(first.source)
    second = parse_clean(printed, name)
    assert structure(second.source) == structure(first.source), printed
    assert format_source(second.source) == printed
    return printed


def ob1(body: str) -> str:
    return f"ORGANIZATION_BLOCK OB 1\nBEGIN\n{body}\nEND_ORGANIZATION_BLOCK\n"


def body_of(printed: str) -> list[str]:
    lines = printed.splitlines()
    return lines[lines.index("BEGIN") + 1 : -1]


def relocate(node: Any, where: ast.Loc) -> None:
    """Sets every position in a tree to ``where`` (as another compiler's nodes would have)."""
    if dataclasses.is_dataclass(node) and not isinstance(node, type):
        for item in dataclasses.fields(node):
            if item.name in ("loc", "end"):
                setattr(node, item.name, where)
            else:
                relocate(getattr(node, item.name), where)
    elif isinstance(node, list):
        for child in node:
            relocate(child, where)
    elif isinstance(node, dict):
        for child in node.values():
            relocate(child, where)


# ---- every source of the repository ---------------------------------------------------------


@pytest.mark.parametrize(
    "path", REPOSITORY_SOURCES, ids=[str(p.relative_to(ROOT)) for p in REPOSITORY_SOURCES]
)
def test_repository_sources_round_trip(path: Path) -> None:
    text = decode(path.read_bytes())
    parsed = parse_source(path.name, text)
    if parsed.diagnostics:
        # a broken source of the bad-input corpus: nothing to round-trip, but what the parser
        # kept still prints, and the skipped input is marked
        assert "bad" in path.parts, parsed.diagnostics
        format_source(parsed.source)
        return
    round_trip(text, path.name)


def test_the_repository_sources_are_found() -> None:
    names = {path.name for path in REPOSITORY_SOURCES}
    assert len(REPOSITORY_SOURCES) > 100
    assert {"coverage.awl", "forms.awl", "loose.awl", "iec_select.awl"} <= names


# ---- snapshot -------------------------------------------------------------------------------

SNAPSHOT_SOURCE = """FUNCTION_BLOCK "Motor"
TITLE = Motor control
{ S7_m_c := 'true' }
AUTHOR : Nasaq
FAMILY : Drives
NAME : MOTOR
VERSION : 0.1
KNOW_HOW_PROTECT
VAR_INPUT
  start { S7_m_c := 'true' } : BOOL ; // start button
  speeds : ARRAY[1..4] OF INT := 4 (0);
END_VAR
VAR
  state : STRUCT
    running : BOOL;
    count : DINT := L#0;
  END_STRUCT;
  name : STRING[16] := 'motor';
  timer : FB 4;
END_VAR
VAR_TEMP
  i : INT;
END_VAR
BEGIN
NETWORK
TITLE = run
      A #start
      JCN M001
      L #state.count
      + L#1
      T #state.count
      L #speeds[2]
      CALL FC 2 (IN := #start, OUT := Q 4.0)
M001: NOP 0
NETWORK
TITLE =
      L DBW [AR1, P#2.0]
      T "Data".values[1, 2].x
      BEU
END_FUNCTION_BLOCK
"""

SNAPSHOT = """FUNCTION_BLOCK "Motor"
TITLE =Motor control
{ S7_m_c := 'true' }
AUTHOR : Nasaq
FAMILY : Drives
NAME : MOTOR
VERSION : 0.1
KNOW_HOW_PROTECT

VAR_INPUT
  start { S7_m_c := 'true' } : BOOL ;\t//start button
  speeds : ARRAY  [1 .. 4 ] OF INT  := 4 (0);
END_VAR
VAR
  state : STRUCT
   running : BOOL ;
   count : DINT  := L#0;
  END_STRUCT ;
  name : STRING  [16 ]  := 'motor';
  timer : FB 4 ;
END_VAR
VAR_TEMP
  i : INT ;
END_VAR
BEGIN
NETWORK
TITLE =run
      A     #start;
      JCN   M001;
      L     #state.count;
      +     L#1;
      T     #state.count;
      L     #speeds[2];
      CALL FC 2 (
           IN                       := #start,
           OUT                      := Q 4.0);
M001: NOP   0;
NETWORK
TITLE =
      L     DBW [AR1,P#2.0];
      T     "Data".values[1,2].x;
      BEU   ;
END_FUNCTION_BLOCK
"""


def test_snapshot_of_a_function_block() -> None:
    assert round_trip(SNAPSHOT_SOURCE) == SNAPSHOT
    (block,) = parse_clean(SNAPSHOT_SOURCE).source.blocks
    assert format_block(block) == SNAPSHOT


# ---- blocks and their headers ---------------------------------------------------------------


def test_block_headers() -> None:
    printed = round_trip(
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nEND_ORGANIZATION_BLOCK\n"
        'FUNCTION_BLOCK "Valve" : VOID\nBEGIN\nEND_FUNCTION_BLOCK\n'
        "FUNCTION FC 2 : INT\nBEGIN\nEND_FUNCTION\n"
        'FUNCTION "Calc" : VOID\nBEGIN\nEND_FUNCTION\n'
        "TYPE UDT 3\nSTRUCT\na : INT;\nEND_STRUCT\nEND_TYPE\n"
        'TYPE "Point"\nSTRUCT\nEND_STRUCT\nEND_TYPE\n'
    )
    headers = [line for line in printed.splitlines() if line and line[0].isalpha()]
    assert headers == [
        "ORGANIZATION_BLOCK OB 1",
        "BEGIN",
        "END_ORGANIZATION_BLOCK",
        'FUNCTION_BLOCK "Valve" : VOID',
        "BEGIN",
        "END_FUNCTION_BLOCK",
        "FUNCTION FC 2 : INT",
        "BEGIN",
        "END_FUNCTION",
        'FUNCTION "Calc" : VOID',
        "BEGIN",
        "END_FUNCTION",
        "TYPE UDT 3",
        "END_TYPE",
        'TYPE "Point"',
        "END_TYPE",
    ]


def test_header_properties_flags_and_attributes() -> None:
    printed = round_trip(
        "DATA_BLOCK DB 5\nTITLE=Shared\n{S7_a:='x';S7_b:='it$'s $$5'}\n{}\nauthor: Me\n"
        "Family : F\nNAME:N1\nVERSION : 1.2\nread_only\nNON_RETAIN\nUNLINKED\n"
        "STRUCT\na : INT;\nEND_STRUCT\nBEGIN\nEND_DATA_BLOCK\n"
    )
    assert printed.splitlines()[:12] == [
        "DATA_BLOCK DB 5",
        "TITLE =Shared",
        "{ S7_a := 'x'; S7_b := 'it$'s $$5' }",
        "{ }",
        "AUTHOR : Me",
        "FAMILY : F",
        "NAME : N1",
        "VERSION : 1.2",
        "READ_ONLY",
        "NON_RETAIN",
        "UNLINKED",
        "",
    ]


def test_attribute_values_are_escaped() -> None:
    block = ast.BlockNode("ORGANIZATION_BLOCK", "OB 1", False, _NO_LOC, _NO_LOC)
    values = {"S7_x": "a'b$c\nd\te\x01"}
    block.head.append(ast.AttributesNode(values, _NO_LOC))
    printed = format_block(block)
    assert "{ S7_x := 'a$'b$$c$Nd$Te$01' }" in printed
    (parsed,) = parse_clean(printed).source.blocks
    assert parsed.head == [ast.AttributesNode(values, parsed.head[0].loc)]


def test_block_comment_goes_below_the_title() -> None:
    text = "ORGANIZATION_BLOCK OB 1\nTITLE = Main\nBEGIN\nEND_ORGANIZATION_BLOCK\n"
    (block,) = parse_clean(text).source.blocks
    block.comment = "first line\nsecond line"
    assert format_block(block).splitlines()[:4] == [
        "ORGANIZATION_BLOCK OB 1",
        "TITLE =Main",
        "//first line",
        "//second line",
    ]


def test_data_blocks() -> None:
    printed = round_trip(
        'DATA_BLOCK DB 1\nFB 10\nBEGIN\nEND_DATA_BLOCK\nDATA_BLOCK "Inst"\nVERSION : 0.1\n"Motor"\n'
        "BEGIN\nstate.running := TRUE;\nspeeds[2] := 5;\nm[1, 2].x := 1, 2;\nEND_DATA_BLOCK\n"
        "DATA_BLOCK DB 3\nSFB -1\nBEGIN\nEND_DATA_BLOCK\n"
        "DATA_BLOCK DB 4\nVERSION : 0.1\n"
        "STRUCT\na : ARRAY[0..3] OF BYTE := 2 (B#16#0, 1 (B#16#1));\n"
        "END_STRUCT;\nBEGIN\na[0] := B#16#FF;\nEND_DATA_BLOCK\n"
    )
    assert printed == (
        "DATA_BLOCK DB 1\nFB 10\nBEGIN\nEND_DATA_BLOCK\n\n"
        'DATA_BLOCK "Inst"\nVERSION : 0.1\n"Motor"\nBEGIN\n   state.running := TRUE;\n'
        "   speeds[2] := 5;\n   m[1, 2].x := 1, 2;\nEND_DATA_BLOCK\n\n"
        "DATA_BLOCK DB 3\nSFB -1\nBEGIN\nEND_DATA_BLOCK\n\n"
        "DATA_BLOCK DB 4\nVERSION : 0.1\n\n  STRUCT\n"
        "   a : ARRAY  [0 .. 3 ] OF BYTE  := 2 (B#16#0, 1 (B#16#1));\n  END_STRUCT ;\nBEGIN\n"
        "   a[0] := B#16#FF;\nEND_DATA_BLOCK\n"
    )


# ---- declarations ---------------------------------------------------------------------------


def test_every_section_and_type_form() -> None:
    printed = round_trip(
        "FUNCTION_BLOCK FB 1\nVAR_INPUT\na : BOOL;\nEND_VAR\n"
        "VAR_OUTPUT\nb : STRING [20];\nEND_VAR\n"
        "VAR_IN_OUT\nc : ARRAY [1..2, -1..1] OF REAL;\nEND_VAR\n"
        "VAR\nd : ARRAY [0..1] OF STRUCT\nx : INT;\n"
        "y : STRUCT\nz : BOOL;\nEND_STRUCT;\nEND_STRUCT;\n"
        'e : UDT 5;\nf : "Point";\ng : FB 2;\nh : SFB 4;\n'
        'i : ARRAY [1..2] OF ARRAY [1..3] OF "Point";\n'
        "j : DATE_AND_TIME := DT#1990-01-01-00:00:00.000;\nk : CHAR := 'a';\n"
        "l : S5TIME := S5T#1S;\n"
        "m : REAL := -1.5e3;\nn : POINTER;\no : ANY;\np : BLOCK_DB;\nq : TIMER;\nEND_VAR\n"
        "VAR_TEMP\nt : INT;\nEND_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n"
    )
    assert printed == (
        "FUNCTION_BLOCK FB 1\nVAR_INPUT\n  a : BOOL ;\nEND_VAR\nVAR_OUTPUT\n"
        "  b : STRING  [20 ] ;\nEND_VAR\nVAR_IN_OUT\n  c : ARRAY  [1 .. 2, -1 .. 1 ] OF REAL ;\n"
        "END_VAR\nVAR\n  d : ARRAY  [0 .. 1 ] OF STRUCT\n   x : INT ;\n   y : STRUCT\n"
        "    z : BOOL ;\n   END_STRUCT ;\n  END_STRUCT ;\n  e : UDT 5 ;\n"
        '  f : "Point" ;\n  g : FB 2 ;\n  h : SFB 4 ;\n'
        '  i : ARRAY  [1 .. 2 ] OF ARRAY  [1 .. 3 ] OF "Point" ;\n'
        "  j : DATE_AND_TIME  := DT#1990-01-01-00:00:00.000;\n  k : CHAR  := 'a';\n"
        "  l : S5TIME  := S5T#1S;\n  m : REAL  := -1.5e3;\n  n : POINTER ;\n  o : ANY ;\n"
        "  p : BLOCK_DB ;\n  q : TIMER ;\nEND_VAR\nVAR_TEMP\n  t : INT ;\nEND_VAR\nBEGIN\n"
        "END_FUNCTION_BLOCK\n"
    )


def test_initial_values() -> None:
    printed = round_trip(
        "DATA_BLOCK DB 1\nSTRUCT\na : ARRAY[1..9] OF INT := 1, 2 (3), 2 (4, 2 (5)), 6;\n"
        "b : BOOL := TRUE;\nc : WORD := W#16#FF;\nd : DWORD := DW#16#1;\ne : TIME := T#1H2M;\n"
        "f : POINTER := P#M 10.0;\ng : CHAR := '$'';\nh : ARRAY[1..2] OF BYTE := B#(1, 2);\n"
        "END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
    )
    assert "   a : ARRAY  [1 .. 9 ] OF INT  := 1, 2 (3), 2 (4, 2 (5)), 6;" in printed
    assert "   g : CHAR  := '$'';" in printed


def test_declaration_comments() -> None:
    printed = round_trip(
        "FUNCTION FC 1 : VOID\nVAR_INPUT\n  a : INT; // first\n  s : STRUCT // a struct\n"
        "    x : BOOL; //inner\n  END_STRUCT;\nEND_VAR\nBEGIN\nEND_FUNCTION\n"
    )
    assert "  a : INT ;\t//first" in printed
    assert "  s : STRUCT\t//a struct" in printed
    assert "   x : BOOL ;\t//inner" in printed
    decl = ast.VarDeclNode("v", ast.NamedTypeNode("INT", None, _NO_LOC), None, {}, _NO_LOC)
    decl.comment = "two\nlines"
    section = ast.VarSectionNode("VAR_TEMP", [decl], _NO_LOC)
    block = ast.BlockNode("FUNCTION", "FC 1", False, _NO_LOC, _NO_LOC, head=[section])
    assert "  v : INT ;\t//two lines" in format_block(block)


def test_format_type_and_values() -> None:
    loc = _NO_LOC
    member = ast.VarDeclNode("x", ast.NamedTypeNode("INT", None, loc), None, {}, loc)
    array = ast.ArrayTypeNode([(1, 2)], ast.StructTypeNode([member], loc), loc)
    assert format_type(array) == "ARRAY  [1 .. 2 ] OF STRUCT\n x : INT ;\nEND_STRUCT"
    assert format_type(ast.RefTypeNode("Motor", True, loc)) == '"Motor"'
    assert format_type(ast.NamedTypeNode("STRING", 8, loc)) == "STRING  [8 ]"
    values: list[ast.InitValue] = [
        ast.ValueNode("NUMBER", "1", loc),
        ast.RepeatNode(2, [ast.ValueNode("IDENT", "TRUE", loc)], loc),
    ]
    assert format_values(values) == "1, 2 (TRUE)"


# ---- code -----------------------------------------------------------------------------------


def test_labels_networks_and_titles() -> None:
    printed = round_trip(
        ob1(
            "NETWORK\nTITLE = first\nM001: A I 0.0\nx: NOP 0\nlong_label: L 1\n"
            "M002:\nNETWORK\nTITLE =\nend:"
        )
    )
    assert body_of(printed) == [
        "NETWORK",
        "TITLE =first",
        "M001: A     I 0.0;",
        "x:    NOP   0;",
        "long_label:",
        "      L     1;",
        "M002:",
        "NETWORK",
        "TITLE =",
        "end:",
    ]


def test_instruction_layout() -> None:
    printed = round_trip(
        ob1(
            "A(\nO I 0.0\n)\nNOT\n+I\n+ 5\n+AR1 P#2.0\n==I\nL -3\nSAVE\nLOOP M001\nM001: BE\n"
            "__ASSERT== __ACCU 1, 5\nU E 0.0\n= A 4.0\nSPA M001"
        )
    )
    assert body_of(printed) == [
        "      A(    ;",
        "      O     I 0.0;",
        "      )     ;",
        "      NOT   ;",
        "      +I    ;",
        "      +     5;",
        "      +AR1  P#2.0;",
        "      ==I   ;",
        "      L     -3;",
        "      SAVE  ;",
        "      LOOP  M001;",
        "M001: BE    ;",
        "      __ASSERT== __ACCU 1, 5;",
        "      U     E 0.0;",
        "      =     A 4.0;",
        "      SPA   M001;",
    ]


OPERANDS = [
    ("I 0.0", "I 0.0"),
    ("MW 10", "MW 10"),
    ("DB5.DBX 2.1", "DB5.DBX 2.1"),
    ("T 3", "T 3"),
    ("FB 10", "FB 10"),
    ("DBW [AR1, P#0.0]", "DBW [AR1,P#0.0]"),
    ("[AR2,P#2.0]", "[AR2,P#2.0]"),
    ("I [MD 2]", "I [MD 2]"),
    ("W[#ptr]", "W [#ptr]"),
    ("#a", "#a"),
    ("#a.b[1, 2].c", "#a.b[1,2].c"),
    ("#arr[3]", "#arr[3]"),
    ('"Motor"', '"Motor"'),
    ('"DB".member', '"DB".member'),
    ('"DB"."member"', '"DB".member'),
    ('"DB"."two words"', '"DB"."two words"'),
    ('"DB"."M1"', '"DB"."M1"'),
    ('"DB"."TYPE"', '"DB"."TYPE"'),
    ('"DB"."1st"', '"DB"."1st"'),
    ('"DB".Motor1', '"DB".Motor1'),
    ('"DB".DBW 2', '"DB".DBW 2'),
    ("DB5.member.x", "DB5.member.x"),
    ("DB5.a[1]", "DB5.a[1]"),
    ("STW", "STW"),
    ("__ACCU 1", "__ACCU 1"),
    ("__STW OV", "__STW OV"),
    ("Motor", "Motor"),
    ("5", "5"),
    ("-2.5E+3", "-2.5E+3"),
    ("L#-5", "L#-5"),
    ("B#(1, 2)", "B#(1, 2)"),
    ("P#M 10.0", "P#M 10.0"),
    ("P##x", "P##x"),
    ("P#DB5.DBX 2.0 BYTE 4", "P#DB5.DBX 2.0 BYTE 4"),
    ("'AB'", "'AB'"),
    ("'a;b//c'", "'a;b//c'"),
    ("S5T#2S", "S5T#2S"),
    ("==0", "==0"),
    ("<>0", "<>0"),
]


@pytest.mark.parametrize(("written", "expected"), OPERANDS, ids=[w for w, _ in OPERANDS])
def test_operands(written: str, expected: str) -> None:
    printed = round_trip(ob1(f"L {written}"))
    assert body_of(printed) == [f"      L     {expected};"]
    (block,) = parse_clean(printed).source.blocks
    instr = block.code[0]
    assert isinstance(instr, ast.InstrNode)
    assert format_operand(instr.operands[0]) == expected


def test_calls() -> None:
    printed = round_trip(
        ob1(
            'CALL FB 1, DB 1\nCALL "Motor" , "MotorDB" (start := I 0.0, stop := , '
            "speed := MW 2,)\nCALL FC 2 ()\nCALL SFC 46\nCALL FB 3, DB 3\n IN1 := M 0.0\n OUT :=\n"
            "M001: CALL FC 4 (a := 1)"
        )
    )
    assert body_of(printed) == [
        "      CALL FB 1 , DB 1;",
        '      CALL "Motor" , "MotorDB" (',
        "           start                    := I 0.0,",
        "           stop                     := ,",
        "           speed                    := MW 2);",
        "      CALL FC 2 ();",
        "      CALL SFC 46;",
        "      CALL FB 3 , DB 3;",
        "           IN1                      := M 0.0;",
        "           OUT                      := ;",
        "M001: CALL FC 4 (",
        "           a                        := 1);",
    ]


def test_format_instruction_and_code() -> None:
    (block,) = parse_clean(ob1("CALL FC 1 (a := #x)\nM001: L #y\nT MW 0")).source.blocks
    call = block.code[0]
    assert isinstance(call, ast.InstrNode)
    assert format_instruction(call) == (
        "      CALL FC 1 (\n           a                        := #x);"
    )
    assert format_code(block.code[1:]) == "M001: L     #y;\n      T     MW 0;\n"
    assert format_code([]) == ""


def test_loose_code_comes_first() -> None:
    printed = round_trip("ORGANIZATION_BLOCK OB 100\nBEGIN\nEND_ORGANIZATION_BLOCK\nL 1\nT MW 0\n")
    assert printed == (
        "      L     1;\n      T     MW 0;\n\n"
        "ORGANIZATION_BLOCK OB 100\nBEGIN\nEND_ORGANIZATION_BLOCK\n"
    )


# ---- trailing comments ----------------------------------------------------------------------


def test_comment_per_instruction() -> None:
    text = ob1("NETWORK\nTITLE = t\nM001: A I 0.0\n= Q 4.0\nCALL FC 1 (a := 1, b := 2)\nBEU")
    first = parse_clean(text)

    def comment(instr: ast.InstrNode) -> str | None:
        if instr.mnemonic == "BEU":
            return None
        return f"SCL line {instr.loc.line}" + ("\nmore" if instr.mnemonic == "=" else "")

    printed = format_source(first.source, comment=comment)
    assert body_of(printed) == [
        "NETWORK",
        "TITLE =t",
        "M001: A     I 0.0;                      // SCL line 5",
        "      =     Q 4.0;                      // SCL line 6 more",
        "      CALL FC 1 (                       // SCL line 7",
        "           a                        := 1,",
        "           b                        := 2);",
        "      BEU   ;",
    ]
    second = parse_clean(printed)
    assert structure(second.source) == structure(first.source)
    (block,) = parse_clean(ob1('L "a symbol name longer than the column"')).source.blocks
    long = format_code(block.code, comment=lambda _: "x")
    assert long == '      L     "a symbol name longer than the column"; // x\n'


# ---- nodes from elsewhere -------------------------------------------------------------------


def test_positions_play_no_part() -> None:
    """The SCL compiler's nodes carry positions in an SCL file: the print must not change."""
    text = (ROOT / "tests/backend/lang/stl/corpus/coverage.awl").read_text(encoding="utf-8")
    parsed = parse_clean(text)
    expected = format_source(parsed.source)
    relocate(parsed.source, ast.Loc(12, 3, 12, 9))
    assert format_source(parsed.source) == expected


def test_nodes_built_by_hand() -> None:
    loc = _NO_LOC
    code: list[ast.CodeItem] = [
        ast.NetworkNode(loc),
        ast.InstrNode("L", [ast.SymbolNode("x", True, [], loc)], None, loc),
        ast.InstrNode("T", [ast.SymbolNode("DB 5", False, ["a", [1, 2]], loc, True)], None, loc),
        ast.InstrNode("+I", [], None, loc),
        ast.LabelNode("M1", loc),
    ]
    block = ast.BlockNode("FUNCTION", "Calc", True, loc, loc, code=code)  # no return type
    printed = format_block(block)
    assert printed == (
        'FUNCTION "Calc" : VOID\nBEGIN\nNETWORK\n      L     #x;\n      T     DB 5.a[1,2];\n'
        "      +I    ;\nM1:\nEND_FUNCTION\n"
    )
    (parsed,) = parse_clean(printed).source.blocks
    assert structure(parsed.code) == structure(code)
    udt = format_block(ast.BlockNode("TYPE", "UDT 1", False, loc, loc))
    assert udt == "TYPE UDT 1\n  STRUCT\n  END_STRUCT ;\nEND_TYPE\n"


def test_syntax_errors_print_as_marks() -> None:
    result = parse_source("bad.awl", ob1("L 1\nL ) (\nT MW 0"))
    assert result.diagnostics
    printed = format_source(result.source)
    assert "// (input skipped after a syntax error)" in printed
    assert "      T     MW 0;" in printed


# ---- speed ----------------------------------------------------------------------------------


def test_formatting_is_fast() -> None:
    text = mixed_program(120_000)
    assert text.count("\n") > 5_000
    source = parse_clean(text).source
    format_source(source)  # warm up (the cached address pattern)
    started = time.perf_counter()
    printed = format_source(source)
    elapsed = time.perf_counter() - started
    assert elapsed < 0.5, elapsed
    assert printed.count("\n") > 5_000

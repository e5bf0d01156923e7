"""The STL syntax tree of a lowered Graph FB, built without the STL parser where it can be.

The generated text is what users read (``--emit stl``) and what the line map refers to, but
Lark reads about 7,000 lines a second, and a 200-step sequencer lowers to ten thousand and
more. Almost every generated line is of a few plain shapes (``A #Step.X``, ``JCN _01A``,
``L L#0``, ``= Q 4.0``), so they become ``ast`` nodes here directly, as the parser would make
them; the block's head up to the user's declarations, and every line of another shape (a
CALL with parameters, a pointer, a status bit), go through the STL parser, the odd lines in
one batch whose positions are mapped back. The STL compiler then compiles the tree as if it
had parsed the text.
"""

from __future__ import annotations

import re
from dataclasses import fields, is_dataclass
from typing import Any

from nasaq.diagnostics import Diagnostic
from nasaq.lang.stl import ast
from nasaq.lang.stl.check import JUMPS
from nasaq.lang.stl.parse import ParseResult, line_comments, parse_source

_WORD = re.compile(r"^[A-Za-z_]\w*$")
# A member name the STL parser reads as an address (``#Step.V1``, ``#x.MW2``).
_NUMBERED = re.compile(
    r"^(?:[ACEILMQTVZ]|[IQEAMLV][BWDX]|DB[BWDX]?|DI[BWDX]?|P[IQEA][BWD])\d", re.IGNORECASE
)
_LOCAL = re.compile(r"^#([A-Za-z_]\w*)((?:\.[A-Za-z_]\w*)*)$")
_GLOBAL = re.compile(r'^"([^"]+)"((?:\.[A-Za-z_]\w*)*)$')
_NUMBER = re.compile(r"^-?\d+$")
_TYPED = re.compile(r"^(?:L|DW|W|B|T|S5T|C|TIME|S5TIME|D|DATE|TOD)#[\w#.:+-]+$", re.IGNORECASE)
_ADDRESS = re.compile(
    r"^(?:[IQEAM][BWDX]?|P[IQEA][BWD]|L[BWDX]?|DB[XBWD]|DI[XBWD]|DB\d+\.DB[XBWD]|T|C|Z|FC|FB"
    r"|SFC|SFB|DB|DI) ?\d+(?:\.\d)?$",
    re.IGNORECASE,
)
_DECLARATION = re.compile(r"^\s*([A-Za-z_]\w*)\s*:\s*([A-Z_]+)(?:\s*:=\s*(\S+?))?\s*;$")
_STRUCT = re.compile(r"^\s*([A-Za-z_]\w*)\s*:\s*STRUCT\s*$")


def _operand(text: str, line: int, jump: bool) -> list[ast.OperandNode] | None:
    """The operand nodes of a line's operand text, None when it is of another shape."""
    loc = ast.Loc(line, 13, line, 13 + len(text))
    first = text[0]
    if jump:
        return [ast.BareNode(text, None, loc)] if _WORD.match(text) else None
    if first == "#":
        if _LOCAL.match(text) is None:
            return None
        name, *parts = text[1:].split(".")
        path: list[str | list[int] | ast.AddressNode] = [
            ast.AddressNode(part, loc) if _NUMBERED.match(part) else part for part in parts
        ]  # the parser reads a member such as V1 as an address
        return [ast.SymbolNode(name, True, path, loc)]
    if first == '"':
        match = _GLOBAL.match(text)
        if match is None or any(_NUMBERED.match(part) for part in match.group(2).split(".")):
            return None
        rest: list[str | list[int] | ast.AddressNode] = [
            part for part in match.group(2).split(".") if part
        ]
        return [ast.SymbolNode(match.group(1), False, rest, loc)]
    if _NUMBER.match(text):
        return [ast.LiteralNode("NUMBER", text, loc)]
    if "#" in text:
        return [ast.LiteralNode("TYPED", text, loc)] if _TYPED.match(text) else None
    if _ADDRESS.match(text):
        return [ast.AddressNode(text, loc)]
    if "," in text:  # CALL FB 2, DB 2
        parts = [part.strip() for part in text.split(",")]
        if len(parts) == 2 and all(_ADDRESS.match(part) for part in parts):
            return [ast.AddressNode(part, loc) for part in parts]
    return None


def _code_line(text: str, line: int) -> list[ast.CodeItem] | None:
    """The items of one generated code line, None when the parser has to read it."""
    if not text.startswith(" ") and not (len(text) > 5 and text[4] == ":" and text[5] == " "):
        if text == "NETWORK":
            return [ast.NetworkNode(ast.Loc(line, 1, line, 8))]
        if text.startswith("TITLE =") and not any(c in text for c in "/'\"{(;"):
            return [ast.TitleNode(text[7:].strip(), ast.Loc(line, 1, line, len(text) + 1))]
        if (text.startswith("//") and "\n" not in text) or not text.strip():
            return []
        return None
    if len(text) > 12 and text[11] != " ":  # a mnemonic of six characters or more
        return None
    mnemonic = text[6:12].rstrip()
    operand = text[12:]
    if not mnemonic or " " in mnemonic or ";" in text or "//" in operand:
        return None
    operands: list[ast.OperandNode] = []
    if operand:
        found = _operand(operand, line, mnemonic.upper() in JUMPS)
        if found is None:
            return None
        operands = found
    loc = ast.Loc(line, 7, line, 7 + len(mnemonic))
    instruction = ast.InstrNode(mnemonic, operands, None, loc)
    if text[0] == " ":
        return [instruction]
    label = text[:4].rstrip()
    return [ast.LabelNode(label, ast.Loc(line, 1, line, len(label) + 1)), instruction]


def _shifted(node: Any, lines: list[int]) -> Any:
    """``node`` with every position moved from the batch's lines to the generated ones."""
    if isinstance(node, ast.Loc):
        return ast.Loc(lines[node.line], node.column, lines[node.end_line], node.end_column)
    if isinstance(node, list):
        return [_shifted(item, lines) for item in node]
    if is_dataclass(node) and not isinstance(node, type):
        for item in fields(node):
            value = getattr(node, item.name)
            if isinstance(value, ast.Loc | list) or is_dataclass(value):
                setattr(node, item.name, _shifted(value, lines))
    return node


class _Declarations:
    """The lowering's own VAR sections (``name : TYPE [:= value];`` and STRUCTs)."""

    def __init__(self) -> None:
        self.sections: list[ast.VarSectionNode] = []
        self.stack: list[tuple[str, ast.Loc, list[ast.VarDeclNode]]] = []

    def line(self, text: str, line: int) -> bool:
        stripped = text.strip()
        loc = ast.Loc(line, 1, line, len(text) + 1)
        if stripped in ("VAR", "VAR_TEMP", "VAR_INPUT", "VAR_OUTPUT"):
            self.sections.append(ast.VarSectionNode(stripped, [], loc))
            return True
        if stripped == "END_VAR" or not self.sections:
            return stripped == "END_VAR"
        members = self.stack[-1][2] if self.stack else self.sections[-1].decls
        struct = _STRUCT.match(text)
        if struct is not None:
            self.stack.append((struct.group(1), loc, []))
            return True
        if stripped == "END_STRUCT;" and self.stack:
            name, start, inner = self.stack.pop()
            parent = self.stack[-1][2] if self.stack else self.sections[-1].decls
            parent.append(ast.VarDeclNode(name, ast.StructTypeNode(inner, start), None, {}, start))
            return True
        match = _DECLARATION.match(text)
        if match is None:
            return False
        name, type_name, value = match.groups()
        init: list[ast.InitValue] | None = None
        if value is not None:
            kind = "NUMBER" if _NUMBER.match(value) else "IDENT"
            init = [ast.ValueNode(kind, value, loc)]
        node_type = ast.NamedTypeNode(type_name, None, loc)
        members.append(ast.VarDeclNode(name, node_type, init, {}, loc))
        return True


def block_tree(
    file: str, lines: list[str], own_from: int, offset: int
) -> tuple[ast.BlockNode | None, list[Diagnostic], dict[int, str]]:
    """The syntax tree of one lowered block: ``lines`` its text, ``own_from`` the index of the
    first line of the lowering's own VAR sections (what comes before is parsed), ``offset`` the
    number of lines before the block in the file. Also the parser's problems and the ``//``
    comments of the parsed head, by file line."""
    head_text = "\n".join(lines[:own_from]) + "\nBEGIN\nEND_FUNCTION_BLOCK\n"
    head = parse_source(file, head_text)
    moved = list(range(offset, offset + own_from + 4))  # head line -> file line
    diagnostics = [_moved_problem(problem, moved) for problem in head.diagnostics]
    comments = {line + offset: text for line, text in head.comments.items()}
    if not head.source.blocks:
        return None, diagnostics, comments
    block = _shifted(head.source.blocks[0], moved)
    declarations = _Declarations()
    begin = own_from
    while begin < len(lines) and lines[begin] != "BEGIN":
        if not declarations.line(lines[begin], offset + begin + 1):
            break
        begin += 1
    if begin >= len(lines) or lines[begin] != "BEGIN":  # not of the shape we write: parse it all
        parsed = parse_source(file, "\n".join(lines) + "\n")
        moved = list(range(offset, offset + len(lines) + 2))
        found = _shifted(parsed.source.blocks[0], moved) if parsed.source.blocks else None
        comments = {line + offset: text for line, text in parsed.comments.items()}
        return found, [_moved_problem(p, moved) for p in parsed.diagnostics], comments
    block.head += declarations.sections
    code: list[ast.CodeItem] = []
    odd: list[tuple[int, int, str]] = []  # (position in code, file line, text)
    for index in range(begin + 1, len(lines) - 1):
        number = offset + index + 1
        items = _code_line(lines[index], number)
        if items is None:
            odd.append((len(code), number, lines[index]))
        else:
            code += items
    if odd:
        code, problems = _with_odd_lines(file, code, odd)
        diagnostics += problems
    block.code = code
    last = offset + len(lines)
    block.end = ast.Loc(last, 1, last, len(lines[-1]) + 1)
    return block, diagnostics, comments


def _moved_problem(problem: Diagnostic, lines: list[int]) -> Diagnostic:
    span = problem.span
    if span is None or span.line is None or not 0 <= span.line < len(lines):
        return problem
    moved = lines[span.line]
    return problem.model_copy(
        update={"span": span.model_copy(update={"line": moved, "end_line": moved})}
    )


def _with_odd_lines(
    file: str, code: list[ast.CodeItem], odd: list[tuple[int, int, str]]
) -> tuple[list[ast.CodeItem], list[Diagnostic]]:
    """``code`` with the lines of other shapes parsed by the STL parser in one batch."""
    batch = ["FUNCTION_BLOCK FB 1", "BEGIN", *(text for _, _, text in odd), "END_FUNCTION_BLOCK"]
    lines = [0, 0, 0, *(number for _, number, _ in odd), odd[-1][1], odd[-1][1]]
    parsed = parse_source(file, "\n".join(batch) + "\n")
    items = parsed.source.blocks[0].code if parsed.source.blocks else []
    by_line: dict[int, list[ast.CodeItem]] = {}
    for item in items:
        by_line.setdefault(item.loc.line, []).append(_shifted(item, lines))
    merged: list[ast.CodeItem] = []
    position = 0
    for index, (at, _, _) in enumerate(odd):
        merged += code[position:at]
        position = at
        merged += by_line.get(index + 3, [])
    merged += code[position:]
    return merged, [_moved_problem(problem, lines) for problem in parsed.diagnostics]


def tree(file: str, blocks: list[tuple[list[str], int, int]]) -> ParseResult:
    """The parse result of a lowered file: per block its lines, the index of its own VAR
    sections and the number of lines before it."""
    nodes: list[ast.BlockNode] = []
    diagnostics: list[Diagnostic] = []
    comments: dict[int, str] = {}
    for lines, own_from, offset in blocks:
        block, problems, found = block_tree(file, lines, own_from, offset)
        if block is not None:
            nodes.append(block)
        diagnostics += problems
        comments |= found
    result = ParseResult(ast.SourceNode(file, nodes, []), diagnostics)
    result.comments = comments or line_comments("")
    return result

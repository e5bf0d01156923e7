"""STL AST → source text in the layout of a STEP 7 "generate source" export.

Used to show the STL the SCL compiler generates (``nasaq compile FILE.scl --emit stl``), so people
can read it as they would read a STEP 7 export: the mnemonic (as stored, of either set) after six
columns of indentation and the operand six columns further (``      L     #x;``), labels in the
indentation (``M001: ``), CALL parameter lists one per line, declarations as ``  name : TYPE ;``.
Every statement ends with ``;``.

Parsing the output with ``parse.parse_source`` gives the input's AST again (``loc`` aside): the
printer writes only what the nodes hold, never their positions, so nodes built by another
compiler (whose locations point into an SCL file) print the same way. What the AST does not
keep cannot be reproduced: spacing inside addresses, comments other than those of declarations
and blocks, and where code outside blocks stood relative to the blocks (it comes first).
``comment`` adds a trailing ``//`` comment to instructions (the SCL compiler's source map).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Sequence
from functools import cache, lru_cache

from nasaq.lang.stl import ast

CommentFn = Callable[[ast.InstrNode], str | None]
"""Returns the trailing comment of an instruction, or None for none."""

_INDENT = " " * 6  # the label column of a STEP 7 export
_ARG_INDENT = " " * 11
_ARG_WIDTH = 24  # STEP 7 pads CALL parameter names to this width
_COMMENT_COLUMN = 40
_NOWHERE = ast.Loc(0, 0, 0, 0)

_END = {
    "ORGANIZATION_BLOCK": "END_ORGANIZATION_BLOCK",
    "FUNCTION_BLOCK": "END_FUNCTION_BLOCK",
    "FUNCTION": "END_FUNCTION",
    "DATA_BLOCK": "END_DATA_BLOCK",
    "TYPE": "END_TYPE",
}
# Words the parser turns back into keywords wherever they stand (see ``parse._RESERVED``):
# a member of that name must be quoted.
_RESERVED = frozenset(
    {
        *_END,
        *_END.values(),
        "BEGIN",
        "END_VAR",
        "END_STRUCT",
        "VAR",
        "VAR_INPUT",
        "VAR_OUTPUT",
        "VAR_IN_OUT",
        "VAR_TEMP",
    }
)
_IDENT = re.compile(r"[^\W\d]\w*")
_CHAR_ESCAPES = {"$": "$$", "'": "$'", "\n": "$N", "\r": "$R", "\t": "$T", "\f": "$P"}


# ---- public API -----------------------------------------------------------------------------


def format_source(source: ast.SourceNode, *, comment: CommentFn | None = None) -> str:
    """A whole file: code outside blocks first (the parser keeps no order between it and the
    blocks), then the blocks, separated by an empty line."""
    printer = _Printer(comment)
    if source.loose_code:
        printer.code(source.loose_code)
    for block in source.blocks:
        if printer.lines:
            printer.lines.append("")
        printer.block(block)
    return printer.text()


def format_block(block: ast.BlockNode, *, comment: CommentFn | None = None) -> str:
    printer = _Printer(comment)
    printer.block(block)
    return printer.text()


def format_code(items: Iterable[ast.CodeItem], *, comment: CommentFn | None = None) -> str:
    """Code items (a block's body, or a snippet) as the lines between BEGIN and END_..."""
    printer = _Printer(comment)
    printer.code(items)
    return printer.text()


def format_instruction(instr: ast.InstrNode, *, comment: CommentFn | None = None) -> str:
    """One statement as in a block body, indented and ended with ``;`` (a CALL with parameters
    takes several lines); no final newline."""
    printer = _Printer(comment)
    printer.instr(instr, _INDENT)
    return "\n".join(printer.lines)


def format_operand(operand: ast.OperandNode) -> str:
    """An operand as the parser reads it back (also for messages and hovers)."""
    if isinstance(operand, ast.AddressNode | ast.LiteralNode | ast.StatusNode):
        return operand.text
    if isinstance(operand, ast.SymbolNode):
        return _symbol(operand)
    if isinstance(operand, ast.BareNode):
        return operand.name if operand.arg is None else f"{operand.name} {operand.arg}"
    inner = format_operand(operand.first)
    if operand.second is not None:
        inner = f"{inner},{format_operand(operand.second)}"
    return f"[{inner}]" if operand.area is None else f"{operand.area} [{inner}]"


def format_type(node: ast.TypeNode) -> str:
    """A declaration's type; a STRUCT takes several lines (members indented by one column)."""
    printer = _Printer(None)
    printer.typed("", node, "", 0)
    return "\n".join(printer.lines)


def format_values(values: Sequence[ast.InitValue]) -> str:
    """An initial value list: ``1, 3 (0), TRUE``."""
    return ", ".join(
        value.text if isinstance(value, ast.ValueNode) else _repeat(value) for value in values
    )


# ---- operands and values --------------------------------------------------------------------


def _symbol(node: ast.SymbolNode) -> str:
    if node.local:
        head = "#" + _name(node.name)
    elif node.absolute_db:
        head = node.name
    else:
        head = f'"{node.name}"'
    if not node.path:
        return head
    parts = [head]
    for step in node.path:
        if isinstance(step, str):
            parts.append("." + _member(step))
        elif isinstance(step, list):
            parts.append("[" + ",".join(map(str, step)) + "]")
        else:
            parts.append("." + step.text)
    return "".join(parts)


@lru_cache(maxsize=4096)
def _member(name: str) -> str:
    """A member name, quoted where the lexer would not read it back as a name: not an
    identifier, a reserved word, or an absolute address (``M1``, ``T3``). Cached: a program
    repeats its member names, and the check is a regular expression."""
    if _IDENT.fullmatch(name) is None or name.upper() in _RESERVED or _is_address(name):
        return f'"{name}"'
    return name


def _name(name: str) -> str:
    """A declared name, quoted as TIA Portal writes one that is no identifier (``"Start 1"``)."""
    return name if _IDENT.fullmatch(name) is not None else f'"{name}"'


def _is_address(word: str) -> bool:
    if not word[-1].isdigit():
        return False
    return _address_pattern().fullmatch(word) is not None


@cache
def _address_pattern() -> re.Pattern[str]:
    """The grammar's own ADDR terminal, so the check follows the grammar."""
    from nasaq.lang.stl.grammar import parser

    return re.compile(parser().get_terminal("ADDR").pattern.to_regexp())


def _repeat(node: ast.RepeatNode) -> str:
    return f"{node.count} ({format_values(node.values)})"


def _chars(text: str) -> str:
    """A ``'...'`` literal of ``text`` with STEP 7's ``$`` escapes (what ``unquote_chars``
    reads back)."""
    out: list[str] = []
    for char in text:
        escaped = _CHAR_ESCAPES.get(char)
        if escaped is not None:
            out.append(escaped)
        elif char < " " or char == "\x7f":
            out.append(f"${ord(char):02X}")
        else:
            out.append(char)
    return "'" + "".join(out) + "'"


def _attributes(values: dict[str, str]) -> str:
    if not values:
        return "{ }"
    return "{ " + "; ".join(f"{name} := {_chars(value)}" for name, value in values.items()) + " }"


def _one_line(text: str) -> str:
    return text.replace("\r\n", " ").replace("\n", " ").replace("\r", " ")


def _block_id(ident: str, quoted: bool) -> str:
    return f'"{ident}"' if quoted else ident


# ---- the printer ----------------------------------------------------------------------------


class _Printer:
    """Collects output lines; one pass over the nodes."""

    __slots__ = ("comment", "lines")

    def __init__(self, comment: CommentFn | None) -> None:
        self.comment = comment
        self.lines: list[str] = []

    def text(self) -> str:
        return "\n".join(self.lines) + "\n" if self.lines else ""

    # ---- blocks -----------------------------------------------------------------------------

    def block(self, block: ast.BlockNode) -> None:
        lines = self.lines
        keyword = block.keyword
        header = f"{keyword} {_block_id(block.ident, block.ident_quoted)}"
        return_type = block.return_type
        if return_type is None and keyword == "FUNCTION":
            return_type = ast.NamedTypeNode("VOID", None, _NOWHERE)  # the grammar requires one
        if return_type is not None:
            self.typed(header + " : ", return_type, "", 0)
        else:
            lines.append(header)
        head = block.head
        previous: ast.HeadItem | None = None
        if head and isinstance(head[0], ast.TitleNode):
            self.head_item(head[0], None)
            previous = head[0]
        if block.comment:  # STEP 7 puts it below the title
            lines.extend("//" + line for line in block.comment.splitlines())
        for item in head[1:] if previous is not None else head:
            self.head_item(item, previous)
            previous = item
        if keyword == "DATA_BLOCK" or keyword == "TYPE":
            self.db_body(block)
            if keyword == "TYPE":
                lines.append("END_TYPE")
                return
            lines.append("BEGIN")
            for value in block.db_values:
                if isinstance(value, ast.DbAssignNode):
                    self.db_assign(value)
                else:
                    lines.append("// (input skipped after a syntax error)")
        else:
            lines.append("BEGIN")
            self.code(block.code)
        lines.append(_END.get(keyword, "END_" + keyword))

    def head_item(self, item: ast.HeadItem, previous: ast.HeadItem | None) -> None:
        lines = self.lines
        if isinstance(item, ast.TitleNode):
            lines.append("TITLE =" + _one_line(item.text))
        elif isinstance(item, ast.HeaderPropNode):
            lines.append(f"{item.key} : {_one_line(item.value)}")
        elif isinstance(item, ast.FlagNode):
            lines.append(item.name)
        elif isinstance(item, ast.AttributesNode):
            lines.append(_attributes(item.values))
        elif isinstance(item, ast.VarSectionNode):
            if previous is not None and not isinstance(previous, ast.VarSectionNode):
                lines.append("")  # STEP 7 sets the interface off from the properties
            lines.append(item.kind)
            for decl in item.decls:
                self.decl(decl, 2)
            lines.append("END_VAR")
        else:
            lines.append("// (input skipped after a syntax error)")

    def db_body(self, block: ast.BlockNode) -> None:
        body = block.db_body
        if body is None:
            if block.keyword != "TYPE":
                return
            body = ast.StructTypeNode([], _NOWHERE)  # the grammar requires one
        if isinstance(body, ast.RefTypeNode):
            self.lines.append(_block_id(body.text, body.quoted))  # an instance DB: ``FB 12``
            return
        if isinstance(body, ast.NamedTypeNode):
            self.lines.append(body.name)  # TIA: the instance DB of a system FB (``TON``)
            return
        if block.head:
            self.lines.append("")  # as before the interface of a code block
        self.typed("  ", body, " ;", 2)

    def db_assign(self, node: ast.DbAssignNode) -> None:
        parts: list[str] = []
        for step in node.path:
            if isinstance(step, str):
                parts.append("." + _name(step) if parts else _name(step))
            else:
                parts.append("[" + ", ".join(map(str, step)) + "]")
        self.lines.append(f"   {''.join(parts)} := {format_values(node.values)};")

    # ---- declarations -----------------------------------------------------------------------

    def decl(self, decl: ast.VarDeclNode, indent: int) -> None:
        name = _name(decl.name)
        if decl.attributes:
            name = f"{name} {_attributes(decl.attributes)}"
        suffix = f"  := {format_values(decl.init)};" if decl.init else " ;"
        first = len(self.lines)
        self.typed(f"{' ' * indent}{name} : ", decl.type, suffix, indent)
        if decl.comment:  # on the name's line, where the compiler looks for it
            self.lines[first] += "\t//" + _one_line(decl.comment)

    def typed(self, prefix: str, node: ast.TypeNode, suffix: str, indent: int) -> None:
        """``prefix`` + the type + ``suffix``; a STRUCT (also as an array element) puts its
        members on the following lines, one column further in, and ``suffix`` after
        END_STRUCT."""
        text: list[str] = [prefix]
        while isinstance(node, ast.ArrayTypeNode):
            dims = ", ".join(f"{low} .. {high}" for low, high in node.dims)
            text.append(f"ARRAY  [{dims} ] OF ")
            node = node.element
        if isinstance(node, ast.StructTypeNode):
            text.append("STRUCT")
            self.lines.append("".join(text))
            for member in node.members:
                self.decl(member, indent + 1)
            self.lines.append(" " * indent + "END_STRUCT" + suffix)
            return
        if isinstance(node, ast.NamedTypeNode):
            text.append(node.name if node.length is None else f"{node.name}  [{node.length} ]")
        else:
            text.append(_block_id(node.text, node.quoted))
        text.append(suffix)
        self.lines.append("".join(text))

    # ---- code -------------------------------------------------------------------------------

    def code(self, items: Iterable[ast.CodeItem]) -> None:
        """Labels of up to four characters share the line of the next statement (STEP 7's
        label column); longer ones, or one before no statement, stand on a line of their own."""
        lines = self.lines
        label = ""
        for item in items:
            if isinstance(item, ast.InstrNode):
                self.instr(item, label or _INDENT)
                label = ""
                continue
            if label:
                lines.append(label.rstrip())
                label = ""
            if isinstance(item, ast.LabelNode):
                if len(item.name) <= 4:
                    label = f"{item.name}:".ljust(6)
                else:
                    lines.append(item.name + ":")
            elif isinstance(item, ast.NetworkNode):
                lines.append("NETWORK")
            elif isinstance(item, ast.TitleNode):
                lines.append("TITLE =" + _one_line(item.text))
            else:
                lines.append("// (input skipped after a syntax error)")
        if label:
            lines.append(label.rstrip())

    def instr(self, instr: ast.InstrNode, lead: str) -> None:
        """``lead`` is the six-column indentation, or the label that stands in it."""
        operands = instr.operands
        mnemonic = instr.mnemonic
        if instr.param_line:  # ``NAME := operand`` under a CALL without parentheses
            value = format_operand(operands[0]) if operands else ""
            line = f"{lead}{' ' * 5}{mnemonic.ljust(_ARG_WIDTH)} := {value};"
            self.finish(line, instr)
            return
        if not operands:
            line = f"{lead}{mnemonic.ljust(5)} "
        elif mnemonic.upper() == "CALL":  # STEP 7: ``CALL FB 1 , DB 1``
            line = f"{lead}{mnemonic} " + " , ".join(map(format_operand, operands))
        else:
            line = f"{lead}{mnemonic.ljust(5)} " + ", ".join(map(format_operand, operands))
        args = instr.args
        if instr.attributes:  # TIA: on a line of its own between the CALL and its parameters
            self.finish(line, instr)
            self.ends(_ARG_INDENT + _attributes(instr.attributes), None, args)
            return
        self.ends(line, instr, args)

    def ends(
        self, line: str, instr: ast.InstrNode | None, args: list[ast.CallArgNode] | None
    ) -> None:
        """``line`` with the CALL's parameter list (or ``;``); its comment when ``instr``."""
        lines = self.lines
        if args is None:
            self.close(line + ";", instr)
        elif not args:
            self.close(line + " ();", instr)
        else:
            self.close(line + " (", instr)
            last = len(args) - 1
            for number, arg in enumerate(args):
                value = "" if arg.value is None else format_operand(arg.value)
                end = ");" if number == last else ","
                lines.append(f"{_ARG_INDENT}{_name(arg.name).ljust(_ARG_WIDTH)} := {value}{end}")

    def close(self, line: str, instr: ast.InstrNode | None) -> None:
        if instr is None:
            self.lines.append(line)
        else:
            self.finish(line, instr)

    def finish(self, line: str, instr: ast.InstrNode) -> None:
        if self.comment is not None:
            text = self.comment(instr)
            if text:
                line = f"{line.ljust(_COMMENT_COLUMN - 1)} // {_one_line(text)}"
        self.lines.append(line)

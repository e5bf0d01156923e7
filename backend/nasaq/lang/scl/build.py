"""Builds ``nasaq.lang.scl.ast`` nodes while the LALR parser reduces (no parse tree).

Each method is named after a rule or alias of ``grammars/scl.lark`` and receives that rule's
children: tokens (named terminals; anonymous punctuation is filtered out by Lark) and what the
methods of its sub-rules returned. Positions come from tokens and child nodes. A token is Lark's
``Token`` in the recovering parse and a ``FastToken`` in the fast one (``nasaq.lang.scl.lalr``):
the methods read only what both have (``type``, the text as ``value``, the position). Statement
lists are new lists that the statement holding them keeps as they are.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any, ClassVar

from lark import Token

from nasaq.lang.scl import ast
from nasaq.lang.scl.lexer import FastToken

# ``m1``, ``i2``, ``qx3``: what the ADDR terminal takes but no S7 address is (an input, output or
# memory bit needs its bit number), so it is an identifier: a variable called m1.
_NOT_AN_ADDRESS = re.compile(r"(?i)(?:I|Q|M|IX|QX|MX)\d+$")

_STMT_TYPES = (
    ast.Assign,
    ast.CallStmt,
    ast.If,
    ast.Case,
    ast.For,
    ast.While,
    ast.Repeat,
    ast.Exit,
    ast.Continue,
    ast.Return,
    ast.Goto,
    ast.Label,
    ast.Empty,
    ast.Region,
    ast.Bad,
)
_STMT_CLASSES = frozenset(_STMT_TYPES)  # a set look-up for the long statement lists
_SECTION_TYPES = (ast.VarSection, ast.ConstSection, ast.LabelSection)


_NOWHERE = ast.Loc(1, 1, 1, 1)
# ``Loc(...)`` as ``_new(_Loc, (line, column, end_line, end_column))``, without
# ``NamedTuple.__new__``'s Python frame: positions are made per node.
_new: Any = tuple.__new__
_Loc = ast.Loc


# A token from Lark (the recovering parse) or from the fast parse: the builder reads its ``type``,
# its text (``value``) and its position.
AnyToken = Token | FastToken
_TOKENS = (Token, FastToken)


def token_loc(token: AnyToken) -> ast.Loc:
    """A token's position (``nasaq.lang.stl.build.loc``; a synthetic token may have none)."""
    line = token.line or 1
    column = token.column or 1
    found: ast.Loc = _new(_Loc, (line, column, token.end_line or line, token.end_column or column))
    return found


def loc_of(item: Any) -> ast.Loc:
    if isinstance(item, _TOKENS):
        return token_loc(item)
    if isinstance(item, list):
        return loc_of(item[-1]) if item else _NOWHERE
    found: ast.Loc = item.loc
    return found


def span(first: Any, last: Any) -> ast.Loc:
    """From the start of ``first`` to the end of ``last``: ``loc_of`` of each, read without
    making their ``Loc`` where they are tokens or nodes (a few per node of the tree)."""
    kind = type(first)
    if kind is FastToken or kind is Token:
        line = first.line or 1
        column = first.column or 1
    else:
        try:
            start = first.loc
        except AttributeError:  # a list
            start = loc_of(first)
        line = start[0]
        column = start[1]
    kind = type(last)
    if kind is FastToken or kind is Token:
        end_line = last.end_line or last.line or 1
        end_column = last.end_column or last.column or 1
    else:
        try:
            end = last.end if isinstance(last, ast.Block) else last.loc
        except AttributeError:
            end = loc_of(last)
        end_line = end[2]
        end_column = end[3]
    found: ast.Loc = _new(_Loc, (line, column, end_line, end_column))
    return found


def _nodes(children: list[Any]) -> list[Any]:
    return [child for child in children if not isinstance(child, _TOKENS)]


def _stmts(children: list[Any]) -> list[ast.Stmt]:
    found: list[Any] = [child for child in children if type(child) in _STMT_CLASSES]
    return found


class _Title(str):
    pass


class _Flag(str):
    pass


class _Prop(tuple[str, str]):
    pass


class _Attributes(list[ast.Attribute]):
    pass


class _Source:
    """A DB's STRUCT or the FB/UDT it is made of (a UDT's STRUCT is one too)."""

    def __init__(self, node: ast.StructType | ast.BlockName) -> None:
        self.node = node


class _Code(list[ast.Stmt]):
    begin = False


# ---- nodes of one token (``AstBuilder.token_rules``) ----------------------------------------


def literal_node(kind: str, text: str, where: ast.Loc) -> ast.Literal:
    if kind == "TRUE" or kind == "FALSE":
        return ast.Literal("BOOL", text.upper(), where)
    return ast.Literal(kind, text, where)


def name_node(kind: str, text: str, where: ast.Loc) -> ast.Name:
    return ast.Name(text, where)


def local_node(kind: str, text: str, where: ast.Loc) -> ast.Local:
    if text[1:2] == '"':  # TIA's #"raw value"
        return ast.Local(text[2:-1], where)
    return ast.Local(text[1:], where)


def symbol_node(kind: str, text: str, where: ast.Loc) -> ast.Symbol:
    return ast.Symbol(text[1:-1], where)


def address_node(kind: str, text: str, where: ast.Loc) -> ast.Address | ast.Name:
    if _NOT_AN_ADDRESS.match(text):  # ``m1 : INT``: an I/Q/M bit needs ``.bit``
        return ast.Name(text, where)
    if text[-2:] in (":P", ":p"):  # TIA's %IW10:P is the peripheral word PIW10
        return ast.Address("P" + text[1:-2], where)
    return ast.Address(text.replace(" ", "").replace("\t", ""), where)


class AstBuilder:
    """Rule callbacks (a plain object, not a ``lark.Transformer``: Lark then builds its own
    helper rules directly; see the STL builder for why)."""

    # ---- file and blocks --------------------------------------------------------------------

    def start(self, children: list[Any]) -> list[Any]:
        return _nodes(children)

    def block_id(self, children: list[Any]) -> ast.BlockName:
        token: AnyToken = children[0]
        text = token.value
        if token.type == "QSYM":
            return ast.BlockName(text[1:-1], quoted=True, loc=token_loc(token))
        compact = text.replace(" ", "").replace("\t", "")
        absolute = token.type == "ADDR"
        return ast.BlockName(compact if absolute else text, absolute=absolute, loc=token_loc(token))

    def _make_block(self, children: list[Any], kind: str) -> ast.Block:
        name: ast.BlockName = children[1]
        block = ast.Block(kind=kind, name=name, loc=span(children[0], name))
        block.end = token_loc(children[-1])
        parts = children[2:-1]
        if kind == "FUNCTION":
            block.return_type = parts.pop(0)
        for child in parts:
            if isinstance(child, _Title):
                block.title = str(child)
            elif isinstance(child, _Prop):
                block.props[child[0]] = child[1]
            elif isinstance(child, _Flag):
                block.flags.append(str(child))
            elif isinstance(child, _Attributes):
                block.attributes.extend(child)
            elif isinstance(child, _SECTION_TYPES):
                block.sections.append(child)
            elif isinstance(child, _Code):
                block.begin = child.begin
                block.code.extend(child)
            elif isinstance(child, ast.Bad):
                block.bad.append(child)
            elif isinstance(child, _Source):
                block.sources.append(child.node)
        return block

    def org_block(self, children: list[Any]) -> ast.Block:
        return self._make_block(children, "ORGANIZATION_BLOCK")

    def fb_block(self, children: list[Any]) -> ast.Block:
        return self._make_block(children, "FUNCTION_BLOCK")

    def fc_block(self, children: list[Any]) -> ast.Block:
        return self._make_block(children, "FUNCTION")

    def program_block(self, children: list[Any]) -> ast.Block:
        return self._make_block(children, "PROGRAM")

    def db_block(self, children: list[Any]) -> ast.Block:
        return self._make_block(children, "DATA_BLOCK")

    def udt_block(self, children: list[Any]) -> ast.Block:
        parts = [
            _Source(child) if isinstance(child, ast.StructType) else child for child in children
        ]
        return self._make_block(parts, "TYPE")

    def db_source(self, children: list[Any]) -> _Source:
        return _Source(children[0])

    # ---- header -----------------------------------------------------------------------------

    def title(self, children: list[Any]) -> _Title:
        text = children[1].value[1:].strip()
        if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
            text = text[1:-1]
        return _Title(text)

    def header_prop(self, children: list[Any]) -> _Prop:
        key, value = children
        text = value.value.strip()
        if len(text) >= 2 and text[0] == text[-1] == "'":
            text = text[1:-1]
        return _Prop((key.value.upper(), text))

    def flag(self, children: list[Any]) -> _Flag:
        return _Flag(children[0].value.upper())

    def attributes(self, children: list[Any]) -> _Attributes:
        return _Attributes(child for child in children if isinstance(child, ast.Attribute))

    def attribute(self, children: list[Any]) -> ast.Attribute:
        name, value = children
        return ast.Attribute(name.value, value.value[1:-1], loc=span(name, value))

    # ---- declarations -----------------------------------------------------------------------

    def var_section(self, children: list[Any]) -> ast.VarSection:
        keyword: AnyToken = children[0]
        words = keyword.value.upper().split()
        decls = [child for child in children if isinstance(child, ast.VarDecl | ast.Bad)]
        modifier = words[1] if len(words) > 1 else None
        return ast.VarSection(words[0], decls, modifier, loc=span(keyword, children[-1]))

    def const_section(self, children: list[Any]) -> ast.ConstSection:
        decls = [child for child in children if isinstance(child, ast.ConstDecl | ast.Bad)]
        return ast.ConstSection(decls, loc=span(children[0], children[-1]))

    def label_section(self, children: list[Any]) -> ast.LabelSection:
        names = [child.value for child in children if child.type == "IDENT"]
        return ast.LabelSection(names, loc=span(children[0], children[-1]))

    def const_decl(self, children: list[Any]) -> ast.ConstDecl:
        name, value = children
        return ast.ConstDecl(name.value, value, loc=span(name, value))

    def var_decl(self, children: list[Any]) -> ast.VarDecl:
        names = [child for child in children if isinstance(child, ast.DeclName)]
        at_name = None
        type_node: ast.TypeNode | None = None
        init: list[ast.InitItem] | None = None
        for index, child in enumerate(children):
            if isinstance(child, _TOKENS) and child.type == "AT":
                at_name = children[index + 1].value
            elif isinstance(child, ast.NamedType | ast.ArrayType | ast.StructType):
                type_node = child
            elif isinstance(child, list):
                init = child
        assert type_node is not None
        return ast.VarDecl(names, type_node, init, at_name, loc=span(names[0], children[-1]))

    def decl_name(self, children: list[Any]) -> ast.DeclName:
        token: AnyToken = children[0]
        attributes = list(children[1]) if len(children) > 1 else []
        quoted = token.type == "QSYM"
        text = token.value[1:-1] if quoted else token.value
        return ast.DeclName(text, quoted, attributes, loc=token_loc(token))

    def init_list(self, children: list[Any]) -> list[ast.InitItem]:
        return list(children)

    def init_repeat(self, children: list[Any]) -> ast.InitRepeat:
        count: AnyToken = children[0]
        values = children[1] if len(children) > 1 else []
        return ast.InitRepeat(count.value, values, loc=span(count, children[-1]))

    def init_brackets(self, children: list[Any]) -> ast.InitList:
        values: list[ast.InitItem] = children[0]
        return ast.InitList(values, loc=span(values[0], values[-1]))

    def init_struct(self, children: list[Any]) -> ast.InitStruct:
        values: list[ast.InitItem] = children[1] if len(children) == 3 else []
        return ast.InitStruct(values, loc=span(children[0], children[-1]))

    def named_type(self, children: list[Any]) -> ast.NamedType:
        token: AnyToken = children[0]
        if token.type == "QSYM":
            return ast.NamedType(token.value[1:-1], quoted=True, loc=token_loc(token))
        length = children[1] if len(children) > 1 else None
        text = token.value
        if token.type == "ADDR":
            text = text.replace(" ", "").replace("\t", "")
        return ast.NamedType(text, length=length, loc=span(token, children[-1]))

    def type_spec(self, children: list[Any]) -> ast.StructType:
        found: ast.StructType = children[0]
        return found

    def array_type(self, children: list[Any]) -> ast.ArrayType:
        dims = [child for child in children if isinstance(child, ast.Dim)]
        element = children[-1]
        return ast.ArrayType(dims, element, loc=span(children[0], element))

    def struct_type(self, children: list[Any]) -> ast.StructType:
        members = [child for child in children if isinstance(child, ast.VarDecl | ast.Bad)]
        return ast.StructType(members, loc=span(children[0], children[-1]))

    def dim(self, children: list[Any]) -> ast.Dim:
        low, high = children
        return ast.Dim(low, high, loc=span(low, high))

    def open_dim(self, children: list[Any]) -> ast.Dim:
        return ast.Dim(None, None, loc=token_loc(children[0]))

    # ---- statements -------------------------------------------------------------------------

    def label(self, children: list[Any]) -> ast.Label:
        return ast.Label(children[0].value, loc=token_loc(children[0]))

    def empty(self, children: list[Any]) -> ast.Empty:
        where = token_loc(children[0]) if children else ast.Loc(1, 1, 1, 1)
        return ast.Empty(loc=where)

    def assign(self, children: list[Any]) -> ast.Assign:
        if len(children) == 2:
            target, value = children
            return ast.Assign(target, value, _join(target, value))
        target, *chain, value = children  # a := b := c
        return ast.Assign(target, value, _join(target, value), chain)

    def compound_assign(self, children: list[Any]) -> ast.Assign:
        target, token, value = children
        op: str = token.value[0]
        combined = ast.Binary(op, target, value, _join(target, value))
        return ast.Assign(target, combined, _join(target, value), op=op)

    def call_stmt(self, children: list[Any]) -> ast.CallStmt:
        call: ast.Call = children[0]
        return ast.CallStmt(call, call.loc)

    def stmts(self, children: list[Any]) -> list[ast.Stmt]:
        """A new plain list, which the statement holding it keeps as its body (no copy)."""
        return _stmts(children)

    def code(self, children: list[Any]) -> _Code:
        found = _Code(_stmts(children[:1]))
        found.extend(children[-1])
        found.begin = _is(children[0], "BEGIN")
        return found

    def db_values(self, children: list[Any]) -> _Code:
        found = _Code(_stmts(children))
        found.begin = True
        return found

    def if_stmt(self, children: list[Any]) -> ast.If:
        keyword, condition, _then, body = children[:4]
        branches = [ast.IfBranch(condition, body, loc=span(keyword, condition))]
        orelse: list[ast.Stmt] | None = None
        for child in children[4:]:
            if isinstance(child, ast.IfBranch):
                branches.append(child)
            elif isinstance(child, _Else):
                orelse = child.body
        return ast.If(branches, orelse, loc=span(keyword, children[-1]))

    def elsif(self, children: list[Any]) -> ast.IfBranch:
        keyword, condition, _then, body = children
        return ast.IfBranch(condition, body, loc=span(keyword, condition))

    def else_part(self, children: list[Any]) -> _Else:
        return _Else(children[-1])

    def case_stmt(self, children: list[Any]) -> ast.Case:
        branches: list[ast.CaseBranch] = []
        for child in children:
            if isinstance(child, ast.CaseBranch):
                branches += _split_at_labels(child)
        orelse = next((child.body for child in children if isinstance(child, _Else)), None)
        return ast.Case(children[1], branches, orelse, loc=span(children[0], children[-1]))

    def case_branch(self, children: list[Any]) -> ast.CaseBranch:
        values = [child for child in children if isinstance(child, ast.CaseValue)]
        return ast.CaseBranch(values, children[-1], loc=span(values[0], values[-1]))

    def case_else(self, children: list[Any]) -> _Else:
        return _Else(children[-1])

    def case_value(self, children: list[Any]) -> ast.CaseValue:
        high = children[1] if len(children) > 1 else None
        return ast.CaseValue(children[0], high, loc=span(children[0], children[-1]))

    def case_name(self, children: list[Any]) -> ast.Name | ast.Local | ast.Symbol:
        token: AnyToken = children[0]
        text, where = token.value, token_loc(token)
        if text.startswith("#"):
            return local_node(token.type, text, where)
        if text.startswith('"'):
            return symbol_node(token.type, text, where)
        return name_node(token.type, text, where)

    def neg_literal(self, children: list[Any]) -> ast.Literal:
        minus, value = children
        return ast.Literal(value.kind, "-" + value.text, loc=span(minus, value))

    def for_stmt(self, children: list[Any]) -> ast.For:
        parts = [child for child in children if not isinstance(child, _TOKENS)]
        step = parts[3] if len(parts) == 5 else None
        return ast.For(
            parts[0], parts[1], parts[2], step, parts[-1], loc=span(children[0], children[-1])
        )

    def while_stmt(self, children: list[Any]) -> ast.While:
        keyword, condition, _do, body = children[:4]
        return ast.While(condition, body, loc=span(keyword, children[-1]))

    def repeat_stmt(self, children: list[Any]) -> ast.Repeat:
        keyword, body, _until, condition = children[:4]
        return ast.Repeat(body, condition, loc=span(keyword, children[-1]))

    def exit_stmt(self, children: list[Any]) -> ast.Exit:
        return ast.Exit(loc=token_loc(children[0]))

    def continue_stmt(self, children: list[Any]) -> ast.Continue:
        return ast.Continue(loc=token_loc(children[0]))

    def return_stmt(self, children: list[Any]) -> ast.Return:
        return ast.Return(loc=token_loc(children[0]))

    def goto_stmt(self, children: list[Any]) -> ast.Goto:
        return ast.Goto(children[1].value, loc=span(children[0], children[1]))

    def region(self, children: list[Any]) -> ast.Region:
        head: AnyToken = children[0]
        title = head.value[len("REGION") :].strip()
        return ast.Region(title, children[1], loc=span(head, children[-1]))

    def bad(self, children: list[Any]) -> ast.Bad:
        return ast.Bad(loc=token_loc(children[0]))

    # ---- expressions ------------------------------------------------------------------------

    def expr(self, children: list[Any]) -> ast.Expr:
        """A flat ``operand (op operand)+`` list → the ``Binary`` tree of S7-SCL precedence
        (operator-precedence parsing; every level is left-associative)."""
        operand = children[0]
        if len(children) == 3:  # one operator: the common case
            return _binary(children[1], operand, children[2])
        if len(children) == 5:  # two: the next most common
            _first, one, middle, two, last = children
            if _LEVEL[one.type] >= _LEVEL[two.type]:
                return _binary(two, _binary(one, operand, middle), last)
            return _binary(one, operand, _binary(two, middle, last))
        pending: list[tuple[int, AnyToken, Any]] = []  # operators waiting for their right operand
        for position in range(1, len(children), 2):
            op: AnyToken = children[position]
            level = _LEVEL[op.type]
            while pending and pending[-1][0] >= level:
                _level, waiting, left = pending.pop()
                operand = _binary(waiting, left, operand)
            pending.append((level, op, operand))
            operand = children[position + 1]
        while pending:
            _level, waiting, left = pending.pop()
            operand = _binary(waiting, left, operand)
        found: ast.Expr = operand
        return found

    def binary(self, children: list[Any]) -> ast.Binary:
        left, op, right = children
        return ast.Binary(op.value.upper(), left, right, span(left, right))

    def unary(self, children: list[Any]) -> ast.Unary:
        op, operand = children
        return ast.Unary(op.value.upper(), operand, loc=span(op, operand))

    def paren(self, children: list[Any]) -> ast.Paren:
        inner = children[0]
        where = loc_of(inner)
        return ast.Paren(
            inner, loc=ast.Loc(where.line, where.column - 1, where.end_line, where.end_column + 1)
        )

    def literal(self, children: list[Any]) -> ast.Literal:
        token: AnyToken = children[0]
        return literal_node(token.type, token.value, token_loc(token))

    def call(self, children: list[Any]) -> ast.Call:
        callee = children[0]
        args = [child for child in children[1:] if isinstance(child, ast.Arg)]
        last = args[-1] if args else callee
        return ast.Call(callee, args, span(callee, last))

    def positional(self, children: list[Any]) -> ast.Arg:
        value = children[0]
        return ast.Arg(None, value, False, loc_of(value))

    def named(self, children: list[Any]) -> ast.Arg:
        name, value = children
        return ast.Arg(_parameter(name), value, loc=span(name, value))

    def output(self, children: list[Any]) -> ast.Arg:
        name, value = children
        return ast.Arg(_parameter(name), value, output=True, loc=span(name, value))

    def name(self, children: list[Any]) -> ast.Name:
        token: AnyToken = children[0]
        return name_node(token.type, token.value, token_loc(token))

    def local(self, children: list[Any]) -> ast.Local:
        token: AnyToken = children[0]
        return local_node(token.type, token.value, token_loc(token))

    def symbol(self, children: list[Any]) -> ast.Symbol:
        token: AnyToken = children[0]
        return symbol_node(token.type, token.value, token_loc(token))

    def address(self, children: list[Any]) -> ast.Address | ast.Name:
        token: AnyToken = children[0]
        return address_node(token.type, token.value, token_loc(token))

    # The rules of one token whose node the fast parse (``nasaq.lang.scl.lalr``) makes straight
    # from the token's kind, text and position, without a ``Token``: by method name, the
    # function the method calls too.
    token_rules: ClassVar[dict[str, Callable[[str, str, ast.Loc], Any]]] = {
        "literal": literal_node,
        "name": name_node,
        "local": local_node,
        "symbol": symbol_node,
        "address": address_node,
    }

    def indexed_address(self, children: list[Any]) -> ast.IndexedAddress:
        area: AnyToken = children[0]
        return ast.IndexedAddress(_compact(area), list(children[1:]), loc=span(area, children[-1]))

    def area_paren(self, children: list[Any]) -> ast.IndexedAddress:
        """TIA's ``%IB(#i)``: STEP 7's ``IB[i]``; with ``:P`` the peripheral ``PIB[i]``."""
        area: AnyToken = children[0]
        last = children[-1]
        peripheral = isinstance(last, _TOKENS) and last.type == "PERIPHERAL"
        indices = list(children[1:-1] if peripheral else children[1:])
        name = _compact(area).lstrip("%")
        return ast.IndexedAddress("P" + name if peripheral else name, indices, span(area, last))

    def member(self, children: list[Any]) -> ast.Member:
        base, token = children
        part: ast.Name | ast.Symbol | ast.Address
        kind = token.type
        where = token_loc(token)
        if kind == "QSYM":
            part = symbol_node(kind, token.value, where)
        elif kind == "DB_ADDR":
            part = address_node(kind, token.value, where)
        else:
            part = name_node(kind, token.value, where)
        return ast.Member(base, part, _join(base, part))

    def slice(self, children: list[Any]) -> ast.Slice:
        base, token = children
        return ast.Slice(base, token.value[1].upper(), int(token.value[2:]), span(base, token))

    def indexed_member(self, children: list[Any]) -> ast.Member:
        base = children[0]
        part = self.indexed_address(children[1:])
        return ast.Member(base, part, loc=span(base, part))

    def index(self, children: list[Any]) -> ast.Index:
        base = children[0]
        return ast.Index(base, list(children[1:]), span(base, children[-1]))


# Binding strength of the binary operators below ``**`` (higher binds tighter).
_LEVEL = {
    "OR": 1,
    "XOR": 2,
    "AND": 3,
    "AMP": 3,
    "EQ": 4,
    "NE": 4,
    "LT": 5,
    "GT": 5,
    "LE": 5,
    "GE": 5,
    "PLUS": 6,
    "MINUS": 6,
    "STAR": 7,
    "SLASH": 7,
    "MOD": 7,
    "DIV": 7,
}


def _binary(op: AnyToken, left: Any, right: Any) -> ast.Binary:
    """``left op right`` (operands are nodes)."""
    start = left.loc
    end = right.loc
    text: str = op.value
    return ast.Binary(text.upper(), left, right, _new(_Loc, (start[0], start[1], end[2], end[3])))


def _join(first: Any, last: Any) -> ast.Loc:
    """``span`` of two expression nodes (not tokens, lists or blocks), in fewer steps."""
    start = first.loc
    end = last.loc
    found: ast.Loc = _new(_Loc, (start[0], start[1], end[2], end[3]))
    return found


def _parameter(token: AnyToken) -> str:
    """A formal parameter's name; TIA may quote it (``"inPar" := x``)."""
    text: str = token.value
    return text[1:-1] if token.type == "QSYM" else text


def _split_at_labels(branch: ast.CaseBranch) -> list[ast.CaseBranch]:
    """A CASE branch whose statements hold ``K2:`` (parsed as a jump label: LALR(1) cannot tell
    it from the label of the next branch) split there: the name is a named constant labelling a
    branch of its own, as TIA Portal reads it."""
    body = branch.body
    if not any(type(statement) is ast.Label for statement in body):
        return [branch]
    found = [ast.CaseBranch(branch.values, [], loc=branch.loc)]
    for statement in body:
        if type(statement) is ast.Label:
            value = ast.CaseValue(ast.Name(statement.name, statement.loc), loc=statement.loc)
            found.append(ast.CaseBranch([value], [], loc=statement.loc))
        else:
            found[-1].body.append(statement)
    return found


class _Else:
    """An ELSE's statements (``else_part``, ``case_else``)."""

    __slots__ = ("body",)

    def __init__(self, body: list[ast.Stmt]) -> None:
        self.body = body


def _is(child: Any, kind: str) -> bool:
    return isinstance(child, _TOKENS) and child.type == kind


def _compact(token: AnyToken) -> str:
    text: str = token.value
    return text.replace(" ", "").replace("\t", "")

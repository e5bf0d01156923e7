"""Builds AST nodes while the LALR parser reduces (Lark inline transformer: no parse tree).

Each method is named after a grammar rule or alias of ``grammars/stl.lark`` and receives that
rule's children: tokens, or what the methods of its sub-rules returned. Positions come from
tokens, so every node gets a line and column even though no tree carries ``meta``.
"""

from __future__ import annotations

from typing import Any

from lark import Token

from nasaq.lang.stl import ast


def loc(token: Token) -> ast.Loc:
    line = token.line or 1
    column = token.column or 1
    return _Loc(line, column, token.end_line or line, token.end_column or column)


def _span(first: ast.Loc, last: ast.Loc) -> ast.Loc:
    return ast.Loc(first.line, first.column, last.end_line, last.end_column)


_Loc = ast.Loc
_TYPE_NODES = (ast.NamedTypeNode, ast.ArrayTypeNode, ast.StructTypeNode, ast.RefTypeNode)


class _CallArgs(list[ast.CallArgNode]):
    pass


class _Index(list[int]):
    pass


class _Init(list[ast.InitValue]):
    pass


class AstBuilder:
    """Rule callbacks; see the grammar for the shape of each rule's children.

    Not a ``lark.Transformer``: Lark calls a transformer's ``__default__`` (through two wrapper
    calls) for every rule without a method, which are its internal helper rules (``_code_item``,
    ``__start_star_0`` ...) that it inlines into their parent. Without ``__default__`` it builds
    their ``Tree`` directly, a third of the reductions of a typical source."""

    # ---- file and blocks --------------------------------------------------------------------

    def start(self, children: list[Any]) -> list[Any]:
        return children

    def _make_block(self, children: list[Any], keyword: str) -> ast.BlockNode:
        head_token: Token = children[0]
        ident: Token = children[1]
        end: Token = children[-1]
        block = ast.BlockNode(
            keyword=keyword,
            ident=str(ident)[1:-1] if ident.type == "QSYM" else str(ident),
            ident_quoted=ident.type == "QSYM",
            loc=_span(loc(head_token), loc(ident)),
            end=loc(end),
        )
        in_body = False
        for child in children[2:-1]:
            if isinstance(child, Token):
                if child.type == "BEGIN":
                    in_body = True
                continue
            if in_body:
                if isinstance(child, ast.DbAssignNode) or (
                    keyword == "DATA_BLOCK" and isinstance(child, ast.BadNode)
                ):
                    block.db_values.append(child)
                else:
                    block.code.append(child)
            elif isinstance(child, _DbBody):
                block.db_body = child.type
            elif isinstance(child, _TYPE_NODES):
                if keyword == "TYPE":
                    block.db_body = child
                else:
                    block.return_type = child
            else:
                block.head.append(child)
        return block

    def org_block(self, children: list[Any]) -> ast.BlockNode:
        return self._make_block(children, "ORGANIZATION_BLOCK")

    def fb_block(self, children: list[Any]) -> ast.BlockNode:
        return self._make_block(children, "FUNCTION_BLOCK")

    def fc_block(self, children: list[Any]) -> ast.BlockNode:
        return self._make_block(children, "FUNCTION")

    def db_block(self, children: list[Any]) -> ast.BlockNode:
        return self._make_block(children, "DATA_BLOCK")

    def udt_block(self, children: list[Any]) -> ast.BlockNode:
        return self._make_block(children, "TYPE")

    def block_id(self, children: list[Token]) -> Token:
        return children[0]

    # ---- header -----------------------------------------------------------------------------

    def title(self, children: list[Token]) -> ast.TitleNode:
        text = str(children[1])[1:].strip()
        return ast.TitleNode(text, _span(loc(children[0]), loc(children[1])))

    def network_title(self, children: list[Token]) -> ast.TitleNode:
        return self.title(children)

    def header_prop(self, children: list[Token]) -> ast.HeaderPropNode:
        key, value = children
        text = str(value).strip()
        return ast.HeaderPropNode(str(key).upper(), text, _span(loc(key), loc(value)))

    def flag(self, children: list[Token]) -> ast.FlagNode:
        return ast.FlagNode(str(children[0]).upper(), loc(children[0]))

    def attributes(self, children: list[tuple[str, str, ast.Loc]]) -> ast.AttributesNode:
        values = {name: value for name, value, _ in children}
        first = children[0][2] if children else ast.Loc(1, 1, 1, 1)
        return ast.AttributesNode(values, first)

    def attribute(self, children: list[Token]) -> tuple[str, str, ast.Loc]:
        name, value = children
        return str(name), unquote_chars(str(value)), loc(name)

    # ---- declarations -----------------------------------------------------------------------

    def var_section(self, children: list[Any]) -> ast.VarSectionNode:
        keyword: Token = children[0]
        decls = [child for child in children[1:-1] if isinstance(child, ast.VarDeclNode)]
        kind = " ".join(str(keyword).upper().split())  # "VAR  CONSTANT" -> "VAR CONSTANT"
        return ast.VarSectionNode(kind, decls, loc(keyword))

    def var_decl(self, children: list[Any]) -> ast.VarDeclNode:
        name: Token = children[0]
        attributes: dict[str, str] = {}
        type_node: ast.TypeNode | None = None
        init: list[ast.InitValue] | None = None
        for child in children[1:]:
            if isinstance(child, ast.AttributesNode):
                attributes = child.values
            elif isinstance(child, _Init):
                init = list(child)
            else:
                type_node = child
        assert type_node is not None
        text = str(name)[1:-1] if name.type == "QSYM" else str(name)
        return ast.VarDeclNode(text, type_node, init, attributes, loc(name))

    def init(self, children: list[_Init]) -> _Init:
        return children[0]

    def init_list(self, children: list[ast.InitValue]) -> _Init:
        return _Init(children)

    def repeat(self, children: list[Any]) -> ast.RepeatNode:
        count: Token = children[0]
        return ast.RepeatNode(int(str(count)), list(children[1]), loc(count))

    def value(self, children: list[Token]) -> ast.ValueNode:
        token = children[0]
        return ast.ValueNode(token.type, str(token), loc(token))

    def named_type(self, children: list[Token]) -> ast.NamedTypeNode:
        name = children[0]
        length = int(str(children[1])) if len(children) > 1 else None
        return ast.NamedTypeNode(str(name).upper(), length, loc(name))

    def array_type(self, children: list[Any]) -> ast.ArrayTypeNode:
        keyword: Token = children[0]
        dims = [child for child in children if isinstance(child, tuple)]
        return ast.ArrayTypeNode(dims, children[-1], loc(keyword))

    def type_spec(self, children: list[Any]) -> Any:
        return children[0]  # the STRUCT alternative (the others have aliases)

    def dim(self, children: list[Token]) -> tuple[int, int]:
        return _bound(str(children[0])), _bound(str(children[1]))

    def struct_type(self, children: list[Any]) -> ast.StructTypeNode:
        members = [child for child in children if isinstance(child, ast.VarDeclNode)]
        return ast.StructTypeNode(members, loc(children[0]))

    def ref_type(self, children: list[Token]) -> ast.RefTypeNode:
        token = children[0]
        quoted = token.type == "QSYM"
        return ast.RefTypeNode(str(token)[1:-1] if quoted else str(token), quoted, loc(token))

    # ---- data blocks ------------------------------------------------------------------------

    def db_body(self, children: list[Any]) -> _DbBody:
        first = children[0]
        if isinstance(first, Token) and first.type == "IDENT":
            return _DbBody(self.named_type([first]))  # TON: a system FB by its name
        if isinstance(first, Token):
            return _DbBody(self.ref_type([first]))
        return _DbBody(first)

    def db_assign(self, children: list[Any]) -> ast.DbAssignNode:
        path, first_loc = children[0]
        return ast.DbAssignNode(path, list(children[1]), first_loc)

    def lvalue(self, children: list[Any]) -> tuple[list[str | list[int]], ast.Loc]:
        path: list[str | list[int]] = []
        for child in children:
            if isinstance(child, _Index):
                path.append(list(child))
            else:
                path.append(str(child)[1:-1] if child.type == "QSYM" else str(child))
        return path, loc(children[0])

    def index(self, children: list[Token]) -> _Index:
        return _Index(int(str(child)) for child in children)

    # ---- code -------------------------------------------------------------------------------

    def label(self, children: list[Token]) -> ast.LabelNode:
        token = children[0]
        return ast.LabelNode(str(token).rstrip(" \t:"), loc(token))

    def network(self, children: list[Token]) -> ast.NetworkNode:
        return ast.NetworkNode(loc(children[0]))

    def bad(self, children: list[Token]) -> ast.BadNode:
        return ast.BadNode(loc(children[0]))

    def instr(self, children: list[Any]) -> ast.InstrNode:
        mnemonic: Token = children[0]
        args: list[ast.CallArgNode] | None = None
        if len(children) > 1 and isinstance(children[-1], _CallArgs):
            args = list(children.pop())
        if len(children) > 1 and isinstance(children[-1], ast.AttributesNode):
            attributes = children.pop().values
            node = ast.InstrNode(str(mnemonic), children[1:], args, loc(mnemonic))
            node.attributes = attributes
            return node
        return ast.InstrNode(str(mnemonic), children[1:], args, loc(mnemonic))

    def param_line(self, children: list[Any]) -> ast.InstrNode:
        name: Token = children[0]
        operands = [children[1]] if len(children) > 1 else []
        return ast.InstrNode(str(name), operands, None, loc(name), param_line=True)

    def call_args(self, children: list[ast.CallArgNode]) -> _CallArgs:
        return _CallArgs(children)

    def call_arg(self, children: list[Any]) -> ast.CallArgNode:
        name: Token = children[0]
        value = children[1] if len(children) > 1 else None
        text = str(name)[1:-1] if name.type == "QSYM" else str(name)
        return ast.CallArgNode(text, value, loc(name))

    # ---- operands ---------------------------------------------------------------------------

    def address(self, children: list[Token]) -> ast.AddressNode:
        return ast.AddressNode(str(children[0]), loc(children[0]))

    def indirect(self, children: list[Any]) -> ast.IndirectNode:
        area: Token = children[0]
        second = children[2] if len(children) > 2 else None
        return ast.IndirectNode(str(area).upper(), children[1], second, loc(area))

    def crossing(self, children: list[Any]) -> ast.IndirectNode:
        first = children[0]
        return ast.IndirectNode(None, first, children[1], first.loc)

    def _symbolic(self, children: list[Any], local: bool) -> ast.SymbolNode:
        head: Token = children[0]
        path: list[str | list[int] | ast.AddressNode] = []
        for child in children[1:]:
            if isinstance(child, _Index):
                path.append(list(child))
            elif child.type == "ADDR":
                path.append(ast.AddressNode(str(child), loc(child)))
            elif child.type == "QSYM":
                path.append(str(child)[1:-1])
            else:
                path.append(str(child))
        name = str(head)[1:-1] if not local else str(head)[1:].strip('"')
        return ast.SymbolNode(name, local, path, loc(head))

    def symbol(self, children: list[Any]) -> ast.SymbolNode:
        return self._symbolic(children, local=False)

    def local(self, children: list[Any]) -> ast.SymbolNode:
        return self._symbolic(children, local=True)

    def db_member(self, children: list[Any]) -> ast.SymbolNode:
        node = self._symbolic(children, local=False)
        node.name = str(children[0])
        node.absolute_db = True
        return node

    def bare(self, children: list[Token]) -> ast.BareNode:
        arg = str(children[1]) if len(children) > 1 else None
        return ast.BareNode(str(children[0]), arg, loc(children[0]))

    def constant(self, children: list[Token]) -> ast.LiteralNode:
        token = children[0]
        return ast.LiteralNode(token.type, str(token), loc(token))

    def status(self, children: list[Token]) -> ast.StatusNode:
        return ast.StatusNode(str(children[0]), loc(children[0]))


class _DbBody:
    __slots__ = ("type",)

    def __init__(self, type_node: ast.TypeNode) -> None:
        self.type = type_node


def unquote_chars(text: str) -> str:
    """The characters of a ``'...'`` literal, with STEP 7's ``$`` escapes resolved."""
    body = text[1:-1]
    if "$" not in body:
        return body
    escapes = {"$": "$", "'": "'", "L": "\n", "N": "\n", "P": "\f", "R": "\r", "T": "\t"}
    out: list[str] = []
    i = 0
    while i < len(body):
        char = body[i]
        if char == "$" and i + 1 < len(body):
            nxt = body[i + 1]
            if nxt.upper() in escapes:
                out.append(escapes[nxt.upper()])
                i += 2
                continue
            hexa = body[i + 1 : i + 3]
            if len(hexa) == 2 and all(c in "0123456789abcdefABCDEF" for c in hexa):
                out.append(chr(int(hexa, 16)))
                i += 3
                continue
        out.append(char)
        i += 1
    return "".join(out)


def _bound(text: str) -> int:
    """An array bound; one of more than 12 digits (past any S7 array, and Python converts at
    most 4,300) stands as 10**12, which the bound checks refuse as they refuse any too big."""
    if len(text.lstrip("+-0")) <= 12:
        return int(text)
    return -(10**12) if text.startswith("-") else 10**12

"""AST → SCL text in one canonical layout (STEP 7 Classic keywords, two-space indentation).

Parsing the output gives an AST equal to the input's (``loc`` aside): parentheses are kept as
``Paren`` nodes, so binary operators print without adding any. Used by the round-trip tests;
later by "format document" and by the "show generated STL" view's source column.
"""

from __future__ import annotations

import re

from nasaq.lang.scl import ast

_INDENT = "  "
_PLAIN_NAME = re.compile(r"[A-Za-z_]\w*")  # a parameter name written without quotes


def expr(node: ast.Expr | ast.InitItem) -> str:
    if isinstance(node, ast.Literal):
        return node.text
    if isinstance(node, ast.Name):
        return node.name
    if isinstance(node, ast.Local):
        return "#" + (node.name if _PLAIN_NAME.fullmatch(node.name) else f'"{node.name}"')
    if isinstance(node, ast.Symbol):
        return f'"{node.name}"'
    if isinstance(node, ast.Address):
        return node.text
    if isinstance(node, ast.IndexedAddress):
        return f"{node.area}[{', '.join(expr(item) for item in node.indices)}]"
    if isinstance(node, ast.Member):
        return f"{expr(node.base)}.{expr(node.name)}"
    if isinstance(node, ast.Slice):
        return f"{expr(node.base)}.%{node.width}{node.index}"
    if isinstance(node, ast.Index):
        return f"{expr(node.base)}[{', '.join(expr(item) for item in node.indices)}]"
    if isinstance(node, ast.Call):
        return f"{expr(node.callee)}({', '.join(_arg(arg) for arg in node.args)})"
    if isinstance(node, ast.Unary):
        space = " " if node.op == "NOT" else ""
        return f"{node.op}{space}{expr(node.operand)}"
    if isinstance(node, ast.Binary):
        return f"{expr(node.left)} {node.op} {expr(node.right)}"
    if isinstance(node, ast.Paren):
        return f"({expr(node.inner)})"
    if isinstance(node, ast.InitRepeat):
        return f"{node.count}({', '.join(expr(item) for item in node.values)})"
    if isinstance(node, ast.InitStruct):
        return f"({', '.join(expr(item) for item in node.values)})"
    return f"[{', '.join(expr(item) for item in node.values)}]"


def _arg(arg: ast.Arg) -> str:
    if arg.name is None:
        return expr(arg.value)
    name = arg.name if _PLAIN_NAME.fullmatch(arg.name) else f'"{arg.name}"'
    return f"{name} {'=>' if arg.output else ':='} {expr(arg.value)}"


def _attributes(attributes: list[ast.Attribute]) -> str:
    inner = "; ".join(f"{item.name} := '{item.value}'" for item in attributes)
    return "{" + inner + "}"


def type_text(node: ast.TypeNode, depth: int) -> str:
    if isinstance(node, ast.NamedType):
        if node.quoted:
            return f'"{node.name}"'
        return node.name + (f"[{expr(node.length)}]" if node.length is not None else "")
    if isinstance(node, ast.ArrayType):
        dims = ", ".join(
            "*" if dim.low is None or dim.high is None else f"{expr(dim.low)}..{expr(dim.high)}"
            for dim in node.dims
        )
        return f"ARRAY[{dims}] OF {type_text(node.element, depth)}"
    lines = ["STRUCT"]
    lines += [_decl(member, depth + 1) for member in node.members]
    lines.append(_INDENT * depth + "END_STRUCT")
    return "\n".join(lines)


def _decl(decl: ast.VarDecl | ast.Bad, depth: int) -> str:
    pad = _INDENT * depth
    if isinstance(decl, ast.Bad):
        return pad + "// (syntax error)"
    names = ", ".join(
        (f'"{name.name}"' if name.quoted else name.name)
        + (" " + _attributes(name.attributes) if name.attributes else "")
        for name in decl.names
    )
    at = f" AT {decl.at}" if decl.at else ""
    init = ""
    if decl.init is not None:
        init = " := " + ", ".join(expr(item) for item in decl.init)
    return f"{pad}{names}{at} : {type_text(decl.type, depth)}{init};"


def _section(section: ast.Section) -> list[str]:
    if isinstance(section, ast.VarSection):
        head = section.kind + (f" {section.modifier}" if section.modifier else "")
        return [head, *(_decl(decl, 1) for decl in section.decls), "END_VAR"]
    if isinstance(section, ast.ConstSection):
        body = [
            f"{_INDENT}{decl.name} := {expr(decl.value)};"
            for decl in section.decls
            if isinstance(decl, ast.ConstDecl)
        ]
        return ["CONST", *body, "END_CONST"]
    return ["LABEL", f"{_INDENT}{', '.join(section.names)};", "END_LABEL"]


def statements(body: list[ast.Stmt], depth: int) -> list[str]:
    lines: list[str] = []
    for node in body:
        lines += _statement(node, depth)
    return lines


def _statement(node: ast.Stmt, depth: int) -> list[str]:
    pad = _INDENT * depth
    if isinstance(node, ast.Assign):
        if node.op is not None and isinstance(node.value, ast.Binary):  # a += b
            return [f"{pad}{expr(node.target)} {node.op}= {expr(node.value.right)};"]
        targets = "".join(f"{expr(target)} := " for target in [node.target, *node.chain])
        return [f"{pad}{targets}{expr(node.value)};"]
    if isinstance(node, ast.CallStmt):
        return [f"{pad}{expr(node.call)};"]
    if isinstance(node, ast.If):
        lines: list[str] = []
        for number, branch in enumerate(node.branches):
            keyword = "IF" if number == 0 else "ELSIF"
            lines.append(f"{pad}{keyword} {expr(branch.condition)} THEN")
            lines += statements(branch.body, depth + 1)
        if node.orelse is not None:
            lines.append(f"{pad}ELSE")
            lines += statements(node.orelse, depth + 1)
        return [*lines, f"{pad}END_IF;"]
    if isinstance(node, ast.Case):
        lines = [f"{pad}CASE {expr(node.selector)} OF"]
        for case_branch in node.branches:
            values = ", ".join(
                expr(value.low) + (f"..{expr(value.high)}" if value.high is not None else "")
                for value in case_branch.values
            )
            lines.append(f"{pad}{_INDENT}{values}:")
            lines += statements(case_branch.body, depth + 2)
        if node.orelse is not None:
            lines.append(f"{pad}ELSE")
            lines += statements(node.orelse, depth + 2)
        return [*lines, f"{pad}END_CASE;"]
    if isinstance(node, ast.For):
        step = f" BY {expr(node.step)}" if node.step is not None else ""
        head = f"{pad}FOR {expr(node.variable)} := {expr(node.start)} TO {expr(node.end)}"
        return [
            f"{head}{step} DO",
            *statements(node.body, depth + 1),
            f"{pad}END_FOR;",
        ]
    if isinstance(node, ast.While):
        return [
            f"{pad}WHILE {expr(node.condition)} DO",
            *statements(node.body, depth + 1),
            f"{pad}END_WHILE;",
        ]
    if isinstance(node, ast.Repeat):
        return [
            f"{pad}REPEAT",
            *statements(node.body, depth + 1),
            f"{pad}UNTIL {expr(node.condition)}",
            f"{pad}END_REPEAT;",
        ]
    if isinstance(node, ast.Region):
        return [
            f"{pad}REGION {node.title}".rstrip(),
            *statements(node.body, depth + 1),
            f"{pad}END_REGION",
        ]
    if isinstance(node, ast.Goto):
        return [f"{pad}GOTO {node.label};"]
    if isinstance(node, ast.Label):
        return [f"{pad}{node.name}:"]
    if isinstance(node, ast.Bad):
        return [f"{pad}// (syntax error)"]
    simple = {ast.Exit: "EXIT;", ast.Continue: "CONTINUE;", ast.Return: "RETURN;", ast.Empty: ";"}
    return [pad + simple[type(node)]]


def _block_name(name: ast.BlockName) -> str:
    return f'"{name.text}"' if name.quoted else name.text


def block(node: ast.Block) -> str:
    head = f"{node.kind} {_block_name(node.name)}"
    if node.return_type is not None:
        head += f" : {type_text(node.return_type, 0)}"
    lines = [head]
    if node.attributes:
        lines.append(_attributes(node.attributes))
    if node.title is not None:
        lines.append(f"TITLE = '{node.title}'")
    lines += [f"{key} : {value}" for key, value in node.props.items()]
    lines += node.flags
    for section in node.sections:
        lines += _section(section)
    for item in node.sources:
        if isinstance(item, ast.StructType):
            lines.append(type_text(item, 0))
        else:
            lines.append(_block_name(item))
    if node.begin:
        lines.append("BEGIN")
    lines += statements(node.code, 1)
    lines.append("END_" + node.kind)
    return "\n".join(lines) + "\n"


def source(node: ast.SourceFile) -> str:
    parts = [_attributes(node.pragmas) + "\n"] if node.pragmas else []
    parts += [block(item) for item in node.blocks]
    return "\n".join(parts)

"""SCL blocks as STL blocks: the header, the interface (with the hidden temporaries last, so the
user's VAR_TEMP keeps the offsets the SCL binder gave it), the code, DB and UDT structures and
the DB's assignment section.

Every code block ends with S7-SCL's epilogue: the block's ENO is the BR bit at its end, its OK
flag. OK is FALSE after an arithmetic error (the OS bit, which a division by zero or an overflow
sets) or when the block sets it (``OK := FALSE``, ``ENO := FALSE``): then it is a hidden BOOL
temporary set TRUE at the start, and ``OK := ...`` clears OS. Read after a call, ``ENO`` is the
called block's ENO (BR), as S7-SCL's manual shows (``FC1(...); IF ENO THEN``).
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.lower.emitter import Emitter
from nasaq.lang.scl.lower.literals import evaluate, stl_constant
from nasaq.lang.scl.lower.places import LoweringError
from nasaq.lang.scl.lower.statements import Statements
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.stl import ast as stl
from nasaq.lang.stl.diag import problem
from nasaq.lang.types import ArrayType, BlockType, DataType, Elementary, StringType, StructType

KEYWORD = {
    BlockKind.OB: "ORGANIZATION_BLOCK",
    BlockKind.FB: "FUNCTION_BLOCK",
    BlockKind.FC: "FUNCTION",
    BlockKind.DB: "DATA_BLOCK",
    BlockKind.UDT: "TYPE",
}
SECTION_KEYWORD = {
    "IN": "VAR_INPUT",
    "OUT": "VAR_OUTPUT",
    "IN_OUT": "VAR_IN_OUT",
    "STAT": "VAR",
    "TEMP": "VAR_TEMP",
}


def lower_block(
    index: SclIndex, block: SclBlock, ctx: Context | None = None
) -> tuple[stl.BlockNode | None, list[Diagnostic]]:
    """The STL form of ``block``; None (with an SCL301 diagnostic) when part of its code is
    beyond the code generator."""
    node = block.node
    ident = f"{block.kind.value} {block.number}"
    result = stl.BlockNode(KEYWORD[block.kind], ident, False, node.loc, node.end)
    result.head = _header(node)
    if block.kind is BlockKind.FC:
        result.return_type = (
            _type_node(block.return_type, node.loc)
            if block.return_type is not None
            else stl.NamedTypeNode("VOID", None, node.loc)
        )
    if block.kind in (BlockKind.DB, BlockKind.UDT):
        try:
            return _data_block(index, block, result), []
        except LoweringError as error:
            where = f"{block.kind.value} {block.number}"
            return None, [problem("SCL301", block.file, error.loc, what=error.what, block=where)]
    try:
        sections = [
            stl.VarSectionNode(
                SECTION_KEYWORD[name],
                [_declaration(index, block, part, node.loc) for part in group],
                node.loc,
            )
            for name, group in block.sections
        ]
        start_info = _start_information(block, sections)
    except LoweringError as error:  # an initial value beyond the code generator
        where = f"{block.kind.value} {block.number}"
        return None, [problem("SCL301", block.file, error.loc, what=error.what, block=where)]
    taken = set(block.variables) | set(block.constants)
    emitter = Emitter(taken)
    lowerer = Statements(index, block, emitter, ctx)
    try:
        _code(lowerer, block)
    except LoweringError as error:
        found = problem(
            "SCL301",
            block.file,
            error.loc,
            what=error.what,
            block=f"{block.kind.value} {block.number}",
        )
        # The block keeps its interface (so that its callers compile) and gets no code.
        result.head += sections
        return result, [*lowerer.diagnostics, found]
    if emitter.temps:
        hidden = [
            stl.VarDeclNode(temp.name, _type_node(temp.type, node.loc), None, {}, node.loc)
            for temp in emitter.temps
        ]
        temps = [section for section in sections if section.kind == "VAR_TEMP"]
        if temps:
            temps[-1].decls += hidden  # after the user's temporaries: their offsets stay
        else:
            sections.append(stl.VarSectionNode("VAR_TEMP", hidden, node.loc))
    if start_info is not None:
        sections.append(start_info)
    result.head += sections
    result.code = emitter.finish()
    return result, lowerer.diagnostics


def _start_information(
    block: SclBlock, sections: list[stl.VarSectionNode]
) -> stl.VarSectionNode | None:
    """An OB's VAR_INPUT (TIA's start information of an optimized OB, ``lang.ob_start_info``)
    taken out of ``sections`` as temporaries after all others, behind 4 bytes the CPU writes
    at the start of every OB (event class, priority, number): Nasaq has no hardware events, so
    they start at 0/FALSE."""
    if block.kind is not BlockKind.OB:
        return None
    inputs = [section for section in sections if section.kind == "VAR_INPUT"]
    if not inputs:
        return None
    for section in inputs:
        sections.remove(section)
    where = block.node.loc
    pad = ArrayType(((0, 3),), Elementary("BYTE"))
    taken = {name.casefold() for name in block.variables}
    name = next(f"_os{k}" for k in range(len(taken) + 1) if f"_os{k}" not in taken)
    decls = [stl.VarDeclNode(name, _type_node(pad, where), None, {}, where)]
    return stl.VarSectionNode("VAR_TEMP", decls + [d for s in inputs for d in s.decls], where)


def _code(lowerer: Statements, block: SclBlock) -> None:
    em = lowerer.em
    node = block.node
    em.loc = node.loc
    lowerer.end_label = em.new_label()
    lowerer.statements(node.code)
    lowerer.text_prologue()  # STRING temporaries get their maximum length first
    if lowerer.ok is not None:  # the code names OK or ENO: OK := TRUE first
        em.loc = node.loc
        start = [stl.InstrNode("SET", [], None, node.loc)]
        start.append(stl.InstrNode("=", [em.ref(lowerer.ok)], None, node.loc))
        em.code[0:0] = start
    em.loc = node.end
    em.place(lowerer.end_label)
    if lowerer.ok is not None:
        em.op("CLR")
        em.op("A", em.ref(lowerer.ok))
        em.op("AN", stl.BareNode("OS", None, em.loc))
    else:
        em.op("CLR")
        em.op("AN", stl.BareNode("OS", None, em.loc))  # ENO: no arithmetic error (OK)
    em.op("SAVE")
    em.op("BE")


def _header(node: ast.Block) -> list[stl.HeadItem]:
    head: list[stl.HeadItem] = []
    if node.title is not None:
        head.append(stl.TitleNode(node.title, node.loc))
    for key, value in node.props.items():
        head.append(stl.HeaderPropNode(key, value, node.loc))
    for flag in node.flags:
        if flag.upper() in ("KNOW_HOW_PROTECT", "READ_ONLY", "NON_RETAIN", "UNLINKED"):
            head.append(stl.FlagNode(flag.upper(), node.loc))
    if node.attributes:
        values = {attribute.name: attribute.value for attribute in node.attributes}
        head.append(stl.AttributesNode(values, node.loc))
    return head


def _type_node(data_type: DataType, loc: ast.Loc) -> stl.TypeNode:
    if isinstance(data_type, Elementary):
        return stl.NamedTypeNode(data_type.name, None, loc)
    if isinstance(data_type, StringType):
        return stl.NamedTypeNode(data_type.name, data_type.length, loc)
    if isinstance(data_type, ArrayType):
        return stl.ArrayTypeNode(list(data_type.dims), _type_node(data_type.element, loc), loc)
    if isinstance(data_type, StructType):
        members = [
            stl.VarDeclNode(part.name, _type_node(part.type, loc), None, {}, loc)
            for part in data_type.fields
        ]
        return stl.StructTypeNode(members, loc)
    return stl.RefTypeNode(f"{data_type.kind} {data_type.number}", False, loc)


def _declaration(index: SclIndex, block: SclBlock, part: object, loc: ast.Loc) -> stl.VarDeclNode:
    from nasaq.lang.types import Field

    assert isinstance(part, Field)
    type_node = _type_node(part.type, loc)
    _with_initials(index, block, type_node, part.type)
    initial = part.initial if isinstance(part.initial, list) else None
    values = _init_values(index, block, initial, part.type) if initial else None
    return stl.VarDeclNode(part.name, type_node, values, {}, loc)


def _with_initials(
    index: SclIndex, block: SclBlock, node: stl.TypeNode, data_type: DataType
) -> None:
    """STRUCT members keep their declared initial values."""
    if isinstance(node, stl.StructTypeNode) and isinstance(data_type, StructType):
        for member, part in zip(node.members, data_type.fields, strict=True):
            _with_initials(index, block, member.type, part.type)
            if isinstance(part.initial, list) and part.initial:
                member.init = _init_values(index, block, part.initial, part.type)
    elif isinstance(node, stl.ArrayTypeNode) and isinstance(data_type, ArrayType):
        _with_initials(index, block, node.element, data_type.element)


def _init_values(
    index: SclIndex, block: SclBlock, items: list[ast.InitItem], data_type: DataType
) -> list[stl.InitValue]:
    element = data_type.element if isinstance(data_type, ArrayType) else data_type
    want = _scalar_name(element)
    found: list[stl.InitValue] = []
    for item in items:
        if isinstance(item, ast.InitRepeat):
            count = int(item.count.replace("_", ""))
            inner = _init_values(index, block, item.values, data_type)
            found.append(stl.RepeatNode(count, inner, item.loc))
        elif isinstance(item, ast.InitList):
            found += _init_values(index, block, item.values, data_type)
        elif isinstance(item, ast.InitStruct):  # TIA's (v1, (), v3): STL has no such value
            raise LoweringError(item.loc, "a structured initial value")
        else:
            value = evaluate(item, index, block)
            if value is None:
                raise LoweringError(item.loc, "this initial value")
            kind, text = stl_constant(value, want)
            found.append(stl.ValueNode(kind, text, item.loc))
    return found


def _scalar_name(data_type: DataType) -> str:
    if isinstance(data_type, Elementary):
        return data_type.name
    if isinstance(data_type, StringType):
        return data_type.name
    return ""


def _data_block(index: SclIndex, block: SclBlock, result: stl.BlockNode) -> stl.BlockNode:
    made_of = block.db_type
    loc = block.node.loc
    if isinstance(made_of, BlockType):
        result.db_body = stl.RefTypeNode(f"{made_of.kind} {made_of.number}", False, loc)
    elif isinstance(made_of, StructType):
        body = _type_node(made_of, loc)
        _with_initials(index, block, body, made_of)
        result.db_body = body
    if block.kind is BlockKind.DB:
        for stmt in block.node.code:
            if isinstance(stmt, ast.Assign):
                path = _db_path(stmt.target)
                value = evaluate(stmt.value, index, block)
                if path is None or value is None:
                    continue
                target_type = _path_type(index, block, path)
                kind, text = stl_constant(value, _scalar_name(target_type) if target_type else "")
                result.db_values.append(
                    stl.DbAssignNode(path, [stl.ValueNode(kind, text, stmt.value.loc)], stmt.loc)
                )
    return result


def _db_path(node: ast.Expr) -> list[str | list[int]] | None:
    if isinstance(node, ast.Name | ast.Local):
        return [node.name]
    if isinstance(node, ast.Member) and isinstance(node.name, ast.Name | ast.Symbol):
        base = _db_path(node.base)
        return None if base is None else [*base, node.name.name]
    if isinstance(node, ast.Index | ast.IndexedAddress):
        base = _db_path(node.base) if isinstance(node, ast.Index) else [node.area]
        numbers = []
        for item in node.indices:
            value = evaluate(item, None, None)
            if value is None or value.kind != "int":
                return None
            numbers.append(int(value.number))
        return None if base is None else [*base, numbers]
    return None


def _path_type(index: SclIndex, block: SclBlock, path: list[str | list[int]]) -> DataType | None:
    slots, _size = index.db_layout(block)
    current = None
    members = slots
    for part in path:
        if isinstance(part, str):
            current = next((s for s in members if s.name.upper() == part.upper()), None)
        elif current is not None:
            current = index.layout.element(current, part)
        if current is None:
            return None
        members = current.members
    return current.type if current is not None else None

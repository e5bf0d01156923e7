"""Source-level nodes of an STL file, each with its position, as the parser builds them.

Nothing here is resolved: addresses keep their text, symbols their names, mnemonics their
spelling (either mnemonic set). Resolution and checks happen in ``resolve``/``check``/``lower``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple


class Loc(NamedTuple):
    """1-based line and column of the first character, and where the node ends (a named tuple:
    every node and token gets one, and a tuple is made faster than a frozen dataclass)."""

    line: int
    column: int
    end_line: int
    end_column: int


# ---- operands -------------------------------------------------------------------------------


@dataclass(slots=True)
class AddressNode:
    """``MW 10``, ``I 0.0``, ``DB5.DBX 2.1``, ``T 3``, ``FB 10`` (kept as text: see addresses)."""

    text: str
    loc: Loc


@dataclass(slots=True)
class IndirectNode:
    """``I [MD 2]`` / ``DBW [AR1, P#0.0]`` (``area`` given) or ``[AR1, P#0.0]`` (area-crossing
    bit access, ``area`` None)."""

    area: str | None
    first: OperandNode
    second: OperandNode | None
    loc: Loc


@dataclass(slots=True)
class SymbolNode:
    """``"Motor"``, ``"DB".member[2].x`` (``local`` False) or ``#var.member`` (``local`` True).

    ``path`` holds member names (str) and index lists (list[int]) in source order; a member
    written as an absolute DB address (``"DB".DBW 2``) is kept as an ``AddressNode``."""

    name: str
    local: bool
    path: list[str | list[int] | AddressNode]
    loc: Loc
    absolute_db: bool = False  # ``DB5.member``: ``name`` is the DB address, not a symbol


@dataclass(slots=True)
class BareNode:
    """An unquoted word, optionally followed by one more word or number: registers (``STW``,
    ``AR2``), status bits (``OV``, ``BR``), ``TRUE``, test operands (``__ACCU 1``, ``__STW OV``),
    or an unquoted symbol."""

    name: str
    arg: str | None
    loc: Loc


@dataclass(slots=True)
class LiteralNode:
    """A constant as written; ``kind`` is the token kind (NUMBER, REAL, TYPED, BYTES, POINTER,
    CHARS)."""

    kind: str
    text: str
    loc: Loc


@dataclass(slots=True)
class StatusNode:
    """``==0``, ``<>0``, ``>0``, ``<0``, ``>=0``, ``<=0`` operands."""

    text: str
    loc: Loc


OperandNode = AddressNode | IndirectNode | SymbolNode | BareNode | LiteralNode | StatusNode


# ---- code -----------------------------------------------------------------------------------


@dataclass(slots=True)
class CallArgNode:
    name: str
    value: OperandNode | None
    loc: Loc


@dataclass(slots=True)
class InstrNode:
    """One statement: a mnemonic with operands; ``args`` for ``CALL ... ( ... )``.

    ``param_line`` marks the editor-style parameter line ``NAME := operand`` that follows a
    ``CALL`` without parentheses (how STEP 7 displays calls); ``mnemonic`` is then the name."""

    mnemonic: str
    operands: list[OperandNode]
    args: list[CallArgNode] | None
    loc: Loc
    param_line: bool = False
    attributes: dict[str, str] | None = None  # TIA: CALL #t {time_type := 'Time'} ( ... )


@dataclass(slots=True)
class LabelNode:
    name: str
    loc: Loc


@dataclass(slots=True)
class NetworkNode:
    loc: Loc


@dataclass(slots=True)
class TitleNode:
    text: str
    loc: Loc


@dataclass(slots=True)
class BadNode:
    """Where the parser skipped input after a syntax error (already reported)."""

    loc: Loc


CodeItem = InstrNode | LabelNode | NetworkNode | TitleNode | BadNode


# ---- declarations ---------------------------------------------------------------------------


@dataclass(slots=True)
class NamedTypeNode:
    """``INT``, ``STRING[20]`` (``length``), ``TIMER``, ``ANY`` ..."""

    name: str
    length: int | None
    loc: Loc


@dataclass(slots=True)
class ArrayTypeNode:
    dims: list[tuple[int, int]]
    element: TypeNode
    loc: Loc


@dataclass(slots=True)
class StructTypeNode:
    members: list[VarDeclNode]
    loc: Loc


@dataclass(slots=True)
class RefTypeNode:
    """``UDT 5``, ``FB 2``, ``SFB 4`` (``quoted`` False) or ``"MyUdt"`` (``quoted`` True)."""

    text: str
    quoted: bool
    loc: Loc


TypeNode = NamedTypeNode | ArrayTypeNode | StructTypeNode | RefTypeNode


@dataclass(slots=True)
class RepeatNode:
    """``3 (0)``: a repeated initial value of an array."""

    count: int
    values: list[InitValue]
    loc: Loc


@dataclass(slots=True)
class ValueNode:
    """An initial or actual value: ``kind`` is the token kind (NUMBER, TYPED, CHARS, IDENT ...)."""

    kind: str
    text: str
    loc: Loc


InitValue = ValueNode | RepeatNode


@dataclass(slots=True)
class VarDeclNode:
    name: str
    type: TypeNode
    init: list[InitValue] | None
    attributes: dict[str, str]
    loc: Loc
    comment: str = ""


@dataclass(slots=True)
class VarSectionNode:
    kind: str  # VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR, VAR_TEMP (upper case)
    decls: list[VarDeclNode]
    loc: Loc


@dataclass(slots=True)
class HeaderPropNode:
    key: str  # AUTHOR, FAMILY, NAME, VERSION
    value: str
    loc: Loc


@dataclass(slots=True)
class FlagNode:
    name: str  # KNOW_HOW_PROTECT, READ_ONLY, NON_RETAIN, UNLINKED
    loc: Loc


@dataclass(slots=True)
class AttributesNode:
    values: dict[str, str]
    loc: Loc


HeadItem = TitleNode | HeaderPropNode | FlagNode | AttributesNode | VarSectionNode | BadNode


@dataclass(slots=True)
class DbAssignNode:
    """``name[2].x := value;`` in the BEGIN section of a DB (path as in ``SymbolNode``)."""

    path: list[str | list[int]]
    values: list[InitValue]
    loc: Loc


@dataclass(slots=True)
class BlockNode:
    """One block of a source: ``keyword`` is ORGANIZATION_BLOCK, FUNCTION_BLOCK, FUNCTION,
    DATA_BLOCK or TYPE; ``ident`` the block id as written (``OB 1``, ``"Main"``)."""

    keyword: str
    ident: str
    ident_quoted: bool
    loc: Loc
    end: Loc
    return_type: TypeNode | None = None
    head: list[HeadItem] = field(default_factory=list)
    code: list[CodeItem] = field(default_factory=list)
    db_body: TypeNode | None = None  # STRUCT, or the FB/SFB/UDT a DB is an instance of
    db_values: list[DbAssignNode | BadNode] = field(default_factory=list)
    comment: str = ""


@dataclass(slots=True)
class SourceNode:
    """A parsed file: its blocks, and code written outside any block (an implicit OB 1, as
    awlsim programs do)."""

    file: str
    blocks: list[BlockNode]
    loose_code: list[CodeItem]

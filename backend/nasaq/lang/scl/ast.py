"""Source-level nodes of an S7-SCL file, each with its position, as the parser builds them.

Nothing is resolved here: names keep their spelling (SCL is case-insensitive; the binder folds
case), addresses and literals their text, types their names. Every node has ``loc`` (the
shared ``Loc`` of the STL front end: 1-based line/column of the first character and the end);
``loc`` takes no part in ``==``, so two parses of equivalent text compare equal (the round-trip
tests rely on it).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.lang.stl.ast import Loc

__all__ = ["Loc"]

_NOWHERE = Loc(1, 1, 1, 1)


# ---- expressions ----------------------------------------------------------------------------


@dataclass(slots=True)
class Literal:
    """A constant as written. ``kind``: INTEGER, REAL, TYPED (``INT#5``, ``16#FF``, ``T#2s``,
    ``D#1990-01-01`` ...), STRING (quotes kept), BOOL (``TRUE``/``FALSE``)."""

    kind: str
    text: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Name:
    """A plain name: a variable, constant, parameter, block, standard function or symbol
    written without quotes (``x``, ``FC1`` is an ``Address``, ``WORD_TO_INT``, ``ENO``)."""

    name: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Local:
    """TIA Portal's ``#name``: a block-local variable or parameter."""

    name: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Symbol:
    """A quoted global symbol ``"Motor"`` (quotes removed)."""

    name: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Address:
    """An absolute operand as written (``M0.0``, ``%MW10``, ``I 1.1``, ``DB10``, ``T14``) or,
    after a ``.``, a DB-relative one (``DW2``, ``dbx0.0``, ``D1.1``)."""

    text: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class IndexedAddress:
    """``MW[i]``, ``I[i, k]``, ``PIW[252 + i]``; after a DB ``DW[i]``, ``DX[w, b]``:
    the area/size prefix and the byte (and bit) expressions."""

    area: str
    indices: list[Expr]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Member:
    """``base.name``; ``name`` is a ``Name``, ``Symbol``, ``Address`` or ``IndexedAddress``."""

    base: Expr
    name: Name | Symbol | Address | IndexedAddress
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Index:
    """``base[i]``, ``base[i, j]`` (array access)."""

    base: Expr
    indices: list[Expr]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Arg:
    """One actual parameter: ``name := value`` (``output`` False), ``name => variable``
    (``output`` True) or positional (``name`` None)."""

    name: str | None
    value: Expr
    output: bool = False
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Call:
    """``FC1(...)``, ``FB1.DB1(...)``, ``#inst(...)``, ``"Block"(...)``, ``SQRT(x)``."""

    callee: Expr
    args: list[Arg]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Unary:
    """``NOT x``, ``-x``, ``+x`` (``op`` upper-cased)."""

    op: str
    operand: Expr
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Binary:
    """``op`` upper-cased: ``OR XOR AND & = <> < > <= >= + - * / MOD DIV **``."""

    op: str
    left: Expr
    right: Expr
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Paren:
    """A parenthesised expression (kept: the type checker reports on what was written)."""

    inner: Expr
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Slice:
    """TIA's slice access (S7-1200/1500): ``x.%X3`` (bit), ``w.%B1`` (byte), ``d.%W0`` (word),
    ``l.%D1`` (doubleword): the ``index``-th part of ``width`` counted from the least significant
    end of ``base``."""

    base: Expr
    width: str  # X, B, W or D
    index: int
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


Variable = Name | Local | Symbol | Address | IndexedAddress | Member | Index | Call | Slice
Expr = Literal | Variable | Unary | Binary | Paren


# ---- statements -----------------------------------------------------------------------------


@dataclass(slots=True)
class Assign:
    """``target := value``; TIA's multiple assignment ``a := b := c`` keeps ``b`` in ``chain``
    (the further targets, left to right): ``b := c`` runs first, then ``a := b``. TIA's
    ``a += b`` is ``a := a + b`` with ``op`` "+" (``value`` the Binary, its left the target)."""

    target: Expr
    value: Expr
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)
    chain: list[Expr] = field(default_factory=list)
    op: str | None = None

    def steps(self) -> list[Assign]:
        """The simple assignments a multiple assignment stands for, in the order they run."""
        if not self.chain:
            return [self]
        targets = [self.target, *self.chain]
        values = [*self.chain, self.value]
        return [
            Assign(target, value, loc=self.loc)
            for target, value in reversed(list(zip(targets, values, strict=True)))
        ]


@dataclass(slots=True)
class CallStmt:
    call: Call
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class IfBranch:
    condition: Expr
    body: list[Stmt]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class If:
    """``branches[0]`` is the IF, the others the ELSIFs; ``orelse`` None without ELSE."""

    branches: list[IfBranch]
    orelse: list[Stmt] | None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class CaseValue:
    """One case label: a value (``high`` None) or a range ``low..high``; a bound is a literal or
    a named constant (``K1``, TIA's ``#K1``, a global constant ``"K"``)."""

    low: Literal | Name | Local | Symbol
    high: Literal | Name | Local | Symbol | None = None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class CaseBranch:
    values: list[CaseValue]
    body: list[Stmt]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Case:
    selector: Expr
    branches: list[CaseBranch]
    orelse: list[Stmt] | None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class For:
    variable: Expr
    start: Expr
    end: Expr
    step: Expr | None
    body: list[Stmt]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class While:
    condition: Expr
    body: list[Stmt]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Repeat:
    body: list[Stmt]
    condition: Expr
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Exit:
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Continue:
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Return:
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Goto:
    label: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Label:
    """``name:`` before a statement (or alone, before ``;`` or the end of a list)."""

    name: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Empty:
    """A lone ``;``."""

    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Region:
    """TIA Portal's ``REGION title ... END_REGION`` (``title`` is the rest of the line)."""

    title: str
    body: list[Stmt]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Bad:
    """Where the parser skipped input after a syntax error (already reported)."""

    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


Stmt = (
    Assign
    | CallStmt
    | If
    | Case
    | For
    | While
    | Repeat
    | Exit
    | Continue
    | Return
    | Goto
    | Label
    | Empty
    | Region
    | Bad
)


# ---- types and declarations -----------------------------------------------------------------


@dataclass(slots=True)
class Attribute:
    """``name := 'value'`` inside ``{ }`` (``value`` without its quotes)."""

    name: str
    value: str
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class NamedType:
    """An elementary type, ``STRING[n]``, UDT, FB (multi-instance), ``TIMER``, ``ANY``,
    ``BLOCK_DB``, ``VOID`` ...: ``name`` as written (``quoted`` for ``"UDT"``), ``length`` the
    ``[n]`` of STRING."""

    name: str
    quoted: bool = False
    length: Expr | None = None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Dim:
    """``low..high`` of an ARRAY; both None for TIA's ``[*]``."""

    low: Expr | None
    high: Expr | None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class ArrayType:
    dims: list[Dim]
    element: TypeNode
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class StructType:
    members: list[VarDecl | Bad]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


TypeNode = NamedType | ArrayType | StructType


@dataclass(slots=True)
class InitRepeat:
    """``n(values)``: the values repeated ``count`` times (an ARRAY initialiser)."""

    count: str
    values: list[InitItem]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class InitList:
    """TIA's bracketed ``[v1, v2, ...]``."""

    values: list[InitItem]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class InitStruct:
    """TIA's ``(v1, (), v3)``: the initial values of a structure's members in order; ``()``
    leaves a member its own."""

    values: list[InitItem]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


InitItem = Expr | InitRepeat | InitList | InitStruct


@dataclass(slots=True)
class DeclName:
    name: str
    quoted: bool = False
    attributes: list[Attribute] = field(default_factory=list)
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class VarDecl:
    """``a, b {attr} : type := init;`` (``at`` is the variable of ``AT`` views)."""

    names: list[DeclName]
    type: TypeNode
    init: list[InitItem] | None = None
    at: str | None = None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class VarSection:
    """``kind`` is the keyword upper-cased (``VAR_INPUT``, ``VAR_TEMP``, ``VAR`` ...);
    ``modifier`` TIA's ``CONSTANT``/``RETAIN``/``NON_RETAIN``/``DB_SPECIFIC``."""

    kind: str
    decls: list[VarDecl | Bad]
    modifier: str | None = None
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class ConstDecl:
    name: str
    value: Expr
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class ConstSection:
    decls: list[ConstDecl | Bad]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class LabelSection:
    names: list[str]
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


Section = VarSection | ConstSection | LabelSection


# ---- blocks and files -----------------------------------------------------------------------


@dataclass(slots=True)
class BlockName:
    """``FB10`` / ``OB1`` (``absolute``), ``Motor`` or ``"Motor"`` (``quoted``)."""

    text: str
    quoted: bool = False
    absolute: bool = False
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class Block:
    """One block. ``kind``: ORGANIZATION_BLOCK, FUNCTION_BLOCK, FUNCTION, PROGRAM, DATA_BLOCK,
    TYPE. ``props`` holds AUTHOR/FAMILY/NAME/VERSION (upper-cased keys, values as written),
    ``flags`` KNOW_HOW_PROTECT, NON_RETAIN ... ; ``source`` is a DB's STRUCT or the FB/UDT it is
    made of, or a UDT's STRUCT (more than one is the binder's error to report); ``code`` the
    statements (for a DB: its value assignments)."""

    kind: str
    name: BlockName
    return_type: TypeNode | None = None
    title: str | None = None
    props: dict[str, str] = field(default_factory=dict)
    flags: list[str] = field(default_factory=list)
    attributes: list[Attribute] = field(default_factory=list)
    sections: list[Section] = field(default_factory=list)
    sources: list[StructType | BlockName] = field(default_factory=list)
    begin: bool = False
    code: list[Stmt] = field(default_factory=list)
    bad: list[Bad] = field(default_factory=list)  # header items skipped after errors
    loc: Loc = field(default=_NOWHERE, compare=False, repr=False)
    end: Loc = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(slots=True)
class SourceFile:
    """A parsed file: its blocks and the ``{ }`` pragmas outside blocks, in source order."""

    file: str
    blocks: list[Block]
    pragmas: list[Attribute] = field(default_factory=list)

"""The state of checking one block: where names are looked up, the types already computed
(each expression is typed, and reported on, once) and the diagnostics found."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.layout import SECTION_ORDER
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import UNKNOWN, Constant, SclBlock, SclIndex, Variable
from nasaq.lang.scl.format import expr as expr_text
from nasaq.lang.scl.typecheck.types import ERROR, DbRef, Type
from nasaq.lang.scl.typecheck.walk import Outline
from nasaq.lang.scl.typecheck.walk import outline as outline_of
from nasaq.lang.stl.diag import problem
from nasaq.lang.types import BlockType, DataType, Elementary, StructType

ExpressionRule = Callable[["Context", Any], Type]


class Context:
    def __init__(
        self,
        index: SclIndex,
        block: SclBlock,
        expressions: dict[type, ExpressionRule],
        outline: Outline | None = None,
    ) -> None:
        self.index = index
        self.block = block
        self.expressions = expressions
        self.diagnostics: list[Diagnostic] = []
        self._types: dict[int, Type] = {}
        self.reported: set[str] = set()  # mistakes reported once per block (undeclared names)
        self.written_actuals: set[int] = set()  # actual parameters of outputs and in/outs (ids)
        self._db_members: dict[str, Variable] | None = None
        self._variable_types: dict[str, Type] = {}
        self._members_of: dict[DbRef | BlockType, dict[str, DataType] | None] = {}
        self._outline = outline

    @property
    def outline(self) -> Outline:
        """The calls and operations of the block's code (``walk.outline``), found once."""
        if self._outline is None:
            self._outline = outline_of(self.block.node.code)
        return self._outline

    @property
    def file(self) -> str:
        return self.block.file

    @property
    def types(self) -> dict[int, Type]:
        """The types found so far by ``id`` of the expression (the code generator reads them)."""
        return self._types

    def report(self, code: str, loc: ast.Loc, **params: Any) -> Type:
        """Records a diagnostic; returns ``ERROR``, the type of what was wrong."""
        self.diagnostics.append(problem(code, self.file, loc, **params))
        return ERROR

    def type_of(self, node: ast.Expr) -> Type:
        """The type of an expression, computed (and its problems reported) once. While it is
        computed it reads as ``ERROR``: a CONST defined through itself is one."""
        key = id(node)
        types = self._types
        found = types.get(key)
        if found is None:
            types[key] = ERROR
            found = types[key] = self.expressions[type(node)](self, node)
        return found

    @staticmethod
    def text(node: ast.Expr) -> str:
        return expr_text(node)

    # ---- names ------------------------------------------------------------------------------

    def variable_type(self, name: str) -> Type | None:
        """The type of a variable of the block as an expression (``declared``), None if there
        is no such variable; cached by spelling, as names are typed at every use."""
        found = self._variable_types.get(name)
        if found is None:
            variable = self.variable(name)
            if variable is None:
                return None
            found = self._variable_types[name] = self.declared(variable.type)
        return found

    def variable(self, name: str) -> Variable | None:
        """A variable of the block; in a DB's assignment section, a member of the DB."""
        found = self.block.variables.get(name.casefold())
        if found is None and self.block.kind is BlockKind.DB:
            found = self._db_variables().get(name.casefold())
        return found

    def _db_variables(self) -> dict[str, Variable]:
        if self._db_members is None:
            made_of = self.block.db_type
            members = self.members(made_of) if made_of is not None else None
            where = self.block.node.name.loc
            self._db_members = {
                key: Variable(key, "STAT", data_type, where)
                for key, data_type in (members or {}).items()
            }
        return self._db_members

    def constant(self, name: str) -> Constant | None:
        return self.block.constants.get(name.casefold())

    @staticmethod
    def declared(data_type: DataType) -> Type:
        """A declared type as an expression's type (an unknown one is silent)."""
        unknown = isinstance(data_type, Elementary) and data_type.name == UNKNOWN.name
        return ERROR if unknown else data_type

    def members(self, value: Type) -> dict[str, DataType] | None:
        """The members a value of this type has (casefolded names), None if it has none; for a
        DB or an FB/UDT instance found once (every ``inst.x`` asks)."""
        if not isinstance(value, DbRef | BlockType):
            return self._members(value)
        if value not in self._members_of:
            self._members_of[value] = self._members(value)
        return self._members_of[value]

    def _members(self, value: Type) -> dict[str, DataType] | None:
        if isinstance(value, DbRef):
            made_of = None if value.number is None else self.index.db_type_of(value.number)
            if made_of is None:
                return None
            value = made_of
        if isinstance(value, StructType):
            return {part.name.casefold(): part.type for part in value.fields}
        if isinstance(value, BlockType):
            expansion = self.index.expand(value)
            if isinstance(expansion, StructType):
                return {part.name.casefold(): part.type for part in expansion.fields}
            if expansion is None:
                return None
            return {
                part.name.casefold(): part.type
                for section, group in expansion
                if section in SECTION_ORDER
                for part in group
            }
        return None

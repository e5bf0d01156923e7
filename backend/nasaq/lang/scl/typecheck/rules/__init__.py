"""The rules of the S7-SCL type checker, one per module.

Expression rules type one kind of node (and report what is wrong with it); statement rules
look at one statement each. ``EXPRESSIONS`` and ``STATEMENTS`` are what the checker runs.

| module | codes | what |
|---|---|---|
| ``undeclared`` | SCL201 | names, ``#locals``, ``"symbols"`` must be declared |
| ``literals`` | SCL218, SCL219 | typed constants: valid, and in range |
| ``members`` | SCL222 | ``a.b``: the member exists |
| ``indexing`` | SCL216, SCL217 | number of indices, indexing a non-array |
| ``operators`` | SCL211, SCL212 | operand types, implicit conversions |
| ``calls`` | — | result types of standard functions and FCs |
| ``assignment`` | SCL213, SCL214, SCL218 | assignment compatibility |
| ``assign_input`` | SCL215 | no assignment to an input parameter |
| ``conditions`` | SCL220 | IF/ELSIF/WHILE/REPEAT conditions are BOOL |
| ``for_variable`` | SCL221 | FOR variable INT/DINT, bounds assignable to it |
"""

from __future__ import annotations

from collections.abc import Callable

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import operands
from nasaq.lang.scl.typecheck.context import Context, ExpressionRule
from nasaq.lang.scl.typecheck.rules import (
    assign_input,
    assignment,
    calls,
    conditions,
    for_variable,
    indexing,
    literals,
    members,
    operators,
    undeclared,
)

EXPRESSIONS: dict[type, ExpressionRule] = {
    ast.Literal: literals.literal,
    ast.Name: undeclared.name,
    ast.Local: undeclared.local,
    ast.Symbol: undeclared.symbol,
    ast.Address: operands.address,
    ast.IndexedAddress: indexing.indexed_address,
    ast.Member: members.member,
    ast.Index: indexing.index,
    ast.Call: calls.call,
    ast.Unary: operators.unary,
    ast.Binary: operators.binary,
    ast.Paren: operators.paren,
}

StatementRule = Callable[[Context, ast.Stmt], None]

STATEMENTS: list[StatementRule] = [
    assign_input.check,
    assignment.check,
    conditions.check,
    for_variable.check,
]

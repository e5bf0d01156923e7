"""The rules of the S7-SCL type checker, one per module.

Expression rules type one kind of node (and report what is wrong with it); statement rules
look at one statement each; block rules look at a whole block (its declarations, or all of its
code at once). ``EXPRESSIONS``, ``STATEMENTS`` and ``BLOCKS`` are what the checker runs.

| module | codes | what |
|---|---|---|
| ``undeclared`` | SCL201 | names, ``#locals``, ``"symbols"`` must be declared |
| ``literals`` | SCL218, SCL219 | typed constants: valid, and in range |
| ``members`` | SCL222 | ``a.b``: the member exists |
| ``slices`` | SCL500, SCL701, SCL702 | TIA's ``x.%X3``/``%B``/``%W``/``%D`` |
| ``indexing`` | SCL216, SCL217, SCL249 | number of indices, arrays only, constant indices |
| ``operators`` | SCL211, SCL212 | operand types, implicit conversions |
| ``calls`` | — | result types of standard functions and FCs |
| ``call_parameters`` | SCL223–SCL234, SCL247, SCL251 | callee, actual parameters, FB calls |
| ``assignment`` | SCL213, SCL214, SCL218, SCL705, SCL706 | assignment (S7-1500: ``implicit``) |
| ``assign_input`` | SCL215 (warning) | an assignment to an input parameter |
| ``conditions`` | SCL220 | IF/ELSIF/WHILE/REPEAT conditions are BOOL |
| ``for_variable`` | SCL221 | FOR variable INT/DINT, bounds assignable to it |
| ``case_labels`` | SCL235, SCL236, SCL248 | CASE selector INT (S7-1500 more), labels, ranges |
| ``counter_writes`` | SCL250 (warning) | no write to the FOR variable inside its loop |
| ``sign_after_operator`` | SCL246 (warning) | ``A * -B`` |
| ``loop_jumps`` | SCL237 | EXIT/CONTINUE inside a loop |
| ``labels`` | SCL238–SCL241, SCL206 | GOTO and jump labels |
| ``return_value`` | SCL242 | an FC assigns its function value |
| ``initial_values`` | SCL243–SCL245 | initial values of declarations |
| ``temp_instances`` | SCL252 | no multi-instance in temporary variables |
| ``db_values`` | SCL243 | the assignment section of a DATA_BLOCK |
"""

from __future__ import annotations

from collections.abc import Callable

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import operands
from nasaq.lang.scl.typecheck.context import Context, ExpressionRule
from nasaq.lang.scl.typecheck.rules import (
    assign_input,
    assignment,
    call_parameters,
    case_labels,
    conditions,
    counter_writes,
    db_values,
    for_variable,
    indexing,
    initial_values,
    labels,
    literals,
    loop_jumps,
    members,
    operators,
    return_value,
    sign_after_operator,
    slices,
    temp_instances,
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
    ast.Call: call_parameters.call,
    ast.Unary: operators.unary,
    ast.Binary: operators.binary,
    ast.Paren: operators.paren,
    ast.Slice: slices.slice_access,
}

StatementRule = Callable[[Context, ast.Stmt], None]
BlockRule = Callable[[Context], None]

# The statements that hold expressions (the sign rule looks inside all of them).
WITH_EXPRESSIONS = (ast.Assign, ast.CallStmt, ast.If, ast.Case, ast.For, ast.While, ast.Repeat)

# The statement rules in the order they run, each with the statements it looks at: the walker
# gives a statement only to the rules of its class.
STATEMENTS: list[tuple[StatementRule, tuple[type, ...]]] = [
    (assign_input.check, (ast.Assign,)),
    (assignment.check, (ast.Assign,)),
    (conditions.check, (ast.If, ast.While, ast.Repeat)),
    (for_variable.check, (ast.For,)),
    (case_labels.check, (ast.Case,)),
    (sign_after_operator.check, WITH_EXPRESSIONS),
]

# Run for every block after its code (if it has code): the declarations, the DB's values.
BLOCKS: list[BlockRule] = [
    initial_values.check,
    temp_instances.check,
    db_values.check,
    loop_jumps.check,
    labels.check,
    return_value.check,
    counter_writes.check,
]

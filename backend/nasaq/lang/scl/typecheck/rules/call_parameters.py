"""Rule: the actual parameters of FC, FB, SFB and S5 timer/counter calls (seeds-003b §2.11),
checked against the callee's formal parameters (``signatures``; the callee is found by
``callee.resolve``, which reports a wrong callee).

- each name must be a parameter of the callee (``SCL223``), given once (``SCL228``);
- ``:=`` supplies an input or in/out, ``=>`` takes an output (TIA); S7-SCL Classic also wrote
  ``Q := x`` for an output, which is accepted. ``=>`` to an input or in/out is ``SCL224``;
- an input takes any value assignable to its type (``types.assignable``: ``SCL213``/``214``/
  ``218``, as assignments); an output is assigned to its actual parameter; an in/out needs an
  actual of the same type (``SCL225``);
- outputs and in/outs need a variable that can be written (``SCL226``; an input parameter of
  the calling block is the warning ``SCL215``, as an assignment to it);
- an FC needs all of its parameters, an FB its in/outs passed by reference (``SCL227``);
- a value without a name only for an FC with exactly one input, alone (``SQRT(x)`` and the
  other standard functions are not checked here), otherwise ``SCL229``;
- a decimal constant to a counter's BCD preset ``PV := 100`` is taken as the word W#16#0064
  (BCD 64), as the book's E67 does: a warning (``SCL247``), ``16#100`` is what is meant;
- an FB (or IEC timer/counter) call is a statement: it has no value, so inside an expression
  (``x := FB1.DB1(...)``, ``IF inst(...) THEN``) it is ``SCL251``, unless the callee itself was
  wrong (reported already).
A mistake in a parameter name does not also report the parameter as missing. The actual
parameters of outputs and in/outs are noted (``Context.written_actuals``): they write their
variable (the FOR rule, ``counter_writes``, reads them).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.descriptor import DbAnyType, is_descriptor
from nasaq.lang.scl.typecheck import callee, implicit, time_dint, variant
from nasaq.lang.scl.typecheck.rules import calls
from nasaq.lang.scl.typecheck.signatures import S5_FUNCTIONS, Param, Signature
from nasaq.lang.scl.typecheck.types import (
    OK,
    BlockRef,
    DbRef,
    IntConst,
    Type,
    Verdict,
    assignable,
    describe,
    is_silent,
    scalar,
)
from nasaq.lang.stl.calls import same_type
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    StringType,
    StructType,
)

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

VALUES = (ast.Literal, ast.Unary, ast.Binary, ast.Paren, ast.Call)
COMPOUND = (ArrayType, StructType, BlockType)
DATA_TYPES = (Elementary, StringType, *COMPOUND)
BLOCK_PARAMETERS = {"BLOCK_FC": "FC", "BLOCK_FB": "FB", "BLOCK_SDB": "SDB"}
BCD_LIMIT = 999  # three BCD digits, the range of an S5 counter
INSTANCES = ("FB", "SFB")
_S5_NUMBER = Elementary("INT")  # blocks called with an instance: they return no value


def call(ctx: Context, node: ast.Call) -> Type:
    result = calls.call(ctx, node)
    reported = len(ctx.diagnostics)
    signature = callee.resolve(ctx, node)
    wrong_callee = len(ctx.diagnostics) > reported
    if signature is not None:
        _check(ctx, node, signature)
    if id(node) not in ctx.outline.statement_calls and not wrong_callee:
        block = _function_block(ctx, node, signature)
        if block is not None:  # an FB has no value: nothing built on the call is reported
            return ctx.report("SCL251", node.loc, name=ctx.text(node.callee), block=block)
    return result


def _function_block(ctx: Context, node: ast.Call, signature: Signature | None) -> str | None:
    """The FB (or SFB) an instance call calls, as messages name it; None for other calls. An FB
    only the symbol table knows has no signature: ``Pump.PumpData(...)`` still shows it (the
    base of a callee ``FB.DB`` is typed already)."""
    if signature is not None:
        return signature.label if signature.kind in INSTANCES else None
    callee = node.callee
    if isinstance(callee, ast.Member):
        base = ctx.type_of(callee.base)
        if isinstance(base, BlockRef) and base.kind.value in INSTANCES:
            return f"{base.kind.value} {base.number}"
    return None


def _check(ctx: Context, node: ast.Call, signature: Signature) -> None:
    positional = [arg for arg in node.args if arg.name is None]
    inputs = signature.inputs()
    single = signature.kind == "FC" and len(node.args) == 1 and len(inputs) == 1
    ordered = signature.kind == "STANDARD"  # built-ins take unnamed parameters in their order
    if ordered:  # inputs, then outputs (TIA: ``RD_SYS_T(#now)``)
        inputs = [p for p in signature.params.values() if p.name not in ("EN", "ENO")]
    if positional and not single and not (ordered and len(positional) <= len(inputs)):
        ctx.report("SCL229", positional[0].loc, block=signature.label)
        return
    supplied: set[str] = set()
    misnamed = False
    for arg in node.args:
        if arg.name is None:
            order = next(n for n, other in enumerate(positional) if other is arg)
            param: Param | None = inputs[order] if ordered else inputs[0]
        else:
            param = signature.params.get(arg.name.casefold())
        if param is None:
            ctx.report("SCL223", arg.loc, block=signature.label, name=arg.name)
            misnamed = True
        elif param.name.casefold() in supplied:
            ctx.report("SCL228", arg.loc, name=param.name)
        else:
            supplied.add(param.name.casefold())
            _argument(ctx, signature, param, arg)
    missing = [
        param.name
        for key, param in signature.params.items()
        if param.required and key not in supplied
    ]
    if missing and not misnamed:
        ctx.report("SCL227", node.loc, block=signature.label, names=", ".join(missing))


def _argument(ctx: Context, signature: Signature, param: Param, arg: ast.Arg) -> None:
    value = ctx.type_of(arg.value)
    if arg.output and param.section != "OUT":
        ctx.report("SCL224", arg.loc, name=param.name, block=signature.label, section=param.section)
        return
    if is_descriptor(param.types[0]):  # VARIANT, ARRAY[*] (S7-1200/1500)
        ctx.written_actuals.add(id(arg.value))
        variant.check_actual(ctx, param.types[0], arg.value, value)
        return
    if isinstance(param.types[0], DbAnyType):  # a DB or a DB_ANY (S7-1200/1500)
        variant.check_db_any(ctx, param.name, arg.value, value)
        return
    if param.section == "IN":
        if param.bcd and isinstance(value, IntConst) and 0 <= value.value <= BCD_LIMIT:
            word = f"W#16#{value.value:04X}"
            ctx.report("SCL247", arg.value.loc, value=value.value, name=param.name, word=word)
            return
        if isinstance(value, IntConst) and signature.label in S5_FUNCTIONS:
            value = _S5_NUMBER  # TV/PV are BCD words: a decimal number is no bit pattern there
        verdict = _passes(value, param.types)
        if verdict.code is not None and not time_dint.implicit(ctx, value, param.types[0]):
            single = len(param.types) == 1
            converted = implicit.accepts(ctx, value, param.types[0], arg.value) if single else None
            if converted is None:
                ctx.report(verdict.code, arg.value.loc, **verdict.params)
            else:
                arg.value = converted  # TIA's implicit conversion of an input (S7-1500)
        return
    ctx.written_actuals.add(id(arg.value))
    formal = param.types[0]
    if _an_instance_of(ctx, value, param):  # RESET_TIMER("IEC_Timer_DB") (``lang/tia_timing``)
        return
    if not _writable(ctx, signature, param, arg.value, value) or is_silent(value):
        return
    if is_silent(formal):
        return
    if param.section == "OUT":
        if isinstance(formal, Elementary) and formal.name == "ANY":
            return  # MOVE_BLK's OUT: the instruction's own rule checks it (``calls``)
        verdict = _fits(formal, value) if isinstance(value, DATA_TYPES) else OK
        if verdict.code == "SCL213":  # no conversion can be written around an output
            verdict = Verdict("SCL214", {"actual": describe(formal), "expected": describe(value)})
        if verdict.code is not None:
            ctx.report(verdict.code, arg.value.loc, **verdict.params)
    elif not _same(formal, value):
        ctx.report(
            "SCL225",
            arg.value.loc,
            name=param.name,
            block=signature.label,
            expected=describe(formal),
            actual=describe(value),
        )


def _passes(value: Type, types: tuple[DataType, ...]) -> Verdict:
    """Whether an input of one of ``types`` takes ``value``: the first type's verdict if not."""
    verdicts = [_fits(value, formal) for formal in types]
    return OK if any(v.code is None for v in verdicts) else verdicts[0]


def _fits(value: Type, formal: DataType) -> Verdict:
    """Whether ``value`` may be stored in ``formal``: ``assignable``, plus what parameter types
    add (ANY, POINTER, BLOCK_xx) and ARRAY/STRUCT/UDT compared by structure."""
    if is_silent(value):
        return OK
    if isinstance(formal, Elementary):
        if formal.name in ("ANY", "POINTER"):
            return OK
        if formal.name == "BLOCK_DB" and isinstance(value, DbRef):
            return OK
        wanted = BLOCK_PARAMETERS.get(formal.name)
        if wanted is not None and isinstance(value, BlockRef) and value.kind.value == wanted:
            return OK
    if isinstance(formal, COMPOUND) and isinstance(value, COMPOUND) and same_type(formal, value):
        return OK
    return assignable(value, formal)


def _same(formal: DataType, value: Type) -> bool:
    """An in/out takes a variable of its own type (any STRING for a STRING, any WSTRING for a
    WSTRING)."""
    if isinstance(formal, StringType):
        return isinstance(value, StringType) and value.wide == formal.wide
    if isinstance(formal, Elementary) and formal.name in ("ANY", "POINTER"):
        return True
    if isinstance(formal, COMPOUND):
        return isinstance(value, COMPOUND) and same_type(formal, value)
    return isinstance(value, Elementary) and scalar(value) == scalar(formal)


def _an_instance_of(ctx: Context, value: Type, param: Param) -> bool:
    """An instance (a multi-instance or an instance DB) of one of the system FBs an in/out of
    TIA's RESET_TIMER/PRESET_TIMER takes (the IEC timers: ``param.types`` lists them)."""
    if param.section != "IN_OUT" or not all(isinstance(t, BlockType) for t in param.types):
        return False
    if isinstance(value, DbRef) and value.number is not None:
        return ctx.index.db_type_of(value.number) in param.types
    return len(param.types) > 1 and value in param.types


def _writable(
    ctx: Context, signature: Signature, param: Param, actual: ast.Expr, value: Type
) -> bool:
    """Reports an actual parameter that cannot take a result; True when it can."""
    root = actual
    while isinstance(root, ast.Member | ast.Index):
        root = root.base
    if isinstance(root, ast.Name | ast.Local | ast.Symbol):
        variable = ctx.variable(root.name)
        is_global = isinstance(root, ast.Symbol) and (
            ctx.index.named(root.name) is not None or ctx.index.symbol(root.name) is not None
        )
        if variable is not None and variable.section == "IN" and not is_global:
            ctx.report("SCL215", root.loc, name=variable.name, block=ctx.block.label)  # warning
    timer = isinstance(value, Elementary) and value.name in ("TIMER", "COUNTER")
    if isinstance(actual, VALUES) or timer or not _is_variable(value):
        ctx.report(
            "SCL226",
            actual.loc,
            section=param.section,
            name=param.name,
            block=signature.label,
            text=ctx.text(actual),
        )
        return False
    return True


def _is_variable(value: Type) -> bool:
    """Only a variable (or an unknown value) has a declared type; a constant or block has not."""
    return is_silent(value) or isinstance(value, DATA_TYPES)

"""The actuals of the system functions of ``nasaq.lang.tia_comm``. RD_SINFO writes the 12 bytes of
a start information (EV_CLASS ... ZI2_3, TIA's SI_classic) into TOP_SI and START_UP_SI: the
actuals must be structures of that layout (a STRUCT, a UDT or an SI_classic), or the CPU would
write over what follows a smaller variable (``SCL950``). A parameter that points at data (AG_SEND's
SEND, AG_RECV's RECV, the start information) takes a variable, not a value (``SCL951``)."""

from __future__ import annotations

from nasaq.lang import tia_comm
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.scl.typecheck.types import BitsConst, CharsConst, IntConst, TimeConst, describe
from nasaq.lang.types import BlockType, DataType, Elementary, StructType

_LAYOUT = tuple(kind for _name, kind in tia_comm.SI_MEMBERS)
_FORMALS = ("TOP_SI", "START_UP_SI")


def _members(ctx: Context, data_type: object) -> tuple[str, ...] | None:
    if isinstance(data_type, BlockType) and data_type.kind == "UDT":
        data_type = ctx.index.expand(data_type)
    if not isinstance(data_type, StructType):
        return None
    kinds = []
    for field in data_type.fields:
        if not isinstance(field.type, Elementary):
            return None
        kinds.append(field.type.name)
    return tuple(kinds)


def check(ctx: Context, node: ast.Call) -> None:
    """SCL950 for a TOP_SI or START_UP_SI actual of another type than the start information."""
    positional = iter(arg.value for arg in node.args if arg.name is None)
    for formal in _FORMALS:
        arg = next((a for a in node.args if (a.name or "").upper() == formal), None)
        value = arg.value if arg is not None else next(positional, None)
        if value is None:
            continue  # a missing parameter is the call rule's to report
        found = ctx.type_of(value)
        if not isinstance(found, DataType) or _members(ctx, found) == _LAYOUT:
            continue
        ctx.report("SCL950", value.loc, formal=formal, type=describe(found))


_VALUES = (ast.Literal, ast.Call, ast.Binary, ast.Unary)
_CONSTANTS = (IntConst, BitsConst, CharsConst, TimeConst)


def check_places(ctx: Context, name: str, node: ast.Call) -> None:
    """SCL951 for a constant or a computed value given to a parameter that points at data."""
    _number, formals, _result = tia_comm.function_parameters(name)
    wanted = [formal for formal, _section, text in formals if text in tia_comm.ANY_VARIABLE]
    order = [formal for formal, _section, _text in formals]
    for position, arg in enumerate(node.args):
        formal = (arg.name or (order[position] if position < len(order) else "")).upper()
        if formal not in wanted:
            continue
        value = arg.value
        while isinstance(value, ast.Paren):
            value = value.inner
        if isinstance(value, _VALUES) or isinstance(ctx.type_of(value), _CONSTANTS):
            ctx.report("SCL951", arg.value.loc, formal=formal, name=name)

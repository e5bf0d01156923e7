"""Rule: a multi-instance (a variable whose type is an FB or an IEC timer/counter such as TON,
also as the element of an ARRAY or the member of a STRUCT) keeps its state from one call to
the next, so it lives in the instance DB: only the static variables (VAR) of an FB may hold one.
In VAR_TEMP, and in the VAR of an FC or OB (temporary too), it is ``SCL252``, at its name."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.scl.typecheck.signatures import IEC_NAMES
from nasaq.lang.types import ArrayType, BlockType, DataType, StructType

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

INSTANCES = ("FB", "SFB")


def check(ctx: Context) -> None:
    block = ctx.block
    for section, fields in block.sections:
        if section != "TEMP":
            continue
        for declared in fields:
            instance = _instance_in(declared.type)
            if instance is None:
                continue
            variable = block.variables.get(declared.name.casefold())
            if variable is not None:
                ctx.report(
                    "SCL252",
                    variable.loc,
                    name=declared.name,
                    type=_shown(ctx, instance),
                    block=block.label,
                )


def _instance_in(data_type: DataType) -> BlockType | None:
    """The FB or SFB type a variable of ``data_type`` is (or holds), None if it holds none."""
    if isinstance(data_type, ArrayType):
        return _instance_in(data_type.element)
    if isinstance(data_type, StructType):
        for member in data_type.fields:
            found = _instance_in(member.type)
            if found is not None:
                return found
        return None
    if isinstance(data_type, BlockType) and data_type.kind in INSTANCES:
        return data_type
    return None


def _shown(ctx: Context, instance: BlockType) -> str:
    """``TON`` for an IEC timer, ``Motor (FB 1)`` for an FB of the sources."""
    if instance.kind == "SFB":
        return IEC_NAMES.get(instance.number, f"SFB {instance.number}")
    label = f"FB {instance.number}"
    found = ctx.index.get(BlockKind.FB, instance.number)
    if found is None or found.name.replace(" ", "").upper() == label.replace(" ", ""):
        return label
    return f"{found.name} ({label})"

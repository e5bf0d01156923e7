"""TIA Portal's call of an IEC timer, counter or edge detector through its instance:
``"IEC_Timer_0_DB".TON(IN := x, PT := T#5S)`` (a single-instance DB of type IEC_TIMER, TON,
TON_TIME ...) and ``#inst.TON(...)`` (a multi-instance). The instruction named after the dot
runs on the instance: ``TP``, ``TON`` and ``TOF`` on any timer instance (one layout), ``CTU``,
``CTD`` and ``CTUD`` on their own instance or on an IEC_COUNTER (laid out as CTUD: ``CTU`` runs
CTUD there with its ``Q`` read from ``QU``, ``CTD`` from ``QD``), ``R_TRIG``/``F_TRIG`` on their
own. Another pairing is ``SCL703``; a DB or variable that is no such instance ``SCL704``."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from nasaq.lang import tia_iec
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import IEC_INSTANCES, SclIndex
from nasaq.lang.scl.typecheck.signatures import IEC_NAMES, Signature, of_instance
from nasaq.lang.scl.typecheck.types import DbRef, Type, is_silent
from nasaq.lang.types import BlockType

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

CTUD = 2
TIMERS = frozenset({3, 4, 5})  # TP, TON, TOF: one layout (``system_blocks``)
# An instruction on an IEC_COUNTER instance (CTUD's layout): its output Q is CTUD's ...
COUNTER_OUTPUTS = {0: "QU", 1: "QD"}


@dataclass(frozen=True, slots=True)
class IecCall:
    """``run`` is the SFB that runs on the instance (``instance`` its SFB type); ``renamed``
    the parameters whose name in the instance differs (CTU's Q is CTUD's QU)."""

    instance: BlockType
    run: int
    renamed: dict[str, str]


def instruction(node: ast.Expr) -> int | None:
    """The SFB an ``x.TON``/``x.CTU``... callee names after its dot; None for other callees."""
    if isinstance(node, ast.Member) and isinstance(node.name, ast.Name):
        return IEC_INSTANCES.get(node.name.name.upper())
    return None


def instance_of(index: SclIndex, value: Type) -> BlockType | None:
    """The SFB instance type of a single-instance DB or multi-instance; None for others."""
    if isinstance(value, DbRef):
        made_of = None if value.number is None else index.db_type_of(value.number)
        value = made_of if made_of is not None else value
    if isinstance(value, BlockType) and value.kind == "SFB":
        return value
    return None


def pairing(instance: BlockType, run: int) -> IecCall | None:
    """How instruction ``run`` runs on ``instance``; None when it cannot."""
    have = instance.number
    typed = tia_iec.paired(have, run)  # CTU_DINT, IEC_DCOUNTER, IEC_LTIMER ... (S7-1500)
    if typed is not None:
        return IecCall(instance, typed[1], typed[2])
    if have == run or (have in TIMERS and run in TIMERS):
        return IecCall(instance, run, {})
    if have == CTUD and run in COUNTER_OUTPUTS:
        return IecCall(instance, CTUD, {"Q": COUNTER_OUTPUTS[run]})
    return None


def resolve(ctx: Context, callee: ast.Member, run: int) -> Signature | None:
    """The signature of ``x.TON(...)``: the instruction's own (reports a wrong instance)."""
    value = ctx.type_of(callee.base)
    if is_silent(value):
        return None
    instance = instance_of(ctx.index, value)
    name = IEC_NAMES[run]
    if instance is None:
        if isinstance(value, DbRef) and (
            value.number is None or ctx.index.db_type_of(value.number) is None
        ):
            return None  # a DB known only at run time, or whose type is wrong (reported)
        ctx.report("SCL704", callee.loc, db=ctx.text(callee.base), name=name)
        return None
    if pairing(instance, run) is None:
        made_of = IEC_NAMES.get(instance.number, f"SFB {instance.number}")
        ctx.report("SCL703", callee.loc, db=ctx.text(callee.base), name=name, instance=made_of)
        return None
    typed = tia_iec.paired(instance.number, run)  # its own types: CTU_DINT's PV is a DINT
    return of_instance(ctx.index, BlockType("SFB", run if typed is None else typed[0]))


__all__ = ["IecCall", "instance_of", "instruction", "pairing", "resolve"]

"""TIME and DINT mixed, as TIA Portal allows on S7-1200/1500 (COMPATIBILITY.md, "S7-1500
profile"): with the block property "IEC check" off (TIA's default, and Nasaq has no such
property), a TIME converts implicitly to a DINT and back (the number of milliseconds, the same
32 bits), so ``#t0 := TIME_TCK();`` into a DINT and ``#elapsed := #now - #t0;`` with a TIME
``#now`` compile. ``TIME + DINT`` and ``TIME - DINT`` (either order) give a TIME, a comparison
of the two compares the milliseconds. An input parameter takes the other type
the same way (hooked in ``rules.assignment``, ``rules.operators``, ``rules.call_parameters``).
S7-SCL Classic (S7-300/400) converts neither way: ``TIME_TO_DINT``/``DINT_TO_TIME``
(``SCL213``, ``SCL211`` as before).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl.typecheck.types import RANGES, IntConst, Type, scalar
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

_PAIR = frozenset({"TIME", "DINT"})
_COMPARE = frozenset({"=", "<>", "<", ">", "<=", ">="})


def implicit(ctx: Context, value: Type, goal: Type) -> bool:
    """Whether ``value`` is stored into ``goal`` by the TIME ↔ DINT conversion."""
    return (
        type(goal) is Elementary
        and type(value) is not IntConst
        and {scalar(value), goal.name} == _PAIR
        and is_s7_1500(ctx.index.profile)
    )


def _name(value: Type) -> str | None:
    if type(value) is IntConst:  # an integer constant with a TIME: a DINT of milliseconds
        low, high = RANGES["DINT"]
        return "DINT" if low <= value.value <= high else None
    return scalar(value)


def combined(ctx: Context, op: str, left: Type, right: Type) -> Elementary | None:
    """The type of ``left op right`` when one is a TIME and the other a DINT (S7-1500)."""
    if {_name(left), _name(right)} != _PAIR or not is_s7_1500(ctx.index.profile):
        return None
    if op in _COMPARE:
        return Elementary("BOOL")
    return Elementary("TIME") if op in ("+", "-") else None


__all__ = ["combined", "implicit"]

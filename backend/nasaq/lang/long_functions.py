"""The standard functions on the 8-byte S7-1200/1500 types, as hidden library FCs beside
``nasaq.lang.long_library``'s operators: no accumulator holds an LREAL or LINT, so
``SQRT(x)`` of an LREAL is ``CALL "SQRT_LREAL" (IN := x, RET_VAL := ...)``, ``MIN(a, b)`` of
LINTs ``MIN_LINT`` and so on (``nasaq.lang.scl.lower.long_functions`` picks the FC by the type
of the values; bodies in ``nasaq.cpu.long_functions``).

- the REAL functions of an LREAL: ``SQR SQRT EXP LN LOG SIN COS TAN ASIN ACOS ATAN`` (an
  LREAL), ``ABS`` of an LREAL or LINT, ``**`` of LREALs (``EXPT_LREAL``);
- ``TRUNC ROUND CEIL FLOOR`` of an LREAL: a DINT, as S7-SCL's (ENO FALSE out of its range);
- ``MIN MAX`` (two inputs; more are chained), ``LIMIT`` (MN, IN, MX) of LINT, ULINT, LREAL,
  LTIME, and ``SEL`` (G, IN0, IN1) of those and LWORD.

They are numbered from ``BASE`` in name order, after the operators' FCs.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.iec_library import LibraryFunction

BASE = 950
REAL_FUNCTIONS = (
    "SQR",
    "SQRT",
    "EXP",
    "LN",
    "LOG",
    "SIN",
    "COS",
    "TAN",
    "ASIN",
    "ACOS",
    "ATAN",
)
ROUNDINGS = ("TRUNC", "ROUND", "CEIL", "FLOOR")
ORDERED = ("LINT", "ULINT", "LREAL", "LTIME")
SELECTED = (*ORDERED, "LWORD")
_INPUTS = {"MIN": ("IN1", "IN2"), "MAX": ("IN1", "IN2"), "LIMIT": ("MN", "IN", "MX")}
FUNCTION_NAMES = frozenset([*REAL_FUNCTIONS, *ROUNDINGS])  # (the ones of one LREAL input)


def signatures() -> list[tuple[str, str, tuple[tuple[str, str], ...]]]:
    """(name, result type, (input, type) ...) of every FC here."""
    found: list[tuple[str, str, tuple[tuple[str, str], ...]]] = [
        (f"{name}_LREAL", "LREAL", (("IN", "LREAL"),)) for name in REAL_FUNCTIONS
    ]
    found += [(f"{name}_LREAL", "DINT", (("IN", "LREAL"),)) for name in ROUNDINGS]
    found += [(f"ABS_{kind}", kind, (("IN", kind),)) for kind in ("LINT", "LREAL")]
    found.append(("EXPT_LREAL", "LREAL", (("IN1", "LREAL"), ("IN2", "LREAL"))))
    for kind in ORDERED:
        for name, inputs in _INPUTS.items():
            found.append((f"{name}_{kind}", kind, tuple((i, kind) for i in inputs)))
    for kind in SELECTED:
        found.append((f"SEL_{kind}", kind, (("G", "BOOL"), ("IN0", kind), ("IN1", kind))))
    return found


def functions() -> list[LibraryFunction]:
    """The FCs, numbered from ``BASE`` in name order."""
    from nasaq.lang.iec_library import LibraryFunction

    return [
        LibraryFunction(
            name,
            number,
            tuple((formal, Elementary(kind)) for formal, kind in inputs),
            Elementary(result),
            name,
        )
        for number, (name, result, inputs) in enumerate(sorted(signatures()), start=BASE)
    ]


def function_name(name: str, kind: str | None) -> str | None:
    """The FC that computes the standard function ``name`` (upper case) on values of type
    ``kind``, None when the accumulators do it (or nothing does)."""
    if kind == "LREAL" and (name in REAL_FUNCTIONS or name in ROUNDINGS):
        return f"{name}_LREAL"
    if name == "ABS" and kind in ("LINT", "LREAL"):
        return f"ABS_{kind}"
    if (name in _INPUTS and kind in ORDERED) or (name == "SEL" and kind in SELECTED):
        return f"{name}_{kind}"
    return None

"""The bodies of the standard functions on the 8-byte S7-1200/1500 types
(``nasaq.lang.long_functions``), Python over the actual parameters' references as
``nasaq.cpu.long_library``'s.

Semantics (S7-1200/1500 with IEEE doubles; *Nasaq* where the manuals leave it open): a function
whose result is not a finite number (``SQRT(-1.0)``, ``LN(0.0)``, ``ASIN(2.0)``) gives NaN or
±infinity and BR = 0 (ENO FALSE); ``**`` is ``EXPT``: a negative base with a whole exponent is
computed, with another exponent NaN. ``TRUNC``/``ROUND``/``CEIL``/``FLOOR`` into a DINT: NaN,
infinity or out of DINT's range give BR = 0 and the low 32 bits (0 for NaN/infinity); ROUND
takes a half to the even neighbour, as TIA's ROUND and the RND instruction do.
``ABS`` of the most negative LINT stays itself (two's complement) with BR = 0. MIN, MAX, LIMIT
and SEL compare the values of their type (LIMIT with MN > MX gives MN and BR = 0).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from nasaq.cpu.long_library import Body, Ref, _get, _set, _wrap
from nasaq.lang.long_functions import ORDERED, REAL_FUNCTIONS, SELECTED

_REAL: dict[str, Callable[[float], float]] = {
    "SQR": lambda x: x * x,
    "SQRT": math.sqrt,
    "EXP": math.exp,
    "LN": math.log,
    "LOG": math.log10,
    "SIN": math.sin,
    "COS": math.cos,
    "TAN": math.tan,
    "ASIN": math.asin,
    "ACOS": math.acos,
    "ATAN": math.atan,
}
_ROUND: dict[str, Callable[[float], int]] = {
    "TRUNC": math.trunc,
    "ROUND": round,
    "CEIL": math.ceil,
    "FLOOR": math.floor,
}
_DINT = (-(2**31), 2**31 - 1)


def _finite(p: list[Ref], value: float) -> int:
    _set(p[-1], "LREAL", value)
    return int(math.isfinite(value))


def _real(name: str) -> Body:
    function = _REAL[name]

    def body(p: list[Ref]) -> int:
        x = float(_get(p[0], "LREAL"))
        try:
            value = function(x)
        except ValueError:  # outside the function's domain
            value = math.nan
        except OverflowError:
            value = math.inf
        return _finite(p, value)

    return body


def _expt(p: list[Ref]) -> int:
    base, exponent = float(_get(p[0], "LREAL")), float(_get(p[1], "LREAL"))
    try:
        value = math.pow(base, exponent)
    except ValueError:
        value = math.nan
    except OverflowError:
        value = math.inf
    return _finite(p, value)


def _rounding(name: str) -> Body:
    function = _ROUND[name]

    def body(p: list[Ref]) -> int:
        x = float(_get(p[0], "LREAL"))
        if not math.isfinite(x):
            _set(p[1], "DINT", 0)
            return 0
        whole = function(x)
        _set(p[1], "DINT", _wrap("DINT", whole))
        return int(_DINT[0] <= whole <= _DINT[1])

    return body


def _absolute(kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        value = _get(p[0], kind)
        if kind == "LREAL":
            _set(p[1], kind, abs(value))
            return 1
        whole = abs(int(value))
        _set(p[1], kind, _wrap(kind, whole))
        return int(whole == _wrap(kind, whole))

    return body


def _extreme(name: str, kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        a, b = _get(p[0], kind), _get(p[1], kind)
        _set(p[2], kind, (min if name == "MIN" else max)(a, b))
        return 1

    return body


def _limit(kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        low, value, high = _get(p[0], kind), _get(p[1], kind), _get(p[2], kind)
        if low > high:
            _set(p[3], kind, low)
            return 0
        _set(p[3], kind, min(max(value, low), high))
        return 1

    return body


def _select(kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        buf, byte, bit = p[0]
        chosen = p[2] if buf is not None and buf[byte] >> bit & 1 else p[1]
        _set(p[3], kind, _get(chosen, kind))
        return 1

    return body


def bodies() -> dict[str, Body]:
    found: dict[str, Body] = {f"{name}_LREAL": _real(name) for name in REAL_FUNCTIONS}
    found.update({f"{name}_LREAL": _rounding(name) for name in _ROUND})
    found.update({f"ABS_{kind}": _absolute(kind) for kind in ("LINT", "LREAL")})
    found["EXPT_LREAL"] = _expt
    for kind in ORDERED:
        found[f"MIN_{kind}"] = _extreme("MIN", kind)
        found[f"MAX_{kind}"] = _extreme("MAX", kind)
        found[f"LIMIT_{kind}"] = _limit(kind)
    for kind in SELECTED:
        found[f"SEL_{kind}"] = _select(kind)
    return found


BODIES: dict[str, Body] = bodies()

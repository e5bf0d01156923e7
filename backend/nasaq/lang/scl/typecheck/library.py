"""The IEC library FCs (``nasaq.lang.iec_library``: CONCAT, I_STRNG, AD_DT_TM, EQ_STRNG ...) as
S7-SCL calls them by name: their result type and their parameters, checked as an FC's (every
input must be supplied; one input may go without its name, ``I_STRNG(no)``).

A block of the sources or a symbol-table block of the same name is that block, not the library
function (``callee.resolve`` and ``rules.calls`` look at the library only for names that are
not blocks of the program).
"""

from __future__ import annotations

from functools import cache

from nasaq.lang.iec_library import FUNCTIONS
from nasaq.lang.scl.typecheck.signatures import BOOL, Param, Signature

NAMES = frozenset(FUNCTIONS)


@cache
def signature(name: str) -> Signature | None:
    function = FUNCTIONS.get(name.upper())
    if function is None:
        return None
    params = {
        formal.casefold(): Param(formal, "IN", (data_type,), True)
        for formal, data_type in function.inputs
    }
    params["en"] = Param("EN", "IN", (BOOL,))
    params["eno"] = Param("ENO", "OUT", (BOOL,))
    return Signature(function.name, "FC", params, function.result)

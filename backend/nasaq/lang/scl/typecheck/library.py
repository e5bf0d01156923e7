"""The IEC library FCs (``nasaq.lang.iec_library``: CONCAT, I_STRNG, AD_DT_TM, EQ_STRNG ...) as
S7-SCL calls them by name: their result type and their parameters, checked as an FC's (every
input must be supplied; one input may go without its name, ``I_STRNG(no)``).

A block of the sources or a symbol-table block of the same name is that block, not the library
function (``callee.resolve`` and ``rules.calls`` look at the library only for names that are
not blocks of the program).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cache

from nasaq.lang.iec_library import FUNCTIONS, WIDE, wide_variant
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.signatures import BOOL, Param, Signature
from nasaq.lang.scl.typecheck.types import Type, scalar
from nasaq.lang.text_instructions import OVERLOADS, overload

# TIA's typed forms of the text functions of a STRING (``CONCAT_STRING``: CONCAT; the WSTRING
# ones, ``CONCAT_WSTRING`` ..., are FCs of their own)
TYPED = {f"{name}_STRING": name for name in WIDE if not name.endswith("_STRNG")}
NAMES = frozenset(FUNCTIONS) | frozenset(OVERLOADS) | frozenset(TYPED)
# TIA's names of formals the Standard Library names otherwise: ``LEN(IN := s)`` is FC 21's S
ALIASES = {"LEN": {"IN": "S"}, "LEN_WSTRING": {"IN": "S"}}


def chosen(name: str, args: Sequence[ast.Arg], values: Sequence[Type]) -> str:
    """The library FC a call of ``name`` with these arguments (and their types) runs:
    ``LEN_WSTRING`` for LEN of a WSTRING, ``VAL_STRG_REAL`` for VAL_STRG of a REAL."""
    kinds = [scalar(value) for value in values]
    picked = overload(TYPED.get(name.upper(), name), [arg.name for arg in args], kinds)
    return wide_variant(picked, values)


@cache
def signature(name: str) -> Signature | None:
    function = FUNCTIONS.get(name.upper())
    if function is None:
        return None
    params = {
        formal.casefold(): Param(formal, "IN", (data_type,), True)
        for formal, data_type in function.inputs
    }
    for alias, formal in ALIASES.get(function.name, {}).items():  # not required: one of two
        params[alias.casefold()] = Param(formal, "IN", params[formal.casefold()].types)
    for section, formal, data_type in function.others:  # VAL_STRG's OUT: an FC's, required
        params[formal.casefold()] = Param(formal, section, (data_type,), True)
    params["en"] = Param("EN", "IN", (BOOL,))
    params["eno"] = Param("ENO", "OUT", (BOOL,))
    return Signature(function.name, "FC", params, function.result)

"""TIA Portal's GetBlockName (S7-1200/1500): the name of the block that calls it, a WSTRING of at
most SIZE characters. The compiler knows the name, so the call is the constant
``WSTRING#'name'`` of the calling block (a real CPU reads the same name from the block's header):
the name as the program declares it, without quotes; a SIZE that is no constant leaves the name
whole (at most 254 characters, the WSTRING's length)."""

from __future__ import annotations

from collections.abc import Callable

from nasaq.lang.scl import ast
from nasaq.lang.tia_comm import GET_BLOCK_NAME

MAX_CHARS = 254


def block_name(
    node: ast.Call, name: str, constant: Callable[[ast.Expr], object]
) -> ast.Literal | None:
    """``WSTRING#'name'`` for a call of GetBlockName in the block ``name``; None for other calls."""
    callee = node.callee
    if not isinstance(callee, ast.Name) or callee.name.upper() != GET_BLOCK_NAME:
        return None
    size = MAX_CHARS
    for arg in node.args:
        if (arg.name or "SIZE").upper() != "SIZE":
            continue
        value = constant(arg.value)
        number = getattr(value, "number", None)
        if getattr(value, "kind", "") == "int" and isinstance(number, int) and number >= 0:
            size = min(size, number)
    text = name[:size].replace("$", "$$").replace("'", "$'")
    return ast.Literal("TYPED", f"WSTRING#'{text}'", node.loc)

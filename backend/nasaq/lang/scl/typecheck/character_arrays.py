"""ATH, HTA, Strg_TO_Chars and Chars_TO_Strg (``nasaq.lang.character_arrays``) in SCL: their
ANY/VARIANT parameters take a variable, not a constant or an expression (``SCL554``, as TIA's
VARIANT parameters), and not yet a parameter of the calling block that
is reached through a pointer (an FC's array, structure or STRING parameter, an FB's in/out, a
VARIANT or ARRAY[*]): the ANY the call builds of it would name one byte, not its length, so
Nasaq refuses it (``SCL801``) rather than convert the wrong number of characters.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.character_arrays import HEX, TO_CHARS, TO_TEXT
from nasaq.lang.scl import ast
from nasaq.lang.scl.descriptor import is_descriptor
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

NAMES = frozenset([*HEX, TO_CHARS, TO_TEXT])
_SPELLING = {"ATH": "ATH", "HTA": "HTA", TO_CHARS: "Strg_TO_Chars", TO_TEXT: "Chars_TO_Strg"}
_VARIABLES = (ast.Name, ast.Local, ast.Symbol, ast.Member, ast.Index, ast.Address)
_POINTED = {"ATH": ("IN", "OUT"), "HTA": ("IN", "OUT"), TO_CHARS: ("CHARS",), TO_TEXT: ("CHARS",)}


def _root(node: ast.Expr) -> ast.Expr:
    while isinstance(node, ast.Member | ast.Index):
        node = node.base
    return node


def check(ctx: Context, name: str, node: ast.Call) -> None:
    """Reports each array-like actual of ``name``'s ANY parameters that is such a parameter."""
    kind = ctx.block.kind
    for arg in node.args:
        if (arg.name or "").upper() not in _POINTED[name]:
            continue
        if not isinstance(arg.value, _VARIABLES):
            ctx.report("SCL554", arg.value.loc, actual=ctx.text(arg.value))
            continue
        root = _root(arg.value)
        if not isinstance(root, ast.Name | ast.Local):
            continue
        variable = ctx.variable(root.name)
        if variable is None:
            continue
        passed = kind is BlockKind.FC and variable.section in ("IN", "OUT", "IN_OUT")
        passed = passed or (kind is BlockKind.FB and variable.section == "IN_OUT")
        elementary = isinstance(ctx.type_of(arg.value), Elementary)  # (a WORD: its width)
        if is_descriptor(variable.type) or (passed and not elementary):
            ctx.report(
                "SCL801",
                arg.value.loc,
                instruction=_SPELLING[name],
                actual=ctx.text(arg.value),
                param=arg.name,
            )

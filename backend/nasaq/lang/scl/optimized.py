"""Optimized blocks (``{ S7_Optimized_Access := 'TRUE' }``), as TIA Portal writes them for the
S7-1200/1500 family.

An optimized DB or FB keeps its data where the CPU likes it and has no absolute addresses: TIA
reaches its variables only by name. Nasaq lays an optimized block out like a standard one (the
layout is internal, nobody can see it), so what this module decides is what a user may write:

- under S7-1200/1500, an absolute access to an optimized DB (``DB5.DBW2``, ``%DB5.DBW2``,
  ``"Data".DBX0.1``, ``"Data".DW[i]``) is an error (SCL600), as in TIA; the instance DB of an
  optimized FB is optimized too (TIA gives an instance DB its FB's access mode);
- under S7-300/400 there are no optimized blocks (TIA offers them for the S7-1200/1500 only):
  ``S7_Optimized_Access := 'TRUE'`` is SCL500 ("needs the S7-1200/1500 profile"), the issue's one
  code for what needs that profile; ``'FALSE'`` is a standard block and fine everywhere;
- the attribute takes ``'TRUE'`` or ``'FALSE'`` (any case); anything else is SCL601.

A block without the attribute is a standard block (STEP 7 Classic sources, TIA's S7-300/400
exports).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.stl.diag import problem

if TYPE_CHECKING:
    from nasaq.lang.scl import ast
    from nasaq.lang.scl.bind import SclBlock, SclIndex

ATTRIBUTE = "s7_optimized_access"


def declare(index: SclIndex, info: SclBlock) -> None:
    """Reads the block's access mode into ``info.optimized``; reports a wrong value, and an
    optimized block under a classic profile (then it stays a standard block)."""
    for attribute in info.node.attributes:
        if attribute.name.casefold() != ATTRIBUTE:
            continue
        value = attribute.value.strip().upper()
        if value not in ("TRUE", "FALSE"):
            index.diagnostics.append(
                problem(
                    "SCL601", info.file, attribute.loc, name=attribute.name, value=attribute.value
                )
            )
            continue
        if value == "FALSE":
            info.optimized = False
        elif is_s7_1500(index.profile):
            info.optimized = True
        else:
            what = f"{attribute.name} := '{attribute.value}'"
            index.diagnostics.append(
                problem("SCL500", info.file, attribute.loc, what=what, profile=index.profile)
            )


def marked(node: ast.Block) -> bool:
    """Whether the source marks the block optimized (``S7_Optimized_Access := 'TRUE'``): a
    source for the S7-1200/1500 family, whatever the profile."""
    return any(
        a.name.casefold() == ATTRIBUTE and a.value.strip().upper() == "TRUE"
        for a in node.attributes
    )


def db_label(index: SclIndex, number: int) -> str:
    """``"Recipe" (DB 5)``, or ``DB 5`` for a DB without a name."""
    found = index.get(BlockKind.DB, number)
    if found is None or found.node.name.absolute:
        return f"DB {number}"
    return f'"{found.name}" (DB {number})'


def optimized_db(index: SclIndex, number: int) -> bool:
    """Whether DB ``number`` is optimized: declared so, or the instance DB of an optimized FB."""
    found = index.get(BlockKind.DB, number)
    if found is not None and found.optimized:
        return True
    made_of = index.db_type_of(number)
    kind = getattr(made_of, "kind", None)
    if kind == "FB":
        fb = index.get(BlockKind.FB, getattr(made_of, "number", 0))
        return fb is not None and fb.optimized
    return False

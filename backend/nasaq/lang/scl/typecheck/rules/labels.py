"""Rule: jump labels (seeds-003b §2.10). A label must be declared in the LABEL section
(``SCL238``, once per label), mark one statement only (``SCL239``), and a GOTO needs a label that
marks a statement (``SCL240``). GOTO may leave a loop but not jump into one (``SCL241``). Many
GOTOs may go to one label. A name declared twice in LABEL sections is ``SCL206``. A block
without a LABEL section is TIA Portal's SCL, whose jump labels are not declared: there only
``SCL239``-``SCL241`` apply (issue 20, the forms part)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.walk import Loops

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


@dataclass(slots=True)
class _Found:
    marks: dict[str, tuple[ast.Label, Loops]]
    gotos: list[tuple[ast.Goto, Loops]]


def check(ctx: Context) -> None:
    _declarations(ctx)
    found = _Found({}, [])
    _jumps(ctx, found)
    for goto, loops in found.gotos:
        mark = found.marks.get(goto.label.casefold())
        if mark is None:
            ctx.report("SCL240", goto.loc, label=goto.label, block=ctx.block.label)
        elif loops[: len(mark[1])] != mark[1]:
            ctx.report("SCL241", goto.loc, label=goto.label)


def _declarations(ctx: Context) -> None:
    seen: set[str] = set()
    for section in ctx.block.node.sections:
        if not isinstance(section, ast.LabelSection):
            continue
        for name in section.names:
            if name.casefold() in seen:
                ctx.report("SCL206", section.loc, name=name, block=ctx.block.label)
            seen.add(name.casefold())


def _declared(ctx: Context, key: str, label: str, where: ast.Loc) -> bool:
    if key in ctx.block.labels or not ctx.block.labels:  # no LABEL section: TIA Portal's
        return True  # jump labels are not declared
    if f"label:{key}" not in ctx.reported:
        ctx.reported.add(f"label:{key}")
        ctx.report("SCL238", where, label=label, block=ctx.block.label)
    return False


def _jumps(ctx: Context, found: _Found) -> None:
    for stmt, loops in ctx.outline.jumps:
        if isinstance(stmt, ast.Label):
            key = stmt.name.casefold()
            first = found.marks.get(key)
            if first is not None:
                ctx.report("SCL239", stmt.loc, label=stmt.name, line=first[0].loc.line)
            elif _declared(ctx, key, stmt.name, stmt.loc):
                found.marks[key] = (stmt, loops)
        elif isinstance(stmt, ast.Goto) and _declared(
            ctx, stmt.label.casefold(), stmt.label, stmt.loc
        ):
            found.gotos.append((stmt, loops))

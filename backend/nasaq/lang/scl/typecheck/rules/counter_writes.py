"""Rule: the control variable of FOR is not written inside its own loop (``SCL250``, a warning):
by an assignment, as the variable of an inner FOR, or as the actual parameter of an output or
in/out, in nested statements too. IEC 61131-3 forbids it; S7-SCL compiles it (its code reads
the variable again for each step, so the loop goes on from the value written), hence a warning,
as for ``A * -B``. Writes are found in the block's one walk (``Outline.counter_writes``); a FOR
whose variable is wrong or unknown was reported already and is not looked at."""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import INTEGERS
from nasaq.lang.types import Elementary

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def check(ctx: Context) -> None:
    for written, loop in ctx.outline.counter_writes:
        if isinstance(written, ast.Arg):
            if id(written.value) not in ctx.written_actuals:
                continue  # an input: read, not written
            written = written.value
        counter = ctx.type_of(loop.variable)
        if not isinstance(counter, Elementary) or counter.name not in INTEGERS:
            continue  # SCL221 or an unknown name, reported with the FOR
        ctx.report("SCL250", written.loc, name=ctx.text(written), line=loop.loc.line)

"""MCR( )MCR MCRA MCRD: the master control relay.

MCR( pushes the RLO ANDed with the current MCR bit (8 levels), )MCR pops; both end the logic
chain (OR 0, STA 1, /FC 0). MCRA/MCRD switch MCR dependency on/off for the rest of the running
block only (a local flag): with it on and the MCR bit 0, ``=`` and ``T`` write 0 and ``S``/``R``
write nothing.
"""

from __future__ import annotations

from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.ir import Instruction


def emit_mcr_open(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(ctx.guarded_call(["_MCR_PUSH(rlo)"]), uses=("rlo",), keep=True)
    _end(ctx)


def emit_mcr_close(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(ctx.guarded_call(["_MCR_POP()"]), keep=True)
    _end(ctx)


def _end(ctx: Ctx) -> None:
    ctx.emit("orb = 0", defs=("orb",), known={"orb": 0})
    ctx.emit("sta = 1", defs=("sta",))
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_mcra(ctx: Ctx, ins: Instruction) -> None:
    ctx.emit(f"mcra = {1 if ins.op == 'MCRA' else 0}", defs=("mcra",))


EMITTERS: dict[str, Emitter] = {
    "MCR(": emit_mcr_open,
    ")MCR": emit_mcr_close,
    "MCRA": emit_mcra,
    "MCRD": emit_mcra,
}

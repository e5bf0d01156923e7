"""Test pseudo-ops (only with ``test_ops=True``): __ASSERT==/<>/</<=/>/>=/==R, __STWRST,
__SLEEP, and the ``Register`` operands ACCU1..ACCU4, STW.x, AR1, AR2, DBNO, DINO.

A failed assertion stops the CPU (SIM513) at its line, which is how self-checking STL programs
report. Without test_ops these instructions are unsupported and stop the CPU too.
"""

from __future__ import annotations

from nasaq.cpu.codegen import access
from nasaq.cpu.codegen.access import Value
from nasaq.cpu.codegen.model import Ctx, Emitter
from nasaq.cpu.memory import address_text
from nasaq.cpu.profile import Profile
from nasaq.cpu.status_word import PACK_EXPR, STATUS_NAMES, TEST_BIT_NAMES
from nasaq.ir import (
    Constant,
    ConstType,
    CounterRef,
    Direct,
    Instruction,
    ParamRef,
    Program,
    Register,
    StatusCondition,
    TimerRef,
)

_RELATIONS = {"==": "==", "<>": "!=", "<": "<", "<=": "<=", ">": ">", ">=": ">=", "==R": "=="}


def register_value(ctx: Ctx, op: Register) -> Value:
    name = op.name.upper()
    if name.startswith("ACCU") and name[4:].isdigit():
        n = int(name[4:])
        if n > ctx.profile.accumulators:
            return Value("0", frozenset())
        return Value(f"a{n}", frozenset({f"a{n}"}))
    if name.startswith("STW."):
        local = TEST_BIT_NAMES.get(name[4:])
        if local is not None:
            return Value(local, frozenset({local}))
    if name == "STW":
        return Value(f"({PACK_EXPR})", frozenset(STATUS_NAMES))
    if name in ("AR1", "AR2", "DBNO", "DINO"):
        return Value(name.lower(), frozenset({name.lower()}))
    if name == "DBLG":
        return Value("len(db)", frozenset({"db"}))
    if name == "DILG":
        return Value("len(di)", frozenset({"di"}))
    ctx.error("SIM522", op="register", detail=name)
    return Value("0", frozenset())


def _operand_value(ctx: Ctx, ins: Instruction, second: bool) -> Value:
    op = ins.operand2 if second else ins.operand
    if op is None:
        return Value("0", frozenset())
    if isinstance(op, StatusCondition | TimerRef | CounterRef) or access.width_of(op) == 1:
        return access.read_bit(ctx, op)
    return access.read_value(ctx, op)


def _text(op: object) -> str:
    if isinstance(op, Constant):
        return op.text or str(op.value)
    if isinstance(op, Register):
        return op.name
    if isinstance(op, Direct):
        return address_text(op.area, int(op.width), op.byte, op.bit, op.db)
    if isinstance(op, ParamRef):
        return f"#{op.name}"
    if isinstance(op, TimerRef | CounterRef):
        return f"{'T' if isinstance(op, TimerRef) else 'C'} {op.number}"
    return str(op)


def _is_int_constant(op: object) -> bool:
    return isinstance(op, Constant) and op.type is ConstType.INT


def emit_assert(ctx: Ctx, ins: Instruction) -> None:
    """Compare two operands as unsigned values; an INT constant is a 16-bit immediate (awlsim's
    model), so it compares with the low word of the other side: ``L -1`` sign-extends into
    ACCU1-H on the CPU, which awlsim's zero-extended immediates do not. The assertion ends a
    logic chain (/FC 0), as awlsim's does."""
    if not _enabled(ctx, ins):
        return
    relation = ins.op[len("__ASSERT") :]
    left = _operand_value(ctx, ins, False)
    right = _operand_value(ctx, ins, True)
    if relation == "==R":
        test = f"_ASSERT_REAL({left.expr}, {right.expr})"
    elif _is_int_constant(ins.operand) or _is_int_constant(ins.operand2):
        test = f"({left.expr}) & 0xFFFF {_RELATIONS[relation]} ({right.expr}) & 0xFFFF"
    else:
        test = f"({left.expr}) {_RELATIONS[relation]} ({right.expr})"
    k = ctx.error_site(
        "SIM513", left=_text(ins.operand), relation=relation, right=_text(ins.operand2)
    )
    ctx.emit(f"if not {test}: _ERR({k})", uses=left.uses | right.uses, keep=True)
    ctx.emit("fc = 0", defs=("fc",), known={"fc": 0})


def emit_stwrst(ctx: Ctx, ins: Instruction) -> None:
    if not _enabled(ctx, ins):
        return
    for name in STATUS_NAMES:
        ctx.emit(f"{name} = 0", defs=(name,), known={name: 0} if name in ("fc", "orb") else None)


def emit_feature(ctx: Ctx, ins: Instruction) -> None:
    """awlsim's ``__FEATURE target[, value]``: ACCU1 := the feature's value (no push).

    Target 0 is the number of accumulators: the CPU takes the profile that has that many when
    the program is loaded (see ``feature_profile``), so here it only reports it. Target 1 is
    "OB start information is written", which is always so here.
    """
    if not _enabled(ctx, ins):
        return
    op = ins.operand
    target = int(op.value) if isinstance(op, Constant) else -1
    if target == 0:
        ctx.emit(f"a1 = {ctx.profile.accumulators}", defs=("a1",))
    elif target == 1:
        ctx.emit("a1 = 1", defs=("a1",))
    else:
        ctx.error("SIM522", op=ins.op, detail=f"{_text(op)} (unknown feature)")


def feature_profile(program: Program, profile: Profile) -> Profile:
    """The profile a test program asks for with ``__FEATURE 0, n`` (n accumulators): 4 is an
    S7-400, 2 an S7-300; without the request, ``profile``."""
    for block in program.blocks.values():
        for ins in block.code:
            if ins.op != "__FEATURE":
                continue
            target, value = ins.operand, ins.operand2
            if isinstance(target, Constant) and target.value == 0 and isinstance(value, Constant):
                for candidate in Profile:
                    if candidate.accumulators == value.value:
                        return candidate
    return profile


def emit_sleep(ctx: Ctx, ins: Instruction) -> None:
    if not _enabled(ctx, ins):
        return
    op = ins.operand
    ms = int(op.value) if isinstance(op, Constant) else 0
    ctx.emit(f"m.sleep({ms})", keep=True)


def _enabled(ctx: Ctx, ins: Instruction) -> bool:
    if ctx.globals.get("_TEST_OPS"):
        return True
    ctx.error("SIM522", op=ins.op, detail="(test pseudo-op; run with test ops enabled)")
    return False


EMITTERS: dict[str, Emitter] = {
    **{f"__ASSERT{rel}": emit_assert for rel in _RELATIONS},
    "__STWRST": emit_stwrst,
    "__SLEEP": emit_sleep,
    "__FEATURE": emit_feature,
}

"""What a call calls, and with which formal parameters (``signatures``).

The forms of S7-SCL (seeds-003b §2.11): ``FC1(...)``/``"Calc"(...)`` an FC; ``FB1.DB1(...)``
an FB with its instance DB (created by the compiler if no DATA_BLOCK declares it);
``"Inst"(...)`` an instance DB; ``inst(...)``/``#inst(...)`` a multi-instance (an FB, or an IEC
timer/counter SFB, declared in VAR); ``S_ODT(...)`` an S5 timer/counter function.

Problems with the callee itself are reported here: an FB without instance (``SCL230``), a block
that does not exist (``SCL231``), something that is no block (``SCL232``), a DB that is not an
instance of the FB (``SCL233``), an FC given a DB (``SCL234``). A block only the symbol table
knows (an STL block, an SFC) has no known interface: its calls are not checked, like the
standard functions (``SQRT``, ``CONCAT`` ...).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nasaq.ir import BlockKind
from nasaq.lang import text_instructions
from nasaq.lang.profiles import is_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck import iec_calls, instructions, library
from nasaq.lang.scl.typecheck.instances import INSTANCE_KINDS, block_id, exists
from nasaq.lang.scl.typecheck.rules.calls import STANDARD, called_by_name
from nasaq.lang.scl.typecheck.signatures import S5_FUNCTIONS, Signature, of_block, of_instance
from nasaq.lang.scl.typecheck.types import BlockRef, DbRef, Type, describe, is_silent
from nasaq.lang.types import BlockType
from nasaq.lang.wide_text import unsimulated_conversion

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context


def resolve(ctx: Context, node: ast.Call) -> Signature | None:
    """The signature to check the call against; None when there is none (reported or unknown)."""
    callee = node.callee
    if isinstance(callee, ast.Member):
        run = iec_calls.instruction(callee)
        if run is not None and ctx.variable(_text(callee.base)) is None:
            named = block_id(ctx.index, ctx.block, callee.base)
            if named is None or named[0] is BlockKind.DB:  # "IEC_Timer_0_DB".TON(...)
                return iec_calls.resolve(ctx, callee, run)
        elif run is not None:  # #inst.TON(...)
            return iec_calls.resolve(ctx, callee, run)
        base = block_id(ctx.index, ctx.block, callee.base)
        if base is not None:
            return _with_instance(ctx, base, callee)
    if isinstance(callee, ast.Name) and called_by_name(ctx, callee.name):
        upper = callee.name.upper()
        if upper not in STANDARD:  # SCALE_X_REAL: SCALE_X
            upper = instructions.typed_form(upper)
        if unsimulated_conversion(upper) and ctx.index.named(callee.name) is None:
            return None  # SCL800 (``rules.calls``)
        classic = not is_s7_1500(ctx.index.profile)
        if classic and upper in text_instructions.S7_1500_ONLY and not ctx.index.named(callee.name):
            return None  # SCL500 (``rules.calls``): its parameters mean nothing there
        if upper in STANDARD and ctx.index.named(callee.name) is None:
            values = [ctx.type_of(arg.value) for arg in node.args]
            wide = library.chosen(upper, node.args, values)  # LEN of a WSTRING: LEN_WSTRING
            if wide == "CONCAT" and is_s7_1500(ctx.index.profile):  # (or CONCAT_STRING)
                return instructions.concat_many()  # TIA: IN1 .. INn
            if wide == "CONCAT_WSTRING" and len(node.args) > 2:  # (WSTRING: S7-1500 only)
                return instructions.concat_many(wide=True)
            found = S5_FUNCTIONS.get(upper) or library.signature(wide)
            return found or instructions.signature(upper)
    if not isinstance(callee, ast.Local) and ctx.variable(_text(callee)) is None:
        named = block_id(ctx.index, ctx.block, callee)
        if named is not None and named[0] is not BlockKind.DB:
            return _block(ctx, named, callee)
    value = ctx.type_of(callee)
    if isinstance(callee, ast.Symbol) and not _callable(value):
        # "Name"(...) calls a global block: a local of that name (a STRING holding the
        # block's result, as TIA projects often name it) is not the callee.
        _undeclared_block(ctx, callee)
        return None
    return _value(ctx, value, callee)


def _callable(value: Type) -> bool:
    kinds = ("FB", "SFB")
    return (
        is_silent(value)
        or isinstance(value, DbRef | BlockRef)
        or (isinstance(value, BlockType) and value.kind in kinds)
    )


def _undeclared_block(ctx: Context, callee: ast.Symbol) -> None:
    """A quoted callee no source, symbol or system block declares: SCL201 names it."""
    ctx.report("SCL201", callee.loc, name=f'"{callee.name}"', block=ctx.block.label)


def _text(node: ast.Expr) -> str:
    return node.name if isinstance(node, ast.Name | ast.Local | ast.Symbol) else ""


def _block(ctx: Context, named: tuple[BlockKind, int], callee: ast.Expr) -> Signature | None:
    """A block called by name, without instance: only an FC may be."""
    kind, number = named
    block = ctx.index.get(kind, number)
    label = f"{kind.value} {number}"
    if kind in INSTANCE_KINDS:
        ctx.report("SCL230", callee.loc, block=block.label if block else label)
        return None
    if kind is BlockKind.FC:
        if block is not None:
            return of_block(block)
        _known(ctx, kind, number, callee)
        return None
    if kind is not BlockKind.SFC:
        ctx.report("SCL232", callee.loc, name=ctx.text(callee), what=label)
    return None


def _known(ctx: Context, kind: BlockKind, number: int, where: ast.Expr) -> bool:
    """A block the sources do not declare exists only if the symbol table names it."""
    if isinstance(where, ast.Address) and ctx.index.symbols.block_symbol(kind, number) is None:
        ctx.report("SCL231", where.loc, block=f"{kind.value} {number}")
        return False
    return True


def _with_instance(
    ctx: Context, named: tuple[BlockKind, int], callee: ast.Member
) -> Signature | None:
    """``FB1.DB1(...)``: the FB's parameters, once the DB is known to be its instance."""
    kind, number = named
    label = f"{kind.value} {number}"
    if kind is BlockKind.FC:
        ctx.report("SCL234", callee.loc, block=label)
        return None
    if kind not in INSTANCE_KINDS:
        ctx.report("SCL232", callee.loc, name=ctx.text(callee), what=label)
        return None
    db = ctx.type_of(callee.name)
    if is_silent(db):
        return None
    if not isinstance(db, DbRef) or db.number is None:
        ctx.report("SCL233", callee.name.loc, db=ctx.text(callee.name), block=label)
        return None
    instance = BlockType(kind.value, number)
    made_of = ctx.index.db_type_of(db.number)
    if made_of is not None and made_of != instance:
        ctx.report("SCL233", callee.name.loc, db=ctx.text(callee.name), block=label)
        return None
    if not exists(ctx.index, kind, number):
        if kind is BlockKind.FB:  # an SFB without a known interface is not checked
            _known(ctx, kind, number, callee.base)
        return None
    return of_instance(ctx.index, instance)


def _value(ctx: Context, value: Type, callee: ast.Expr) -> Signature | None:
    """A callee known by its value: an instance (multi-instance, instance DB) or an FC."""
    if is_silent(value):
        return None
    if isinstance(value, BlockType) and value.kind in ("FB", "SFB"):
        return of_instance(ctx.index, value)
    if isinstance(value, DbRef):
        made_of = None if value.number is None else ctx.index.db_type_of(value.number)
        if isinstance(made_of, BlockType) and made_of.kind in ("FB", "SFB"):
            return of_instance(ctx.index, made_of)
        if made_of is None:
            return None  # a DB the sources do not declare
    if isinstance(value, BlockRef):
        return _block(ctx, (value.kind, value.number), callee)
    ctx.report("SCL232", callee.loc, name=ctx.text(callee), what=describe(value))
    return None

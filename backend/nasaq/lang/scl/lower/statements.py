"""Statements, as S7-SCL compiles them: IF/ELSIF/ELSE and CASE to conditional jumps, FOR as a
loop tested before the first pass and after each step (the end value is evaluated once, the
step is a constant or evaluated once and its sign decides the test), WHILE and REPEAT,
EXIT/CONTINUE to the loop's labels, RETURN to the block's epilogue, GOTO to the label of the
LABEL section. Assignments store with ``T`` or ``=``; a STRUCT, UDT or ARRAY assignment copies
element by element.
"""

from __future__ import annotations

from copy import copy

from nasaq.lang.layout import Slot
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.literals import Value, stl_constant
from nasaq.lang.scl.lower.longs import is_long
from nasaq.lang.scl.lower.places import Access, LoweringError, Selector
from nasaq.lang.scl.lower.slices import assign_slice
from nasaq.lang.scl.lower.tia_timing import TiaTiming
from nasaq.lang.scl.lower.variant import Variants
from nasaq.lang.scl.lower.wide_control import WIDE_COUNTERS, WIDE_SELECTORS, WideControl
from nasaq.lang.scl.typecheck.types import scalar
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
)

_SIMPLE_COPY = ("BOOL",)
_ZERO = Value("int", 0)
_ONE = Value("int", 1)


class Statements(WideControl, Variants, TiaTiming):
    def statements(self, body: list[ast.Stmt]) -> None:
        for stmt in body:
            self.statement(stmt)

    def statement(self, stmt: ast.Stmt) -> None:
        self.em.loc = stmt.loc
        method = getattr(self, "do_" + type(stmt).__name__.lower())
        method(stmt)
        if self.hoisted:
            self.drop_hoisted()

    # ---- simple statements ------------------------------------------------------------------

    def do_assign(self, stmt: ast.Assign) -> None:
        if stmt.chain:  # a := b := c: b := c, then a := b
            for step in stmt.steps():
                self.do_assign(step)
            return
        if type(stmt.target) is ast.Slice:
            assign_slice(self, stmt.target, stmt.value)
            return
        em = self.em
        target = self.type_of(stmt.target)
        kind = scalar(target)
        if isinstance(target, StringType) or kind == "DATE_AND_TIME" or is_long(kind):
            self.assign_text(stmt)  # ``strings``, ``dates``, ``longs``
            return
        if isinstance(target, StructType | ArrayType | BlockType):
            self.copy(stmt)
            return
        if kind == "BOOL":
            access = self.access(stmt.target)
            self.condition(stmt.value)
            if access.root == "ok":  # OK := ...: errors before this no longer count
                following = em.new_label()
                em.jump("JOS", following)
                em.place(following)
            em.op("=", self.operand(access, stmt.target.loc))
            return
        if kind is None:
            raise LoweringError(stmt.loc, "this assignment")
        access = self.access(stmt.target)
        self.load_value(stmt.value, kind)
        if self.needs_setup(access):
            temp = em.temp(Elementary("DWORD"))
            em.op("T", em.ref(temp))
            operand = self.operand(access, stmt.target.loc)
            em.op("L", em.ref(temp))
            em.release(temp)
        else:
            operand = self.operand(access, stmt.target.loc)
        em.op("T", operand)

    def needs_setup(self, access: Access) -> bool:
        return not self.plain(access)

    def copy(self, stmt: ast.Assign) -> None:
        """``a := b`` of a structured type: every elementary part, in layout order."""
        target = self.access(stmt.target)
        source = self.access(stmt.value) if self.is_variable(stmt.value) else None
        if source is None:
            raise LoweringError(stmt.loc, "assigning this value to a structure")
        data_type = self.type_of(stmt.target)
        if not isinstance(data_type, StructType | ArrayType | BlockType):
            raise LoweringError(stmt.loc, "STRING assignments")
        self.copy_parts(target, source, data_type, stmt.loc)

    def copy_parts(self, target: Access, source: Access, data_type: DataType, loc: ast.Loc) -> None:
        """Copies every elementary part of a structured ``source`` to ``target``, in layout
        order. A variable index (``a[i] := b[j]``) computes each part's address in AR1 just
        before its use, as an elementary ``a[i].x := b[j].x`` does."""
        em = self.em
        root = self.index.layout.place([Field("x", data_type)])[0]
        for path, slot in self.leaves(root, []):
            if isinstance(slot.type, StringType) or slot.type == Elementary("DATE_AND_TIME"):
                parts = (_extend(source, path), slot.type, _extend(target, path), slot.type)
                self.copy_places(*parts, loc)  # ``strings``, ``dates``
                continue
            if not isinstance(slot.type, Elementary):
                raise LoweringError(loc, "copying this structure")
            left_access = _extend(target, path)
            right = self.operand(_extend(source, path), loc)
            if slot.type.name in _SIMPLE_COPY:
                em.op("A", right)  # the set-up of ``left`` (L, +D, LAR1, OPN) keeps the RLO
                em.op("=", self.operand(left_access, loc))
                continue
            em.op("L", right)
            if self.needs_setup(left_access):
                temp = em.temp(Elementary("DWORD"))
                em.op("T", em.ref(temp))
                left = self.operand(left_access, loc)
                em.op("L", em.ref(temp))
                em.release(temp)
            else:
                left = self.operand(left_access, loc)
            em.op("T", left)

    def leaves(
        self, slot: Slot, path: list[str | list[int]]
    ) -> list[tuple[list[str | list[int]], Slot]]:
        """Every elementary part of a placed variable with its path (members, index lists)."""
        data_type = slot.type
        found: list[tuple[list[str | list[int]], Slot]] = []
        if isinstance(data_type, ArrayType):
            for indices in _all_indices(data_type.dims):
                element = self.index.layout.element(slot, list(indices))
                if element is not None:
                    found += self.leaves(element, [*path, list(indices)])
            return found
        if slot.members:
            for member in slot.members:
                found += self.leaves(member, [*path, member.name])
            return found
        return [(path, slot)]

    def do_callstmt(self, stmt: ast.CallStmt) -> None:
        self.call_statement(stmt.call)

    def do_empty(self, stmt: ast.Empty) -> None:
        return

    def do_bad(self, stmt: ast.Bad) -> None:  # pragma: no cover - only with syntax errors
        raise LoweringError(stmt.loc, "code with syntax errors")

    def do_region(self, stmt: ast.Region) -> None:
        self.statements(stmt.body)

    def do_label(self, stmt: ast.Label) -> None:
        self.em.place(self.user_label(stmt.name))

    def do_goto(self, stmt: ast.Goto) -> None:
        self.em.jump("JU", self.user_label(stmt.label))

    def user_label(self, name: str) -> str:
        key = name.casefold()
        if key not in self.user_labels:
            self.user_labels[key] = self.em.new_label()
        return self.user_labels[key]

    def do_return(self, stmt: ast.Return) -> None:
        self.em.jump("JU", self.end_label)

    def do_exit(self, stmt: ast.Exit) -> None:
        if not self.loops:
            raise LoweringError(stmt.loc, "EXIT outside a loop")
        self.em.jump("JU", self.loops[-1][1])

    def do_continue(self, stmt: ast.Continue) -> None:
        if not self.loops:
            raise LoweringError(stmt.loc, "CONTINUE outside a loop")
        self.em.jump("JU", self.loops[-1][0])

    # ---- branches ---------------------------------------------------------------------------

    def do_if(self, stmt: ast.If) -> None:
        em = self.em
        done = em.new_label()
        for position, branch in enumerate(stmt.branches):
            em.loc = branch.condition.loc
            last = position == len(stmt.branches) - 1 and stmt.orelse is None
            following = done if last else em.new_label()
            self.condition(branch.condition)
            self.drop_hoisted()
            em.jump("JCN", following)
            self.statements(branch.body)
            if not last:
                em.jump("JU", done)
                em.place(following)
        if stmt.orelse is not None:
            self.statements(stmt.orelse)
        em.place(done)

    def do_case(self, stmt: ast.Case) -> None:
        em = self.em
        kind = scalar(self.type_of(stmt.selector)) or "INT"
        if kind in WIDE_SELECTORS:
            self.wide_case(stmt, kind)
            return
        unsigned = kind == "UDINT"  # compared with the top bits flipped (labels too)
        kind = "DINT" if kind in ("DINT", "DWORD", "SINT", "USINT", "UINT", "UDINT") else "INT"
        suffix = "I" if kind == "INT" else "D"
        self.load_value(stmt.selector, kind)
        if unsigned:
            em.op("XOD", em.literal("TYPED", "DW#16#80000000"))
        selector = em.temp(Elementary(kind))
        em.op("T", em.ref(selector))
        targets: list[str] = []
        for branch in stmt.branches:
            label = em.new_label()
            targets.append(label)
            em.loc = branch.loc
            for value in branch.values:
                low = self.case_value(value.low, kind, unsigned)
                if value.high is None:
                    em.op("L", em.ref(selector))
                    em.load_text(*low)
                    em.op("==" + suffix)
                else:
                    high = self.case_value(value.high, kind, unsigned)
                    em.op("A(")
                    em.op("L", em.ref(selector))
                    em.load_text(*low)
                    em.op(">=" + suffix)
                    em.op(")")
                    em.op("A(")
                    em.op("L", em.ref(selector))
                    em.load_text(*high)
                    em.op("<=" + suffix)
                    em.op(")")
                em.jump("JC", label)
        em.release(selector)
        otherwise, done = em.new_label(), em.new_label()
        em.jump("JU", otherwise)
        for branch, label in zip(stmt.branches, targets, strict=True):
            em.place(label)
            self.statements(branch.body)
            em.jump("JU", done)
        em.place(otherwise)
        if stmt.orelse is not None:
            self.statements(stmt.orelse)
        em.place(done)

    def case_value(
        self,
        node: ast.Literal | ast.Name | ast.Local | ast.Symbol,
        kind: str,
        unsigned: bool = False,
    ) -> tuple[str, str]:
        value = self.constant(node)
        if value is None:
            raise LoweringError(node.loc, "this CASE label")
        if unsigned and value.kind == "int":  # a UDINT label, its top bit flipped, as a DINT
            flipped = (int(value.number) ^ 0x80000000) & 0xFFFFFFFF
            value = Value("int", flipped - (1 << 32) if flipped >> 31 else flipped)
        return stl_constant(value, kind)

    # ---- loops ------------------------------------------------------------------------------

    def loop(self, body: list[ast.Stmt], again: str, leave: str) -> None:
        self.loops.append((again, leave))
        self.statements(body)
        self.loops.pop()

    def do_for(self, stmt: ast.For) -> None:
        em = self.em
        kind = self.loop_kind(self.scalar_of(stmt.variable))
        if kind in WIDE_COUNTERS:
            self.wide_for(stmt, kind)
            return
        suffix = "I" if kind == "INT" else "D"
        counter = stmt.variable
        top, step_label, leave = em.new_label(), em.new_label(), em.new_label()
        self.load_value(stmt.start, kind)
        em.op("T", self.operand(self.access(counter), counter.loc))
        end = self.constant(stmt.end)
        end_temp = None
        if end is None:
            end_temp = em.temp(Elementary(kind))
            self.load_value(stmt.end, kind)
            em.op("T", em.ref(end_temp))
        step = self.constant(stmt.step) if stmt.step is not None else None
        step_temp = None
        if stmt.step is not None and step is None:
            step_temp = em.temp(Elementary(kind))
            self.load_value(stmt.step, kind)
            em.op("T", em.ref(step_temp))
        em.place(top)
        em.loc = stmt.loc
        upward = step is None or step.number >= 0

        def test(compare: str) -> None:
            self.load_value(counter, kind)
            if end_temp is not None:
                em.op("L", em.ref(end_temp))
            else:
                assert end is not None
                em.load_text(*stl_constant(end, kind))
            em.op(compare + suffix)

        if step_temp is not None:  # the direction is known at run time only
            em.op("A(")
            em.op("L", em.ref(step_temp))
            em.load_text(*stl_constant(_ZERO, kind))
            em.op(">=" + suffix)
            em.op("A(")
            test("<=")
            em.op(")")
            em.op(")")
            em.op("O(")
            em.op("L", em.ref(step_temp))
            em.load_text(*stl_constant(_ZERO, kind))
            em.op("<" + suffix)
            em.op("A(")
            test(">=")
            em.op(")")
            em.op(")")
        else:
            test("<=" if upward else ">=")
        em.jump("JCN", leave)
        if step_temp is None and self.plain(self.access(counter)):
            # the test after the step: ``T`` leaves the counter in ACCU1, so the next pass
            # costs L, +, T, L, compare, JC (the first test above is the same test)
            body = em.new_label()
            em.place(body)
            self.loop(stmt.body, step_label, leave)
            em.loc = stmt.loc
            em.place(step_label)
            self.load_value(counter, kind)
            em.load_text(*stl_constant(step if step is not None else _ONE, kind))
            em.op("+" + suffix)
            em.op("T", self.operand(self.access(counter), counter.loc))
            if end_temp is not None:
                em.op("L", em.ref(end_temp))
            else:
                assert end is not None
                em.load_text(*stl_constant(end, kind))
            em.op(("<=" if upward else ">=") + suffix)
            em.jump("JC", body)
            em.place(leave)
            if end_temp is not None:
                em.release(end_temp)
            return
        self.loop(stmt.body, step_label, leave)
        em.loc = stmt.loc
        em.place(step_label)
        self.load_value(counter, kind)
        if step_temp is not None:
            em.op("L", em.ref(step_temp))
        else:
            em.load_text(*stl_constant(step if step is not None else _ONE, kind))
        em.op("+" + suffix)
        em.op("T", self.operand(self.access(counter), counter.loc))
        em.jump("JU", top)
        em.place(leave)
        for temp in (end_temp, step_temp):
            if temp is not None:
                em.release(temp)

    def do_while(self, stmt: ast.While) -> None:
        em = self.em
        top, leave = em.new_label(), em.new_label()
        em.place(top)
        self.condition(stmt.condition)
        self.drop_hoisted()
        em.jump("JCN", leave)
        self.loop(stmt.body, top, leave)
        em.loc = stmt.loc
        em.jump("JU", top)
        em.place(leave)

    def do_repeat(self, stmt: ast.Repeat) -> None:
        em = self.em
        top, test, leave = em.new_label(), em.new_label(), em.new_label()
        em.place(top)
        self.loop(stmt.body, test, leave)
        em.loc = stmt.condition.loc
        em.place(test)
        self.condition(stmt.condition)
        self.drop_hoisted()
        em.jump("JCN", top)
        em.place(leave)


def _all_indices(dims: tuple[tuple[int, int], ...]) -> list[tuple[int, ...]]:
    combos: list[tuple[int, ...]] = [()]
    for low, high in dims:
        combos = [(*combo, value) for combo in combos for value in range(low, high + 1)]
    return combos


def _extend(access: Access, path: list[str | list[int]]) -> Access:
    """``access`` followed by ``path``; a row of a matrix (``m[2]``) followed by an element
    index (``[1]``) is one index list (``m[2, 1]``): S7 has no arrays of arrays."""
    extended = copy(access)
    parts = [_literal_indices(part) for part in path]
    base = list(access.path)
    if base and parts and isinstance(base[-1], list) and isinstance(parts[0], list):
        base[-1] = [*base[-1], *parts[0]]
        parts = parts[1:]
    extended.path = [*base, *parts]
    return extended


def _literal_indices(part: str | list[int]) -> Selector:
    if isinstance(part, list):
        return [ast.Literal("INTEGER", str(value)) for value in part]
    return part

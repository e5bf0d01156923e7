"""FOR and CASE over the S7-1200/1500 integers no accumulator compares directly.

A FOR counter of type UDINT, LINT or ULINT and a CASE selector of type LINT or ULINT (TIA
Portal's help: "FOR: Run in counting loop", "CASE: Create multiway branch", both "integer"
on S7-1200/1500) are lowered as SCL of the same meaning, whose comparisons and additions the
8-byte and UDINT lowering already computes (``lower.longs``: library FCs for LINT/ULINT, the
flipped-top-bit compare for UDINT):

- ``FOR v := a TO e BY s DO body END_FOR`` is ``v := a;`` then, while ``v <= e`` (``>=`` for
  a negative step; both tests for a step known only at run time), ``body; v := v + s``. ``e``
  and ``s`` are evaluated once, before the first pass, into temporaries, as S7-SCL does.
  CONTINUE goes to the step, EXIT past the loop.
- ``CASE x OF 1, 5..9: ...`` evaluates ``x`` once and tests each branch's labels in order
  (``x = 1 OR x >= 5 AND x <= 9``); the first branch that matches runs, else ELSE.

The temporaries enter the expressions as nodes of their own (a ``Name`` no source can spell),
typed and hoisted to the temporary only while a test or step is lowered.
"""

from __future__ import annotations

from typing import TypeVar

from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.long_functions import LongFunctions
from nasaq.lang.scl.lower.longs import is_long
from nasaq.lang.scl.lower.places import Access
from nasaq.lang.scl.lower.strings import unparen
from nasaq.lang.scl.typecheck.types import scalar
from nasaq.lang.types import Elementary

WIDE_COUNTERS = frozenset({"UDINT", "LINT", "ULINT"})
WIDE_SELECTORS = frozenset({"LINT", "ULINT"})
_BOOL = Elementary("BOOL")
_N = TypeVar("_N", bound="ast.Expr | ast.Assign")


class WideControl(LongFunctions):
    # ---- provided by the statements part ------------------------------------------------------

    def statements(self, body: list[ast.Stmt]) -> None:  # pragma: no cover - overridden
        raise NotImplementedError

    def loop(self, body: list[ast.Stmt], again: str, leave: str) -> None:  # pragma: no cover
        raise NotImplementedError

    def do_assign(self, stmt: ast.Assign) -> None:  # pragma: no cover - overridden
        raise NotImplementedError

    # ---- T_ADD / T_SUB of an LTIME ------------------------------------------------------------

    def long_function(self, node: ast.Call) -> tuple[str, list[ast.Expr]] | None:
        found = super().long_function(node)
        callee = node.callee
        if found is not None or not isinstance(callee, ast.Name):
            return found
        name = callee.name.upper()
        if name not in ("T_ADD", "T_SUB") or self.index.named(callee.name) is not None:
            return None
        values = self.arguments(node, "IN1", "IN2")
        if scalar(self.type_of(values[0])) != "LTIME":
            return None
        return ("ADD_LTIME" if name == "T_ADD" else "SUB_LTIME"), values

    # ---- FOR ------------------------------------------------------------------------------------

    def wide_for(self, stmt: ast.For, kind: str) -> None:
        em = self.em
        made = _Made(self, kind)
        counter = stmt.variable
        self.do_assign(made.typed(ast.Assign(counter, stmt.start, stmt.loc), None))
        self.drop_hoisted()
        end = made.once(stmt.end)
        step: ast.Expr = made.typed(ast.Literal("INTEGER", "1", stmt.loc), kind)
        if stmt.step is not None:
            step = made.once(stmt.step)
        constant = self.constant(step) if not made.is_temp(step) else None
        top, step_label, leave = em.new_label(), em.new_label(), em.new_label()
        em.place(top)
        em.loc = stmt.loc
        upward = made.compare("<=", counter, end, stmt.loc)
        downward = made.compare(">=", counter, end, stmt.loc)
        if kind != "LINT" or (constant is not None and constant.number >= 0):
            test = upward  # an unsigned step is never negative
        elif constant is not None:
            test = downward
        else:
            zero = made.typed(ast.Literal("INTEGER", "0", stmt.loc), kind)
            test = made.logic(
                "OR",
                made.logic("AND", made.compare(">=", step, zero, stmt.loc), upward),
                made.logic("AND", made.compare("<", step, zero, stmt.loc), downward),
            )
        made.test(test)
        em.jump("JCN", leave)
        self.loop(stmt.body, step_label, leave)
        em.loc = stmt.loc
        em.place(step_label)
        increment = made.typed(ast.Binary("+", counter, step, stmt.loc), kind)
        made.run(made.typed(ast.Assign(counter, increment, stmt.loc), None))
        em.jump("JU", top)
        em.place(leave)
        made.release()

    # ---- CASE -----------------------------------------------------------------------------------

    def wide_case(self, stmt: ast.Case, kind: str) -> None:
        em = self.em
        made = _Made(self, kind)
        selector = made.once(stmt.selector)
        targets: list[str] = []
        for branch in stmt.branches:
            label = em.new_label()
            targets.append(label)
            em.loc = branch.loc
            test: ast.Expr | None = None
            for value in branch.values:
                low = made.typed(value.low, kind)
                if value.high is None:
                    one = made.compare("=", selector, low, value.loc)
                else:
                    high = made.typed(value.high, kind)
                    one = made.logic(
                        "AND",
                        made.compare(">=", selector, low, value.loc),
                        made.compare("<=", selector, high, value.loc),
                    )
                test = one if test is None else made.logic("OR", test, one)
            if test is not None:
                made.test(test)
                em.jump("JC", label)
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
        made.release()


class _Made:
    """The nodes a wide FOR/CASE makes, typed for the lowering, and its temporaries."""

    def __init__(self, owner: WideControl, kind: str) -> None:
        self.owner = owner
        self.kind = kind
        self.data_type = Elementary(kind)
        self.nodes: list[object] = []  # kept alive while their ids key the type table
        self.temps: dict[int, Temp] = {}

    def typed(self, node: _N, kind: str | None) -> _N:
        self.nodes.append(node)
        if kind is not None:
            self.owner.checked[id(node)] = Elementary(kind)
        return node

    def compare(self, op: str, left: ast.Expr, right: ast.Expr, loc: ast.Loc) -> ast.Expr:
        node = ast.Binary(op, left, right, loc)
        self.nodes.append(node)
        self.owner.checked[id(node)] = _BOOL
        return node

    def logic(self, op: str, left: ast.Expr, right: ast.Expr) -> ast.Expr:
        node = ast.Binary(op, left, right, left.loc)
        self.nodes.append(node)
        self.owner.checked[id(node)] = _BOOL
        return node

    def is_temp(self, node: ast.Expr) -> bool:
        return id(node) in self.temps

    def once(self, value: ast.Expr) -> ast.Expr:
        """``value`` as it is when a constant, else a node standing for a temporary that holds
        it, computed now."""
        owner, em = self.owner, self.owner.em
        if owner.constant(unparen(value)) is not None:
            return value
        temp = em.temp(self.data_type)
        if is_long(self.kind):
            owner.store_long(value, Access("temp", temp=temp), self.kind, value.loc)
        else:
            owner.hoist(value)
            owner.load_value(value, self.kind)
            em.op("T", em.ref(temp))
        owner.drop_hoisted()
        node = self.typed(ast.Name(f"{self.kind} once", value.loc), self.kind)
        self.temps[id(node)] = temp
        return node

    def _hoisting(self) -> None:
        self.owner.hoisted.update(self.temps)

    def _settled(self) -> None:
        for key in self.temps:
            self.owner.hoisted.pop(key, None)
        self.owner.drop_hoisted()

    def test(self, condition: ast.Expr) -> None:
        """RLO := ``condition``; the temporaries of its comparisons are released."""
        self._hoisting()
        self.owner.condition(condition)
        self._settled()

    def run(self, stmt: ast.Assign) -> None:
        self._hoisting()
        self.owner.do_assign(stmt)
        self._settled()

    def release(self) -> None:
        checked = self.owner.checked
        for node in self.nodes:
            checked.pop(id(node), None)
        for temp in self.temps.values():
            self.owner.em.release(temp)
        self.temps.clear()

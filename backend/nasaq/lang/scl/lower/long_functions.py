"""The standard functions on the 8-byte S7-1200/1500 types (``nasaq.lang.long_functions``):
``SQRT(x)`` of an LREAL, ``TRUNC(x)``, ``ABS``, ``MIN``/``MAX``/``LIMIT``/``SEL`` of LINT,
ULINT, LREAL, LTIME (SEL also LWORD), and ``**`` of LREALs call their hidden library FC instead
of being compiled in line (no accumulator holds these values). ``MIN``/``MAX`` of more than two
values chain the two-input FC through a temporary. A call with ``EN``/``ENO`` of these is not
compiled yet (``SCL301``).
"""

from __future__ import annotations

from nasaq.lang import long_functions
from nasaq.lang.iec_library import FUNCTIONS
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.instructions import Instructions
from nasaq.lang.scl.lower.references import Result
from nasaq.lang.scl.typecheck import instructions
from nasaq.lang.scl.typecheck.rules.calls import called_by_name
from nasaq.lang.scl.typecheck.types import scalar
from nasaq.lang.stl import ast as stl

_SELECTIONS = {"MIN": (), "MAX": (), "LIMIT": ("MN", "IN", "MX"), "SEL": ("G", "IN0", "IN1")}


class LongFunctions(Instructions):
    def long_function(self, node: ast.Call) -> tuple[str, list[ast.Expr]] | None:
        """The library FC a standard function call computes with, and its values in the FC's
        input order; None when the call is compiled as before."""
        callee = node.callee
        if not isinstance(callee, ast.Name):
            return None
        name = callee.name.upper()
        if name not in _SELECTIONS and name != "ABS" and name not in long_functions.FUNCTION_NAMES:
            return None
        if self.index.named(callee.name) is not None or not called_by_name(self.ctx, callee.name):
            return None  # the program's own block or variable of that name
        if any((arg.name or "").upper() in ("EN", "ENO") for arg in node.args):
            return None
        if name in _SELECTIONS:
            kind = scalar(self.type_of(node))
            if long_functions.function_name(name, kind) is None:
                return None
            if _SELECTIONS[name]:
                values = self.arguments(node, *_SELECTIONS[name])
            else:
                values = [arg.value for arg in instructions.arguments(node, name)]
        else:
            values = self.arguments(node, "IN")
            kind = scalar(self.type_of(values[0]))
        found = long_functions.function_name(name, kind)
        return None if found is None else (found, values)

    def call_result(self, node: ast.Call) -> Temp:
        found = self.long_function(node)
        if found is None:
            return super().call_result(node)
        name, values = found
        result = FUNCTIONS[name].result
        assert result is not None
        temp = self.em.temp(result)
        self.long_call(name, values, temp)
        return temp

    def call_value(self, node: ast.Call) -> None:
        if self.long_function(node) is None:
            super().call_value(node)
            return
        temp = self.call_result(node)  # a DINT (TRUNC ...): into ACCU1
        self.em.op("L", self.em.ref(temp))
        self.em.release(temp)

    def long_value(self, node: ast.Expr, kind: str, have: str | None, result: Result) -> None:
        found = self.long_function(node) if isinstance(node, ast.Call) else None
        if found is not None and have == kind:
            self.long_call(*found, result)
            return
        if isinstance(node, ast.Binary) and node.op == "**" and kind == have == "LREAL":
            self.library_call("EXPT_LREAL", [node.left, node.right], result)
            return
        super().long_value(node, kind, have, result)

    def long_call(self, name: str, values: list[ast.Expr], result: Result) -> None:
        """``result := name(values)``; MIN/MAX of more than two values pairwise."""
        if len(values) <= len(FUNCTIONS[name].inputs):
            self.library_call(name, values, result)
            return
        em = self.em
        function = FUNCTIONS[name]
        _formal, data_type = function.inputs[0]
        so_far = em.temp(data_type)
        self.library_call(name, values[:2], so_far)
        for position, value in enumerate(values[2:], start=3):
            operand, temp = self.input_actual(value, data_type)
            last = position == len(values)
            target = (em.ref(result) if isinstance(result, Temp) else result) if last else None
            args = [em.arg("IN1", em.ref(so_far)), em.arg("IN2", operand)]
            args.append(em.arg("RET_VAL", target if target is not None else em.ref(so_far)))
            em.call([stl.SymbolNode(function.name, False, [], em.loc)], args)
            if temp is not None:
                em.release(temp)
        em.release(so_far)

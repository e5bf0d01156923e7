"""DATE_AND_TIME values and date arithmetic, as S7-SCL compiles them.

A DATE_AND_TIME is 8 BCD bytes (year, month, day, hour, minute, second, two digits of the
milliseconds, the last digit and the weekday, 1 = Sunday); two-digit years 90-99 are
1990-1999, 00-89 are 2000-2089.
- ``t := DT#...`` writes the 8 bytes (two doublewords); ``t := u`` copies them, through the
  places of ``references`` (any variable, also through parameter pointers).
- ``DT + TIME``, ``DT - TIME``, ``DT - DT`` and the comparisons call the library's AD_DT_TM,
  SB_DT_TM, SB_DT_DT, EQ_DT ... NE_DT, as S7-SCL does; a DT result goes straight into the
  target when it is a plain variable, else into a temporary.
- ``DATE - DATE`` is a TIME: the difference of the day numbers times 86 400 000 ms.
TIME, TIME_OF_DAY and DATE otherwise compute as DINT (``expressions``).
"""

from __future__ import annotations

from nasaq.lang.iec_library import DT_ARITHMETIC, DT_COMPARE, STRING_COMPARE, WSTRING_COMPARE
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.expressions import COMPARISONS
from nasaq.lang.scl.lower.literals import Value, dt_body
from nasaq.lang.scl.lower.places import Access, LoweringError
from nasaq.lang.scl.lower.references import DT, DWORD, Place, Result
from nasaq.lang.scl.lower.strings import Strings, unparen
from nasaq.lang.scl.typecheck.types import scalar
from nasaq.lang.stl.constants import ConstantError, date_and_time_bytes

MS_PER_DAY = 86_400_000


class Dates(Strings):
    # ---- assignments ------------------------------------------------------------------------

    def store_dt(self, value: ast.Expr, target: Access, loc: ast.Loc) -> None:
        em = self.em
        inner = unparen(value)
        hoisted = id(inner) in self.hoisted
        constant = None if hoisted else self.constant(inner)
        if constant is not None:
            place = self.locate(target, DT, loc)
            self.reach(place)
            self.write_bytes(self.dt_constant(constant, loc), 0)
            self.release_place(place)
            return
        name = None if hoisted else self.library_operation(inner)
        if isinstance(inner, ast.Call | ast.Binary) and not hoisted:
            if isinstance(inner, ast.Binary) and name is None:
                raise LoweringError(loc, "this DATE_AND_TIME value")
            temp = None if self.direct(target) else em.temp(DT)
            result: Result = temp if temp is not None else self.operand(target, loc)
            if isinstance(inner, ast.Binary) and name is not None:
                self.library_call(name, [inner.left, inner.right], result)
            else:
                assert isinstance(inner, ast.Call)
                self.user_call(inner, result)
            if temp is not None:
                self.copy_places(Access("temp", temp=temp), DT, target, DT, loc)
                em.release(temp)
            return
        if hoisted or self.is_variable(inner):
            self.copy_places(self.access(inner), DT, target, DT, loc)
            return
        raise LoweringError(loc, "this DATE_AND_TIME value")

    def copy_dt(self, source: Place, target: Place) -> None:
        em = self.em
        first, second = em.temp(DWORD), em.temp(DWORD)
        self.reach(source)
        em.op("L", self.at("D", 0))
        em.op("T", em.ref(first))
        em.op("L", self.at("D", 4))
        em.op("T", em.ref(second))
        self.reach(target)
        em.op("L", em.ref(first))
        em.op("T", self.at("D", 0))
        em.op("L", em.ref(second))
        em.op("T", self.at("D", 4))
        em.release(first)
        em.release(second)

    # ---- constants --------------------------------------------------------------------------

    def dt_constant(self, value: Value, loc: ast.Loc) -> bytes:
        if value.kind != "DATE_AND_TIME":
            raise LoweringError(loc, "this DATE_AND_TIME value")
        try:
            return date_and_time_bytes(dt_body(value.text), value.text)
        except ConstantError:
            raise LoweringError(loc, f"DT#{value.text}") from None

    def dt_text(self, value: Value, loc: ast.Loc) -> str:
        self.dt_constant(value, loc)  # reports what cannot be a DATE_AND_TIME
        return "DT#" + dt_body(value.text)

    # ---- operations -------------------------------------------------------------------------

    def library_operation(self, node: ast.Expr) -> str | None:
        """The library FC of a STRING comparison (``strings``) or a DATE_AND_TIME comparison,
        sum or difference; asked of every operation in a condition, so the operator first."""
        if not isinstance(node, ast.Binary):
            return None
        op = node.op
        comparison = op in COMPARISONS
        if not comparison and op not in ("+", "-"):
            return None
        left, right = scalar(self.type_of(node.left)), scalar(self.type_of(node.right))
        if comparison:
            if left == "WSTRING" or right == "WSTRING":  # ``nasaq.lang.wide_text``
                return WSTRING_COMPARE[op]
            if left == "STRING" or right == "STRING":
                return STRING_COMPARE[op]
            if left == "DATE_AND_TIME" or right == "DATE_AND_TIME":
                return DT_COMPARE[op]
            return None
        if left == "DATE_AND_TIME":
            return DT_ARITHMETIC.get((op, right or ""))
        return None

    def binary(self, node: ast.Binary, have: str) -> None:
        """DT - DT (a TIME) through SB_DT_DT; DATE - DATE in milliseconds."""
        if have not in ("DATE_AND_TIME", "TIME"):  # what DT +/- and DATE - DATE give
            super().binary(node, have)
            return
        em = self.em
        name = self.library_operation(node)
        if name is not None:
            temp = self.library_result(node, name)
            em.op("L", em.ref(temp))
            em.release(temp)
            return
        left, right = scalar(self.type_of(node.left)), scalar(self.type_of(node.right))
        if node.op == "-" and left == right == "DATE":
            self.operands(node, "DINT")
            em.op("-D")
            em.load_text("TYPED", f"L#{MS_PER_DAY}")
            em.op("*D")
            return
        super().binary(node, have)

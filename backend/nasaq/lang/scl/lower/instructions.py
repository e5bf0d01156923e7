"""TIA Portal's instructions with more than a value: ``EN``/``ENO`` on every built-in function,
``SCALE_X``/``NORM_X`` and the block moves ``MOVE_BLK``, ``UMOVE_BLK``, ``FILL_BLK``, compiled in
line (the S7-1200/1500 system manual, "Conversion operations" and "Move operations").

- **EN/ENO** of a built-in (``y := INT_TO_BYTE(EN := c, IN := i, ENO => ok)``): with EN FALSE
  the function does not run, its value is 0 and ENO FALSE; otherwise ENO is TRUE unless the
  function found one of its errors (``eno_status``, which the functions clear).
- **SCALE_X** ``OUT = VALUE * (MAX - MIN) + MIN`` computed in REAL, rounded to the nearest
  integer (*Nasaq*: RND, ties to even) when MIN/MAX are INT or DINT. **NORM_X** ``OUT = (VALUE -
  MIN) / (MAX - MIN)``, a REAL. ENO is FALSE when MAX <= MIN, when VALUE is not a number or
  infinite, and (SCALE_X) when the result does not fit OUT's type; OUT is then what the formula
  gives (the low bits when it does not fit), as the manual's "intermediate result".
- **MOVE_BLK / UMOVE_BLK** ``(IN := a[i], COUNT := n, OUT => b[j])`` copy n elements from a[i]
  on to b[j] on, element by element upwards (UMOVE_BLK is the uninterruptible one: the same
  here, the simulator runs one block at a time). **FILL_BLK** ``(IN := v, COUNT := n, OUT =>
  b[j])`` writes v into n elements from b[j] on. When n elements do not fit in the source or
  target ARRAY from the given element on, the elements that fit are moved and ENO is FALSE (the
  S7-1200 manual); COUNT <= 0 moves nothing. Elements are BYTE/CHAR, WORD/INT/DATE, DWORD/DINT/
  REAL/TIME/TIME_OF_DAY; a BOOL array is ``SCL301`` (*Nasaq*: not done yet). Overlapping areas
  are copied upwards, element by element (*Nasaq*).
"""

from __future__ import annotations

from nasaq.lang import dtl, tia_comm
from nasaq.lang.iec_library import FUNCTIONS, LibraryFunction
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.longs import Longs
from nasaq.lang.scl.lower.places import Access, LoweringError
from nasaq.lang.scl.lower.references import DT, Place
from nasaq.lang.scl.typecheck import instructions
from nasaq.lang.scl.typecheck.types import scalar
from nasaq.lang.stl import ast as stl
from nasaq.lang.types import ArrayType, DataType, Elementary, StringType

BOOL = Elementary("BOOL")
DINT = Elementary("DINT")
DWORD = Elementary("DWORD")
REAL_MAX = "3.402823e+38"
_SIZES = {
    "BYTE": "B",
    "CHAR": "B",
    "WORD": "W",
    "INT": "W",
    "DATE": "W",
    "S5TIME": "W",
    "DWORD": "D",
    "DINT": "D",
    "REAL": "D",
    "TIME": "D",
    "TIME_OF_DAY": "D",
}
_BITS = {"B": 8, "W": 16, "D": 32}
_RANGES = {"INT": ("-32768", "32767")}
# T_ADD, T_SUB, T_DIFF of DATE_AND_TIME values and T_COMBINE call the IEC library's FCs
_LIBRARY = {
    ("T_ADD", "DATE_AND_TIME"): "AD_DT_TM",
    ("T_SUB", "DATE_AND_TIME"): "SB_DT_TM",
    ("T_DIFF", "DATE_AND_TIME"): "SB_DT_DT",
}
DAY_MS = "L#86400000"
_CONCATS = ("CONCAT", "CONCAT_STRING", "CONCAT_WSTRING")
# REAL to integer conversions whose ENO says whether the value fitted
_ROUNDING = {
    "REAL_TO_INT": "INT",
    "REAL_TO_DINT": "DINT",
    "ROUND": "DINT",
    "TRUNC": "DINT",
    "CEIL": "DINT",
    "FLOOR": "DINT",
}


class Instructions(Longs):
    eno_status: Temp | None = None  # FALSE once the running built-in found an error

    # ---- EN and ENO -------------------------------------------------------------------------

    def enable_args(self, node: ast.Call) -> tuple[ast.Expr | None, ast.Expr | None]:
        enable = eno = None
        for arg in node.args:
            name = (arg.name or "").upper()
            if name == "EN":
                enable = arg.value
            elif name == "ENO":
                eno = arg.value
        return enable, eno

    def function_value(self, node: ast.Call, name: str) -> None:
        enable, eno = self.enable_args(node)
        if enable is None and eno is None:
            self.instruction(node, name)
            return
        em = self.em
        outer = self.eno_status
        status = self.eno_status = em.temp(BOOL) if eno is not None else None
        value = em.temp(DWORD)
        skip = done = ""
        if enable is not None:
            self.condition(enable)
            self.drop_hoisted()
            skip, done = em.new_label(), em.new_label()
            em.jump("JCN", skip)
        if status is not None:
            em.op("SET")
            em.op("=", em.ref(status))
        self.instruction(node, name)
        em.op("T", em.ref(value))
        if enable is not None:
            em.jump("JU", done)
            em.place(skip)
            em.load_text("NUMBER", "0")
            em.op("T", em.ref(value))
            if status is not None:
                em.op("CLR")
                em.op("=", em.ref(status))
            em.place(done)
        if eno is not None and status is not None:
            em.op("A", em.ref(status))
            em.op("=", self.operand(self.access(eno), eno.loc))
            em.release(status)
        self.eno_status = outer
        em.op("L", em.ref(value))
        em.release(value)

    def function_condition(self, node: ast.Call, name: str) -> None:
        enable, eno = self.enable_args(node)
        if enable is None and eno is None:
            super().function_condition(node, name)
            return
        em = self.em
        self.function_value(node, name)
        em.load_text("NUMBER", "1")
        em.op("AW")
        em.load_text("NUMBER", "0")
        em.op("<>I")

    def parameter(self, node: ast.Call, name: str, formal: str) -> ast.Expr:
        """The actual of ``formal``: named, or unnamed in the instruction's parameter order."""
        positional = [arg.value for arg in node.args if arg.name is None]
        for arg in node.args:
            if (arg.name or "").upper() == formal:
                return arg.value
        signature = instructions.signature(name)
        order = list(signature.params.values()) if signature is not None else []
        names = [p.name for p in order if p.name not in ("EN", "ENO")]
        position = names.index(formal) if formal in names else len(positional)
        if position >= len(positional):
            raise LoweringError(node.loc, f"{name} without {formal}")
        return positional[position]

    def fail_if(self) -> None:
        """ENO := FALSE when the RLO is 1 (nothing when no ENO is asked for)."""
        status = self.eno_status
        if status is None:
            return
        em = self.em
        keep = em.new_label()
        em.jump("JCN", keep)
        em.op("CLR")
        em.op("=", em.ref(status))
        em.place(keep)

    def instruction(self, node: ast.Call, name: str) -> None:
        if name in ("SCALE_X", "NORM_X"):
            self.scale(node, name)
        elif name in instructions.BLOCK_MOVES:
            self.block_move(node, name)
        elif name in instructions.CLOCKS:
            self.read_clock(node, name)
        elif name in tia_comm.SYSTEM_FUNCTIONS:
            self.system_function(node, name)
        elif name in instructions.TIME_FUNCTIONS:
            self.time_arithmetic(node, name)
        elif name in instructions.DTL_CONVERSIONS:
            self.dtl_conversion(node, name)
        elif name == "RE_TRIGR":  # SFC 43: retrigger the cycle monitoring (nothing simulated)
            self.em.call([stl.AddressNode("SFC 43", node.loc)], [])
        elif name == "TIME_TCK":  # SFC 64: RET_VAL := the system time
            ret = self.em.temp(Elementary("TIME"))
            sfc = stl.AddressNode("SFC 64", node.loc)
            self.em.call([sfc], [self.em.arg("RET_VAL", self.em.ref(ret))])
            self.em.op("L", self.em.ref(ret))
            self.em.release(ret)
        else:
            super().function_value(node, name)
            if self.eno_status is not None and name in _ROUNDING:
                self.rounding_failed(_ROUNDING[name])

    def rounding_failed(self, kind: str) -> None:
        """ENO FALSE when a REAL did not fit the integer it was rounded to (RND/TRUNC set OV;
        an INT result is checked against INT's range), as TIA's conversions report it."""
        em = self.em
        em.op("A", stl.BareNode("OV", None, em.loc))
        self.fail_if()
        if kind in _RANGES:
            low, high = _RANGES[kind]
            keep = em.temp(DINT)
            em.op("T", em.ref(keep))
            em.load_text("TYPED", f"L#{low}")
            em.op("<D")  # ACCU2 (the value) < low
            em.op("O(")
            em.op("L", em.ref(keep))
            em.load_text("TYPED", f"L#{high}")
            em.op(">D")
            em.op(")")
            self.fail_if()
            em.op("L", em.ref(keep))
            em.release(keep)

    # ---- SCALE_X and NORM_X -----------------------------------------------------------------

    def scale(self, node: ast.Call, name: str) -> None:
        em = self.em
        low, value, high = self.arguments(node, "MIN", "VALUE", "MAX")
        parts = []
        for part in (low, value, high):
            temp = em.temp(Elementary("REAL"))
            self.load_value(part, "REAL")
            em.op("T", em.ref(temp))
            parts.append(temp)
        mn, v, mx = parts
        if self.eno_status is not None:
            em.op("L", em.ref(mx))
            em.op("L", em.ref(mn))
            em.op("<=R")  # MAX <= MIN
            self.fail_if()
            em.op("L", em.ref(v))
            em.op("ABS")
            em.load_text("REAL", REAL_MAX)
            em.op("<=R")
            em.op("NOT")  # not a number, or infinite
            self.fail_if()
        if name == "NORM_X":
            em.op("L", em.ref(mx))
            em.op("L", em.ref(mn))
            em.op("-R")
            em.op("T", em.ref(mx))  # MAX - MIN (two accumulators)
            em.op("L", em.ref(v))
            em.op("L", em.ref(mn))
            em.op("-R")
            em.op("L", em.ref(mx))
            em.op("/R")
        else:
            em.op("L", em.ref(mx))
            em.op("L", em.ref(mn))
            em.op("-R")
            em.op("L", em.ref(v))
            em.op("*R")
            em.op("L", em.ref(mn))
            em.op("+R")
            result = self.scalar_of(node)
            if result in ("INT", "DINT"):
                self.to_integer(result)
        for temp in parts:
            em.release(temp)

    def to_integer(self, kind: str) -> None:
        """ACCU1 (REAL) rounded to ``kind``; ENO FALSE when it does not fit."""
        self.em.op("RND")
        if self.eno_status is not None:
            self.rounding_failed(kind)

    # ---- MOVE_BLK, UMOVE_BLK, FILL_BLK ------------------------------------------------------

    def block_move(self, node: ast.Call, name: str) -> None:
        em = self.em
        source, count = self.arguments(node, "IN", "COUNT")
        target = self.parameter(node, name, "OUT")
        width = self.element_width(target, name)
        if name != "FILL_BLK" and self.element_width(source, name) != width:
            raise LoweringError(source.loc, f"{name} between elements of different sizes")
        n = em.temp(DINT)
        self.load_value(count, "DINT")
        em.op("T", em.ref(n))
        self.clip(n, target)
        value: Temp | None = None
        src: Place | None = None
        if name == "FILL_BLK":
            value = em.temp(DWORD)
            self.load_value(source, self.scalar_of(target))
            em.op("T", em.ref(value))
        else:
            self.clip(n, source)
            src = self.place_of(source)
        dst = self.place_of(target)
        step = _BITS[width]
        switch = src is not None and self.two_dbs(src, dst)
        if src is not None:
            self.open_place(src)
        self.open_place(dst)
        top, done = em.new_label(), em.new_label()
        em.place(top)
        em.op("L", em.ref(n))
        em.load_text("TYPED", "L#0")
        em.op("<=D")
        em.jump("JC", done)
        if src is not None:
            self.copy_element(src, dst, width, 0, switch)
            self.advance((src, dst), step)
        else:
            assert value is not None
            self.reach(dst, open_db=False)
            em.op("L", em.ref(value))
            em.op("T", self.at(width, 0))
            self.advance((dst,), step)
        em.op("L", em.ref(n))
        em.load_text("TYPED", "L#1")
        em.op("-D")
        em.op("T", em.ref(n))
        em.jump("JU", top)
        em.place(done)
        for place in (src, dst):
            if place is not None:
                self.release_place(place)
        if value is not None:
            em.release(value)
        em.release(n)

    def element_width(self, node: ast.Expr, name: str) -> str:
        kind = scalar(self.type_of(node))
        width = _SIZES.get(kind or "")
        if width is None:
            raise LoweringError(node.loc, f"{name} of {kind or 'these'} elements")
        return width

    def clip(self, n: Temp, element: ast.Expr) -> None:
        """n := the elements that fit from ``element`` to the end of its ARRAY (ENO FALSE when
        fewer than n); a variable that is no array element holds one."""
        em = self.em
        while isinstance(element, ast.Paren):
            element = element.inner
        room: str | None = "1"
        index: ast.Expr | None = None
        if isinstance(element, ast.Index):
            array = self.type_of(element.base)
            if not isinstance(array, ArrayType):
                raise LoweringError(element.loc, "this array element")
            constants = [self.constant(i) for i in element.indices]
            if all(c is not None and c.kind == "int" for c in constants):
                position = 0
                for (low, high), found in zip(array.dims, constants, strict=True):
                    assert found is not None
                    position = position * (high - low + 1) + int(found.number) - low
                room = str(max(array.count - position, 0))
            elif len(array.dims) == 1:
                room, index = None, element.indices[0]
                low, high = array.dims[0]
            else:
                raise LoweringError(element.loc, "an element of a matrix chosen at run time")
        limit = em.temp(DINT)
        if room is not None:
            em.load_text("TYPED", f"L#{room}")
        else:
            assert index is not None
            em.load_text("TYPED", f"L#{high + 1}")
            self.load_value(index, "DINT")
            em.op("-D")  # high + 1 - index
        em.op("T", em.ref(limit))
        em.op("L", em.ref(n))
        em.op("<D")  # the room < n
        keep = em.new_label()
        em.jump("JCN", keep)
        em.op("L", em.ref(limit))
        em.op("T", em.ref(n))
        self.clear_status()
        em.place(keep)
        em.release(limit)

    def clear_status(self) -> None:
        if self.eno_status is not None:
            self.em.op("CLR")
            self.em.op("=", self.em.ref(self.eno_status))

    # ---- RD_SINFO, AG_SEND, AG_RECV (``nasaq.lang.tia_comm``) --------------------------------
    def system_function(self, node: ast.Call, name: str) -> None:
        """``CALL SFC n`` with every parameter; RET_VAL (when there is one) into ACCU 1. A
        start information (RD_SINFO) is passed as the variable the program gives."""
        from nasaq.lang.system_types import parse

        em = self.em
        number, formals, result = tia_comm.function_parameters(name)
        args: list[stl.CallArgNode] = []
        used: list[Temp] = []
        after: list[tuple[Temp, ast.Expr]] = []
        for formal, section, text in formals:
            value = self.parameter(node, name, formal)
            if text in tia_comm.ANY_VARIABLE:
                operand = self.operand(self.access(value), value.loc)
            elif section == "OUT":
                operand, temp = self.output_actual(value, parse(text))
                if temp is not None:
                    after.append((temp, value))
            else:
                operand, temp = self.input_actual(value, parse(text))
                if temp is not None:
                    used.append(temp)
            args.append(em.arg(formal, operand))
        ret = None if result is None else em.temp(parse(result))
        if ret is not None:
            args.append(em.arg("RET_VAL", em.ref(ret)))
        em.call([stl.AddressNode(f"SFC {number}", node.loc)], args)
        for temp in used:
            em.release(temp)
        for temp, place in after:
            self.store_from(temp, place)
            em.release(temp)
        if ret is not None:
            em.op("L", em.ref(ret))
            em.release(ret)

    # ---- RD_SYS_T, RD_LOC_T, READ_CLK -------------------------------------------------------

    def read_clock(self, node: ast.Call, name: str) -> None:
        """``CALL SFC 1 (RET_VAL := r, CDT := t)``: READ_CLK, into the DATE_AND_TIME t, or into
        a hidden one that is then taken apart into the DTL (BCD to binary)."""
        em = self.em
        target = self.parameter(node, name, instructions.CLOCKS[name])
        ret = em.temp(Elementary("INT"))
        direct = not dtl.is_dtl(self.type_of(target)) and self.passes_as_is(target, DT)
        hidden = None if direct else em.temp(DT)
        output = self.operand(self.access(target), target.loc) if hidden is None else em.ref(hidden)
        sfc = stl.AddressNode("SFC 1", node.loc)
        em.call([sfc], [em.arg("RET_VAL", em.ref(ret)), em.arg("CDT", output)])
        if hidden is not None:
            source = self.locate(Access("temp", temp=hidden), DT, node.loc)
            if dtl.is_dtl(self.type_of(target)):
                self.dt_to_dtl(source, self.place_of(target))
            else:
                self.copy_dt(source, self.place_of(target))
                self.release_place(source)
            em.release(hidden)
        em.op("L", em.ref(ret))
        em.release(ret)

    def dt_to_dtl(self, source: Place, target: Place) -> None:
        """target (a DTL) := source (a DATE_AND_TIME): the BCD fields as numbers, the year
        90-99 as 19xx and 00-89 as 20xx, the weekday (1 = Sunday in both), the milliseconds as
        nanoseconds. Both places are used up."""
        em = self.em
        self.open_place(target)  # the DATE_AND_TIME is a temporary: no DB for it

        def put(width: str, offset: int) -> None:
            self.reach(target, open_db=False)
            em.op("TAK")
            em.op("T", self.at(width, offset))

        self.reach(source, open_db=False)
        em.op("L", self.at("B", 0))
        em.op("BTI")
        year = em.temp(Elementary("INT"))
        em.op("T", em.ref(year))
        em.load_text("NUMBER", "90")
        em.op("<I")
        century, done = em.new_label(), em.new_label()
        em.jump("JCN", century)
        em.op("L", em.ref(year))
        em.load_text("NUMBER", "2000")
        em.op("+I")
        em.jump("JU", done)
        em.place(century)
        em.op("L", em.ref(year))
        em.load_text("NUMBER", "1900")
        em.op("+I")
        em.place(done)
        put("W", dtl.OFFSETS["YEAR"])
        em.release(year)
        for byte, member in ((1, "MONTH"), (2, "DAY"), (3, "HOUR"), (4, "MINUTE"), (5, "SECOND")):
            self.reach(source, open_db=False)
            em.op("L", self.at("B", byte))
            em.op("BTI")
            put("B", dtl.OFFSETS[member])
        self.reach(source, open_db=False)
        em.op("L", self.at("B", 7))
        em.load_text("NUMBER", "15")
        em.op("AW")
        put("B", dtl.OFFSETS["WEEKDAY"])
        millis = em.temp(Elementary("INT"))
        self.reach(source, open_db=False)
        em.op("L", self.at("B", 6))
        em.op("BTI")
        em.load_text("NUMBER", "10")
        em.op("*I")
        em.op("T", em.ref(millis))
        em.op("L", self.at("B", 7))
        em.op("SRW", em.literal("NUMBER", "4"))
        em.op("L", em.ref(millis))
        em.op("+I")
        em.op("ITD")
        em.load_text("TYPED", "L#1000000")
        em.op("*D")
        put("D", dtl.NANOSECOND_OFFSET)
        em.release(millis)
        self.release_place(source)
        self.release_place(target)

    # ---- T_ADD, T_SUB, T_DIFF, T_COMBINE ----------------------------------------------------

    def time_library(self, node: ast.Call) -> LibraryFunction | None:
        """The IEC library FC a time function calls: T_COMBINE D_TOD_DT, and T_ADD, T_SUB,
        T_DIFF of DATE_AND_TIME values AD_DT_TM, SB_DT_TM, SB_DT_DT."""
        callee = node.callee
        if not isinstance(callee, ast.Name) or self.ctx.variable(callee.name) is not None:
            return None
        name = callee.name.upper()
        if name not in instructions.TIME_FUNCTIONS or self.index.named(callee.name) is not None:
            return None
        if name == "T_COMBINE":
            return FUNCTIONS["D_TOD_DT"]
        first = next((a.value for a in node.args if (a.name or "").upper() == "IN1"), None)
        if first is None:
            return None
        found = _LIBRARY.get((name, scalar(self.type_of(first)) or ""))
        return FUNCTIONS[found] if found is not None else None

    def library_function(self, node: ast.Call) -> LibraryFunction | None:
        return super().library_function(node) or self.time_library(node)

    def target(
        self, node: ast.Call
    ) -> tuple[list[stl.OperandNode], dict[str, tuple[str, DataType, str]], DataType | None]:
        function = self.time_library(node)
        if function is None:
            return super().target(node)
        formals = {
            given.casefold(): ("IN", kind, formal)
            for given, (formal, kind) in zip(("IN1", "IN2"), function.inputs, strict=True)
        }
        return [stl.SymbolNode(function.name, False, [], node.loc)], formals, function.result

    def time_arithmetic(self, node: ast.Call, name: str) -> None:
        """TIME, TIME_OF_DAY and DATE values, in ACCU1: a TIME_OF_DAY from T_ADD/T_SUB wraps
        round midnight (*Nasaq*, as a clock does); T_DIFF of DATEs is days * 86 400 000 ms."""
        em = self.em
        first, second = self.arguments(node, "IN1", "IN2")
        if name == "T_DIFF" and dtl.is_dtl(self.type_of(first)):
            self.dtl_difference(first, second, node.loc)
            return
        kind = scalar(self.type_of(first)) or ""
        if kind not in ("TIME", "TIME_OF_DAY", "DATE") or (kind == "DATE" and name != "T_DIFF"):
            raise LoweringError(node.loc, f"{name} of a {kind or 'value of this type'}")
        self.load_value(first, kind)
        temp = em.temp(DINT)
        em.op("T", em.ref(temp))
        self.load_value(second, kind if name == "T_DIFF" else "TIME")
        em.op("L", em.ref(temp))
        em.op("TAK")  # ACCU2 = IN1, ACCU1 = IN2
        em.op("+D" if name == "T_ADD" else "-D")
        if kind == "DATE":
            em.load_text("TYPED", DAY_MS)
            em.op("*D")
        elif kind == "TIME_OF_DAY" and name != "T_DIFF":
            em.load_text("TYPED", DAY_MS)
            em.op("MOD")
            em.op("T", em.ref(temp))
            em.load_text("TYPED", "L#0")
            em.op("<D")
            keep = em.new_label()
            em.jump("JCN", keep)
            em.op("L", em.ref(temp))
            em.load_text("TYPED", DAY_MS)
            em.op("+D")
            em.op("T", em.ref(temp))
            em.place(keep)
            em.op("L", em.ref(temp))
        em.release(temp)

    def dtl_difference(self, first: ast.Expr, second: ast.Expr, loc: ast.Loc) -> None:
        """T_DIFF of two DTLs: both as DATE_AND_TIME values, then SB_DT_DT (so 1990-2089, to
        the millisecond)."""
        em = self.em
        stamps = []
        for value in (first, second):
            stamp = em.temp(DT)
            self.dtl_to_dt(self.place_of(value), self.locate(Access("temp", temp=stamp), DT, loc))
            stamps.append(stamp)
        ret = em.temp(Elementary("TIME"))
        args = [em.arg("T1", em.ref(stamps[0])), em.arg("T2", em.ref(stamps[1]))]
        args.append(em.arg("RET_VAL", em.ref(ret)))
        em.call([stl.SymbolNode("SB_DT_DT", False, [], loc)], args)
        em.op("L", em.ref(ret))
        for temp in (*stamps, ret):
            em.release(temp)

    def dtl_conversion(self, node: ast.Call, name: str) -> None:
        """DTL_TO_TOD, DTL_TO_DATE: the DTL as a DATE_AND_TIME, then the IEC library's DT_TOD
        or DT_DATE (so a DATE of 1990-2089, *Nasaq*; the time of day of any year)."""
        em = self.em
        (value,) = self.arguments(node, "IN")
        stamp = em.temp(DT)
        self.dtl_to_dt(self.place_of(value), self.locate(Access("temp", temp=stamp), DT, node.loc))
        ret = em.temp(Elementary(instructions.DTL_CONVERSIONS[name]))
        args = [em.arg("IN", em.ref(stamp)), em.arg("RET_VAL", em.ref(ret))]
        library = "DT_TOD" if name == "DTL_TO_TOD" else "DT_DATE"
        em.call([stl.SymbolNode(library, False, [], node.loc)], args)
        em.op("L", em.ref(ret))
        em.release(stamp)
        em.release(ret)

    def dtl_to_dt(self, source: Place, target: Place) -> None:
        """target (a DATE_AND_TIME) := source (a DTL): the fields in BCD, the year as two
        digits (1990-2089), the nanoseconds as milliseconds. Both places are used up."""
        em = self.em
        self.open_place(source)  # the DATE_AND_TIME is a temporary: no DB for it

        def put(offset: int) -> None:
            self.reach(target, open_db=False)
            em.op("TAK")
            em.op("T", self.at("B", offset))

        self.reach(source, open_db=False)
        em.op("L", self.at("W", dtl.OFFSETS["YEAR"]))
        em.op("L", em.literal("NUMBER", "100"))
        em.op("MOD")  # 1990-2089: the last two digits
        em.op("ITB")
        put(0)
        for byte, member in ((1, "MONTH"), (2, "DAY"), (3, "HOUR"), (4, "MINUTE"), (5, "SECOND")):
            self.reach(source, open_db=False)
            em.op("L", self.at("B", dtl.OFFSETS[member]))
            em.op("ITB")
            put(byte)
        digits = em.temp(Elementary("WORD"))
        self.reach(source, open_db=False)
        em.op("L", self.at("D", dtl.NANOSECOND_OFFSET))
        em.load_text("TYPED", "L#1000000")
        em.op("/D")
        em.op("ITB")  # three BCD digits of milliseconds
        em.op("T", em.ref(digits))
        em.op("SRW", em.literal("NUMBER", "4"))
        put(6)
        em.op("L", em.ref(digits))
        em.load_text("NUMBER", "15")
        em.op("AW")
        em.op("SLW", em.literal("NUMBER", "4"))
        em.op("T", em.ref(digits))
        self.reach(source, open_db=False)
        em.op("L", self.at("B", dtl.OFFSETS["WEEKDAY"]))
        em.op("L", em.ref(digits))
        em.op("OW")
        put(7)
        em.release(digits)
        self.release_place(source)
        self.release_place(target)

    # ---- CONCAT of more than two texts (TIA, S7-1200/1500; of WSTRINGs CONCAT_WSTRING) ------

    def user_call(self, node: ast.Call, result: Temp | stl.OperandNode | None) -> None:
        texts = self.concat_inputs(node)
        if texts is None:
            super().user_call(node, result)
            return
        em = self.em
        if result is None:
            raise LoweringError(node.loc, "CONCAT as a statement")
        name = self.library_function(node)
        text = StringType(254, wide=name is not None and name.name == "CONCAT_WSTRING")
        callee = "CONCAT_WSTRING" if text.wide else "CONCAT"
        done: Temp | None = None
        for position in range(1, len(texts)):
            last = position == len(texts) - 1
            into = result if last else em.temp(text)
            first = em.ref(done) if done is not None else None
            used: list[Temp] = []
            args = []
            for formal, value in (("IN1", texts[0]), ("IN2", texts[position])):
                if formal == "IN1" and first is not None:
                    args.append(em.arg("IN1", first))
                    continue
                operand, temp = self.input_actual(value, text)
                args.append(em.arg(formal, operand))
                if temp is not None:
                    used.append(temp)
            target = em.ref(into) if isinstance(into, Temp) else into
            args.append(em.arg("RET_VAL", target))
            em.call([stl.SymbolNode(callee, False, [], node.loc)], args)
            for temp in used:
                em.release(temp)
            if done is not None:
                em.release(done)
            done = into if isinstance(into, Temp) and not last else None

    def concat_inputs(self, node: ast.Call) -> list[ast.Expr] | None:
        """IN1 .. INn of a CONCAT with more than two inputs, in order; None for other calls."""
        callee = node.callee
        if not isinstance(callee, ast.Name) or callee.name.upper() not in _CONCATS:
            return None
        if self.ctx.variable(callee.name) is not None or self.index.named(callee.name):
            return None
        found: dict[int, ast.Expr] = {}
        for arg in node.args:
            name = (arg.name or "").upper()
            if name in ("EN", "ENO"):
                raise LoweringError(arg.loc, "EN/ENO on a CONCAT of more than two texts")
            if name.startswith("IN") and name[2:].isdigit():
                found[int(name[2:])] = arg.value
        if len(found) <= 2:
            return None
        return [found[n] for n in sorted(found)]

"""Calls: FCs (with a return value into a temporary), FBs with an instance DB or as
multi-instances (IEC timers and counters included), SFCs, and the S5 timer and counter
functions, which STEP 7's S7-SCL compiles to the timer/counter instructions of the box.

Actual parameters become STL ``CALL`` arguments: a constant is written for the formal's type,
a variable of the formal's type is passed as it is, anything else is computed into a
temporary first (outputs: copied from a temporary after the call when they need a
conversion). ``EN`` makes the call conditional; ``ENO =>`` receives BR after the call (the
callee's ENO), FALSE when EN was FALSE.

A structure or array chosen by a variable index (``"Db".keys[i].edge``) is passed through a
temporary of its type: copied in before the call and, for an in/out, back after it. STEP 7
passes a pointer to the element itself; the two differ only when the callee also reaches the
element another way during the call (issue 20, the gaps part).
"""

from __future__ import annotations

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.descriptor import is_descriptor
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.expressions import Expressions
from nasaq.lang.scl.lower.literals import stl_constant
from nasaq.lang.scl.lower.places import Access, LoweringError
from nasaq.lang.scl.typecheck.iec_calls import instance_of, instruction, pairing
from nasaq.lang.scl.typecheck.instructions import typed_form
from nasaq.lang.scl.typecheck.rules.calls import STANDARD, called_by_name
from nasaq.lang.scl.typecheck.types import BlockRef, DbRef, scalar
from nasaq.lang.stl import ast as stl
from nasaq.lang.types import ArrayType, BlockType, DataType, Elementary, StringType, StructType

TIMERS = {"S_PULSE": "SP", "S_PEXT": "SE", "S_ODT": "SD", "S_ODTS": "SS", "S_OFFDT": "SF"}
COUNTERS = {"S_CU": ("CU",), "S_CD": ("CD",), "S_CUD": ("CU", "CD")}
# System functions S7-SCL knows by name when the symbol table does not name them.
SYSTEM_FUNCTIONS: dict[str, tuple[int, DataType | None]] = {
    "STP": (46, None),
    "TIME_TCK": (64, Elementary("TIME")),
}
Formals = dict[str, tuple[str, DataType, str]]  # casefolded -> (section, type, spelling)


class Calls(Expressions):
    # ---- entry points -----------------------------------------------------------------------

    def call_statement(self, node: ast.Call) -> None:
        name = self.standard_name(node)
        if name in TIMERS or name in COUNTERS:
            self.timer_or_counter(node, name, want_value=False)
            return
        if name is not None:
            self.call_value(node)  # a standard function as a statement: its value is dropped
            return
        self.user_call(node, None)

    def call_result(self, node: ast.Call) -> Temp:
        """The call's value in a temporary of its type."""
        data_type = self.type_of(node)
        kind = scalar(data_type)
        name = self.standard_name(node)
        if kind is None or (name is None and not isinstance(data_type, Elementary | StringType)):
            raise LoweringError(node.loc, "the value of this call")
        if name is None:
            temp = self.em.temp(
                data_type if isinstance(data_type, Elementary) else Elementary(kind)
            )
            self.user_call(node, temp)
            return temp
        temp = self.em.temp(Elementary(kind))
        if kind == "BOOL":
            self.function_condition(node, name)
            self.em.op("=", self.em.ref(temp))
        else:
            self.call_value(node)
            self.em.op("T", self.em.ref(temp))
        return temp

    def call_value(self, node: ast.Call) -> None:
        name = self.standard_name(node)
        if name in TIMERS or name in COUNTERS:
            self.timer_or_counter(node, name, want_value=True)
            return
        if name is not None:
            self.function_value(node, name)
            return
        temp = self.call_result(node)
        self.em.op("L", self.em.ref(temp))
        self.em.release(temp)

    def standard_name(self, node: ast.Call) -> str | None:
        callee = node.callee
        if not isinstance(callee, ast.Name) or not called_by_name(self.ctx, callee.name):
            return None
        upper = callee.name.upper()
        if upper not in STANDARD:  # SCALE_X_REAL: SCALE_X
            upper = typed_form(upper)
        if upper in STANDARD and self.index.named(callee.name) is None:
            return upper
        return None

    # ---- user blocks ------------------------------------------------------------------------

    def target(self, node: ast.Call) -> tuple[list[stl.OperandNode], Formals, DataType | None]:
        """The STL call target, the formal parameters and the FC's return type."""
        loc = node.loc
        callee = node.callee
        if isinstance(callee, ast.Member) and instruction(callee) is not None:
            found = self.iec_target(callee, instruction(callee) or 0)
            if found is not None:
                return found
        if isinstance(callee, ast.Member):
            kind = self.type_of(callee.base)
            if isinstance(kind, BlockRef) and kind.kind in (BlockKind.FB, BlockKind.SFB):
                db = self.db_number(callee.name)  # FB1.DB1(...), SFB4.DB2(IN := TRUE ...)
                fb = kind.kind.value
                target: list[stl.OperandNode] = [
                    stl.AddressNode(f"{fb} {kind.number}", loc),
                    stl.AddressNode(f"DB {db}", loc),
                ]
                return target, self.formals(BlockType(fb, kind.number)), None
        if isinstance(callee, ast.Name | ast.Local):
            variable = self.ctx.variable(callee.name)
            if variable is not None and isinstance(variable.type, BlockType):
                formals = self.formals(variable.type)
                return [stl.SymbolNode(variable.name, True, [], loc)], formals, None
            unknown = self.index.named(callee.name) is None and not self.index.symbol(callee.name)
            if callee.name.upper() in SYSTEM_FUNCTIONS and unknown:
                number, returns = SYSTEM_FUNCTIONS[callee.name.upper()]
                return [stl.AddressNode(f"SFC {number}", loc)], {}, returns
        kind = self.type_of(callee)
        if isinstance(kind, DbRef) and kind.number is not None:
            made_of = self.index.db_type_of(kind.number)
            if isinstance(made_of, BlockType) and made_of.kind in ("FB", "SFB"):
                target = [
                    stl.AddressNode(f"{made_of.kind} {made_of.number}", loc),
                    stl.AddressNode(f"DB {kind.number}", loc),
                ]
                return target, self.formals(made_of), None
        if isinstance(kind, BlockRef):
            text = f"{kind.kind.value} {kind.number}"
            if kind.kind is BlockKind.FC:
                block = self.index.get(BlockKind.FC, kind.number)
                formals = self.formals_of_fc(kind.number)
                returns = block.return_type if block is not None else None
                return [stl.AddressNode(text, loc)], formals, returns
            if kind.kind is BlockKind.SFC:
                known = dict(SYSTEM_FUNCTIONS.values())
                return [stl.AddressNode(text, loc)], {}, known.get(kind.number)
        raise LoweringError(loc, "this call")

    def iec_target(
        self, callee: ast.Member, run: int
    ) -> tuple[list[stl.OperandNode], Formals, DataType | None] | None:
        """``"IEC_Timer_0_DB".TON(...)``: ``CALL SFB 4, DB n``; ``#inst.TON(...)``: ``CALL
        #inst`` (``typecheck.iec_calls``); None when the base is no IEC instance."""
        loc = callee.loc
        value = self.type_of(callee.base)
        instance = instance_of(self.index, value)
        pair = None if instance is None else pairing(instance, run)
        if pair is None:
            return None
        formals = self.formals(BlockType("SFB", pair.run))
        for name, spelling in pair.renamed.items():
            formals[name.casefold()] = formals[spelling.casefold()]
        if isinstance(value, DbRef) and value.number is not None:
            target: list[stl.OperandNode] = [
                stl.AddressNode(f"SFB {pair.run}", loc),
                stl.AddressNode(f"DB {value.number}", loc),
            ]
            return target, formals, None
        base = callee.base
        variable = self.ctx.variable(base.name) if isinstance(base, ast.Name | ast.Local) else None
        if variable is None or pair.run != pair.instance.number:
            raise LoweringError(loc, f"this call of {callee.name.name}")  # type: ignore[union-attr]
        return [stl.SymbolNode(variable.name, True, [], loc)], formals, None

    def db_number(self, node: ast.Expr) -> int:
        if isinstance(node, ast.Address):
            text = node.text.upper().replace(" ", "")
            if text.startswith("DB") and text[2:].isdigit():
                return int(text[2:])
        if isinstance(node, ast.Name | ast.Symbol):
            block = self.index.named(node.name)
            if block is not None and block.kind is BlockKind.DB:
                return block.number
            symbol = self.index.symbol(node.name)
            if symbol is not None and symbol.parsed.block is BlockKind.DB:
                return symbol.parsed.number
        raise LoweringError(node.loc, "this instance data block")

    def formals(self, block: BlockType) -> Formals:
        expansion = self.index.expand(block)
        found: Formals = {}
        if isinstance(expansion, list):
            for section, group in expansion:
                if section in ("IN", "OUT", "IN_OUT"):
                    for part in group:
                        found[part.name.casefold()] = (section, part.type, part.name)
        return found

    def formals_of_fc(self, number: int) -> Formals:
        block = self.index.get(BlockKind.FC, number)
        found: Formals = {}
        if block is not None:
            for section, group in block.sections:
                if section in ("IN", "OUT", "IN_OUT"):
                    for part in group:
                        found[part.name.casefold()] = (section, part.type, part.name)
        return found

    def user_call(self, node: ast.Call, result: Temp | stl.OperandNode | None) -> None:
        em = self.em
        target, formals, returns = self.target(node)
        enable: ast.Expr | None = None
        eno: ast.Expr | None = None
        args: list[stl.CallArgNode] = []
        after: list[tuple[Temp, ast.Expr]] = []
        used: list[Temp] = []
        copies: list[tuple[Temp, Access | None]] = []
        for arg in node.args:
            name = (arg.name or "").upper()
            if name == "EN":
                enable = arg.value
                continue
            if name == "ENO":
                eno = arg.value
                continue
            if arg.name is None:
                ins = list({f[2]: f for f in formals.values() if f[0] == "IN"}.values())
                if len(ins) != 1:
                    raise LoweringError(arg.loc, "a call without parameter names")
                section, data_type, spelling = ins[0]
            elif arg.name.casefold() in formals:
                section, data_type, spelling = formals[arg.name.casefold()]
            else:  # a block whose interface is not known here (an SFC): passed as written
                section, data_type, spelling = ("OUT" if arg.output else "IN"), None, arg.name
            if data_type is not None and is_descriptor(data_type):  # VARIANT, ARRAY[*]
                operand, temp = self.descriptor_actual(arg.value, data_type)
                if temp is not None:
                    used.append(temp)
            elif section == "OUT" or arg.output:
                operand, temp = self.output_actual(arg.value, data_type)
                if temp is not None:
                    after.append((temp, arg.value))
            elif data_type is not None and self.structure_by_variable_index(arg.value, data_type):
                # A pointer to a computed place cannot be written in a CALL: the element goes
                # through a temporary, copied in before and (in/out) back after the call.
                access = self.access(arg.value)
                copied = em.temp(data_type)
                self.copy_parts(Access("local", copied.name), access, data_type, arg.loc)
                operand = em.ref(copied)
                copies.append((copied, access if section == "IN_OUT" else None))
            elif section == "IN_OUT":
                operand = self.operand(self.access(arg.value), arg.value.loc)
            else:
                operand, temp = self.input_actual(arg.value, data_type)
                if temp is not None:
                    used.append(temp)
            args.append(em.arg(spelling, operand))
        dropped = None
        if returns is not None and returns != Elementary("VOID") and result is None:
            dropped = result = em.temp(returns)  # a function called as a statement
        if result is not None and returns is not None:
            value = em.ref(result) if isinstance(result, Temp) else result  # or the target
            args.append(em.arg("RET_VAL", value))
        skip = done = ""
        if enable is not None:
            self.condition(enable)
            self.drop_hoisted()
            skip, done = em.new_label(), em.new_label()
            em.jump("JCN", skip)
        em.call(target, args)
        if dropped is not None:
            em.release(dropped)
        for temp in used:
            em.release(temp)
        for temp, place in after:
            self.store_from(temp, place)
            em.release(temp)
        for copied, back in copies:
            if back is not None:
                self.copy_parts(back, Access("local", copied.name), copied.type, em.loc)
            em.release(copied)
        if eno is not None:
            em.op("A", stl.BareNode("BR", None, em.loc))
            em.op("=", self.operand(self.access(eno), eno.loc))
        if enable is not None:
            em.jump("JU", done)
            em.place(skip)
            if eno is not None:
                em.op("CLR")
                em.op("=", self.operand(self.access(eno), eno.loc))
            else:
                em.op("NOP", em.literal("NUMBER", "0"))
            em.place(done)

    def input_actual(
        self, value: ast.Expr, formal: DataType | None
    ) -> tuple[stl.OperandNode, Temp | None]:
        em = self.em
        want = scalar(formal) if formal is not None else None
        constant = self.constant(value)
        if constant is not None and (want is not None or formal is None):
            kind, text = stl_constant(constant, want or self.scalar_of(value))
            if kind == "IDENT":  # TRUE/FALSE: STL reads them as names, as in `a := TRUE`
                return stl.BareNode(text, None, em.loc), None
            return em.literal(kind, text), None
        if self.passes_as_is(value, formal) or self.any_actual(value, formal):
            return self.operand(self.access(value), value.loc), None
        if formal is None or want is None or not isinstance(formal, Elementary | StringType):
            raise LoweringError(value.loc, "this actual parameter")
        temp = em.temp(formal)
        if want == "BOOL":
            self.condition(value)
            self.drop_hoisted()
            em.op("=", em.ref(temp))
        else:
            self.load_value(value, want)
            em.op("T", em.ref(temp))
        return em.ref(temp), temp

    def output_actual(
        self, value: ast.Expr, formal: DataType | None
    ) -> tuple[stl.OperandNode, Temp | None]:
        if self.passes_as_is(value, formal) or self.any_actual(value, formal):
            return self.operand(self.access(value), value.loc), None
        if formal is None or not isinstance(formal, Elementary):
            raise LoweringError(value.loc, "this output parameter")
        temp = self.em.temp(formal)
        return self.em.ref(temp), temp

    def structure_by_variable_index(self, value: ast.Expr, formal: DataType) -> bool:
        """A structured actual parameter (passed as a pointer) whose place depends on a
        variable index (``"Db".items[i].state``)."""
        structured = isinstance(formal, StructType | ArrayType)
        if not (structured or (isinstance(formal, BlockType) and formal.kind == "UDT")):
            return False
        if not self.is_variable(value):
            return False
        try:
            access = self.access(value)
        except LoweringError:
            return False
        return access.root in ("local", "db") and self.constant_path(access.path) is None

    def passes_as_is(self, value: ast.Expr, formal: DataType | None) -> bool:
        """A variable of the formal's own type, reached without set-up code."""
        if not self.is_variable(value) or id(value) in self.hoisted:
            return id(value) in self.hoisted and formal == self.hoisted[id(value)].type
        actual = self.type_of(value)
        if formal is not None and actual != formal and scalar(actual) != scalar(formal):
            return False
        try:
            access = self.access(value)
        except LoweringError:
            return False
        return self.plain(access)

    def any_actual(self, value: ast.Expr, formal: DataType | None) -> bool:
        """A variable of any type given to an ANY formal: passed as it is, the STL call makes
        the ANY of it (type and count of its declaration), as STEP 7's SCL does."""
        if formal != Elementary("ANY") or not self.is_variable(value) or id(value) in self.hoisted:
            return False
        try:
            return self.plain(self.access(value))
        except LoweringError:
            return False

    def store_from(self, temp: Temp, place: ast.Expr) -> None:
        em = self.em
        have = scalar(temp.type) or "INT"
        if have == "BOOL":
            em.op("A", em.ref(temp))
            em.op("=", self.operand(self.access(place), place.loc))
            return
        em.op("L", em.ref(temp))
        self.convert(have, self.scalar_of(place))
        em.op("T", self.operand(self.access(place), place.loc))

    # ---- S5 timers and counters -------------------------------------------------------------

    def timer_or_counter(self, node: ast.Call, name: str, want_value: bool) -> None:
        em = self.em
        args = {(arg.name or "").upper(): arg.value for arg in node.args}
        is_timer = name in TIMERS
        number = args.get("T_NO" if is_timer else "C_NO")
        if number is None:
            raise LoweringError(node.loc, f"{name} without {'T_NO' if is_timer else 'C_NO'}")
        unit = self.timer_operand(number, "T" if is_timer else "C")
        if is_timer:
            start = args.get("S")
            if start is not None:
                time = args.get("TV")
                saved = self.preload(time, "S5TIME")
                self.condition(start)
                self.drop_hoisted()
                self.load_preloaded(time, saved, "S5TIME")
                em.op(TIMERS[name], unit)
        else:
            for edge in COUNTERS[name]:
                if edge in args:
                    self.condition(args[edge])
                    self.drop_hoisted()
                    em.op(edge, unit)
            if "S" in args:
                preset = args.get("PV")
                saved = self.preload(preset, "WORD")
                self.condition(args["S"])
                self.drop_hoisted()
                self.load_preloaded(preset, saved, "WORD")
                em.op("S", unit)
        if "R" in args:
            self.condition(args["R"])
            self.drop_hoisted()
            em.op("R", unit)
        binary = args.get("BI" if is_timer else "CV")
        if binary is not None:
            em.op("L", unit)
            em.op("T", self.operand(self.access(binary), binary.loc))
        if "Q" in args:
            em.op("A", unit)
            em.op("=", self.operand(self.access(args["Q"]), args["Q"].loc))
        if want_value:
            em.op("LC", unit)

    def preload(self, value: ast.Expr | None, want: str) -> Temp | None:
        """A time or preset that needs code goes into a temporary before the logic string."""
        if value is None or self.simple(value):
            return None
        temp = self.em.temp(Elementary(want))
        self.load_value(value, want)
        self.em.op("T", self.em.ref(temp))
        return temp

    def load_preloaded(self, value: ast.Expr | None, temp: Temp | None, want: str) -> None:
        if temp is not None:
            self.em.op("L", self.em.ref(temp))
            self.em.release(temp)
        elif value is not None:
            self.load_value(value, want)
        else:
            self.em.load_text("TYPED", "S5T#0MS" if want == "S5TIME" else "W#16#0")

    def timer_operand(self, node: ast.Expr, area: str) -> stl.OperandNode:
        constant = self.constant(node)
        if constant is not None and constant.kind == "int":
            return stl.AddressNode(f"{area} {int(constant.number)}", node.loc)
        kind = self.scalar_of(node)
        if kind in ("TIMER", "COUNTER"):
            return self.operand(self.access(node), node.loc)
        temp = self.em.temp(Elementary("WORD"))
        self.load_value(node, "WORD")
        self.em.op("T", self.em.ref(temp))
        return stl.IndirectNode(area, self.em.ref(temp), None, node.loc)

    # ---- provided by the VARIANT part (``variant``) -------------------------------------------

    def descriptor_actual(
        self, value: ast.Expr, formal: DataType
    ) -> tuple[stl.OperandNode, Temp | None]:  # pragma: no cover
        raise NotImplementedError

    # ---- provided by the statements ---------------------------------------------------------

    def copy_parts(
        self, target: Access, source: Access, data_type: DataType, loc: ast.Loc
    ) -> None:  # pragma: no cover
        raise NotImplementedError

    # ---- provided by the standard functions -------------------------------------------------

    def function_value(self, node: ast.Call, name: str) -> None:  # pragma: no cover
        raise NotImplementedError

    def function_condition(self, node: ast.Call, name: str) -> None:  # pragma: no cover
        raise NotImplementedError

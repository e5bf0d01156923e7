"""Where SCL variables live, as STL operands.

A variable whose indices are all constant becomes a symbolic STL operand (``#motor.speed``,
``"Data".values[3]``, ``DB10.DBW 2``, ``MW 10``) and the STL compiler resolves it. A variable
index (``#values[i]``, ``MW[i]``, ``DB10.DW[i]``) is computed as STEP 7's SCL compiler does:
the bit offset goes into AR1 and the access is register-indirect, area-internal
(``DIW [AR1, P#0.0]`` in an FB, whose AR2 is added first so that multi-instances work;
``LW [AR1, P#0.0]`` for temporaries; ``DBW [AR1, P#0.0]`` after ``OPN DB n``). An array passed
to an FC is reached through its parameter pointer: ``L P##param`` gives the 6-byte DB pointer,
whose DB is opened and whose area pointer is added to the offset (``W [AR1, P#0.0]``,
area-crossing).

``operand`` may emit such set-up code, so its result must be used by the very next instruction.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.diagnostics import Diagnostic
from nasaq.ir import BlockKind
from nasaq.lang.layout import Slot
from nasaq.lang.scl import ast
from nasaq.lang.scl.bind import SclBlock, SclIndex
from nasaq.lang.scl.block_name import block_name
from nasaq.lang.scl.lower.emitter import Emitter, Temp
from nasaq.lang.scl.lower.literals import Value, evaluate
from nasaq.lang.scl.typecheck.context import Context
from nasaq.lang.scl.typecheck.operands import indexed_type
from nasaq.lang.scl.typecheck.rules import EXPRESSIONS
from nasaq.lang.scl.typecheck.types import (
    ANYTHING,
    BlockRef,
    DbRef,
    Special,
    Type,
    scalar,
    wider,
)
from nasaq.lang.stl import ast as stl
from nasaq.lang.stl.diag import problem
from nasaq.lang.types import ArrayType, DataType, Elementary, Field, StringType, type_text

_WIDTH_LETTER = {"BOOL": "X", "BYTE": "B", "CHAR": "B", "WORD": "W", "DWORD": "D"}
_DB_PARTS = {"DX": "DBX", "DB": "DBB", "DW": "DBW", "DD": "DBD", "D": "DBX"}
Selector = str | list[ast.Expr]
# Operators whose constant operands are folded at compile time (bit operations only on bit
# strings: a BOOL ``TRUE AND x`` is a condition, not a constant).
_FOLDED = frozenset(["+", "-", "*", "DIV", "MOD", "AND", "&", "OR", "XOR"])
# A variable index of a path: its index expressions, the array type, the element stride in bits.
Term = tuple[list[ast.Expr], ArrayType, int]


class LoweringError(Exception):
    """A construct the code generator cannot lower (reported as a diagnostic, block skipped)."""

    def __init__(self, loc: ast.Loc, what: str) -> None:
        super().__init__(what)
        self.loc = loc
        self.what = what


@dataclass(slots=True)
class Access:
    """A variable reference taken apart: ``root`` says where it starts.

    ``root``: ``local`` (a variable of the block: ``name``), ``db`` (``db`` number or ``name`` a
    DB symbol, ``path`` inside it), ``address`` (``name`` the absolute text), ``indexed``
    (``area`` with byte/bit expressions in ``indices``), ``ret`` (the FC's return value),
    ``ok`` (the OK flag / ENO), ``temp`` (a hidden temporary)."""

    root: str
    name: str = ""
    db: int | None = None
    db_expr: ast.Expr | None = None  # WORD_TO_BLOCK_DB(x).DW[i]
    path: list[Selector] = field(default_factory=list)
    area: str = ""
    indices: list[ast.Expr] = field(default_factory=list)
    temp: Temp | None = None


class Base:
    """State shared by the parts of the code generator for one block."""

    def __init__(
        self, index: SclIndex, block: SclBlock, em: Emitter, ctx: Context | None = None
    ) -> None:
        self.index = index
        self.block = block
        self.em = em
        self.ctx = ctx if ctx is not None else Context(index, block, EXPRESSIONS)
        self.checked = self.ctx.types  # id(expression) -> its type, as the checker found it
        self.diagnostics: list[Diagnostic] = []
        self.hoisted: dict[int, Temp] = {}  # id(call) -> the temporary that holds its value
        self.constants: dict[int, tuple[ast.Expr, Value | None]] = {}  # id -> (node, value)
        self.references: dict[str, Slot] | None = None  # an FB's by-reference slots by name
        self.loops: list[tuple[str, str]] = []  # (continue label, exit label), innermost last
        self.user_labels: dict[str, str] = {}
        self.ok: Temp | None = None  # the OK flag, when the block uses OK or ENO
        self.end_label = ""

    # ---- types ------------------------------------------------------------------------------

    def type_of(self, node: ast.Expr) -> Type:
        key = id(node)
        temp = self.hoisted.get(key)
        if temp is not None:
            return temp.type
        found = self.checked.get(key)  # the checker typed nearly everything already
        if found is None:
            found = self.ctx.type_of(node)
        if found is ANYTHING and isinstance(node, ast.Call):
            return self.selection_type(node)
        return found

    def selection_type(self, node: ast.Call) -> Type:
        """MAX, MIN, LIMIT, SEL, MUX take the common type of their inputs (the checker leaves
        them untyped)."""
        callee = node.callee
        name = callee.name.upper() if isinstance(callee, ast.Name | ast.Symbol) else ""
        symbol = self.index.symbol(name) if name else None
        if name == "TIME_TCK" or (
            symbol is not None
            and symbol.parsed.block is BlockKind.SFC
            and symbol.parsed.number == 64
        ):
            return Elementary("TIME")  # SFC 64 TIME_TCK: the system time in ms
        skip = {"SEL": ("G",), "MUX": ("K",)}.get(name, ())
        if name not in ("MAX", "MIN", "LIMIT", "SEL", "MUX"):
            return ANYTHING
        common: str | None = None
        for arg in node.args:
            if (arg.name or "").upper() in skip:
                continue
            kind = scalar(self.type_of(arg.value))
            if kind is None:
                return ANYTHING
            common = kind if common is None else (wider(common, kind) or common)
        return Elementary(common) if common is not None else ANYTHING

    def scalar_of(self, node: ast.Expr) -> str:
        data_type = self.type_of(node)
        found = scalar(data_type)
        if found is None:
            shown = data_type.name if isinstance(data_type, Special) else "a block"
            if isinstance(data_type, DataType):
                shown = type_text(data_type)
            raise LoweringError(node.loc, f"a value of type {shown}")
        return found

    def constant(self, node: ast.Expr) -> Value | None:
        """The value of a constant expression (folded, as S7-SCL does), None for others; asked
        again and again for the same nodes, so remembered."""
        known = self.constants.get(id(node))
        if known is not None:
            return known[1]
        found = self.fold(node)
        self.constants[id(node)] = (node, found)  # the node is kept, so its id stays its own
        return found

    def fold(self, node: ast.Expr) -> Value | None:
        """``evaluate`` where the parts are constants (known from ``constant``), so a long
        expression is not walked again at each of its levels."""
        kind = type(node)
        if kind is ast.Literal:
            return evaluate(node, self.index, self.block)
        if kind is ast.Paren:
            assert isinstance(node, ast.Paren)
            return self.constant(node.inner)
        if kind is ast.Name or kind is ast.Local:
            assert isinstance(node, ast.Name | ast.Local)
            if node.name.casefold() not in self.block.constants:
                return None
            return evaluate(node, self.index, self.block)
        if kind is ast.Unary:
            assert isinstance(node, ast.Unary)
            if self.constant(node.operand) is None:
                return None
            return evaluate(node, self.index, self.block)
        if kind is ast.Binary:
            assert isinstance(node, ast.Binary)
            if node.op not in _FOLDED or self.constant(node.left) is None:
                return None
            if self.constant(node.right) is None:
                return None
            return evaluate(node, self.index, self.block)  # constant folding, as S7-SCL does
        if kind is ast.Call:
            assert isinstance(node, ast.Call)
            name = block_name(node, self.block.name, self.constant)
            return None if name is None else evaluate(name, self.index, self.block)
        return None

    def report(self, code: str, loc: ast.Loc, **params: object) -> None:
        self.diagnostics.append(problem(code, self.block.file, loc, **params))

    # ---- taking variables apart -------------------------------------------------------------

    def access(self, node: ast.Expr) -> Access:
        if isinstance(node, ast.Paren):
            return self.access(node.inner)
        if id(node) in self.hoisted:
            return Access("temp", temp=self.hoisted[id(node)])
        if isinstance(node, ast.Name | ast.Local):
            return self.named(node.name, node, isinstance(node, ast.Local))
        if isinstance(node, ast.Symbol):
            return self.global_symbol(node.name, node)
        if isinstance(node, ast.Address):
            return self.absolute(node.text.lstrip("%").replace(" ", ""), node)
        if isinstance(node, ast.IndexedAddress):
            # an array called m, i, q ... read as an area; ``I[i, k]`` next to ``i : INT`` is
            # the input area (the checker's rule: only an array is indexed)
            array = self.ctx.variable(node.area)
            if array is not None and isinstance(array.type, ArrayType):
                return Access("local", array.name, path=[node.indices])
            return Access("indexed", area=node.area.upper().lstrip("%"), indices=node.indices)
        if isinstance(node, ast.Member):
            base_type = self.type_of(node.base)
            if isinstance(base_type, DbRef):
                return self.db_member(node, base_type)
            base = self.access(node.base)
            member = node.name
            if isinstance(member, ast.Name | ast.Symbol):
                base.path.append(member.name)
                return base
            raise LoweringError(node.loc, "this member access")
        if isinstance(node, ast.Index):
            base = self.access(node.base)
            text = isinstance(self.type_of(node.base), StringType)
            base.path.append(_CharIndex(node.indices) if text else node.indices)
            return base
        raise LoweringError(node.loc, "this expression as a variable")

    def named(self, name: str, node: ast.Expr, local: bool) -> Access:
        variable = self.ctx.variable(name)
        if variable is not None:
            return Access("local", variable.name)
        upper = name.upper()
        if upper in ("OK", "ENO") and not local:
            return Access("ok")
        if self.block.kind is BlockKind.FC and self.index.named(name) is self.block:
            return Access("ret")
        if not local:
            return self.global_symbol(name, node)
        raise LoweringError(node.loc, f"#{name}")

    def global_symbol(self, name: str, node: ast.Expr) -> Access:
        block = self.index.named(name)
        if block is not None and block.kind is BlockKind.DB:
            return Access("db", db=block.number)
        if block is self.block and block.kind is BlockKind.FC:
            return Access("ret")
        symbol = self.index.symbol(name)
        if symbol is None:
            # No global of that name: a "quoted" local, as the checker reads it (``symbol``
            # in ``typecheck.rules.undeclared``), or a local constant.
            variable = self.ctx.variable(name)
            if variable is not None:
                return Access("local", variable.name)
            raise LoweringError(node.loc, f'"{name}"')
        if symbol.parsed.kind == "block" and symbol.parsed.block is BlockKind.DB:
            return Access("db", db=symbol.parsed.number)
        return Access("address", name=symbol.address.replace(" ", ""))

    def absolute(self, text: str, node: ast.Expr) -> Access:
        upper = text.upper()
        if upper.startswith("DB") and upper[2:].isdigit():
            return Access("db", db=int(upper[2:]))
        own = self.block.kind is BlockKind.FC and self.index.named(upper) is self.block
        if upper.startswith("FC") and own:
            return Access("ret")
        return Access("address", name=upper)

    def db_member(self, node: ast.Member, db: DbRef) -> Access:
        # WORD_TO_BLOCK_DB(x).DW[i]: the DB is only known (and opened) at run time
        runtime = db.number is None
        base = Access("db", db_expr=node.base) if runtime else Access("db", db=db.number)
        member = node.name
        if isinstance(member, ast.Address):
            part = member.text.upper().replace(" ", "")
            base.path.append("@" + part)
            return base
        if isinstance(member, ast.IndexedAddress):
            base.root = "db"
            base.area = member.area.upper()
            base.indices = member.indices
            base.path.append("@indexed")
            return base
        base.path.append(member.name)
        return base

    # ---- operands ---------------------------------------------------------------------------

    def operand(self, access: Access, loc: ast.Loc) -> stl.OperandNode:
        """The STL operand of ``access``; emits set-up code (AR1, OPN) when indices vary."""
        em = self.em
        if access.root == "temp":
            assert access.temp is not None
            return em.ref(access.temp)
        if access.root == "ok":
            return em.ref(self.ok_flag())  # see ``Expressions.logic``: OS clears it too
        if access.root == "ret":
            return stl.SymbolNode("RET_VAL", True, [], loc)
        if access.root == "address":
            return stl.AddressNode(access.name, loc)
        if access.root == "indexed":
            return self.indexed_memory(access, loc)
        if access.root == "db":
            return self.db_operand(access, loc)
        constant = self.constant_path(access.path)
        if constant is not None and not (access.path and self.by_reference(access.name)):
            return stl.SymbolNode(access.name, True, constant, loc)
        return self.computed_local(access, loc)

    def by_reference(self, name: str) -> Slot | None:
        """The instance slot of an FB's structured IN_OUT, which holds a DB pointer."""
        if self.block.kind is not BlockKind.FB:
            return None
        if self.references is None:  # asked at every access: the slots by name, once
            slots, _ = self.index.instance_layout(self.block)
            self.references = {slot.name.upper(): slot for slot in slots if slot.by_reference}
        return self.references.get(name.upper())

    def plain(self, access: Access) -> bool:
        """Whether ``operand`` gives this access without set-up code (nothing in between the
        accumulators and the instruction that uses it)."""
        if access.root in ("indexed",) or access.indices or access.db_expr is not None:
            return False
        if access.root in ("temp", "ok", "ret", "address"):
            return True
        if self.constant_path(access.path) is None:
            return False
        return not (access.root == "local" and access.path and self.by_reference(access.name))

    def ok_flag(self) -> Temp:
        """The OK flag's temporary, made at its first use (the block sets it TRUE at its start,
        see ``blocks``); never one from the pool, whose earlier users would overwrite it."""
        if self.ok is None:
            self.ok = Temp(self.em.fresh_name(), Elementary("BOOL"))
            self.em.temps.append(self.ok)
        return self.ok

    def constant_path(self, path: list[Selector]) -> list[str | list[int] | stl.AddressNode] | None:
        result: list[str | list[int] | stl.AddressNode] = []
        for part in path:
            if isinstance(part, str):
                result.append(part)
                continue
            if type(part) is _CharIndex:
                return None  # STL has no name for a character of a STRING: by its offset
            numbers: list[int] = []
            for item in part:
                value = self.constant(item)
                if value is None or value.kind != "int":
                    return None
                numbers.append(int(value.number))
            result.append(numbers)
        return result

    def db_operand(self, access: Access, loc: ast.Loc) -> stl.OperandNode:
        em = self.em
        path = access.path
        if path and path[-1] == "@indexed":
            self.offset_into_ar1(access.indices, access.area, loc)
            self.open_db(access, loc)
            width = _DB_PARTS.get(access.area, "DB" + access.area[-1])
            return stl.IndirectNode(width, stl.BareNode("AR1", None, loc), _p0(loc), loc)
        if path and isinstance(path[0], str) and path[0].startswith("@"):
            part = path[0][1:]
            prefix = next((p for p in ("DBX", "DBB", "DBW", "DBD") if part.startswith(p)), None)
            if prefix is None:
                for short in ("DX", "DB", "DW", "DD", "D"):
                    if part.startswith(short):
                        prefix = _DB_PARTS[short]
                        part = part[len(short) :]
                        break
            else:
                part = part[3:]
            text = f"{prefix} {part}"
            if access.db is not None:
                return stl.AddressNode(f"DB{access.db}.{text}", loc)
            self.open_db(access, loc)
            return stl.AddressNode(text, loc)
        constant = self.constant_path(path)
        if constant is not None and access.db is not None:
            if not constant:
                raise LoweringError(loc, "a data block as a value")
            return stl.SymbolNode(f"DB{access.db}", False, constant, loc, absolute_db=True)
        if access.db is None:
            raise LoweringError(loc, "a member of a data block chosen at run time")
        db = self.index.get(BlockKind.DB, access.db)
        if db is None:
            raise LoweringError(loc, f"DB {access.db}")
        slots, _size = self.index.db_layout(db)
        slot, terms = self.walk(slots, path, loc)
        self.sum_offset(slot, terms, loc)
        em.op("LAR1")
        em.op("OPN", stl.AddressNode(f"DB {access.db}", loc))
        return self.register_operand("DB", slot.type, loc)

    def open_db(self, access: Access, loc: ast.Loc) -> None:
        if access.db is not None:
            self.em.op("OPN", stl.AddressNode(f"DB {access.db}", loc))
            return
        number = _block_db_number(access.db_expr)
        if number is None:
            raise LoweringError(loc, "a data block chosen at run time (not WORD_TO_BLOCK_DB)")
        temp = self.em.temp(Elementary("WORD"))
        self.load_value(number, "WORD")
        self.em.op("T", self.em.ref(temp))
        self.em.op("OPN", stl.IndirectNode("DB", self.em.ref(temp), None, loc))
        self.em.release(temp)

    def indexed_memory(self, access: Access, loc: ast.Loc) -> stl.OperandNode:
        self.offset_into_ar1(access.indices, access.area, loc)
        return stl.IndirectNode(access.area, stl.BareNode("AR1", None, loc), _p0(loc), loc)

    def offset_into_ar1(self, indices: list[ast.Expr], area: str, loc: ast.Loc) -> None:
        """``MW[i]`` / ``M[i, j]``: AR1 := byte * 8 (+ bit)."""
        _kind, count = indexed_type(area)
        em = self.em
        self.load_value(indices[0], "DINT")
        em.op("SLD", em.literal("NUMBER", "3"))
        if count == 2 and len(indices) > 1:
            temp = em.temp(Elementary("DINT"))
            em.op("T", em.ref(temp))
            self.load_value(indices[1], "DINT")
            em.op("L", em.ref(temp))
            em.op("+D")
            em.release(temp)
        em.op("LAR1")

    def computed_local(self, access: Access, loc: ast.Loc) -> stl.OperandNode:
        variable = self.ctx.variable(access.name)
        assert variable is not None
        em = self.em
        if variable.section == "TEMP":
            slots, _ = self.index.temp_layout(self.block)
            slot, terms = self.walk(slots, [access.name, *access.path], loc)
            self.sum_offset(slot, terms, loc)
            em.op("LAR1")
            return self.register_operand("L", slot.type, loc)
        pointer = self.by_reference(access.name)
        if pointer is not None:
            return self.through_pointer(access, variable.type, pointer.offset_bits, loc)
        if self.block.kind is BlockKind.FB:
            slots, _ = self.index.instance_layout(self.block)
            slot, terms = self.walk(slots, [access.name, *access.path], loc)
            self.sum_offset(slot, terms, loc)
            em.op("TAR2")
            em.op("AD", em.literal("TYPED", "DW#16#FFFFFF"))
            em.op("+D")
            em.op("LAR1")
            return self.register_operand("DI", slot.type, loc)
        # an FC parameter: its pointer is in the caller's frame, ``L P##param`` finds it
        return self.through_pointer(access, variable.type, None, loc)

    def through_pointer(
        self, access: Access, data_type: DataType, pointer_bits: int | None, loc: ast.Loc
    ) -> stl.OperandNode:
        """An element of a structure passed by reference (an FC parameter: ``pointer_bits``
        None; an FB's structured IN_OUT: the pointer's place in the instance). The 6-byte DB
        pointer (DB number, area pointer) is followed, area-crossing, as STEP 7 does."""
        em = self.em
        root = self.index.layout.place([Field(access.name, data_type)])
        slot, terms = self.walk(root, [access.name, *access.path], loc)
        self.sum_offset(slot, terms, loc)
        offset = em.temp(Elementary("DINT"))
        number = em.temp(Elementary("WORD"))
        em.op("T", em.ref(offset))
        if pointer_bits is None:
            em.op("L", em.literal("POINTER", f"P##{access.name}"))
            area = ""  # P##param points into the V area: area-crossing
        else:
            em.load_text(*_dint(pointer_bits))
            em.op("TAR2")
            em.op("AD", em.literal("TYPED", "DW#16#FFFFFF"))
            em.op("+D")
            area = "DI"
        em.op("LAR1")
        ar1 = stl.BareNode("AR1", None, loc)
        em.op("L", stl.IndirectNode(area + "W", ar1, _p0(loc), loc))
        em.op("T", em.ref(number))
        em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
        second = stl.LiteralNode("POINTER", "P#2.0", loc)
        em.op("L", stl.IndirectNode(area + "D", ar1, second, loc))
        em.op("L", em.ref(offset))
        em.op("+D")
        em.op("LAR1")
        em.release(offset)
        em.release(number)
        return self.register_operand("", slot.type, loc)

    def walk(
        self, slots: list[Slot], path: list[Selector], loc: ast.Loc
    ) -> tuple[Slot, list[Term]]:
        """The slot a path ends at (variable indices at their low bounds) and the variable
        terms: (index expressions, array dims, element stride in bits)."""
        current: Slot | None = None
        terms: list[Term] = []
        members = slots
        for part in path:
            if isinstance(part, str):
                wanted = part.upper()
                current = next((s for s in members if s.name.upper() == wanted), None)
                if current is None:
                    raise LoweringError(loc, part)
                members = current.members
                continue
            # TIA's s[i]: the characters after the header, addressed by offset (STL has no
            # name for them), whatever the index
            text = current is not None and isinstance(current.type, StringType)
            if text and current is not None:
                current = _characters(current)
            if current is None or not isinstance(current.type, ArrayType):
                raise LoweringError(loc, "this index")
            array = current.type
            lows: list[int] = []
            variable: list[ast.Expr] = []
            # With a variable index, the term sums every index of the list (``m[i, 1]``): the
            # element is then taken at the low bounds, the constant ones included.
            computed = text or any(self.constant(item) is None for item in part)
            for item, (low, _high) in zip(part, array.dims, strict=False):
                value = self.constant(item)
                known = value is not None and value.kind == "int" and not computed
                lows.append(int(value.number) if known and value is not None else low)
                variable.append(item)
            while len(lows) < len(array.dims):  # a row of a matrix
                lows.append(array.dims[len(lows)][0])
            element = self.index.layout.element(current, lows)
            if element is None:
                raise LoweringError(loc, "an index outside the array")
            if computed:
                stride = self.index.layout.stride(array.element)
                terms.append((variable, array, stride))
            current = element
            members = element.members
        if current is None:
            raise LoweringError(loc, "this variable")
        return current, terms

    def sum_offset(self, slot: Slot, terms: list[Term], loc: ast.Loc) -> None:
        """ACCU1 := the bit offset of the element (slot offset + index terms), as a DINT."""
        em = self.em
        em.load_text(*_dint(slot.offset_bits))
        for indices, array, stride in terms:
            saved = em.temp(Elementary("DINT"))
            em.op("T", em.ref(saved))
            first = True
            for position, (item, (low, high)) in enumerate(zip(indices, array.dims, strict=False)):
                if not first:
                    em.load_text(*_dint(high - low + 1))
                    em.op("*D")
                    partial = em.temp(Elementary("DINT"))
                    em.op("T", em.ref(partial))
                self.load_value(item, "DINT")
                if low:
                    em.load_text(*_dint(low))
                    em.op("-D")
                if not first:
                    em.op("L", em.ref(partial))
                    em.op("+D")
                    em.release(partial)
                first = False
                del position
            remaining = 1
            for low, high in array.dims[len(indices) :]:
                remaining *= high - low + 1
            em.load_text(*_dint(stride * remaining))
            em.op("*D")
            em.op("L", em.ref(saved))
            em.op("+D")
            em.release(saved)

    def register_operand(self, area: str, data_type: DataType, loc: ast.Loc) -> stl.OperandNode:
        name = scalar(data_type) if not isinstance(data_type, StringType) else None
        letter = _WIDTH_LETTER.get(name or "", "")
        if not letter:
            width = getattr(data_type, "bits", 0) if isinstance(data_type, Elementary) else 0
            letter = {16: "W", 32: "D", 8: "B", 1: "X"}.get(width, "")
        if not letter:
            raise LoweringError(loc, "a structured element chosen by a variable index")
        prefix = area + letter if area else letter
        if area == "" and letter == "X":
            prefix = ""
        return stl.IndirectNode(prefix or None, stl.BareNode("AR1", None, loc), _p0(loc), loc)

    # ---- provided by the expression part ----------------------------------------------------

    def load_value(self, node: ast.Expr, want: str) -> None:  # pragma: no cover - overridden
        raise NotImplementedError


def _block_db_number(node: ast.Expr | None) -> ast.Expr | None:
    """The DB number inside ``WORD_TO_BLOCK_DB(number)``."""
    while isinstance(node, ast.Paren):
        node = node.inner
    if not isinstance(node, ast.Call) or len(node.args) != 1:
        return None
    callee = node.callee
    if not isinstance(callee, ast.Name) or callee.name.upper() != "WORD_TO_BLOCK_DB":
        return None
    return node.args[0].value


def _p0(loc: ast.Loc) -> stl.LiteralNode:
    return stl.LiteralNode("POINTER", "P#0.0", loc)


def _dint(number: int) -> tuple[str, str]:
    return "TYPED", f"L#{number}"


__all__ = ["Access", "Base", "BlockRef", "LoweringError"]


def _characters(text: Slot) -> Slot | None:
    """A (W)STRING slot as the array of its characters ``[1..n]`` after the two length
    fields; None for a STRING held by reference (its characters are elsewhere)."""
    data_type = text.type
    if not isinstance(data_type, StringType) or text.by_reference:
        return None
    char = Elementary("WCHAR" if data_type.wide else "CHAR")
    header = 16 * data_type.char_bytes
    chars = ArrayType(((1, max(1, data_type.length)),), char)
    size = text.size_bits - header
    return Slot(text.name, chars, text.offset_bits + header, size, section=text.section)


class _CharIndex(list[ast.Expr]):
    """The index of a character of a (W)STRING in an access path (``s[i]``, TIA)."""

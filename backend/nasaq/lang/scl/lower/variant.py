"""VARIANT and ``ARRAY[*]`` parameters in STL (S7-1200/1500): the descriptor at work.

The representation is ``nasaq.lang.scl.descriptor``'s: the caller fills a descriptor (an ANY
pointer as STEP 7 builds it, then the UDT number, the dimensions, the element count, the
size and the bounds) in a temporary and passes it as a structure. So:

- **caller** (``descriptor_actual``): TYPE, COUNT, UDT, DIMS, ELEMENTS, BYTES and BOUNDS are
  constants of the actual's declared type; DB and PTR are computed at run time as STEP 7
  computes an ANY's: a DB variable ``16#84`` with its DB, an FB's static variable ``16#84``
  with the instance DB (``DINO``) and AR2's offset added (multi-instances), a temporary
  ``16#87`` (the caller's local data as the callee sees it), a structure the caller itself
  got by pointer (an FC parameter, an FB's in/out) the pointer it got. A VARIANT or
  ``ARRAY[*]`` parameter given to another one is passed on as it is.
- **callee** (``descriptor_operand``): ``#arr[i, j].x`` reads the descriptor through the
  parameter (``L P##arr`` in an FC, the instance's DB pointer for an FB's in/out, the
  instance itself for an FB's VARIANT input), computes the element's bit offset from the
  bounds at run time (row-major, as S7 stores arrays) and reaches it register-indirect,
  area-crossing (``W [AR1, P#0.0]`` after ``OPN DB``).
- **instructions**: ``LOWER_BOUND``/``UPPER_BOUND`` read BOUNDS, ``CountOfElements``
  ELEMENTS (0 when no array, as TIA Portal), ``IS_ARRAY`` DIMS <> 0, ``TypeOf(v) = T``
  compares TYPE and UDT (and DIMS = 0), ``TypeOfElements(v) = T`` TYPE and UDT.

Not done (COMPATIBILITY.md "VARIANT, ARRAY[*], DB_ANY"): a temporary given to a VARIANT that
is passed on a second time (its ``16#87`` pointer means the next caller's local data there);
no index check against the actual's bounds (a real S7-1500 reports an access error).
"""

from __future__ import annotations

from nasaq.ir import BlockKind
from nasaq.lang.scl import ast
from nasaq.lang.scl.descriptor import (
    CODES,
    OFFSETS,
    STRUCTURE,
    VARIANT,
    DbAnyType,
    OpenArray,
    VariantParam,
    is_descriptor,
    type_code,
    udt_number,
)
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.literals import Value, stl_constant
from nasaq.lang.scl.lower.long_functions import LongFunctions
from nasaq.lang.scl.lower.places import Access, LoweringError
from nasaq.lang.scl.typecheck import variant as checks
from nasaq.lang.scl.typecheck.types import DbRef, scalar
from nasaq.lang.stl import ast as stl
from nasaq.lang.types import (
    ArrayType,
    BlockType,
    DataType,
    Elementary,
    Field,
    StringType,
    StructType,
)

DINT, WORD, BOOL = Elementary("DINT"), Elementary("WORD"), Elementary("BOOL")
DWORD = Elementary("DWORD")
# RET_VAL when the bytes do not fit (TIA's "value outside the array" of Serialize/Deserialize;
# Nasaq gives it to MOVE_BLK_VARIANT, VariantGet and VariantPut too: COMPATIBILITY.md)
_OUTSIDE = "W#16#8382"
_DB_AREA, _DI_AREA, _V_AREA = "DW#16#84000000", "DW#16#85000000", "DW#16#87000000"
_PARAMS = ("IN", "OUT", "IN_OUT")
_EN = ("EN", "ENO")


class Variants(LongFunctions):
    # ---- the callee: elements and fields -----------------------------------------------------

    def descriptor_of(self, access: Access) -> DataType | None:
        if access.root != "local":
            return None
        variable = self.ctx.variable(access.name)
        if variable is None or not is_descriptor(variable.type):
            return None
        return variable.type

    def operand(self, access: Access, loc: ast.Loc) -> stl.OperandNode:
        found = self.descriptor_of(access)
        if found is not None:
            return self.descriptor_operand(access, found, loc)
        return super().operand(access, loc)

    def plain(self, access: Access) -> bool:
        if self.descriptor_of(access) is not None and access.path:
            return False
        return super().plain(access)

    def locate_descriptor(self, name: str, loc: ast.Loc) -> None:
        """AR1 := an area-crossing pointer to the descriptor of parameter ``name`` (its DB
        opened when it lies in one)."""
        em = self.em
        ar1 = stl.BareNode("AR1", None, loc)
        pointer = self.by_reference(name)
        number = em.temp(WORD)
        if pointer is not None:  # an FB's in/out: the instance holds a DB pointer to it
            em.load_text("TYPED", f"L#{pointer.offset_bits}")
            self.instance_offset()
            em.op("LAR1")
            em.op("L", stl.IndirectNode("DIW", ar1, _at(0, loc), loc))
            em.op("T", em.ref(number))
            em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
            em.op("L", stl.IndirectNode("DID", ar1, _at(2, loc), loc))
            em.op("LAR1")
        elif self.block.kind is BlockKind.FB:  # an FB's VARIANT input: in the instance
            slots, _ = self.index.instance_layout(self.block)
            slot = next(s for s in slots if s.name.upper() == name.upper())
            em.load_text("TYPED", f"L#{slot.offset_bits}")
            self.instance_offset()
            em.load_text("TYPED", _DI_AREA)
            em.op("OD")
            em.op("LAR1")
        else:  # an FC parameter: ``P##name`` points at the DB pointer the caller made
            em.op("L", em.literal("POINTER", f"P##{name}"))
            em.op("LAR1")
            em.op("L", stl.IndirectNode("W", ar1, _at(0, loc), loc))
            em.op("T", em.ref(number))
            em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
            em.op("L", stl.IndirectNode("D", ar1, _at(2, loc), loc))
            em.op("LAR1")
        em.release(number)

    def instance_offset(self) -> None:
        """ACCU1 := ACCU1 + AR2's byte offset (the multi-instance's place in the DI)."""
        em = self.em
        em.op("TAR2")
        em.op("AD", em.literal("TYPED", "DW#16#FFFFFF"))
        em.op("+D")

    def field(self, name: str, offset: int, width: str, loc: ast.Loc) -> stl.OperandNode:
        """A descriptor field after ``locate_descriptor`` (``D [AR1, P#14.0]``)."""
        ar1 = stl.BareNode("AR1", None, loc)
        return stl.IndirectNode(width, ar1, _at(OFFSETS[name] + offset, loc), loc)

    def descriptor_operand(
        self, access: Access, data_type: DataType, loc: ast.Loc
    ) -> stl.OperandNode:
        """``#arr[i, j].member`` of an ``ARRAY[*]`` parameter, register-indirect."""
        em = self.em
        path = access.path
        if not isinstance(data_type, OpenArray) or not path or isinstance(path[0], str):
            raise LoweringError(loc, f"#{access.name} as a value")
        indices = path[0]
        if len(indices) != data_type.dims:
            raise LoweringError(loc, "a row of an ARRAY[*]")
        root = self.index.layout.place([Field("e", data_type.element)])
        slot, terms = self.walk(root, ["e", *path[1:]], loc)
        if terms:
            raise LoweringError(loc, "a variable index inside an element of an ARRAY[*]")
        values: list[Temp] = []
        for item in indices:  # before AR1 and the DB register are set: they may use them
            temp = em.temp(DINT)
            self.load_value(item, "DINT")
            em.op("T", em.ref(temp))
            values.append(temp)
        self.locate_descriptor(access.name, loc)
        linear = em.temp(DINT)
        for k, temp in enumerate(values):
            low = self.field("BOUNDS", 8 * k, "D", loc)
            if k:
                em.op("L", self.field("BOUNDS", 8 * k + 4, "D", loc))
                em.op("L", self.field("BOUNDS", 8 * k, "D", loc))
                em.op("-D")
                em.load_text("TYPED", "L#1")
                em.op("+D")
                em.op("L", em.ref(linear))
                em.op("*D")
                em.op("T", em.ref(linear))
            em.op("L", em.ref(temp))
            em.op("L", low)
            em.op("-D")
            if k:
                em.op("L", em.ref(linear))
                em.op("+D")
            em.op("T", em.ref(linear))
            em.release(temp)
        stride = self.index.layout.stride(data_type.element)
        em.op("L", em.ref(linear))
        em.load_text("TYPED", f"L#{stride}")
        em.op("*D")
        if slot.offset_bits:
            em.load_text("TYPED", f"L#{slot.offset_bits}")
            em.op("+D")
        em.op("T", em.ref(linear))
        number = em.temp(WORD)
        em.op("L", self.field("DB", 0, "W", loc))
        em.op("T", em.ref(number))
        em.op("L", self.field("PTR", 0, "D", loc))
        em.op("L", em.ref(linear))
        em.op("+D")
        em.op("LAR1")
        em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
        em.release(number)
        em.release(linear)
        return self.register_operand("", slot.type, loc)

    # ---- the caller: building a descriptor ---------------------------------------------------

    def descriptor_actual(
        self, value: ast.Expr, formal: DataType
    ) -> tuple[stl.OperandNode, Temp | None]:
        """The actual for a VARIANT/``ARRAY[*]`` formal: a descriptor in a temporary, or the
        caller's own descriptor parameter passed on."""
        em = self.em
        loc = value.loc
        while isinstance(value, ast.Paren):
            value = value.inner
        actual = self.type_of(value)
        access = self.access(value)
        if isinstance(actual, DataType) and is_descriptor(actual):
            if access.root != "local" or access.path:
                raise LoweringError(loc, "this VARIANT actual")
            return stl.SymbolNode(access.name, True, [], loc), None
        if not isinstance(actual, DataType):
            raise LoweringError(loc, "this VARIANT actual")
        temp = em.temp(formal)
        self.fill_constants(temp, actual, loc)
        self.address_into(access, temp, loc)
        return em.ref(temp), temp

    def set_field(self, temp: Temp, name: str, kind: str, text: str, loc: ast.Loc) -> None:
        self.em.load_text(kind, text)
        self.em.op("T", stl.SymbolNode(temp.name, True, [name], loc))

    def fill_constants(self, temp: Temp, actual: DataType, loc: ast.Loc) -> None:
        size = (self.index.layout.size_bits(actual) + 7) // 8
        dims = actual.dims if isinstance(actual, ArrayType) else ()
        elements = actual.count if isinstance(actual, ArrayType) else 1
        code = type_code(actual)
        structured = code == STRUCTURE and not _is_byte(actual)
        count = size if structured else elements
        self.set_field(temp, "ID", "TYPED", "B#16#10", loc)
        self.set_field(temp, "TYPE", "TYPED", f"B#16#{code:02X}", loc)
        self.set_field(temp, "COUNT", "TYPED", f"W#16#{count & 0xFFFF:04X}", loc)
        self.set_field(temp, "UDT", "TYPED", f"W#16#{udt_number(actual):04X}", loc)
        self.set_field(temp, "DIMS", "NUMBER", str(len(dims)), loc)
        self.set_field(temp, "ELEMENTS", "TYPED", f"L#{elements if dims else 1}", loc)
        self.set_field(temp, "BYTES", "TYPED", f"L#{size}", loc)
        for k, (low, high) in enumerate(dims):
            for offset, bound in ((0, low), (1, high)):
                self.em.load_text("TYPED", f"L#{bound}")
                node = stl.SymbolNode(temp.name, True, ["BOUNDS", [2 * k + offset + 1]], loc)
                self.em.op("T", node)

    def address_into(self, access: Access, temp: Temp, loc: ast.Loc) -> None:
        """DB and PTR of the descriptor: where the actual lies, computed at run time."""
        em = self.em
        ptr = stl.SymbolNode(temp.name, True, ["PTR"], loc)
        db = stl.SymbolNode(temp.name, True, ["DB"], loc)
        plain_db = access.root == "db" and access.db is not None and access.db_expr is None
        if plain_db and access.path and not _absolute_part(access):
            block = self.index.get(BlockKind.DB, access.db or 0)
            if block is None:
                raise LoweringError(loc, f"DB {access.db} as a VARIANT actual")
            slots, _ = self.index.db_layout(block)
            slot, terms = self.walk(slots, access.path, loc)
            self.sum_offset(slot, terms, loc)
            em.load_text("TYPED", _DB_AREA)
            em.op("OD")
            em.op("T", ptr)
            em.load_text("TYPED", f"W#16#{access.db or 0:04X}")
            em.op("T", db)
            return
        variable = self.ctx.variable(access.name) if access.root == "local" else None
        if variable is None:
            raise LoweringError(loc, "this actual for a VARIANT or ARRAY[*] parameter")
        if variable.section == "TEMP":
            slots, _ = self.index.temp_layout(self.block)
            slot, terms = self.walk(slots, [access.name, *access.path], loc)
            self.sum_offset(slot, terms, loc)
            em.load_text("TYPED", _V_AREA)  # the caller's local data, as the callee sees it
            em.op("OD")
            em.op("T", ptr)
            em.load_text("TYPED", "W#16#0")
            em.op("T", db)
            return
        pointer = self.by_reference(access.name)
        by_pointer = self.block.kind is BlockKind.FC and variable.section in _PARAMS
        if pointer is not None or by_pointer:
            if not _structured(variable.type):
                raise LoweringError(loc, "an elementary FC parameter as a VARIANT actual")
            self.follow_pointer(access, variable.type, pointer.offset_bits if pointer else None)
            em.op("TAR1")
            em.op("T", ptr)
            em.op("L", stl.BareNode("DBNO", None, loc))
            em.op("T", db)
            return
        if self.block.kind is not BlockKind.FB:
            raise LoweringError(loc, "this actual for a VARIANT or ARRAY[*] parameter")
        slots, _ = self.index.instance_layout(self.block)
        slot, terms = self.walk(slots, [access.name, *access.path], loc)
        self.sum_offset(slot, terms, loc)
        self.instance_offset()
        em.load_text("TYPED", _DB_AREA)
        em.op("OD")
        em.op("T", ptr)
        em.op("L", stl.BareNode("DINO", None, loc))
        em.op("T", db)

    def follow_pointer(self, access: Access, data_type: DataType, pointer_bits: int | None) -> None:
        """AR1 := the actual's place inside a structure the block got by pointer (DB opened),
        as ``places.through_pointer`` reaches its elements."""
        em = self.em
        loc = em.loc
        root = self.index.layout.place([Field(access.name, data_type)])
        slot, terms = self.walk(root, [access.name, *access.path], loc)
        self.sum_offset(slot, terms, loc)
        offset, number = em.temp(DINT), em.temp(WORD)
        em.op("T", em.ref(offset))
        area = ""
        if pointer_bits is None:
            em.op("L", em.literal("POINTER", f"P##{access.name}"))
        else:
            em.load_text("TYPED", f"L#{pointer_bits}")
            self.instance_offset()
            area = "DI"
        em.op("LAR1")
        ar1 = stl.BareNode("AR1", None, loc)
        em.op("L", stl.IndirectNode(area + "W", ar1, _at(0, loc), loc))
        em.op("T", em.ref(number))
        em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
        em.op("L", stl.IndirectNode(area + "D", ar1, _at(2, loc), loc))
        em.op("L", em.ref(offset))
        em.op("+D")
        em.op("LAR1")
        em.release(offset)
        em.release(number)

    # ---- instructions ------------------------------------------------------------------------

    def function_value(self, node: ast.Call, name: str) -> None:
        if name not in checks.NAMES:
            super().function_value(node, name)
            return
        em = self.em
        if name in checks.COPIES:
            self.copy_instruction(node, name)
            return
        if name in checks.MEMORY_PARAMS:
            self.peek_or_poke(node, name)
            return
        if name in ("DB_ANY_TO_UINT", "UINT_TO_DB_ANY"):  # the number's 16 bits as they are
            (value,) = [a.value for a in node.args if (a.name or "").upper() not in _EN]
            self.load_db_number(value)
            return
        target = self.descriptor_argument(node)
        self.locate_descriptor(target, node.loc)
        if name in checks.BOUNDS:
            dim = self.dimension(node)
            offset = 8 * (dim - 1) + (4 if name == "UPPER_BOUND" else 0)
            em.op("L", self.field("BOUNDS", offset, "D", node.loc))
        elif name == "COUNTOFELEMENTS":  # TIA: 0 for a VARIANT that points at no array
            done = em.new_label()
            em.load_text("TYPED", "L#0")
            em.op("L", self.field("DIMS", 0, "W", node.loc))
            em.op("==I")
            em.jump("JC", done)
            em.op("L", self.field("ELEMENTS", 0, "D", node.loc))
            em.place(done)
        elif name == "IS_ARRAY":
            self.function_condition(node, name)
        else:
            raise LoweringError(node.loc, f"{checks.name_spelling(name)} outside a comparison")

    # ---- copies: Serialize, Deserialize, VariantGet, VariantPut, MOVE_BLK_VARIANT -------------

    def copy_instruction(self, node: ast.Call, name: str) -> None:
        """The copying instructions, byte by byte between the two places (their descriptors);
        ACCU1 := RET_VAL (0, or ``_OUTSIDE`` when the bytes do not fit: nothing copied)."""
        em = self.em
        args = {(a.name or "").upper(): a.value for a in node.args}
        source_name, target_name, order = checks.COPIES[name]
        for number, arg in enumerate(node.args):
            if arg.name is None:
                args[order[number]] = arg.value
        source = self.endpoint(args[source_name])
        target = self.endpoint(args[target_name])
        count, from_at, to_at = em.temp(DINT), em.temp(DINT), em.temp(DINT)
        position = args.get("POS")
        em.load_text("TYPED", "L#0")
        em.op("T", em.ref(from_at))
        em.op("T", em.ref(to_at))
        if name == "SERIALIZE" or name == "DESERIALIZE":
            assert position is not None
            self.load_value(position, "DINT")
            em.op("T", em.ref(to_at if name == "SERIALIZE" else from_at))
            em.op("L", em.ref((source if name == "SERIALIZE" else target)[2]))
        elif name == "MOVE_BLK_VARIANT":  # COUNT elements of SRC's size, zero-based indices
            size = em.temp(DINT)
            em.op("L", em.ref(source[2]))
            em.op("L", em.ref(source[3]))
            em.op("/D")
            em.op("T", em.ref(size))
            for key, temp in (("SRC_INDEX", from_at), ("DEST_INDEX", to_at)):
                self.load_value(args[key], "DINT")
                em.op("L", em.ref(size))
                em.op("*D")
                em.op("T", em.ref(temp))
            self.load_value(args["COUNT"], "DINT")
            em.op("L", em.ref(size))
            em.op("*D")
            em.release(size)
        else:  # VariantGet / VariantPut: the whole variable, of the same size
            em.op("L", em.ref(source[2]))
        em.op("T", em.ref(count))
        outside, done = em.new_label(), em.new_label()
        for at, (_db, _ptr, size_temp, _n) in ((from_at, source), (to_at, target)):
            em.op("L", em.ref(at))
            em.load_text("TYPED", "L#0")
            em.op("<D")
            em.jump("JC", outside)
            em.op("L", em.ref(at))
            em.op("L", em.ref(count))
            em.op("+D")
            em.op("L", em.ref(size_temp))
            em.op(">D")
            em.jump("JC", outside)
        if name in ("VARIANTGET", "VARIANTPUT"):
            em.op("L", em.ref(count))
            em.op("L", em.ref(target[2]))
            em.op("<>D")
            em.jump("JC", outside)
        self.copy_loop(source, target, count, from_at, to_at)
        if position is not None:  # POS moves past the bytes copied
            self.load_value(position, "DINT")
            em.op("L", em.ref(count))
            em.op("+D")
            em.op("T", self.operand(self.access(position), position.loc))
        em.load_text("NUMBER", "0")
        em.jump("JU", done)
        em.place(outside)
        em.load_text("TYPED", _OUTSIDE)
        em.place(done)
        for temp in (*source, *target, count, from_at, to_at):
            em.release(temp)

    def endpoint(self, value: ast.Expr) -> tuple[Temp, Temp, Temp, Temp]:
        """(DB, PTR, BYTES, ELEMENTS) of a place, from its descriptor, in temporaries."""
        em = self.em
        inner = value
        while isinstance(inner, ast.Paren):
            inner = inner.inner
        fields = (
            ("DB", WORD, "W"),
            ("PTR", DWORD, "D"),
            ("BYTES", DINT, "D"),
            ("ELEMENTS", DINT, "D"),
        )
        temps = tuple(em.temp(kind) for _name, kind, _width in fields)
        actual = self.type_of(inner)
        if isinstance(actual, DataType) and is_descriptor(actual):
            name = self.descriptor_argument_of(inner)
            self.locate_descriptor(name, inner.loc)
            for temp, (field_name, _kind, width) in zip(temps, fields, strict=True):
                em.op("L", self.field(field_name, 0, width, inner.loc))
                em.op("T", em.ref(temp))
        else:
            _operand, built = self.descriptor_actual(inner, VARIANT)
            assert built is not None
            for temp, (field_name, _kind, _width) in zip(temps, fields, strict=True):
                em.op("L", stl.SymbolNode(built.name, True, [field_name], inner.loc))
                em.op("T", em.ref(temp))
            em.release(built)
        return temps[0], temps[1], temps[2], temps[3]

    def copy_loop(
        self,
        source: tuple[Temp, Temp, Temp, Temp],
        target: tuple[Temp, Temp, Temp, Temp],
        count: Temp,
        from_at: Temp,
        to_at: Temp,
    ) -> None:
        """``count`` bytes from ``source`` + ``from_at`` to ``target`` + ``to_at``."""
        em = self.em
        loc = em.loc
        index, byte = em.temp(DINT), em.temp(Elementary("BYTE"))
        top, end = em.new_label(), em.new_label()
        em.load_text("TYPED", "L#0")
        em.op("T", em.ref(index))
        em.place(top)
        em.op("L", em.ref(index))
        em.op("L", em.ref(count))
        em.op(">=D")
        em.jump("JC", end)
        ar1 = stl.BareNode("AR1", None, loc)
        for (number, pointer, _size, _n), at, load in (
            (source, from_at, True),
            (target, to_at, False),
        ):
            em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
            em.op("L", em.ref(index))
            em.op("L", em.ref(at))
            em.op("+D")
            em.op("SLD", em.literal("NUMBER", "3"))
            em.op("L", em.ref(pointer))
            em.op("+D")
            em.op("LAR1")
            if load:
                em.op("L", stl.IndirectNode("B", ar1, _at(0, loc), loc))
                em.op("T", em.ref(byte))
            else:
                em.op("L", em.ref(byte))
                em.op("T", stl.IndirectNode("B", ar1, _at(0, loc), loc))
        em.op("L", em.ref(index))
        em.load_text("TYPED", "L#1")
        em.op("+D")
        em.op("T", em.ref(index))
        em.jump("JU", top)
        em.place(end)
        em.release(index)
        em.release(byte)

    # ---- DB_ANY, PEEK and POKE ----------------------------------------------------------------

    def input_actual(
        self, value: ast.Expr, formal: DataType | None
    ) -> tuple[stl.OperandNode, Temp | None]:
        if isinstance(formal, DbAnyType) and isinstance(self.type_of(value), DbRef):
            number = self.type_of(value)
            assert isinstance(number, DbRef)
            assert number.number is not None
            temp = self.em.temp(Elementary("UINT"))  # STL takes no constant for a UINT
            self.load_db_number(value)
            self.em.op("T", self.em.ref(temp))
            return self.em.ref(temp), temp
        return super().input_actual(value, formal)

    def load_db_number(self, value: ast.Expr) -> None:
        """ACCU1 := a DB number: a DB (``"Data"``, DB5) or a DB_ANY/UINT value."""
        found = self.type_of(value)
        if isinstance(found, DbRef) and found.number is not None:
            self.em.load_text(*stl_constant(Value("int", found.number), "UINT"))
            return
        self.load_value(value, "UINT")

    def peek_or_poke(self, node: ast.Call, name: str) -> None:
        """PEEK/POKE (TIA): the area a constant, the byte (and bit) offset computed at run
        time, the DB opened from its number; register-indirect, area-internal."""
        em = self.em
        loc = node.loc
        order = checks.MEMORY_PARAMS[name]
        args: dict[str, ast.Expr] = {}
        position = 0
        for arg in node.args:
            key = (arg.name or "").upper()
            if key in _EN:
                continue
            args[key or order[position]] = arg.value
            position += 1
        area = checks.memory_area(self.ctx, args["AREA"])
        if area is None:
            raise LoweringError(loc, f"{name} of this area")
        value = args.get("VALUE")
        kept: Temp | None = None
        width = (
            "X" if name.endswith("_BOOL") else {"PEEK_WORD": "W", "PEEK_DWORD": "D"}.get(name, "B")
        )
        if value is not None:  # computed first: it may use AR1 and the DB register
            kind = "BOOL" if name == "POKE_BOOL" else self.poke_kind(value)
            width = {"BOOL": "X", "BYTE": "B", "WORD": "W", "DWORD": "D"}[kind]
            kept = em.temp(Elementary(kind))
            if kind == "BOOL":
                self.condition(value)
                self.drop_hoisted()
                em.op("=", em.ref(kept))
            else:
                self.load_value(value, kind)
                em.op("T", em.ref(kept))
        number = em.temp(WORD)
        if area == "DB":
            self.load_db_number(args["DBNUMBER"])
            em.op("T", em.ref(number))
        offset = em.temp(DINT)
        self.load_value(args["BYTEOFFSET"], "DINT")
        em.op("SLD", em.literal("NUMBER", "3"))
        if "BITOFFSET" in args:
            em.op("T", em.ref(offset))
            self.load_value(args["BITOFFSET"], "DINT")
            em.op("L", em.ref(offset))
            em.op("+D")
        em.op("LAR1")
        if area == "DB":
            em.op("OPN", stl.IndirectNode("DB", em.ref(number), None, loc))
        prefix = ("DB" if area == "DB" else area) + width
        if prefix == "DBX" or width != "X":
            target = stl.IndirectNode(prefix, stl.BareNode("AR1", None, loc), _at(0, loc), loc)
        else:  # I, Q, M bits
            target = stl.IndirectNode(area, stl.BareNode("AR1", None, loc), _at(0, loc), loc)
        if kept is not None:
            em.op("A" if width == "X" else "L", em.ref(kept))
            em.op("=" if width == "X" else "T", target)
            em.release(kept)
        elif width == "X":
            em.op("A", target)
        else:
            em.op("L", target)
        em.release(number)
        em.release(offset)

    def poke_kind(self, value: ast.Expr) -> str:
        kind = scalar(self.type_of(value))
        return kind if kind in ("BYTE", "WORD", "DWORD") else "BYTE"

    def function_condition(self, node: ast.Call, name: str) -> None:
        if name == "PEEK_BOOL":
            self.peek_or_poke(node, name)
            return
        if name != "IS_ARRAY":
            super().function_condition(node, name)
            return
        em = self.em
        self.locate_descriptor(self.descriptor_argument(node), node.loc)
        em.op("L", self.field("DIMS", 0, "W", node.loc))
        em.load_text("NUMBER", "0")
        em.op("<>I")

    def descriptor_argument(self, node: ast.Call) -> str:
        """The name of the VARIANT/``ARRAY[*]`` parameter an instruction is given."""
        args = [a for a in node.args if (a.name or "").upper() not in ("EN", "ENO", "DIM")]
        if not args:
            raise LoweringError(node.loc, "this argument of a VARIANT instruction")
        return self.descriptor_argument_of(args[0].value)

    def descriptor_argument_of(self, value: ast.Expr) -> str:
        while isinstance(value, ast.Paren):
            value = value.inner
        if isinstance(value, ast.Name | ast.Local):
            variable = self.ctx.variable(value.name)
            if variable is not None and is_descriptor(variable.type):
                return variable.name
        raise LoweringError(value.loc, "this argument of a VARIANT instruction")

    def dimension(self, node: ast.Call) -> int:
        args = [a for a in node.args if (a.name or "").upper() not in ("EN", "ENO")]
        named = [a for a in args if (a.name or "").upper() == "DIM"]
        value = named[0].value if named else args[1].value
        number = checks.constant_dimension(self.ctx, value)
        if number is None:
            raise LoweringError(value.loc, "a dimension that is no constant")
        return number

    # ---- TypeOf(v) = T ------------------------------------------------------------------------

    def hoist(self, node: ast.Expr) -> None:
        if isinstance(node, ast.Binary) and checks.type_test(node) is not None:
            if id(node) not in self.hoisted:
                self.hoisted[id(node)] = self.type_test_result(node)
            return
        super().hoist(node)

    def compare(self, node: ast.Binary) -> None:
        temp = self.hoisted.get(id(node))
        if temp is not None:
            self.em.op("A", self.em.ref(temp))
            return
        super().compare(node)

    def type_test_result(self, node: ast.Binary) -> Temp:
        found = checks.type_test(node)
        assert found is not None
        call, other = found
        wanted = checks.named_type(self.ctx, other)
        if wanted is None:
            raise LoweringError(other.loc, "this data type")
        em = self.em
        name = checks.name_of(call) or ""
        self.locate_descriptor(self.descriptor_argument(call), node.loc)
        code = CODES.get(wanted.name, STRUCTURE) if isinstance(wanted, Elementary) else None
        if isinstance(wanted, StringType):
            code = CODES[wanted.name]
        if code is None:
            code = type_code(wanted)
        result = em.temp(BOOL)
        em.op("L", self.field("TYPE", 0, "B", node.loc))
        em.load_text("NUMBER", str(code))
        em.op("==I")
        em.op("A(")
        em.op("L", self.field("UDT", 0, "W", node.loc))
        em.load_text("NUMBER", str(udt_number(wanted)))
        em.op("==I")
        em.op(")")
        if name == "TYPEOF":
            em.op("A(")
            em.op("L", self.field("DIMS", 0, "W", node.loc))
            em.load_text("NUMBER", "0")
            em.op("==I")
            em.op(")")
        if node.op == "<>":
            em.op("NOT")
        em.op("=", em.ref(result))
        return result


def _at(byte: int, loc: ast.Loc) -> stl.LiteralNode:
    return stl.LiteralNode("POINTER", f"P#{byte}.0", loc)


def _absolute_part(access: Access) -> bool:
    first = access.path[0] if access.path else None
    return isinstance(first, str) and first.startswith("@")


def _structured(data_type: DataType) -> bool:
    return isinstance(data_type, ArrayType | StructType | StringType) or (
        isinstance(data_type, BlockType) and data_type.kind == "UDT"
    )


def _is_byte(data_type: DataType) -> bool:
    element = data_type.element if isinstance(data_type, ArrayType) else data_type
    return isinstance(element, Elementary) and element.name == "BYTE"


__all__ = ["VariantParam", "Variants"]

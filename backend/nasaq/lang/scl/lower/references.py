"""STRING and DATE_AND_TIME variables at run time, and calls of the IEC library FCs.

Neither fits an accumulator, so S7-SCL moves them byte by byte (or four bytes at a time)
through an area-crossing pointer. ``locate`` computes that pointer into a DWORD temporary (a
``Place``): ``P#L``/``P#DIX``/``P#DBX`` plus the variable's offset, with variable indices, the
multi-instance base (AR2) of an FB, or through the 6-byte DB pointer of an FC parameter or of
an FB's structured IN_OUT, whose DB number is then known only at run time. ``reach`` opens the
place's DB and loads AR1; ``B [AR1, P#n.0]`` and ``D [AR1, P#n.0]`` then reach its bytes.

``library_call`` calls an IEC library FC (``nasaq.lang.iec_library``) by name, ``CALL
"CONCAT"``: the STL compiler adds the library block to the program (``nasaq.lang.stl.library``).
"""

from __future__ import annotations

from dataclasses import dataclass

from nasaq.ir import BlockKind
from nasaq.lang.iec_library import FUNCTIONS, LibraryFunction
from nasaq.lang.layout import Slot
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.functions import Functions
from nasaq.lang.scl.lower.places import Access, LoweringError, Selector
from nasaq.lang.scl.typecheck import library
from nasaq.lang.scl.typecheck.rules.calls import called_by_name
from nasaq.lang.scl.typecheck.types import Type
from nasaq.lang.stl import ast as stl
from nasaq.lang.types import DataType, Elementary, Field

DWORD = Elementary("DWORD")
WORD = Elementary("WORD")
DT = Elementary("DATE_AND_TIME")
# The area byte of an area-crossing pointer (STEP 7: L 86, DI 85, DB 84).
_AREA = {"L": "DW#16#86000000", "DI": "DW#16#85000000", "DB": "DW#16#84000000"}

Result = Temp | stl.OperandNode  # where a function value goes: a temporary or the target itself


@dataclass(slots=True)
class Place:
    """A STRING or DATE_AND_TIME at run time: ``pointer`` (a DWORD temporary) holds its
    area-crossing address, ``db`` is the DB to open first (a number, a WORD temporary with the
    number, or None: not in a DB); ``length`` is a STRING's declared maximum length, None when
    only byte 0 knows it (a parameter passed by reference)."""

    pointer: Temp
    db: int | Temp | None = None
    length: int | None = None


class References(Functions):
    # ---- places -----------------------------------------------------------------------------

    def locate(self, access: Access, data_type: Type, loc: ast.Loc) -> Place:
        """Code that computes where ``access`` is (see the module doc)."""
        em = self.em
        length = getattr(data_type, "length", None)
        if access.root == "temp":
            assert access.temp is not None
            pointer = em.temp(DWORD)
            em.op("L", em.literal("POINTER", f"P##{access.temp.name}"))
            em.op("T", em.ref(pointer))
            return Place(pointer, None, length)
        if access.root == "ret" and self.block.return_type is not None:
            return self.through(access, "RET_VAL", self.block.return_type, None, loc)
        if access.root == "db" and access.db is not None and access.db_expr is None:
            db = self.index.get(BlockKind.DB, access.db)
            if db is None or any(isinstance(p, str) and p.startswith("@") for p in access.path):
                raise LoweringError(loc, "this STRING or DATE_AND_TIME")
            slots, _size = self.index.db_layout(db)
            return self.pointer_to(slots, list(access.path), "DB", access.db, length, loc)
        if access.root != "local":
            raise LoweringError(loc, "this STRING or DATE_AND_TIME")
        variable = self.ctx.variable(access.name)
        if variable is None:
            hidden = next((temp for temp in em.temps if temp.name == access.name), None)
            if hidden is None:
                raise LoweringError(loc, access.name)
            return self.in_hidden(hidden, access.path, length, loc)
        path = [access.name, *access.path]
        if variable.section == "TEMP":
            slots, _size = self.index.temp_layout(self.block)
            return self.pointer_to(slots, path, "L", None, length, loc)
        reference = self.by_reference(access.name)
        if reference is not None:
            return self.through(access, access.name, variable.type, reference.offset_bits, loc)
        if self.block.kind is BlockKind.FB:
            slots, _size = self.index.instance_layout(self.block)
            return self.pointer_to(slots, path, "DI", None, length, loc)
        return self.through(access, access.name, variable.type, None, loc)  # an FC parameter

    def in_hidden(
        self, temp: Temp, path: list[Selector], length: int | None, loc: ast.Loc
    ) -> Place:
        """A part of a structured hidden temporary (a structure passed through one, see
        ``calls``): its pointer plus the part's constant offset."""
        em = self.em
        slots = self.index.layout.place([Field(temp.name, temp.type)])
        slot, _terms = self.walk(slots, [temp.name, *path], loc)
        pointer = em.temp(DWORD)
        em.op("L", em.literal("POINTER", f"P##{temp.name}"))
        em.load_text("TYPED", f"L#{slot.offset_bits}")
        em.op("+D")
        em.op("T", em.ref(pointer))
        return Place(pointer, None, length)

    def pointer_to(
        self,
        slots: list[Slot],
        path: list[Selector],
        area: str,
        db: int | None,
        length: int | None,
        loc: ast.Loc,
    ) -> Place:
        em = self.em
        slot, terms = self.walk(slots, path, loc)
        self.sum_offset(slot, terms, loc)
        if area == "DI":  # the multi-instance base
            em.op("TAR2")
            em.op("AD", em.literal("TYPED", "DW#16#FFFFFF"))
            em.op("+D")
        em.op("OD", em.literal("TYPED", _AREA[area]))
        pointer = em.temp(DWORD)
        em.op("T", em.ref(pointer))
        return Place(pointer, db, length)

    def through(
        self,
        access: Access,
        name: str,
        data_type: DataType,
        pointer_bits: int | None,
        loc: ast.Loc,
    ) -> Place:
        """A variable inside a parameter passed as a DB pointer: an FC parameter (``L P##p``
        gives the pointer's place in the V area) or an FB's structured IN_OUT (the pointer is in
        the instance, at ``pointer_bits``)."""
        em = self.em
        root = self.index.layout.place([Field(name, data_type)])
        slot, terms = self.walk(root, [name, *access.path], loc)
        self.sum_offset(slot, terms, loc)
        offset = em.temp(Elementary("DINT"))
        em.op("T", em.ref(offset))
        if pointer_bits is None:
            em.op("L", em.literal("POINTER", f"P##{name}"))
            area = ""
        else:
            em.load_text("TYPED", f"L#{pointer_bits}")
            em.op("TAR2")
            em.op("AD", em.literal("TYPED", "DW#16#FFFFFF"))
            em.op("+D")
            area = "DI"
        em.op("LAR1")
        number = em.temp(WORD)
        em.op("L", self.at(area + "W", 0))
        em.op("T", em.ref(number))
        em.op("L", self.at(area + "D", 2))
        em.op("L", em.ref(offset))
        em.op("+D")
        pointer = em.temp(DWORD)
        em.op("T", em.ref(pointer))
        em.release(offset)
        return Place(pointer, number, None)

    def reach(self, place: Place, open_db: bool = True) -> None:
        """DB register := the place's DB (``open_db``), AR1 := its address."""
        em = self.em
        if open_db:
            self.open_place(place)
        em.op("L", em.ref(place.pointer))
        em.op("LAR1")

    def open_place(self, place: Place) -> None:
        em = self.em
        if isinstance(place.db, int):
            em.op("OPN", em.address(f"DB {place.db}"))
        elif place.db is not None:
            em.op("OPN", stl.IndirectNode("DB", em.ref(place.db), None, em.loc))

    def at(self, prefix: str, byte: int) -> stl.IndirectNode:
        """``B [AR1, P#byte.0]`` (``prefix`` B, W, D; area-crossing)."""
        loc = self.em.loc
        offset = stl.LiteralNode("POINTER", f"P#{byte}.0", loc)
        return stl.IndirectNode(prefix, stl.BareNode("AR1", None, loc), offset, loc)

    def release_place(self, place: Place) -> None:
        self.em.release(place.pointer)
        if isinstance(place.db, Temp):
            self.em.release(place.db)

    def place_of(self, node: ast.Expr) -> Place:
        """Where the variable ``node`` (or the hoisted value it stands for) is."""
        return self.locate(self.access(node), self.type_of(node), node.loc)

    # ---- library calls ----------------------------------------------------------------------

    def library_call(self, name: str, values: list[ast.Expr], result: Result) -> None:
        """``CALL "name" (inputs := values, RET_VAL := result)``."""
        em = self.em
        function: LibraryFunction = FUNCTIONS[name]
        args: list[stl.CallArgNode] = []
        used: list[Temp] = []
        for (formal, data_type), value in zip(function.inputs, values, strict=True):
            operand, temp = self.input_actual(value, data_type)
            args.append(em.arg(formal, operand))
            if temp is not None:
                used.append(temp)
        target = em.ref(result) if isinstance(result, Temp) else result
        args.append(em.arg("RET_VAL", target))
        em.call([stl.SymbolNode(function.name, False, [], em.loc)], args)
        for temp in used:
            em.release(temp)

    def library_function(self, node: ast.Call) -> LibraryFunction | None:
        """The library FC a call names, unless a variable or block of the program has the name."""
        callee = node.callee
        if not isinstance(callee, ast.Name) or not called_by_name(self.ctx, callee.name):
            return None
        upper = callee.name.upper()
        if upper not in library.NAMES or self.index.named(callee.name) is not None:
            return None
        values = [self.type_of(arg.value) for arg in node.args]
        return FUNCTIONS[library.chosen(upper, node.args, values)]  # LEN_WSTRING, VAL_STRG_INT

    def standard_name(self, node: ast.Call) -> str | None:
        """Library FCs are called as FCs, not compiled in line."""
        if self.library_function(node) is not None:
            return None
        return super().standard_name(node)

    def target(
        self, node: ast.Call
    ) -> tuple[list[stl.OperandNode], dict[str, tuple[str, DataType, str]], DataType | None]:
        function = self.library_function(node)
        if function is None:
            return super().target(node)
        formals = {name.casefold(): ("IN", kind, name) for name, kind in function.inputs}
        for section, name, kind in function.others:
            formals[name.casefold()] = (section, kind, name)
        for alias, name in library.ALIASES.get(function.name, {}).items():  # LEN(IN := s)
            formals[alias.casefold()] = formals[name.casefold()]
        callee = stl.SymbolNode(function.name, False, [], node.loc)
        return [callee], formals, function.result

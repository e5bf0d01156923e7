"""STRING values, as S7-SCL compiles them.

A STRING[n] is n + 2 bytes: the maximum length n, the current length, the characters.
- ``s := t`` copies ``min(current length of t, maximum length of s)`` characters and sets the
  current length of s; byte 0 of s is never written. A copy is a loop over the characters
  through two area-crossing pointers (``references``), so any two places work: temporaries,
  instance data (multi-instances too), DBs, array elements with variable indices, parameters
  passed by reference.
- ``s := 'text'`` writes the characters four at a time, cut to the declared length; when the
  target's length is known only at run time (a parameter), the text goes into a temporary and
  is copied from there.
- ``s := c`` (a CHAR) gives a string of that one character (none if s has length 0).
- A function value goes straight into the target when it is a variable that needs no set-up
  code (``s := CONCAT(...)`` passes ``#s`` as RET_VAL), else into a STRING[254] temporary that
  is then copied (also every STRING input that is not a plain variable: a nested call, an
  element chosen by a variable index, a CHAR).
- Comparisons ``= <> < > <= >=`` call the library's EQ_STRNG ... NE_STRNG (S7-SCL does) before
  the logic string that uses the result (``hoist``); a CHAR compared with a STRING is a
  one-character string.
- STRING temporaries (the block's own and the hidden ones) get their maximum length at the start
  of the block and are empty (S7's L stack holds whatever the last block left there).
- ``STRING_TO_CHAR(s)`` is the first character of s; ``CHAR_TO_STRING(c)`` as ``s := c``.
- WSTRING (``nasaq.lang.wide_text``) is the same code with 2-byte characters: WORD header
  fields, W accesses and steps of 16 bits (the ``width`` of a copy); a WCHAR is its one
  character. Its comparisons and functions call the library's ``EQ_WSTRING``, ``LEN_WSTRING``...
"""

from __future__ import annotations

from itertools import product

from nasaq.lang.iec_library import FUNCTIONS, STRING_COMPARE
from nasaq.lang.layout import Slot
from nasaq.lang.scl import ast
from nasaq.lang.scl.lower.emitter import Temp
from nasaq.lang.scl.lower.expressions import COMPARISONS
from nasaq.lang.scl.lower.literals import Value
from nasaq.lang.scl.lower.places import Access, LoweringError
from nasaq.lang.scl.lower.references import DT, Place, References
from nasaq.lang.scl.typecheck.types import Type, scalar
from nasaq.lang.stl import ast as stl
from nasaq.lang.stl.build import unquote_chars
from nasaq.lang.types import ArrayType, DataType, Elementary, StringType

LONGEST = StringType(254)
_UNIT = {1: "B", 2: "W"}  # a STRING's or WSTRING's characters and header fields
_WIDTHS = ((4, "D", "DW#16#{:08X}"), (2, "W", "W#16#{:04X}"), (1, "B", "B#16#{:02X}"))


def unparen(node: ast.Expr) -> ast.Expr:
    while isinstance(node, ast.Paren):
        node = node.inner
    return node


def chars_of(value: Value) -> bytes | None:
    """The characters of a constant: a text (``'A$42'``) or a character code (``CHAR#65``)."""
    if value.kind == "chars":
        text = value.text if value.text.startswith("'") else f"'{value.text}'"
        try:
            return unquote_chars(text).encode("latin-1")
        except UnicodeEncodeError:
            return None
    if value.kind == "int" and 0 <= int(value.number) <= 255:
        return bytes((int(value.number),))
    return None


def wide_chars_of(value: Value) -> bytes | None:
    """The UTF-16 code units (big-endian) of a WSTRING/WCHAR constant, or of a character code."""
    if value.kind == "chars":
        text = value.text if value.text.startswith("'") else f"'{value.text}'"
        return unquote_chars(text).encode("utf-16-be", errors="surrogatepass")
    if value.kind == "int" and 0 <= int(value.number) <= 0xFFFF:
        return int(value.number).to_bytes(2, "big")
    return None


def _width(data_type: Type) -> int:
    """Bytes a character: 2 in a WSTRING, 1 in a STRING."""
    return data_type.char_bytes if isinstance(data_type, StringType) else 1


def _header(data_type: StringType) -> tuple[int, ...]:
    """The WORDs a STRING/WSTRING starts with when empty: the maximum length, then 0."""
    if data_type.wide:
        return (data_type.length, 0)
    return (data_type.length << 8,)


def chars_literal(chars: bytes) -> str:
    """STL's ``'...'`` for ``chars`` (``$hh`` for quotes, ``$`` and unprintable bytes)."""
    body = "".join(
        chr(byte) if 32 <= byte < 127 and chr(byte) not in "'$" else f"${byte:02X}"
        for byte in chars
    )
    return f"'{body}'"


class Strings(References):
    # ---- assignments ------------------------------------------------------------------------

    def assign_text(self, stmt: ast.Assign) -> None:
        """``target := value`` for a STRING or DATE_AND_TIME target."""
        target_type = self.type_of(stmt.target)
        access = self.access(stmt.target)
        if isinstance(target_type, StringType):
            self.store_text(stmt.value, access, target_type, stmt.loc)
        else:
            self.store_dt(stmt.value, access, stmt.loc)

    def store_text(self, value: ast.Expr, target: Access, target_type: Type, loc: ast.Loc) -> None:
        em = self.em
        inner = unparen(value)
        hoisted = id(inner) in self.hoisted
        constant = None if hoisted else self.constant(inner)
        width = _width(target_type)
        if constant is not None:
            chars = chars_of(constant) if width == 1 else wide_chars_of(constant)
            if chars is None:
                raise LoweringError(loc, f"this {scalar(target_type)} constant")
            place = self.locate(target, target_type, loc)
            self.text_constant(chars, place, loc, width)
            self.release_place(place)
            return
        if not hoisted and scalar(self.type_of(inner)) == ("CHAR", "WCHAR")[width - 1]:
            self.text_char(inner, target, target_type, loc)
            return
        if isinstance(inner, ast.Call) and not hoisted:
            if self.standard_name(inner) == "CHAR_TO_STRING":
                (char,) = self.arguments(inner, "IN")
                self.text_char(char, target, target_type, loc)
                return
            if self.direct(target):
                self.user_call(inner, self.operand(target, loc))
                return
            longest = StringType(254, width == 2)
            temp = em.temp(longest)
            self.user_call(inner, temp)
            self.copy_places(Access("temp", temp=temp), longest, target, target_type, loc)
            em.release(temp)
            return
        if hoisted or self.is_variable(inner):
            self.copy_places(self.access(inner), self.type_of(inner), target, target_type, loc)
            return
        raise LoweringError(loc, "this STRING value")

    def copy_places(
        self, source: Access, source_type: Type, target: Access, target_type: Type, loc: ast.Loc
    ) -> None:
        origin = self.locate(source, source_type, loc)
        place = self.locate(target, target_type, loc)
        if isinstance(target_type, StringType):
            self.copy_text(origin, place, target_type.char_bytes)
        else:
            self.copy_dt(origin, place)
        self.release_place(origin)
        self.release_place(place)

    def direct(self, access: Access) -> bool:
        """Whether a function may write its value straight into ``access`` (RET_VAL := it)."""
        if access.root not in ("local", "temp", "db", "ret") or not self.plain(access):
            return False
        return not (access.root == "local" and self.by_reference(access.name))

    def call_result(self, node: ast.Call) -> Temp:
        """A STRING function value in a STRING[254] temporary."""
        found = self.type_of(node)
        if isinstance(found, StringType) and self.constant(node) is not None:  # GetBlockName
            kept = self.em.temp(StringType(254, found.wide))
            self.store_text(node, Access("temp", temp=kept), kept.type, node.loc)
            return kept
        if isinstance(found, StringType) and self.standard_name(node) is None:
            temp = self.em.temp(StringType(254, found.wide))
            self.user_call(node, temp)
            return temp
        return super().call_result(node)

    # ---- the copies -------------------------------------------------------------------------

    def text_constant(self, chars: bytes, place: Place, loc: ast.Loc, width: int = 1) -> None:
        """``chars`` (``width`` bytes a character) into the STRING or WSTRING at ``place``."""
        em = self.em
        if place.length is None and chars:  # the room is known at run time only
            temp = em.temp(StringType(len(chars) // width, width == 2))
            staged = self.locate(Access("temp", temp=temp), temp.type, loc)
            self.text_constant(chars, staged, loc, width)
            self.copy_text(staged, place, width)
            self.release_place(staged)
            em.release(temp)
            return
        count = min(len(chars) // width, place.length or 0)
        self.reach(place)
        self.write_bytes(chars[: count * width], 2 * width)
        em.load_text("NUMBER", str(count))
        em.op("T", self.at(_UNIT[width], width))

    def write_bytes(self, data: bytes, start: int) -> None:
        """``data`` to ``B [AR1, P#start.0]`` on, four bytes at a time."""
        em = self.em
        position = 0
        while position < len(data):
            for width, prefix, text in _WIDTHS:
                if len(data) - position >= width:
                    part = int.from_bytes(data[position : position + width], "big")
                    em.load_text("TYPED", text.format(part))
                    em.op("T", self.at(prefix, start + position))
                    position += width
                    break

    def text_char(self, value: ast.Expr, target: Access, target_type: Type, loc: ast.Loc) -> None:
        em = self.em
        width = _width(target_type)
        unit = _UNIT[width]
        char = em.temp(Elementary(("BYTE", "WORD")[width - 1]))
        self.load_value(value, ("CHAR", "WCHAR")[width - 1])
        em.op("T", em.ref(char))
        place = self.locate(target, target_type, loc)
        self.reach(place)
        if place.length == 0:
            em.load_text("NUMBER", "0")
        elif place.length is not None:
            em.op("L", em.ref(char))
            em.op("T", self.at(unit, 2 * width))
            em.load_text("NUMBER", "1")
        else:
            empty, done = em.new_label(), em.new_label()
            em.op("L", self.at(unit, 0))
            em.load_text("NUMBER", "0")
            em.op("==I")
            em.jump("JC", empty)
            em.op("L", em.ref(char))
            em.op("T", self.at(unit, 2 * width))
            em.load_text("NUMBER", "1")
            em.jump("JU", done)
            em.place(empty)
            em.load_text("NUMBER", "0")
            em.place(done)
        em.op("T", self.at(unit, width))
        em.release(char)
        self.release_place(place)

    def copy_text(self, source: Place, target: Place, width: int = 1) -> None:
        """target := source: ``min(current length, room)`` characters (``width`` bytes each)
        and the new length. The pointers move on with the characters (the places are used
        up)."""
        em = self.em
        unit = _UNIT[width]
        count = em.temp(Elementary("INT"))
        keep, top, done = em.new_label(), em.new_label(), em.new_label()
        if target.length is not None:
            em.load_text("NUMBER", str(target.length))
        else:
            self.reach(target)
            em.op("L", self.at(unit, 0))
        em.op("T", em.ref(count))
        self.reach(source)
        em.op("L", self.at(unit, width))
        em.op("L", em.ref(count))
        em.op(">=I")  # the source's length >= the room: the room it is
        em.jump("JC", keep)
        em.op("TAK")
        em.op("T", em.ref(count))
        em.place(keep)
        self.reach(target)
        em.op("L", em.ref(count))
        em.op("T", self.at(unit, width))
        switch = self.two_dbs(source, target)
        em.place(top)
        em.op("L", em.ref(count))
        em.load_text("NUMBER", "0")
        em.op("<=I")
        em.jump("JC", done)
        self.copy_element(source, target, unit, 2 * width, switch)
        self.advance((source, target), 8 * width)
        em.op("L", em.ref(count))
        em.load_text("NUMBER", "1")
        em.op("-I")
        em.op("T", em.ref(count))
        em.jump("JU", top)
        em.place(done)
        em.release(count)

    @staticmethod
    def two_dbs(source: Place, target: Place) -> bool:
        """Whether a copy between the places opens two different DBs in turn (otherwise the one
        DB stays open)."""
        both = source.db is not None and target.db is not None
        return both and not (isinstance(source.db, int) and source.db == target.db)

    def copy_element(
        self, source: Place, target: Place, unit: str, byte: int, switch: bool
    ) -> None:
        """The ``unit`` (B, W, D) at ``byte`` of ``target`` := the one of ``source``, the step of
        a copy loop (``switch``: the places are in two DBs, see ``two_dbs``)."""
        em = self.em
        self.reach(source, open_db=switch)
        em.op("L", self.at(unit, byte))
        self.reach(target, open_db=switch)
        em.op("TAK")
        em.op("T", self.at(unit, byte))

    def advance(self, places: tuple[Place, ...], bits: int) -> None:
        """The pointers of ``places`` on by ``bits`` (to the next element of a copy loop)."""
        em = self.em
        for place in places:
            em.op("L", em.ref(place.pointer))
            em.load_text("TYPED", f"L#{bits}")
            em.op("+D")
            em.op("T", em.ref(place.pointer))

    def copy_dt(self, source: Place, target: Place) -> None:  # pragma: no cover - ``dates``
        raise NotImplementedError

    def store_dt(self, value: ast.Expr, target: Access, loc: ast.Loc) -> None:  # pragma: no cover
        raise NotImplementedError

    # ---- STRING and DATE_AND_TIME inputs ----------------------------------------------------

    def input_actual(
        self, value: ast.Expr, formal: DataType | None
    ) -> tuple[stl.OperandNode, Temp | None]:
        if isinstance(formal, StringType) or formal == DT:
            return self.reference_input(value, formal)
        return super().input_actual(value, formal)

    def reference_input(
        self, value: ast.Expr, formal: DataType
    ) -> tuple[stl.OperandNode, Temp | None]:
        """A STRING or DATE_AND_TIME input: a constant, a variable passed as it is (the FC gets
        a pointer to it), or anything else in a temporary."""
        em = self.em
        inner = unparen(value)
        if id(inner) in self.hoisted:
            return em.ref(self.hoisted[id(inner)]), None
        constant = self.constant(inner)
        wide = isinstance(formal, StringType) and formal.wide  # no STL literal: a temporary
        if constant is not None and not wide:
            return self.reference_constant(constant, formal, inner.loc), None
        is_text = isinstance(formal, StringType)
        if self.is_variable(inner):
            have = self.type_of(inner)
            same = isinstance(have, StringType) if is_text else have == DT
            access = self.access(inner)
            if same and self.direct(access):
                return self.operand(access, inner.loc), None
        temp = em.temp(formal)  # a STRING of the formal's length (the FC may write its input)
        if is_text:
            self.store_text(inner, Access("temp", temp=temp), formal, inner.loc)
        else:
            self.store_dt(inner, Access("temp", temp=temp), inner.loc)
        return em.ref(temp), temp

    def reference_constant(self, value: Value, formal: DataType, loc: ast.Loc) -> stl.LiteralNode:
        if isinstance(formal, StringType):
            chars = chars_of(value)
            if chars is None:
                raise LoweringError(loc, "this STRING constant")
            return self.em.literal("CHARS", chars_literal(chars))
        return self.em.literal("TYPED", self.dt_text(value, loc))

    def dt_text(self, value: Value, loc: ast.Loc) -> str:  # pragma: no cover - ``dates``
        raise NotImplementedError

    # ---- comparisons ------------------------------------------------------------------------

    def library_operation(self, node: ast.Expr) -> str | None:
        """The library FC S7-SCL calls for this operation, if it calls one."""
        if isinstance(node, ast.Binary) and node.op in COMPARISONS:
            kinds = {scalar(self.type_of(node.left)), scalar(self.type_of(node.right))}
            if "STRING" in kinds:
                return STRING_COMPARE[node.op]
        return None

    def library_result(self, node: ast.Binary, name: str) -> Temp:
        temp = self.em.temp(FUNCTIONS[name].result)
        self.library_call(name, [node.left, node.right], temp)
        return temp

    def compare(self, node: ast.Binary) -> None:
        if id(node) in self.hoisted:
            self.em.op("A", self.em.ref(self.hoisted[id(node)]))
            return
        if self.library_operation(node) is not None:  # pragma: no cover - hoisted first
            raise LoweringError(node.loc, "this comparison")
        super().compare(node)

    # ---- conversions ------------------------------------------------------------------------

    def function_value(self, node: ast.Call, name: str) -> None:
        if name != "STRING_TO_CHAR":
            super().function_value(node, name)
            return
        em = self.em
        (value,) = self.arguments(node, "IN")
        inner = unparen(value)
        temp = None
        if id(inner) in self.hoisted or self.is_variable(inner):
            place = self.place_of(inner)
        else:
            temp = em.temp(LONGEST)
            self.store_text(inner, Access("temp", temp=temp), LONGEST, inner.loc)
            place = self.locate(Access("temp", temp=temp), LONGEST, inner.loc)
        self.reach(place)
        em.op("L", self.at("B", 2))
        self.release_place(place)
        if temp is not None:
            em.release(temp)

    # ---- STRING temporaries -----------------------------------------------------------------

    def text_prologue(self) -> None:
        """At the start of the block: every STRING temporary := '' with its maximum length."""
        em = self.em
        code, em.code = em.code, []
        em.loc = self.block.node.loc
        slots, _size = self.index.temp_layout(self.block)
        for offset, text in self.strings_in(slots):
            for word, value in enumerate(_header(text)):
                em.load_text("TYPED", f"W#16#{value:04X}")
                em.op("T", em.address(f"LW {offset + 2 * word}"))
        for temp in em.temps:
            if isinstance(temp.type, StringType):
                em.op("L", em.literal("POINTER", f"P##{temp.name}"))
                em.op("LAR1")
                for word, value in enumerate(_header(temp.type)):
                    em.load_text("TYPED", f"W#16#{value:04X}")
                    em.op("T", self.at("W", 2 * word))
        em.code += code

    def strings_in(self, slots: list[Slot]) -> list[tuple[int, StringType]]:
        """(byte, type) of every STRING and WSTRING in ``slots``, array elements included."""
        found: list[tuple[int, StringType]] = []
        for slot in slots:
            data_type = slot.type
            if isinstance(data_type, StringType):
                found.append((slot.offset_bits // 8, data_type))
            elif isinstance(data_type, ArrayType) and not isinstance(data_type.element, Elementary):
                first = self.index.layout.element(slot, [low for low, _high in data_type.dims])
                if first is None or not self.strings_in([first]):
                    continue
                for indices in product(*(range(low, high + 1) for low, high in data_type.dims)):
                    element = self.index.layout.element(slot, list(indices))
                    if element is not None:
                        found += self.strings_in([element])
            else:
                found += self.strings_in(slot.members)
        return found

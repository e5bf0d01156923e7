"""The bytes of a data block: every variable's default, then its declared initial value,
then the actual value from the DB's BEGIN section (STEP 7's "actual values" on download).

Values are stored as the CPU holds them: big-endian, BOOLs as bits, STRING[n] as max length,
current length and characters, DATE_AND_TIME as 8 BCD bytes, TIMER/COUNTER/BLOCK_* numbers as
words, POINTER as DB number + area pointer (6 bytes).
"""

from __future__ import annotations

import struct

from nasaq.diagnostics import Diagnostic
from nasaq.ir import ConstType
from nasaq.lang.layout import Layout, Slot
from nasaq.lang.limits import MAX_INIT_VALUES
from nasaq.lang.profiles import S7_1500_TYPES
from nasaq.lang.s7_1500_values import initial_bytes
from nasaq.lang.stl import ast, constants
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.build import unquote_chars
from nasaq.lang.stl.diag import problem
from nasaq.lang.types import ArrayType, DataType, Elementary, Field, StringType, type_text

_DT = Elementary("DATE_AND_TIME")
_DT_DEFAULT = bytes((0x90, 0x01, 0x01, 0, 0, 0, 0, 0x02))
_FITS = {
    "BYTE": {ConstType.BYTE, ConstType.CHAR, ConstType.INT},
    "CHAR": {ConstType.CHAR, ConstType.BYTE},
    "WORD": {ConstType.WORD, ConstType.BYTE, ConstType.BYTES, ConstType.INT},
    "INT": {ConstType.INT, ConstType.WORD},
    "DWORD": {
        ConstType.DWORD,
        ConstType.WORD,
        ConstType.BYTE,
        ConstType.BYTES,
        ConstType.DINT,
        ConstType.INT,
    },
    "DINT": {ConstType.DINT, ConstType.INT},
    "REAL": {ConstType.REAL},
    "S5TIME": {ConstType.S5TIME},
    "TIME": {ConstType.TIME, ConstType.DINT},
    "DATE": {ConstType.DATE},
    "TIME_OF_DAY": {ConstType.TOD},
}
_LIMITS = {
    "BYTE": (0, 0xFF),
    "WORD": (-32768, 0xFFFF),
    "INT": (-32768, 32767),
    "DINT": (-(2**31), 2**31 - 1),
    "DWORD": (-(2**31), 0xFFFFFFFF),
}


class BadValueError(ValueError):
    pass


def _wchar_bytes(value: ast.ValueNode) -> bytes:
    if value.kind == "CHARS":
        units = unquote_chars(value.text).encode("utf-16-be", errors="surrogatepass")
        if len(units) != 2:
            raise BadValueError
        return units
    try:
        code = (
            int(value.text)
            if value.kind == "NUMBER"
            else constants.parse_literal(value.kind, value.text, None).pattern
        )
    except (constants.ConstantError, ValueError, OverflowError):
        raise BadValueError from None
    if not 0 <= code <= 0xFFFF:
        raise BadValueError
    return code.to_bytes(2, "big")


def scalar_bytes(data_type: DataType, value: ast.ValueNode) -> bytes | int:
    """Bytes of one value (an int 0/1 for BOOL); raises BadValueError when it does not fit."""
    if isinstance(data_type, StringType):
        if value.kind != "CHARS":
            raise BadValueError
        text = unquote_chars(value.text)
        if data_type.wide:  # WSTRING: WORD lengths, UTF-16 code units (``lang.wide_text``)
            units = text.encode("utf-16-be", errors="surrogatepass")
            if len(units) // 2 > data_type.length:
                raise BadValueError
            header = data_type.length.to_bytes(2, "big") + (len(units) // 2).to_bytes(2, "big")
            return header + units.ljust(2 * data_type.length, b"\0")
        if len(text) > data_type.length:
            raise BadValueError
        body = text.encode("latin-1", errors="replace").ljust(data_type.length, b"\0")
        return bytes([data_type.length, len(text)]) + body
    assert isinstance(data_type, Elementary)
    name = data_type.name
    text = value.text
    if name == "BOOL":
        upper = text.upper()
        if upper in ("TRUE", "1"):
            return 1
        if upper in ("FALSE", "0"):
            return 0
        raise BadValueError
    if name in ("TIMER", "COUNTER") or name.startswith("BLOCK_"):
        number = _number_of(value)
        return struct.pack(">H", number)
    if name == "DATE_AND_TIME":
        prefix, _, moment = text.partition("#")
        if prefix.upper() not in ("DT", "DATE_AND_TIME"):
            raise BadValueError
        try:
            return constants.date_and_time_bytes(moment, text)
        except constants.ConstantError:
            raise BadValueError from None
    if name == "POINTER":
        if value.kind != "POINTER":
            raise BadValueError
        constant = constants.pointer(text)
        db = int(text.split("DB", 1)[1].split(".")[0]) if ".DB" in text.upper() else 0
        return struct.pack(">HI", db, constant.pattern)
    if name in ("ANY",):
        raise BadValueError
    if name == "WCHAR":  # one UTF-16 code unit (``nasaq.lang.wide_text``)
        return _wchar_bytes(value)
    if name in S7_1500_TYPES:  # SINT ... LTIME: ``nasaq.lang.s7_1500_values``
        found = initial_bytes(name, value.kind, text)
        if found is None:
            raise BadValueError
        return found
    if value.kind == "NUMBER" and name in _LIMITS:
        if len(text.lstrip("+-0")) > 20:  # out of every range; int() refuses 4,300 digits
            raise BadValueError
        number = int(text)
        low, high = _LIMITS[name]
        if not low <= number <= high:
            raise BadValueError
        pattern = number & 0xFFFFFFFF
    elif value.kind == "NUMBER" and name == "REAL":
        pattern = constants.real_pattern(float(text))
    else:
        try:
            raw = unquote_chars(text) if value.kind == "CHARS" else None
            constant = constants.parse_literal(value.kind, text, raw)
        except (constants.ConstantError, OverflowError):
            raise BadValueError from None
        if constant.type not in _FITS.get(name, set()):
            raise BadValueError
        pattern = constant.pattern
    size = data_type.bits // 8
    return (pattern & ((1 << data_type.bits) - 1)).to_bytes(size, "big")


def _number_of(value: ast.ValueNode) -> int:
    if value.kind == "NUMBER":
        return int(value.text)
    if value.kind != "ADDR":
        raise BadValueError
    try:
        parsed = parse_address(value.text)
    except AddressError:
        raise BadValueError from None
    if parsed.kind not in ("timer", "counter", "block"):
        raise BadValueError
    return parsed.number


def flatten(values: list[ast.InitValue]) -> list[ast.ValueNode]:
    """The values with their repeat factors expanded; at most ``MAX_INIT_VALUES`` (and one
    more, so that a caller counting them still sees too many): ``2147483648 (TRUE)`` would
    otherwise loop for minutes."""
    flat: list[ast.ValueNode] = []
    for value in values:
        if len(flat) > MAX_INIT_VALUES:
            break
        if isinstance(value, ast.RepeatNode):
            inner = flatten(value.values)
            if not inner:
                continue
            times = min(value.count, MAX_INIT_VALUES // len(inner) + 1)
            flat.extend(inner * times)
        else:
            flat.append(value)
    return flat[: MAX_INIT_VALUES + 1]


class DataBuilder:
    def __init__(self, layout: Layout, size_bits: int, file: str) -> None:
        self.layout = layout
        self.data = bytearray(size_bits // 8)
        self.file = file
        self.diagnostics: list[Diagnostic] = []

    def defaults(self, slots: list[Slot]) -> None:
        """Declared initial values (and STRING headers) of ``slots`` and their members."""
        for slot in slots:
            if isinstance(slot.type, StringType):
                start = slot.offset_bits // 8
                if slot.type.wide:  # WSTRING: the maximum length is a WORD
                    self.data[start : start + 2] = slot.type.length.to_bytes(2, "big")
                else:
                    self.data[start] = slot.type.length
            elif slot.type == _DT:  # STEP 7's default: DT#1990-01-01-00:00:00.000, a Monday
                start = slot.offset_bits // 8
                self.data[start : start + 8] = _DT_DEFAULT
            if slot.members:
                self.defaults(slot.members)
            if isinstance(slot.type, ArrayType) and (
                not isinstance(slot.type.element, Elementary) or slot.type.element == _DT
            ):
                # STRING headers, and the declared initial values inside each STRUCT/UDT element
                for element in self._elements(slot, expand=True):
                    self.defaults([element])
            if isinstance(slot.initial, list) and slot.initial:
                first = slot.initial[0]
                self.assign(slot, slot.initial, first.loc)
            elif isinstance(slot.initial, bool | int | float):  # a system block's member
                self.preset(slot, slot.initial)

    def preset(self, slot: Slot, value: bool | int | float) -> None:
        """An initial value a system block's interface gives (``system_types.initial``)."""
        byte, bit = divmod(slot.offset_bits, 8)
        kind = slot.type.name if isinstance(slot.type, Elementary) else ""
        if kind == "BOOL":
            mask = 1 << bit
            self.data[byte] = (self.data[byte] | mask) if value else (self.data[byte] & ~mask)
        elif kind in ("REAL", "LREAL"):
            self.data[byte : byte + slot.size_bits // 8] = struct.pack(
                ">f" if kind == "REAL" else ">d", float(value)
            )
        elif kind:
            size = slot.size_bits // 8
            self.data[byte : byte + size] = (int(value) % (1 << 8 * size)).to_bytes(size, "big")

    def _elements(self, slot: Slot, expand: bool = False) -> list[Slot]:
        """The element slots of an array (``expand``: with their members laid out)."""
        assert isinstance(slot.type, ArrayType)
        element = slot.type.element
        stride = self.layout.stride(element)
        elements = []
        for linear in range(slot.type.count):
            offset = slot.offset_bits + linear * stride
            if expand:
                elements.append(self.layout.place([Field(slot.name, element)], offset)[0])
            else:
                elements.append(Slot(slot.name, element, offset, 0))
        return elements

    def assign(self, slot: Slot, values: list[ast.InitValue], where: ast.Loc) -> None:
        flat = flatten(values)
        targets = self._elements(slot) if isinstance(slot.type, ArrayType) else [slot]
        if len(flat) > len(targets) or (not isinstance(slot.type, ArrayType) and len(flat) != 1):
            self.bad(slot, flat[0] if flat else None, where)
            return
        for target, value in zip(targets, flat, strict=False):
            if not isinstance(target.type, Elementary | StringType):
                self.bad(target, value, value.loc)
                return
            try:
                encoded = scalar_bytes(target.type, value)
            except (BadValueError, OverflowError):
                self.bad(target, value, value.loc)
                return
            byte, bit = divmod(target.offset_bits, 8)
            if isinstance(encoded, int):
                mask = 1 << bit
                self.data[byte] = (self.data[byte] | mask) if encoded else (self.data[byte] & ~mask)
            else:
                self.data[byte : byte + len(encoded)] = encoded

    def bad(self, slot: Slot, value: ast.ValueNode | None, where: ast.Loc) -> None:
        self.diagnostics.append(
            problem(
                "STL226",
                self.file,
                value.loc if value is not None else where,
                value=value.text if value is not None else "(nothing)",
                name=slot.name,
                type=type_text(slot.type),
            )
        )

    def actual_values(self, slots: list[Slot], assigns: list[ast.DbAssignNode]) -> None:
        root = Slot("", Elementary("BYTE"), 0, 0, members=slots)
        for assign in assigns:
            slot = self.walk(root, assign)
            if slot is not None:
                self.assign(slot, assign.values, assign.loc)

    def walk(self, root: Slot, assign: ast.DbAssignNode) -> Slot | None:
        current = root
        shown = ""
        for part in assign.path:
            if isinstance(part, list):
                found = self.layout.element(current, part)
                if found is None:
                    self.diagnostics.append(
                        problem(
                            "STL217",
                            self.file,
                            assign.loc,
                            name=shown,
                            index=", ".join(map(str, part)),
                        )
                    )
                    return None
            else:
                found = current.member(part)
                if found is None:
                    self.diagnostics.append(
                        problem(
                            "STL216", self.file, assign.loc, name=shown or "the DB", member=part
                        )
                    )
                    return None
                shown = f"{shown}.{part}" if shown else part
            current = found
        return current

"""Watch, trend, modify and force targets: what a user types, resolved to a typed address.

The CPU knows bytes at addresses, the program knows names and types. So that a watch table shows
``-5`` for an INT rather than ``65531`` and accepts ``T#2S`` for a TIME, the monitor resolves each
entry once, against the downloaded program, into a :class:`Target` (an address with an elementary
type); reading and writing it afterwards needs no names. Accepted, case and spacing as STEP 7
allows them:

- addresses: ``I0.0 IB0 IW0 ID0`` (Q, M, German E and A alike), ``PIB0 PIW256 PID0`` (PQ, German
  PE and PA alike), ``DB1.DBX0.0 DB1.DBB0 DB1.DBW0 DB1.DBD0``, ``T1``, ``C1``/``Z1``; typed by
  width (BOOL, BYTE, WORD, DWORD);
- symbols, quoted or not (``"Motor"``, ``Motor``). a symbol has the type its symbol table declares
  (``Program.symbol_types``), else the width of its address;
- DB variables: ``DB1.level``, ``"Tank".level``, ``DB1.s.x``, ``DB1.arr[3]``, ``DB1.m[1, 2]``,
  instance DBs ``DB5.count`` and their multi-instances ``DB5.t1.ET``, and addresses in a symbolic
  DB (``"Tank".DBW2``).

Layouts are ``Block.interface`` (an instance DB without one uses its FB's), where the compilers
put the standard S7-300/400 layout; array elements are placed by the same rules as
``nasaq.lang.layout``: BOOLs packed, BYTE and CHAR one byte each, anything else word-aligned.
"""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

from nasaq.cpu import Cpu
from nasaq.cpu.bcd import int_to_bcd
from nasaq.cpu.memory import db_size
from nasaq.cpu.timers import BASES_MS
from nasaq.diagnostics import render
from nasaq.diagnostics.phrases import Phrase, phrase
from nasaq.headless.addresses import (
    AddressError,
    CounterAddress,
    TimerAddress,
    address_text,
    parse_address,
    parse_number,
)
from nasaq.ir import Area, Block, BlockKind, ConstType, Direct, Program, Variable, Width
from nasaq.ir.types import (
    ACCU_TYPES,
    ELEMENTARY_BITS,
    LONG_TYPES,
    NUMBER_TYPES,
    TYPE_ALIASES,
    array_shape,
)
from nasaq.lang.stl import addresses as stl_addresses
from nasaq.lang.stl.constants import ConstantError, real_pattern, typed
from nasaq.monitor import long_values
from nasaq.monitor.values import Value, decode

EXAMPLES = 'MW10, DB1.DBW2, T1, "Motor", DB1.level'
_WIDTH_TYPES = {Width.BIT: "BOOL", Width.BYTE: "BYTE", Width.WORD: "WORD", Width.DWORD: "DWORD"}
# The elementary types a target can have, with their access width.
_TYPE_WIDTHS = {name: Width(ELEMENTARY_BITS[name]) for name in ACCU_TYPES}
_WATCHED_AREAS = (Area.I, Area.Q, Area.M, Area.PI, Area.PQ, Area.DB)
_WIDTHS = {"B": Width.BYTE, "W": Width.WORD, "D": Width.DWORD}

_ABSOLUTE = re.compile(
    r"^(?:[IEQAM]\s*[BWD]?|DB\s*\d+\s*\.\s*DB[XBWD]|[TCZ])\s*\d+(?:\.\d+)*$", re.IGNORECASE
)
_PERIPHERAL = re.compile(
    r"^P\s*(?P<area>[IEQA])\s*(?P<size>[XBWD]?)\s*(?P<byte>\d+)(?P<bit>\.\d+)?$", re.IGNORECASE
)
_LOCAL = re.compile(r"^(?:#|[LV]\s*[BWD]?\s*\d)", re.IGNORECASE)
_OPEN_DB = re.compile(r"^D[BI]\s*[XBWD]\s*\d", re.IGNORECASE)
_SYMBOLIC_DB_ADDRESS = re.compile(
    r'^"(?P<symbol>[^"]+)"\s*\.\s*(?P<rest>DB[XBWD]\s*\d+(?:\.\d+)?)$', re.IGNORECASE
)
_HEAD = re.compile(r'"(?P<symbol>[^"]+)"|DB\s*(?P<db>\d+)\b|(?P<name>[A-Za-z_]\w*)', re.IGNORECASE)
_SELECTOR = re.compile(
    r'\s*(?:\.\s*(?:"(?P<quoted>[^"]+)"|(?P<name>[A-Za-z_]\w*))|\[(?P<indices>[^\]]*)\])'
)
_STRING = re.compile(r"^(W?)STRING\s*\[\s*(\d+)\s*\]$", re.IGNORECASE)  # W: WSTRING
# FB IN_OUT parameters of these types hold a pointer to the actual parameter, not its value.
_BY_REFERENCE = re.compile(r"^(?:ARRAY|W?STRING|STRUCT|UDT|DATE_AND_TIME$|DT$)", re.IGNORECASE)

Selector = str | tuple[int, ...]


class TargetError(ValueError):
    """A target or value the monitor cannot use. ``code`` is MON603 (no such address, symbol or
    variable) or MON606 (a value that does not fit or parse); ``str()`` says why and what works."""

    def __init__(self, code: str, target: str, reason: Phrase | str) -> None:
        self.code = code
        self.params: dict[str, object] = {"target": target, "reason": reason}
        self.diagnostic = render(code, None, target=target, reason=reason)
        super().__init__(self.diagnostic.message)


@dataclass(frozen=True, slots=True)
class Target:
    """``text`` is the canonical spelling (``MW10``, ``DB1.level``, ``"Motor"``); ``type`` an
    elementary type or TIMER / COUNTER (then ``direct`` is None and ``timer``/``counter`` set)."""

    text: str
    type: str
    direct: Direct | None
    timer: int | None = None
    counter: int | None = None


def resolve(text: str, program: Program, symbol_types: Mapping[str, str] | None = None) -> Target:
    """The target ``text`` names in ``program``; :class:`TargetError` MON603 if none.

    ``symbol_types`` (symbol name as in ``program.symbols`` -> declared type, as the symbol table
    has it) types symbols beyond their width: an INT symbol on MW10 reads signed."""
    types = program.symbol_types if symbol_types is None else symbol_types
    return _Resolver(text.strip(), program, types).target()


def is_input(target: Target) -> bool:
    return target.direct is not None and target.direct.area in (Area.I, Area.PI)


def is_output(target: Target) -> bool:
    return target.direct is not None and target.direct.area in (Area.Q, Area.PQ)


# -- resolving -------------------------------------------------------------------------------


class _Resolver:
    def __init__(self, text: str, program: Program, symbol_types: Mapping[str, str]) -> None:
        self.text = text
        self.program = program
        self.symbols = _symbol_index(program.symbols)
        self.types = symbol_types
        self.db = 0  # the DB whose variables are being resolved

    def error(self, reason: Phrase | str) -> TargetError:
        return TargetError("MON603", self.text, reason)

    def target(self) -> Target:
        text = self.text
        if not text:
            raise self.error(phrase("target_empty", examples=EXAMPLES))
        if _ABSOLUTE.match(text) or _PERIPHERAL.match(text):
            try:
                return self.address(text)
            except TargetError:
                if text.casefold() not in self.symbols:
                    raise
        if _LOCAL.match(text):
            raise self.error(phrase("target_local"))
        if _OPEN_DB.match(text):
            raise self.error(phrase("target_open_db"))
        if (name := self.symbols.get(_unquoted(text).casefold())) is not None:
            return self.symbol(name)
        if match := _SYMBOLIC_DB_ADDRESS.match(text):
            return self.symbolic_db_address(match["symbol"], match["rest"])
        return self.path(text)

    # absolute addresses

    def address(self, text: str) -> Target:
        if match := _PERIPHERAL.match(text):
            return self.peripheral(match)
        try:
            address = parse_address(text)
        except AddressError as error:
            reason = error.phrase or str(error).removeprefix(text.strip().upper() + ": ")
            raise self.error(reason) from None
        if isinstance(address, TimerAddress):
            return Target(f"T{address.number}", "TIMER", None, timer=address.number)
        if isinstance(address, CounterAddress):
            return Target(f"C{address.number}", "COUNTER", None, counter=address.number)
        if address.db is not None:
            self.check_db_range(address)
        return Target(address_text(address), _WIDTH_TYPES[address.width], address)

    def peripheral(self, match: re.Match[str]) -> Target:
        size = match["size"].upper()
        if match["bit"] is not None or size in ("", "X"):
            raise self.error(phrase("target_peripheral_width"))
        area = Area.PI if match["area"].upper() in ("I", "E") else Area.PQ
        direct = Direct(area, _WIDTHS[size], int(match["byte"]))
        return Target(address_text(direct), _WIDTH_TYPES[direct.width], direct)

    def data_block(self, number: int) -> Block:
        block = self.program.get(BlockKind.DB, number)
        if block is None:
            known = [f"DB{n}" for kind, n in sorted(self.program.blocks) if kind is BlockKind.DB]
            raise self.error(
                phrase("db_missing_has", db=number, known=_listed(known))
                if known
                else phrase("db_missing_none", db=number)
            )
        return block

    def check_db_range(self, direct: Direct) -> None:
        assert direct.db is not None
        size = db_size(self.data_block(direct.db), self.program)
        if direct.byte + max(1, int(direct.width) // 8) > size:
            raise self.error(
                phrase(
                    "db_range_last", db=direct.db, size=size, last=f"DB{direct.db}.DBB{size - 1}"
                )
                if size
                else phrase("db_range_empty", db=direct.db, size=size)
            )

    # symbols

    def symbol_name(self, name: str) -> str:
        found = self.symbols.get(name.casefold())
        if found is not None:
            return found
        close = difflib.get_close_matches(name.casefold(), list(self.symbols), n=1, cutoff=0.75)
        raise self.error(
            phrase("symbol_unknown_close", name=name, close=self.symbols[close[0]])
            if close
            else phrase("symbol_unknown", name=name, examples=EXAMPLES)
        )

    def parsed_symbol(self, name: str) -> stl_addresses.Parsed:
        address = self.program.symbols[name]
        try:
            return stl_addresses.parse_address(address)
        except stl_addresses.AddressError:
            raise self.error(phrase("symbol_not_address", name=name, address=address)) from None

    def symbol(self, name: str) -> Target:
        parsed, label, address = self.parsed_symbol(name), f'"{name}"', self.program.symbols[name]
        if parsed.kind == "timer":
            return Target(label, "TIMER", None, timer=parsed.number)
        if parsed.kind == "counter":
            return Target(label, "COUNTER", None, counter=parsed.number)
        if parsed.kind == "block":
            if parsed.block is BlockKind.DB:
                return self.variable(self.data_block(parsed.number), label, [])
            raise self.error(phrase("symbol_is_block", label=label, address=address))
        area, width = parsed.area, parsed.width
        if (
            area is None
            or width is None
            or area not in _WATCHED_AREAS
            or (area is Area.DB and parsed.db is None)
        ):
            raise self.error(phrase("symbol_is_local", label=label, address=address))
        direct = Direct(area, width, parsed.byte, parsed.bit, parsed.db)
        if direct.db is not None:
            self.check_db_range(direct)
        return Target(label, self.symbol_type(name, direct.width), direct)

    def symbol_type(self, name: str, width: Width) -> str:
        declared = _canonical(self.types.get(name, ""))
        return declared if _TYPE_WIDTHS.get(declared) == width else _WIDTH_TYPES[width]

    def symbol_db(self, name: str) -> Block:
        parsed = self.parsed_symbol(name)
        if parsed.kind != "block" or parsed.block is not BlockKind.DB:
            raise self.error(phrase("symbol_not_db", name=name, address=self.program.symbols[name]))
        return self.data_block(parsed.number)

    def symbolic_db_address(self, symbol: str, rest: str) -> Target:
        name = self.symbol_name(symbol)
        block = self.symbol_db(name)
        found = self.address(f"DB{block.number}.{rest}")
        return Target(f'"{name}".{found.text.split(".", 1)[1]}', found.type, found.direct)

    # DB variables

    def path(self, text: str) -> Target:
        head = _HEAD.match(text)
        selectors = _selectors(text, head.end()) if head is not None else None
        if head is None or selectors is None:
            raise self.error(phrase("target_unreadable", examples=EXAMPLES))
        if head["db"] is not None:
            number = int(head["db"])
            return self.variable(self.data_block(number), f"DB{number}", selectors)
        name = self.symbol_name(head["symbol"] or head["name"])
        if not selectors:
            return self.symbol(name)
        return self.variable(self.symbol_db(name), f'"{name}"', selectors)

    def variable(self, block: Block, label: str, selectors: list[Selector]) -> Target:
        top = _layout(block, self.program)
        if not top:
            raise self.error(phrase("db_no_layout", label=label, example=f"DB{block.number}.DBW0"))
        if not selectors:
            raise self.error(
                phrase(
                    "db_name_variable",
                    label=label,
                    example=f"{label}.{top[0].name}",
                    known=_names(top),
                )
            )
        self.db = block.number
        path, current = label, None
        for selector in selectors:
            if isinstance(selector, str):
                current = self.member(current, top, selector, path)
                path = f"{path}.{current.name}"
            else:
                current = self.element(current, selector, path)
                path = f"{path}[{','.join(str(index) for index in selector)}]"
        assert current is not None
        return self.leaf(current, path, block.number)

    def member(
        self, parent: Variable | None, top: list[Variable], name: str, path: str
    ) -> Variable:
        if parent is None:
            candidates = top
        elif array_shape(parent.type) is not None:
            raise self.error(
                phrase("index_first", path=path, type=parent.type, example=_first(path, parent))
            )
        elif not parent.members:
            raise self.error(phrase("type_no_variables", path=path, type=parent.type))
        else:
            candidates = parent.members
        found = next((v for v in candidates if v.name.casefold() == name.casefold()), None)
        if found is None:
            raise self.error(
                phrase("no_such_variable", path=path, name=name, known=_names(candidates))
            )
        if found.section == "IN_OUT" and _BY_REFERENCE.match(found.type):
            raise self.error(phrase("in_out_pointer", path=f"{path}.{found.name}", type=found.type))
        return found

    def element(self, parent: Variable | None, indices: tuple[int, ...], path: str) -> Variable:
        shape = array_shape(parent.type) if parent is not None else None
        if parent is None or shape is None:
            raise self.error(
                phrase("db_not_array", path=path)
                if parent is None
                else phrase("type_not_array", path=path, type=parent.type)
            )
        dims, element_type = shape
        if len(indices) != len(dims):
            raise self.error(
                phrase(
                    "index_count",
                    path=path,
                    type=parent.type,
                    count=len(dims),
                    example=_first(path, parent),
                )
            )
        linear, count = 0, 1
        for index, (low, high) in zip(indices, dims, strict=True):
            if not low <= index <= high:
                raise self.error(
                    phrase(
                        "index_outside",
                        index=index,
                        low=low,
                        high=high,
                        path=path,
                        type=parent.type,
                    )
                )
            linear = linear * (high - low + 1) + index - low
            count *= high - low + 1
        name = f"{parent.name}[{','.join(str(index) for index in indices)}]"
        layout = self.element_layout(element_type)
        if layout is None:  # e.g. ARRAY OF STRUCT: the IR keeps no member list for its elements
            start = (parent.offset_bits + linear * (parent.size_bits // count)) // 8
            raise self.error(
                phrase(
                    "element_layout",
                    type=element_type,
                    path=path,
                    name=name,
                    start=f"DB{self.db}.DBB{start}",
                )
            )
        stride, size, members = layout
        offset = parent.offset_bits + linear * stride
        return Variable(name, element_type, "", offset, size, members=_shifted(members, offset))

    def element_layout(self, element_type: str) -> tuple[int, int, list[Variable]] | None:
        """Stride and size in bits of one element, with its variables from offset 0."""
        kind = _canonical(element_type)
        if kind in ELEMENTARY_BITS:
            bits = ELEMENTARY_BITS[kind]
            return (bits if bits <= 8 else _even(bits)), bits, []
        if string := _STRING.match(element_type):
            size = _even((int(string[2]) + 2) * (16 if string[1] else 8))
            return size, size, []
        udt = re.match(r"^UDT\s*(\d+)$", element_type, re.IGNORECASE)
        block = self.program.get(BlockKind.UDT, int(udt[1])) if udt else None
        if block is None:
            return None
        size = _even(max((v.offset_bits + v.size_bits for v in block.interface), default=0))
        return size, size, block.interface

    def leaf(self, variable: Variable, path: str, db: int) -> Target:
        kind = _canonical(variable.type)
        if kind in NUMBER_TYPES:  # a TIMER/COUNTER/BLOCK_xx parameter holds a number
            kind = "WORD"
        width = _TYPE_WIDTHS.get(kind)
        if width is not None:
            offset = variable.offset_bits
            bit = offset % 8 if width is Width.BIT else 0
            return Target(path, kind, Direct(Area.DB, width, offset // 8, bit, db=db))
        if kind in LONG_TYPES or _STRING.match(kind):
            # 8 bytes, or a string, from the variable's first byte (``long_values`` reads them)
            kind = kind if kind in LONG_TYPES else re.sub(r"\s+", "", kind)
            start = variable.offset_bits // 8
            return Target(path, kind, Direct(Area.DB, Width.DWORD, start, db=db))
        if array_shape(variable.type) is not None:
            raise self.error(
                phrase("add_index", path=path, type=variable.type, example=_first(path, variable))
            )
        if variable.members:
            raise self.error(
                phrase(
                    "name_member",
                    path=path,
                    type=variable.type,
                    example=f"{path}.{variable.members[0].name}",
                    known=_names(variable.members),
                )
            )
        first = f"DB{db}.DBB{variable.offset_bits // 8}"
        raise self.error(
            phrase(
                "not_elementary",
                path=path,
                type=variable.type,
                bytes=variable.size_bits // 8,
                first=first,
            )
        )


# A watch list resolves all its entries against one program: its symbol index is kept.
_last_index: list[tuple[dict[str, str], int, dict[str, str]]] = []


def _symbol_index(symbols: dict[str, str]) -> dict[str, str]:
    """The program's symbol names by their casefolded spelling (STEP 7 ignores case)."""
    if not _last_index or _last_index[0][0] is not symbols or _last_index[0][1] != len(symbols):
        _last_index[:] = [(symbols, len(symbols), {name.casefold(): name for name in symbols})]
    return _last_index[0][2]


def _unquoted(text: str) -> str:
    if len(text) > 1 and text[0] == text[-1] == '"' and '"' not in text[1:-1]:
        return text[1:-1]
    return text


def _selectors(text: str, position: int) -> list[Selector] | None:
    """The ``.name`` and ``[i, j]`` parts after the head, or None if something else follows."""
    selectors: list[Selector] = []
    while position < len(text):
        match = _SELECTOR.match(text, position)
        if match is None:
            return None
        if match["indices"] is not None:
            try:
                selectors.append(tuple(int(part) for part in match["indices"].split(",")))
            except ValueError:
                raise TargetError("MON603", text, phrase("array_index_whole")) from None
        else:
            selectors.append(match["quoted"] or match["name"])
        position = match.end()
    return selectors


def _layout(block: Block, program: Program) -> list[Variable]:
    interface = block.interface
    if not interface and block.instance_of is not None:
        fb = program.get(BlockKind.FB, block.instance_of)
        interface = fb.interface if fb is not None else []
    return [v for v in interface if v.section not in ("TEMP", "RETURN")]


def _first(path: str, array: Variable) -> str:
    shape = array_shape(array.type)
    lows = ",".join(str(low) for low, _high in shape[0]) if shape else "1"
    return f"{path}[{lows}]"


def _shifted(variables: list[Variable], offset: int) -> list[Variable]:
    return [
        Variable(
            v.name,
            v.type,
            v.section,
            v.offset_bits + offset,
            v.size_bits,
            members=_shifted(v.members, offset),
        )
        for v in variables
    ]


def _canonical(type_text: str) -> str:
    upper = type_text.strip().upper()
    return TYPE_ALIASES.get(upper, upper)


def _even(bits: int) -> int:
    return (bits + 15) // 16 * 16


def _names(variables: list[Variable]) -> str:
    return _listed([v.name for v in variables])


def _listed(items: list[str], limit: int = 12) -> str:
    shown = ", ".join(items[:limit])
    return shown + (", ..." if len(items) > limit else "")


# -- reading and writing -----------------------------------------------------------------------


def read(target: Target, cpu: Cpu) -> Value:
    """The value of ``target`` in ``cpu``: BOOL a bool, INT/DINT/TIME signed, REAL a float (or
    "NaN", "+Inf", "-Inf"), CHAR a one-character str, S5TIME ms, a timer its remaining ms, a
    counter its count; None when its DB is not loaded. TargetError MON603 when the CPU has no
    such address (beyond its memory or its timers)."""
    if target.timer is not None:
        return cpu.timer(_numbered(target, target.timer, cpu, "T"))[1]
    if target.counter is not None:
        return cpu.counter(_numbered(target, target.counter, cpu, "C"))[1]
    direct = _direct(target)
    kind = _canonical(target.type)
    try:
        if kind in LONG_TYPES:
            return decode(kind, long_values.read_long(cpu, direct))
        if kind.endswith("]"):
            return long_values.read_string(cpu, direct, kind)
        pattern = cpu.read(direct)
    except KeyError:
        return None
    except IndexError:
        raise _outside(target, direct, cpu) from None
    return decode(kind, pattern)


def write(target: Target, cpu: Cpu, value: bool | int | float | str | None) -> None:
    """Stores ``value`` (see :func:`encode`) at ``target``; timers and counters: MON606."""
    kind = _canonical(target.type)
    text = ""
    if kind.endswith("]"):
        chars = long_values.string_value(kind, value)
        if not isinstance(chars, str):
            raise _bad(target, chars)
        text = chars
    else:
        pattern = encode(target, value)
    direct = _direct(target)
    try:
        if kind.endswith("]"):
            long_values.write_string(cpu, direct, kind, text)
        elif kind in LONG_TYPES:
            long_values.write_long(cpu, direct, pattern)
        else:
            cpu.write(direct, pattern)
    except KeyError:
        raise TargetError("MON603", target.text, phrase("db_not_loaded", db=direct.db)) from None
    except IndexError:
        raise _outside(target, direct, cpu) from None


def _direct(target: Target) -> Direct:
    if target.direct is None:
        raise TargetError("MON603", target.text, phrase("no_memory_address"))
    return target.direct


def _numbered(target: Target, number: int, cpu: Cpu, prefix: str) -> int:
    count = cpu.profile.timers if prefix == "T" else cpu.profile.counters
    if not 0 <= number < count:
        last = f"{prefix}{count - 1}"
        raise TargetError(
            "MON603",
            target.text,
            phrase("numbered_range", cpu=cpu.profile.value, first=f"{prefix}0", last=last),
        )
    return number


def _outside(target: Target, direct: Direct, cpu: Cpu) -> TargetError:
    if direct.db is not None:
        size = len(cpu.db_bytes(direct.db) or b"")
        return TargetError("MON603", target.text, phrase("db_length", db=direct.db, size=size))
    size = len(cpu.area_bytes(direct.area))
    area = direct.area.value
    return TargetError(
        "MON603",
        target.text,
        phrase("area_range", cpu=cpu.profile.value, first=f"{area}B0", last=f"{area}B{size - 1}"),
    )


# -- encoding ------------------------------------------------------------------------------------

_INTEGERS = frozenset(
    {ConstType.INT, ConstType.DINT, ConstType.BYTE, ConstType.WORD, ConstType.DWORD}
)
# Typed constants (``T#2S``, ``16#FF``) each type accepts; plain numbers suit every type.
_CONSTANTS = {
    "TIME": frozenset({ConstType.TIME, ConstType.S5TIME}),
    "S5TIME": frozenset({ConstType.TIME, ConstType.S5TIME}),
    "DATE": frozenset({ConstType.DATE}),
    "TIME_OF_DAY": frozenset({ConstType.TOD}),
}
# Whole-number types: the values they take (negative BYTE/WORD/DWORD values are stored as their
# two's complement, as the command line does) and how to say so.
_RANGES: dict[str, tuple[int, int, Phrase]] = {
    "BYTE": (-128, 0xFF, phrase("range", low="-128", high="255 (16#FF)")),
    "WORD": (-32768, 0xFFFF, phrase("range", low="-32768", high="65535 (16#FFFF)")),
    "DWORD": (
        -(2**31),
        2**32 - 1,
        phrase("range", low="-2147483648", high="4294967295 (16#FFFFFFFF)"),
    ),
    "INT": (-32768, 32767, phrase("range", low="-32768", high="32767")),
    "DINT": (-(2**31), 2**31 - 1, phrase("range", low="-2147483648", high="2147483647")),
    "TIME": (
        -(2**31) + 1,
        2**31 - 1,
        phrase("range", low="T#-24D20H31M23S647MS", high="T#24D20H31M23S647MS"),
    ),
    "S5TIME": (0, 9_990_000, phrase("range", low="S5T#0MS", high="S5T#2H46M30S")),
    "DATE": (0, 65378, phrase("range", low="D#1990-1-1", high="D#2168-12-31")),
    "TIME_OF_DAY": (0, 86_399_999, phrase("range", low="TOD#0:0:0", high="TOD#23:59:59.999")),
    "CHAR": (0, 255, phrase("char_range")),
}
_EXAMPLE_VALUES = {
    "BOOL": "TRUE",
    "BYTE": "16#FF",
    "WORD": "16#FFFF",
    "DWORD": "16#FFFF_FFFF",
    "INT": "-5",
    "DINT": "100000",
    "REAL": "1.5",
    "TIME": "T#1M30S",
    "S5TIME": "S5T#2S",
    "DATE": "D#2024-1-31",
    "TIME_OF_DAY": "TOD#13:30:00",
    "CHAR": "'A'",
}
_BOOLS = {"1": 1, "0": 0, "TRUE": 1, "FALSE": 0}
_SPECIAL_REALS = {"NAN": math.nan, "INF": math.inf, "+INF": math.inf, "-INF": -math.inf}


def encode(target: Target, value: bool | int | float | str | None) -> int:
    """The unsigned bit pattern that stores ``value`` as ``target``'s type; TargetError MON606
    when it does not parse or fit. Strings are what users type: ``TRUE``, ``-3``, ``16#FF``,
    ``2#1010``, ``1.5``, ``T#1M30S``, ``S5T#2S`` (the smallest time base that holds it),
    ``D#2024-1-31``, ``TOD#13:30:00``, ``'A'``."""
    kind = _canonical(target.type)
    if target.timer is not None or target.counter is not None or kind in ("TIMER", "COUNTER"):
        raise _bad(target, phrase("timers_not_written"))
    if value is None:
        raise _bad(
            target, phrase("value_needed", type=kind, example=_EXAMPLE_VALUES.get(kind, "0"))
        )
    if kind == "BOOL":
        return _encode_bool(target, value)
    if kind == "REAL":
        return _encode_real(target, value)
    if kind in long_values.WIDE_TYPES:
        pattern = long_values.encode(kind, value)
        if not isinstance(pattern, int):
            raise _bad(target, pattern)
        return pattern
    if kind not in _RANGES:
        raise _bad(target, phrase("type_not_writable", type=target.type))
    number = _whole(target, kind, value)
    low, high, allowed = _RANGES[kind]
    if not low <= number <= high:
        raise _bad(target, phrase("value_not_fit", value=_shown(value), type=kind, allowed=allowed))
    if kind == "S5TIME":
        return _s5time(number)
    return number & ((1 << ELEMENTARY_BITS[kind]) - 1)


def _bad(target: Target, reason: Phrase) -> TargetError:
    return TargetError("MON606", target.text, reason)


def _shown(value: bool | int | float | str) -> str:
    return value.strip() if isinstance(value, str) else str(value)


def _encode_bool(target: Target, value: bool | int | float | str) -> int:
    if isinstance(value, int) and value in (0, 1):
        return int(value)
    if isinstance(value, str) and value.strip().upper() in _BOOLS:
        return _BOOLS[value.strip().upper()]
    raise _bad(target, phrase("not_bool", value=_shown(value)))


def _encode_real(target: Target, value: bool | int | float | str) -> int:
    if isinstance(value, bool):
        raise _bad(target, phrase("not_real", value=value))
    number: float | None
    if isinstance(value, str):
        number = _SPECIAL_REALS.get(value.strip().upper())
        if number is None:
            number = float(_parse(target, "REAL", value))
    else:
        number = float(value)
    try:
        return real_pattern(number)
    except OverflowError:
        allowed = phrase("range", low="-3.402823E+38", high="3.402823E+38")
        raise _bad(
            target, phrase("value_not_fit", value=_shown(value), type="REAL", allowed=allowed)
        ) from None


def _whole(target: Target, kind: str, value: bool | int | float | str) -> int:
    if kind == "CHAR" and isinstance(value, str) and (char := _char(value)) is not None:
        return ord(char)
    number = _parse(target, kind, value) if isinstance(value, str) else value
    if isinstance(number, float):
        if not number.is_integer():
            raise _bad(
                target,
                phrase("not_whole", value=_shown(value), type=kind, allowed=_RANGES[kind][2]),
            )
        return int(number)
    return int(number)


def _char(text: str) -> str | None:
    """``A``, ``'A'`` or ``"A"`` → ``A``; anything else is not a character."""
    if len(text) == 1:
        return text
    if len(text) == 3 and text[0] == text[2] and text[0] in "'\"":
        return text[1]
    return None


def _parse(target: Target, kind: str, text: str) -> int | float:
    cleaned = text.strip()
    example = _EXAMPLE_VALUES.get(kind, "0")
    if "#" in cleaned and kind != "REAL":
        try:
            constant = typed(cleaned)
        except ConstantError as error:
            try:
                return parse_number(cleaned)  # -16#FF, which is no STEP 7 constant
            except AddressError:
                raise _bad(target, _constant_reason(cleaned, error)) from None
        if constant.type not in _CONSTANTS.get(kind, _INTEGERS):
            raise _bad(
                target,
                phrase(
                    "constant_of_type",
                    value=cleaned,
                    actual=constant.type.value,
                    type=kind,
                    example=example,
                ),
            )
        return constant.value
    try:
        return parse_number(cleaned)
    except AddressError:
        raise _bad(
            target, phrase("not_of_type", value=repr(cleaned), type=kind, example=example)
        ) from None


def _constant_reason(cleaned: str, error: ConstantError) -> Phrase:
    if error.code == "STL214":
        kind = str(error.params["type"])
        allowed = _RANGES[kind][2] if kind in _RANGES else phrase("out_of_range")
        return phrase("value_not_fit", value=cleaned, type=kind, allowed=allowed)
    return phrase(
        "not_constant", value=cleaned, reason=error.params.get("reason", "not a constant")
    )


def _s5time(ms: int) -> int:
    """S5TIME in the smallest time base that holds ``ms`` (finer parts are dropped, as STEP 7
    does): 3 BCD digits, the base code in bits 12-13."""
    code = next(code for code, base in enumerate(BASES_MS) if ms // base <= 999)
    return code << 12 | int_to_bcd(ms // BASES_MS[code], 3)

"""Cross-references and the assignment list of a project, as TIA Portal / STEP 7 show them.

Both are read from the compiled program, not from the text: every language lowers to the same
STL IR, whose instructions carry the resolved operand (a symbol is already its address, a
``"DB".member`` its DB address) and an origin (file, line, column, network, LAD/FBD element).
So one walk over the IR finds the uses in STL, SCL and LAD/FBD alike, and a symbol written one
way and its address written the other are the same operand, as on a CPU.

Decisions (STEP 7 behaviour, written down here):
- A use's access comes from the instruction: ``A/O/X/L`` read, ``=``/``T`` write, ``S``/``R``
  set/reset, ``FP``/``FN`` read and write their edge bit, timer starts (``SP``...``SF``) "start",
  ``CU``/``CD`` "count", ``FR`` "enable", ``CALL``/``UC``/``CC`` call, ``OPN`` open. A block
  parameter's actual operand is read for IN, written for OUT/RET_VAL, both for IN_OUT.
- Cross-references of an address list the overlapping accesses too (``QB 4`` for ``Q 4.0``),
  marked ``exact: false``, as STEP 7's "overlapping accesses" view does.
- SCL has no networks: its uses have ``network: null``; its column is the statement's.
- LAD/FBD: a use is placed on its network's ``NETWORK`` line with the element id (the LAD
  editor selects the element; the text format keeps no position per element).
- S7-Graph: a use is placed on the line of the part it was written in (the step's action row,
  the transition, the interlock ...), with the origin element (``S3/A2``, ``T1/e1``; see
  ``nasaq/lang/graph/SEMANTICS.md`` §5) and no network.
- A block's own interface (``#var``: L stack, instance data through AR2, FC parameters) is not
  a project-wide operand and is not listed.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Literal

from pydantic import BaseModel, Field

from nasaq.cpu.memory import address_text
from nasaq.ir import (
    Area,
    Block,
    BlockKind,
    BlockRef,
    CounterRef,
    Direct,
    Instruction,
    MemoryIndirect,
    Operand,
    Program,
    TimerRef,
    Variable,
)
from nasaq.lang.lad.compile import LoweredFile, lower_file
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.workbench.names import language_of
from nasaq.workbench.project_compile import compile_project
from nasaq.workbench.tree import BLOCK_KINDS

Access = Literal[
    "read", "write", "read_write", "set", "reset", "start", "count", "enable", "call", "open"
]
ASSIGNED_AREAS = (Area.I, Area.Q, Area.M, Area.PI, Area.PQ)

_READ = frozenset(
    {"A", "AN", "O", "ON", "X", "XN", "L", "LC", "A(", "AN(", "O(", "ON(", "X(", "XN("}
)
_BY_OP: dict[str, Access] = {
    "=": "write",
    "T": "write",
    "S": "set",
    "R": "reset",
    "FP": "read_write",
    "FN": "read_write",
    "SP": "start",
    "SE": "start",
    "SD": "start",
    "SS": "start",
    "SF": "start",
    "CU": "count",
    "CD": "count",
    "FR": "enable",
    "CALL": "call",
    "UC": "call",
    "CC": "call",
    "OPN": "open",
}
_BY_SECTION: dict[str, Access] = {
    "IN": "read",
    "OUT": "write",
    "RETURN": "write",
    "IN_OUT": "read_write",
}
_WIDTH_NAMES = {1: "bit", 8: "byte", 16: "word", 32: "dword"}


class XrefError(Exception):
    """A target that names nothing in the project (a catalogue code with its parameters)."""

    def __init__(self, code: str, **params: object) -> None:
        super().__init__(code)
        self.code = code
        self.params = params


@dataclass(frozen=True, slots=True)
class Operated:
    """One operand as a place: memory (area, db, bit range), a timer, a counter or a block."""

    kind: str  # "memory", "timer", "counter", "block"
    area: Area | None = None
    db: int | None = None
    start: int = 0  # first bit
    bits: int = 0  # width in bits (memory)
    block: str = ""  # "FB 10"; "DB 1" for a DB access
    number: int = 0  # timer/counter number

    def text(self) -> str:
        if self.kind == "timer":
            return f"T {self.number}"
        if self.kind == "counter":
            return f"C {self.number}"
        if self.kind == "block":
            return self.block
        assert self.area is not None
        return address_text(self.area, self.bits, self.start // 8, self.start % 8, self.db)

    def overlaps(self, other: Operated) -> bool:
        if self.kind != other.kind:
            return False
        if self.kind == "memory":
            return (
                self.area == other.area
                and self.db == other.db
                and self.start < other.start + other.bits
                and other.start < self.start + self.bits
            )
        return self.block == other.block and self.number == other.number


class XrefEntry(BaseModel):
    file: str
    block: str = Field(description="'OB 1', 'FB 10'")
    block_name: str = Field(description="The block's symbol, empty when it has none")
    language: str = Field(description="stl, scl, lad, fbd or graph")
    network: int | None = Field(description="1-based network; null in SCL")
    line: int
    column: int
    element: str | None = Field(description="LAD/FBD element id")
    access: Access
    instruction: str = Field(
        description="The STL instruction the use compiles to: 'A', '=', 'CALL'"
    )
    address: str = Field(description="The operand used: 'Q 4.0', 'QB 4', 'DB1.DBD 0', 'FC 10'")
    symbol: str = Field(description="The operand's symbol, empty when it has none")
    exact: bool = Field(description="False for an overlapping access ('QB 4' for 'Q 4.0')")


class XrefResult(BaseModel):
    target: str = Field(description="What was asked for, as the project names it")
    address: str = Field(description="What it resolves to: 'Q 4.0', 'FB 10', 'DB1.DBD 4'")
    symbol: str
    entries: list[XrefEntry]


class AssignedBit(BaseModel):
    bit: int
    read: bool
    write: bool
    symbol: str


class AssignedByte(BaseModel):
    area: str = Field(description="I, Q, M, PI, PQ")
    byte: int
    bits: list[AssignedBit] = Field(description="The bits used one by one, 0..7")
    widths: list[str] = Field(description="Wider accesses starting here: 'byte', 'word', 'dword'")
    symbols: list[str] = Field(description="Symbols of the wider accesses starting here")


class AssignedTimer(BaseModel):
    kind: Literal["T", "C"]
    number: int
    accesses: list[Access]
    symbol: str


class AssignmentList(BaseModel):
    bytes: list[AssignedByte]
    timers: list[AssignedTimer] = Field(description="Timers and counters, T first")


@dataclass(frozen=True, slots=True)
class _Use:
    place: Operated
    access: Access
    instruction: str
    block: Block
    line: int
    column: int
    network: int | None
    element: str | None


def _place(operand: Operand | None) -> Operated | None:
    if isinstance(operand, Direct):
        if operand.area in (Area.L, Area.V, Area.DI):
            return None
        return Operated(
            "memory",
            operand.area,
            operand.db,
            operand.byte * 8 + operand.bit,
            int(operand.width),
        )
    if isinstance(operand, TimerRef):
        return Operated("timer", number=operand.number)
    if isinstance(operand, CounterRef):
        return Operated("counter", number=operand.number)
    if isinstance(operand, BlockRef):
        kind = BlockKind.DB if operand.kind == BlockKind.DI else operand.kind
        return Operated("block", block=f"{kind.value} {operand.number}")
    return None


def _access(instr: Instruction, place: Operated) -> Access:
    op = instr.op
    if op in _READ:
        return "read"
    access = _BY_OP.get(op, "read")
    if place.kind == "counter" and op == "S":
        return "set"
    return access


def _section(callee: Block | None, name: str) -> str:
    for var in callee.interface if callee is not None else ():
        if var.name == name:
            return var.section
    return "IN"


def _instruction_uses(instr: Instruction, program: Program) -> Iterator[tuple[Operated, Access]]:
    operand = instr.operand
    if isinstance(operand, MemoryIndirect):
        pointer = _place(operand.pointer) if isinstance(operand.pointer, Direct) else None
        if pointer is not None:
            yield pointer, "read"
    place = _place(operand)
    if place is not None and instr.call is None:
        yield place, _access(instr, place)
    if place is not None and place.kind == "memory" and place.db is not None:
        yield Operated("block", block=f"DB {place.db}"), _access(instr, place)
    call = instr.call
    if call is None:
        return
    yield Operated("block", block=f"{call.block.kind.value} {call.block.number}"), "call"
    if isinstance(call.instance, BlockRef):
        yield Operated("block", block=f"DB {call.instance.number}"), "open"
    callee = program.get(call.block.kind, call.block.number)
    for arg in call.args:
        used = _place(arg.value)
        if used is None:
            continue
        access = _BY_SECTION.get(_section(callee, arg.name), "read")
        yield used, access
        if used.kind == "memory" and used.db is not None:
            yield Operated("block", block=f"DB {used.db}"), access


def project_uses(program: Program, texts: dict[str, str]) -> list[_Use]:
    """Every use of a global operand in the user's code blocks, in block and code order."""
    found: list[_Use] = []
    lowered: dict[str, LoweredFile] = {}
    for block in program.blocks.values():
        if block.file not in texts or BLOCK_KINDS.get(block.kind) is None or not block.code:
            continue
        language = language_of(block.file)
        if language in ("lad", "fbd", "graph") and block.file not in lowered:
            lowered[block.file] = _lowered(block.file, texts[block.file], language)
        for instr in block.code:
            origin = instr.origin
            if origin is None or origin.file not in texts:
                continue
            line, column, network = origin.line, origin.column, origin.network
            if origin.file in lowered:  # the IR has the generated STL's line: its network's
                line, network = lowered[origin.file].place(origin.line)
                column = 1
            for place, access in _instruction_uses(instr, program):
                found.append(
                    _Use(
                        place,
                        access,
                        instr.op,
                        block,
                        line,
                        column,
                        None if language == "scl" else network,
                        origin.element,
                    )
                )
    return found


def _lowered(file: str, text: str, language: str | None) -> LoweredFile:
    """The STL a LAD/FBD or S7-Graph file lowers to, with its map back to the file's lines."""
    if language == "graph":
        from nasaq.lang.graph.compile import lower_file as lower_graph  # Graph builds on LAD

        return lower_graph(file, text)
    return lower_file(file, text)


class _Names:
    """Symbol names by the place they name (the first symbol, should two name one place)."""

    def __init__(self, program: Program) -> None:
        self.by_text: dict[str, str] = {}
        self.by_key: dict[str, str] = {}  # casefolded symbol -> symbol as written
        for name, address in program.symbols.items():
            self.by_key.setdefault(name.casefold(), name)
            try:
                place = _parsed_place(address)
            except AddressError:
                continue
            if place is not None:
                self.by_text.setdefault(place.text(), name)

    def of(self, place: Operated) -> str:
        return self.by_text.get(place.text(), "")

    def of_text(self, address: str) -> str:
        """The symbol of an address as written (``Q4.0``, ``FB 10``), empty when none."""
        try:
            place = _parsed_place(address)
        except AddressError:
            return ""
        return self.of(place) if place is not None else ""


def _parsed_place(text: str) -> Operated | None:
    parsed = parse_address(text)
    if parsed.kind == "timer":
        return Operated("timer", number=parsed.number)
    if parsed.kind == "counter":
        return Operated("counter", number=parsed.number)
    if parsed.kind == "block" and parsed.block is not None:
        kind = BlockKind.DB if parsed.block == BlockKind.DI else parsed.block
        return Operated("block", block=f"{kind.value} {parsed.number}")
    if parsed.area is None or parsed.width is None:
        return None
    return Operated(
        "memory", parsed.area, parsed.db, parsed.byte * 8 + parsed.bit, int(parsed.width)
    )


def _member(block: Block, path: str) -> Variable | None:
    variables = block.interface
    found: Variable | None = None
    for part in path.split("."):
        found = next((var for var in variables if var.name.casefold() == part.casefold()), None)
        if found is None:
            return None
        variables = found.members
    return found


def _split_member(target: str) -> tuple[str, str | None]:
    """``"Data".Speed`` -> (``Data``, ``Speed``); ``"Motor"`` -> (``Motor``, None)."""
    text = target.strip()
    if text.startswith('"'):
        close = text.find('"', 1)
        if close > 0:
            rest = text[close + 1 :].strip()
            return text[1:close], rest[1:].strip() if rest.startswith(".") and len(
                rest
            ) > 1 else None
    return text, None


def _target(target: str, program: Program, names: _Names) -> tuple[Operated, str, str]:
    """The place ``target`` names, its address text and its symbol."""
    text = " ".join(target.split())
    if not text:
        raise XrefError("XRF701", target=target)
    head, member = _split_member(text)
    if member is None and not text.startswith('"') and "." in text and text[:2].upper() == "DB":
        db_text, _, member_text = text.partition(".")
        if not member_text.upper().startswith(("DBX", "DBB", "DBW", "DBD")):
            head, member = db_text, member_text
    if member is None:
        try:
            place = _parsed_place(text)
        except AddressError:
            place = None
        if place is not None and not text.startswith('"'):
            return place, place.text(), names.of(place)
    symbol = names.by_key.get(head.casefold())
    address = program.symbols.get(symbol) if symbol is not None else None
    if address is None:
        try:
            place = _parsed_place(head)  # "DB 1".member, DB1.member
        except AddressError:
            place = None
        if place is None or member is None:
            raise XrefError("XRF701", target=target)
        symbol = names.of(place)
    else:
        place = _parsed_place(address)
        if place is None:
            raise XrefError("XRF701", target=target)
    if member is None:
        return place, place.text(), symbol or ""
    if place.kind != "block" or not place.block.startswith("DB "):
        raise XrefError("XRF702", target=target, name=head)
    number = int(place.block.split()[1])
    block = program.get(BlockKind.DB, number)
    variable = _member(block, member) if block is not None else None
    if variable is None:
        raise XrefError("XRF703", target=target, name=head, member=member)
    width = variable.size_bits if variable.size_bits in (1, 8, 16, 32) else 0
    bits = width or variable.size_bits
    member_place = Operated("memory", Area.DB, number, variable.offset_bits, max(bits, 1))
    shown = member_place.text() if width else f"DB{number}.DBX {variable.offset_bits // 8}.0"
    return member_place, shown, f"{symbol or place.block}.{variable.name}"


def _entry(use: _Use, names: _Names, exact: bool) -> XrefEntry:
    block = use.block
    return XrefEntry(
        file=block.file,
        block=f"{block.kind.value} {block.number}",
        block_name=block.name,
        language=language_of(block.file) or "stl",
        network=use.network,
        line=use.line,
        column=use.column,
        element=use.element,
        access=use.access,
        instruction=use.instruction,
        address=use.place.text(),
        symbol=names.of(use.place),
        exact=exact,
    )


def _compiled(sources: list[tuple[str, str]]) -> Program:
    return compile_project(sources).program


def references(sources: list[tuple[str, str]], target: str) -> XrefResult:
    """Where ``target`` (a symbol, an address, a block or a DB member) is used in the project."""
    program = _compiled(sources)
    names = _Names(program)
    place, address, symbol = _target(target, program, names)
    entries: list[XrefEntry] = []
    seen: set[tuple[object, ...]] = set()
    for use in project_uses(program, dict(sources)):
        if not place.overlaps(use.place):
            continue
        exact = use.place == place if place.kind == "memory" else True
        key = (use.block.file, use.line, use.column, use.element, use.access, use.place)
        if key in seen:
            continue  # an SCL statement lowered to several loads of one operand
        seen.add(key)
        entries.append(_entry(use, names, exact))
    entries.sort(key=lambda item: (not item.exact, item.file, item.line, item.column))
    return XrefResult(target=target.strip(), address=address, symbol=symbol, entries=entries)


def assignment_list(sources: list[tuple[str, str]]) -> AssignmentList:
    """Which I/Q/M/PI/PQ bytes and bits, timers and counters the program uses, and how."""
    program = _compiled(sources)
    names = _Names(program)
    bits: dict[tuple[str, int], dict[int, list[bool]]] = {}
    wide: dict[tuple[str, int], dict[int, str]] = {}
    counted: dict[tuple[str, int], list[Access]] = {}
    for use in project_uses(program, dict(sources)):
        place = use.place
        if place.kind in ("timer", "counter"):
            key = ("T" if place.kind == "timer" else "C", place.number)
            accesses = counted.setdefault(key, [])
            if use.access not in accesses:
                accesses.append(use.access)
            continue
        if place.kind != "memory" or place.area not in ASSIGNED_AREAS or place.db is not None:
            continue
        assert place.area is not None
        where = (place.area.value, place.start // 8)
        if place.bits == 1:
            flags = bits.setdefault(where, {}).setdefault(place.start % 8, [False, False])
            flags[0] = flags[0] or use.access in ("read", "read_write")
            flags[1] = flags[1] or use.access not in ("read",)
        else:
            wide.setdefault(where, {})[place.bits] = names.of(place)
    order = {area.value: index for index, area in enumerate(ASSIGNED_AREAS)}
    rows = [
        AssignedByte(
            area=area,
            byte=byte,
            bits=[
                AssignedBit(
                    bit=bit,
                    read=flags[0],
                    write=flags[1],
                    symbol=names.of(Operated("memory", Area(area), None, byte * 8 + bit, 1)),
                )
                for bit, flags in sorted(bits.get((area, byte), {}).items())
            ],
            widths=[_WIDTH_NAMES[size] for size in sorted(wide.get((area, byte), {}))],
            symbols=[name for _, name in sorted(wide.get((area, byte), {}).items()) if name],
        )
        for area, byte in sorted(set(bits) | set(wide), key=lambda key: (order[key[0]], key[1]))
    ]
    timers = [
        AssignedTimer(
            kind="T" if kind == "T" else "C",
            number=number,
            accesses=accesses,
            symbol=names.of(Operated("timer" if kind == "T" else "counter", number=number)),
        )
        for (kind, number), accesses in sorted(counted.items())
    ]
    return AssignmentList(bytes=rows, timers=timers)

"""Blocks and programs in STL IR form: what a compiler hands to the CPU."""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.ir.fast_init import fast_init
from nasaq.ir.operands import BlockKind, CallInfo, Operand


@fast_init
@dataclass(frozen=True, slots=True)
class Origin:
    """Where an instruction came from: the STL line, or the SCL line, or the LAD/FBD element."""

    file: str
    line: int
    column: int
    network: int | None = None  # 1-based network of the block
    element: str | None = None  # LAD/FBD element id or Graph step/transition id


@dataclass(slots=True)
class Instruction:
    op: str  # international mnemonic, canonical spelling: "A", "AN(", "=", "L", "JC", "+I", "==I"
    operand: Operand | None = None
    origin: Origin | None = None
    operand2: Operand | None = None  # second operand of the test pseudo-ops: __ASSERT== M 0.0, 1
    label: str | None = None  # label defined on this instruction ("M001:")
    call: CallInfo | None = None  # for CALL only


@dataclass(slots=True)
class Variable:
    """One entry of a block interface or DB structure, with its standard S7-300/400 layout."""

    name: str
    type: str  # the declared type as text: "BOOL", "ARRAY[1..4] OF INT", "STRUCT", "UDT 5"
    section: str  # "IN", "OUT", "IN_OUT", "STAT", "TEMP", "RETURN", or "" in DBs and UDTs
    offset_bits: int  # from the start of its area (instance DB, L stack, DB)
    size_bits: int
    initial: object = None
    comment: str = ""
    members: list[Variable] = field(default_factory=list)  # STRUCT / UDT members, nested


@dataclass(slots=True)
class Network:
    title: str
    first: int  # index of its first instruction in Block.code
    comment: str = ""


@dataclass(slots=True)
class Block:
    kind: BlockKind  # OB, FB, FC, DB or UDT
    number: int
    name: str = ""  # symbolic name, if any
    title: str = ""
    file: str = ""
    attributes: dict[str, str] = field(default_factory=dict)  # AUTHOR, FAMILY, VERSION, {S7_...}
    interface: list[Variable] = field(default_factory=list)
    return_type: str | None = None  # FC only: "VOID", "INT", ...
    code: list[Instruction] = field(default_factory=list)
    networks: list[Network] = field(default_factory=list)
    labels: dict[str, int] = field(default_factory=dict)  # label -> index in code
    temp_bytes: int = 0  # size of the block's L stack frame
    # Data blocks (shared or instance) and the instance layout of FBs:
    instance_of: int | None = None  # DB: the FB number of an instance DB
    data: bytes = b""  # DB: the actual values (BEGIN section over the initial values)
    know_how_protect: bool = False


@dataclass(slots=True)
class Program:
    """Everything a download contains: code blocks and data blocks by (kind, number)."""

    blocks: dict[tuple[BlockKind, int], Block] = field(default_factory=dict)
    symbols: dict[str, str] = field(default_factory=dict)  # symbol name -> absolute address text
    symbol_types: dict[str, str] = field(default_factory=dict)  # symbol name -> declared type

    def add(self, block: Block) -> None:
        self.blocks[(block.kind, block.number)] = block

    def get(self, kind: BlockKind, number: int) -> Block | None:
        return self.blocks.get((kind, number))

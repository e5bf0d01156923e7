"""What STEP 7's CALL puts in the V area and instance DB: DB pointers, ANY pointers, copies.

Formats (STEP 7, "Format of the parameter types POINTER and ANY"): a POINTER is 6 bytes, DB
number then a 32-bit area pointer; an ANY is 10 bytes: 16#10, data type, repetition factor,
DB number, area pointer. An FC gets ARRAY/STRUCT/STRING/DT/POINTER parameters as a DB pointer
in the caller's local data (its V area) and ANY parameters as an ANY there; constants and DB
elements are copied into the V area; ``L P##param`` points at that V data.
"""

from __future__ import annotations

from builder import DBW, INT, MB, MD, MW, P, after, block, db, ins, var

from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallArg,
    CallInfo,
    Constant,
    ConstType,
    Direct,
    Instruction,
    MemoryIndirect,
    ParamRef,
    RegisterIndirect,
    Width,
)

FC7 = BlockRef(BlockKind.FC, 7)
FB7 = BlockRef(BlockKind.FB, 7)


def call_block(blk: BlockRef, instance: BlockRef | None = None, **args: object) -> Instruction:
    info = CallInfo(blk, instance, tuple(CallArg(k, v) for k, v in args.items()))  # type: ignore[arg-type]
    return Instruction("CALL", call=info)


def param_pointer(name: str) -> Constant:
    """``P##name`` as the STL compiler hands it over (its value is resolved per call)."""
    return Constant(ConstType.POINTER, 0x87000000, 0, f"P##{name}")


def ar1(width: Width, byte: int) -> RegisterIndirect:
    """``W [AR1, P#byte.0]`` (area-crossing)."""
    return RegisterIndirect(width, None, 1, byte * 8)


def dump_pointer(name: str, into: int, words: tuple[tuple[Width, int], ...]) -> list[object]:
    """L P##name, LAR1, then each (width, offset) read through AR1 into MD into, into+4 ..."""
    code: list[object] = [ins("L", param_pointer(name)), ins("T", MD(into)), ins("LAR1")]
    for k, (width, offset) in enumerate(words):
        code += [ins("L", ar1(width, offset)), ins("T", MD(into + 4 * (k + 1)))]
    return code


def test_structured_fc_parameter_is_a_db_pointer_in_the_v_area() -> None:
    fc = block(
        BlockKind.FC,
        7,
        [
            *dump_pointer("ARR", 20, ((Width.WORD, 0), (Width.DWORD, 2))),
            ins("L", ParamRef(0, "ARR", Width.WORD, bit_offset=16)),  # ARR[2] directly
            ins("T", MW(40)),
        ],
        interface=[var("ARR", "ARRAY[1..2] OF INT", "IN", 0, 32)],
    )
    cpu = after(
        call_block(FC7, ARR=Direct(Area.DB, Width.BYTE, 4, db=2)),
        extra=(fc, db(2, 8, bytes([0, 0, 0, 0, 0, 11, 0, 22]))),
    )
    assert cpu.read(MD(20)) >> 24 == 0x87  # P#V ...
    assert cpu.read(MD(24)) == 2  # the DB number
    assert cpu.read(MD(28)) == 0x84000000 | 4 * 8  # P#DBX 4.0
    assert cpu.read(MW(40)) == 22


def test_fc_pointer_of_a_marker_and_of_a_db_element() -> None:
    """An elementary actual in I/Q/M is pointed at directly; a DB element is copied into the V
    area (and back for OUT), so the pointer is a P#V one and writes through it arrive."""
    fc = block(
        BlockKind.FC,
        7,
        [
            ins("L", param_pointer("A")),
            ins("T", MD(20)),
            ins("L", param_pointer("B")),
            ins("T", MD(24)),
            ins("LAR1"),
            ins("L", INT(77)),
            ins("T", ar1(Width.WORD, 0)),  # OUT B written through its pointer
        ],
        interface=[var("A", "INT", "IN", 0, 16), var("B", "INT", "OUT", 16, 16)],
    )
    cpu = after(
        call_block(FC7, A=MW(10), B=DBW(3, 2)),
        extra=(fc, db(3, 4)),
    )
    assert cpu.read(MD(20)) == P(10, 0, Area.M).pattern
    assert cpu.read(MD(24)) >> 24 == 0x87
    assert cpu.read(DBW(3, 2)) == 77


def test_fc_pointer_and_any_parameters() -> None:
    fc = block(
        BlockKind.FC,
        7,
        [
            *dump_pointer("PTR", 20, ((Width.WORD, 0), (Width.DWORD, 2))),
            *dump_pointer("SRC", 40, ((Width.DWORD, 0), (Width.WORD, 4), (Width.DWORD, 6))),
            *dump_pointer("BIT", 60, ((Width.DWORD, 0), (Width.WORD, 4), (Width.DWORD, 6))),
        ],
        interface=[
            var("PTR", "POINTER", "IN", 0, 48),
            var("SRC", "ANY", "IN", 0, 80),
            var("BIT", "ANY", "IN", 0, 80),
        ],
    )
    area_constant = Constant(ConstType.POINTER, 0x84000000 | 10 * 8, 80, "P#DB50.DBX 10.0 WORD 3")
    cpu = after(
        call_block(FC7, PTR=Direct(Area.DB, Width.BIT, 6, 1, db=9), SRC=area_constant, BIT=MB(5)),
        extra=(fc,),  # DB 9 and DB 50 need not exist to point at them
    )
    assert (cpu.read(MD(24)), cpu.read(MD(28))) == (9, 0x84000000 | 6 * 8 + 1)
    assert cpu.read(MD(44)) == 0x10_04_0003  # S7, WORD, 3 of them
    assert (cpu.read(MD(48)), cpu.read(MD(52))) == (50, 0x84000000 | 80)
    assert cpu.read(MD(64)) == 0x10_02_0001  # MB 5: one BYTE
    assert (cpu.read(MD(68)), cpu.read(MD(72))) == (0, P(5, 0, Area.M).pattern)


def test_fb_pointer_any_and_structured_in_out_live_in_the_instance() -> None:
    fb = block(
        BlockKind.FB,
        7,
        [
            ins("L", Direct(Area.DI, Width.DWORD, 12)),  # IO's DB pointer: area pointer part
            ins("LAR1"),
            ins("L", Direct(Area.DI, Width.WORD, 10)),  # ... and its DB number
            ins("T", MW(30)),
            ins("L", INT(0x55)),
            ins("T", ar1(Width.BYTE, 1)),  # writes the actual's second byte
        ],
        interface=[
            var("PTR", "POINTER", "IN", 0, 48),
            var("SRC", "ANY", "IN", 48, 80),
            var("IO", "STRUCT", "IN_OUT", 80, 48),
        ],
    )
    cpu = after(
        call_block(FB7, BlockRef(BlockKind.DB, 1), PTR=MW(2), SRC=MD(4), IO=MB(50)),
        extra=(fb, db(1, 16, instance_of=7)),
    )
    instance = cpu.db_bytes(1) or b""
    assert instance[0:6] == bytes([0, 0]) + P(2, 0, Area.M).pattern.to_bytes(4, "big")
    assert instance[6:10] == bytes([0x10, 0x06, 0, 1])  # one DWORD
    assert instance[10:16] == bytes([0, 0]) + P(50, 0, Area.M).pattern.to_bytes(4, "big")
    assert cpu.read(MB(51)) == 0x55
    assert cpu.read(MW(30)) == 0


def test_constants_for_string_and_date_and_time_parameters() -> None:
    fc = block(
        BlockKind.FC,
        7,
        [
            *dump_pointer("TEXT", 20, ((Width.WORD, 0), (Width.DWORD, 2))),
            ins("L", ParamRef(0, "TEXT", Width.DWORD)),  # max length, length, 'ab'
            ins("T", MD(40)),
            ins("L", ParamRef(1, "WHEN", Width.DWORD)),
            ins("T", MD(44)),
        ],
        interface=[
            var("TEXT", "STRING[4]", "IN", 0, 48),
            var("WHEN", "DATE_AND_TIME", "IN", 0, 64),
        ],
    )
    text = Constant(ConstType.STRING, 0x6162, 2, "'ab'")
    when = Constant(ConstType.DATE_AND_TIME, 0x98_02_03_16_17_20_21_13, 0, "DT#98-2-3-16:17:20.211")
    cpu = after(call_block(FC7, TEXT=text, WHEN=when), extra=(fc,))
    assert cpu.read(MD(24)) == 0  # DB number 0: the copy lives in the V area
    assert cpu.read(MD(28)) >> 24 == 0x87
    assert cpu.read(MD(40)) == 0x04_02_61_62
    assert cpu.read(MD(44)) == 0x98_02_03_16


def test_block_numbers_through_memory_indirect_actuals() -> None:
    fb = block(
        BlockKind.FB,
        7,
        [ins("L", Direct(Area.DI, Width.WORD, 0)), ins("T", MW(20))],
        interface=[var("DBNR", "BLOCK_DB", "IN", 0, 16)],
    )
    indirect = MemoryIndirect(None, None, MW(14), target="DB")
    cpu = after(
        ins("L", INT(42)),
        ins("T", MW(14)),
        call_block(FB7, BlockRef(BlockKind.DB, 1), DBNR=indirect),
        extra=(fb, db(1, 2, instance_of=7)),
    )
    assert cpu.read(MW(20)) == 42


def test_computed_local_addresses_beyond_the_declared_temporaries() -> None:
    cpu = after(
        ins("L", P(8)),
        ins("T", Direct(Area.L, Width.DWORD, 0)),
        ins("L", INT(9)),
        ins("T", MemoryIndirect(Width.WORD, Area.L, Direct(Area.L, Width.DWORD, 0))),
        ins("L", Direct(Area.L, Width.WORD, 8)),
        ins("T", MW(0)),
    )
    assert cpu.read(MW(0)) == 9
    assert cpu.mode == "RUN"


def test_calls_share_one_v_area_after_the_local_data_the_block_uses() -> None:
    fc = block(
        BlockKind.FC,
        7,
        [ins("L", ParamRef(0, "A", Width.WORD)), ins("T", MW(20))],
        interface=[var("A", "INT", "IN", 0, 16)],
    )
    cpu = after(
        ins("L", INT(1234)),
        ins("T", Direct(Area.L, Width.WORD, 30)),  # undeclared local data the OB keeps
        call_block(FC7, A=INT(5)),
        call_block(FC7, A=INT(6)),
        ins("L", Direct(Area.L, Width.WORD, 30)),
        ins("T", MW(22)),
        extra=(fc,),
    )
    assert (cpu.read(MW(20)), cpu.read(MW(22))) == (6, 1234)
    compiled = cpu._engine.loader.get(BlockKind.OB, 1)
    assert compiled is not None
    assert compiled.frame_size == 34  # L 0-31 of the OB, one 2-byte constant copy for both calls

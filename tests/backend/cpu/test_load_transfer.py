"""L, T, L STW / T STW, DB registers, accumulators and the 2/4 accumulator profiles."""

from __future__ import annotations

from builder import (
    DBW,
    DBX,
    DINT,
    INT,
    LW,
    MB,
    MD,
    MW,
    QW,
    STW,
    WORD,
    M,
    P,
    after,
    block,
    db,
    ins,
    reg,
    run_ob1,
    stw_bits,
)

from nasaq.cpu import Profile
from nasaq.ir import Area, BlockKind, BlockRef, Direct, Width


def test_load_pushes_and_zero_extends() -> None:
    cpu = after(ins("L", DINT(-1)), ins("T", MD(0)), ins("L", MB(0)), ins("L", MW(0)))
    assert cpu.accu1 == 0xFFFF
    assert cpu.accu2 == 0xFF


def test_transfer_big_endian() -> None:
    cpu = after(ins("L", DINT(0x11223344)), ins("T", MD(4)), ins("T", MW(10)), ins("T", MB(12)))
    assert cpu.area_bytes("M")[4:13] == bytes([0x11, 0x22, 0x33, 0x44, 0, 0, 0x33, 0x44, 0x44])


def test_transfer_status_word_writes_all_nine_bits() -> None:
    """STL manual, T STW: bits 0 to 8 of ACCU 1 go to the status word (writes x in every
    column of the status word table), on the S7-300 as on the S7-400."""
    for profile in Profile:
        cpu = after(ins("L", WORD(0x1FF)), ins("T", STW), profile=profile)
        assert cpu.stw == 0x1FF
        cpu = after(ins("SET"), ins("SAVE"), ins("L", WORD(0x009)), ins("T", STW), profile=profile)
        assert stw_bits(cpu.stw) == {**dict.fromkeys(stw_bits(0), 0), "FC": 1, "OR": 1}


def test_transfer_status_word_sets_up_the_next_logic_operation() -> None:
    # /FC = 1, RLO = 0, OR = 1 written by T STW: the next A combines with them
    cpu = after(ins("L", WORD(0b1001)), ins("T", STW), ins("A", M(0, 0)))
    assert stw_bits(cpu.stw)["RLO"] == 1  # (RLO AND M0.0) OR OR-bit


def test_load_status_word_on_the_s7_300_leaves_out_fc_sta_or() -> None:
    """STL manual, L STW: an S7-300 loads only bits 1, 4, 5, 6, 7 and 8."""
    code = (ins("L", WORD(0x1FF)), ins("T", STW), ins("L", STW))
    assert after(*code).accu1 == 0x1F2
    assert after(*code, profile=Profile.S7_400).accu1 == 0x1FF


def test_data_blocks_and_registers() -> None:
    data = db(5, 10, bytes([0, 0, 0x12, 0x34]))
    cpu = after(
        ins("L", DBW(5, 2)),
        ins("T", MW(0)),
        ins("L", INT(7)),
        ins("T", DBW(None, 4)),
        ins("L", reg("DBNO")),
        ins("T", MW(2)),
        ins("L", reg("DBLG")),
        ins("T", MW(4)),
        ins("SET"),
        ins("=", DBX(None, 6, 1)),
        extra=(data,),
    )
    assert cpu.read(MW(0)) == 0x1234
    assert cpu.read(DBW(5, 4)) == 7
    assert cpu.read(MW(2)) == 5
    assert cpu.read(MW(4)) == 10
    assert cpu.read(DBX(5, 6, 1)) == 1


def test_open_and_exchange_db_registers() -> None:
    cpu = after(
        ins("OPN", BlockRef(BlockKind.DB, 5)),
        ins("OPN", BlockRef(BlockKind.DI, 6)),
        ins("CDB"),
        ins("L", reg("DBNO")),
        ins("L", reg("DINO")),
        extra=(db(5, 4), db(6, 8)),
    )
    assert (cpu.accu2, cpu.accu1) == (6, 5)


def test_db_not_loaded_stops_with_location() -> None:
    cpu = run_ob1(ins("L", INT(1)), ins("OPN", BlockRef(BlockKind.DB, 9)))
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM505"
    assert cpu.stop_reason == "OB1 network 1, line 2: DB 9 is not loaded (SIM505)"


def test_area_length_errors() -> None:
    cpu = run_ob1(ins("L", MW(2047)))
    assert cpu.stop_code == "SIM503"
    assert cpu.stop_reason == "OB1 network 1, line 1: area length error reading MW 2047 (SIM503)"
    cpu = run_ob1(ins("L", INT(1)), ins("T", DBW(3, 8)), extra=(db(3, 8),))
    assert cpu.stop_code == "SIM504"
    assert "DB3.DBW 8" in (cpu.stop_reason or "")
    assert cpu.read(DBW(3, 6)) == 0  # nothing was written


def test_local_data_and_peripherals() -> None:
    cpu = after(ins("L", INT(9)), ins("T", LW(2)), ins("L", LW(2)), ins("T", QW(0)))
    assert cpu.accu1 == 9
    assert cpu.read(QW(0)) == 9
    cpu = after(ins("L", INT(0x1234)), ins("T", Direct(Area.PQ, Width.WORD, 256)))
    assert cpu.read(Direct(Area.PQ, Width.WORD, 256)) == 0x1234
    assert cpu.read(QW(256)) == 0x1234  # S7-300: T PQW also updates the PIQ
    cpu = after(
        ins("L", INT(0x1234)),
        ins("T", Direct(Area.PQ, Width.WORD, 256)),
        profile=Profile.S7_400,
    )
    assert cpu.read(QW(256)) == 0


def test_peripheral_access_error_is_an_io_error() -> None:
    cpu = run_ob1(ins("L", Direct(Area.PI, Width.WORD, 4000)))
    assert cpu.stop_code == "SIM518"


def test_two_and_four_accumulators() -> None:
    cpu = after(ins("L", INT(1)), ins("L", INT(2)), ins("L", INT(3)))
    assert (cpu.accu1, cpu.accu2) == (3, 2)
    cpu = after(ins("L", INT(1)), ins("PUSH"), ins("L", INT(3)), ins("TAK"))
    assert (cpu.accu1, cpu.accu2) == (1, 3)
    cpu = after(ins("L", INT(1)), ins("L", INT(2)), ins("POP"))
    assert cpu.accu1 == 1
    s4 = Profile.S7_400
    cpu = after(
        ins("L", INT(1)), ins("PUSH"), ins("PUSH"), ins("PUSH"), ins("L", INT(5)), profile=s4
    )
    assert (cpu.accu1, cpu.accu2, cpu.accu3, cpu.accu4) == (5, 1, 1, 1)
    cpu = after(
        ins("L", INT(4)),
        ins("PUSH"),
        ins("L", INT(3)),
        ins("PUSH"),
        ins("L", INT(2)),
        ins("PUSH"),
        ins("L", INT(1)),
        ins("POP"),
        profile=s4,
    )
    assert (cpu.accu1, cpu.accu2, cpu.accu3) == (2, 3, 4)
    cpu = after(ins("L", INT(1)), ins("L", INT(2)), ins("ENT"), ins("LEAVE"), profile=s4)
    assert (cpu.accu1, cpu.accu2) == (2, 1)
    cpu = run_ob1(ins("ENT"))
    assert cpu.stop_code == "SIM523"


def test_caw_cad() -> None:
    assert after(ins("L", DINT(0x11223344)), ins("CAW")).accu1 == 0x11224433
    assert after(ins("L", DINT(0x11223344)), ins("CAD")).accu1 == 0x44332211


def test_load_pointer_constant() -> None:
    cpu = after(ins("L", P(10, 3)), ins("L", P(2, 0, Area.M)))
    assert cpu.accu2 == 0x53
    assert cpu.accu1 == 0x83000010


def test_block_with_instruction_block_helper() -> None:
    b = block(BlockKind.OB, 1, [ins("L", INT(3))])
    assert b.code[0].origin is not None
    assert b.code[0].origin.line == 1

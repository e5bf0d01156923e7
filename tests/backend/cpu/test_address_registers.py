"""Address registers and memory-/register-indirect addressing, area-internal and -crossing."""

from __future__ import annotations

from builder import DINT, INT, MD, MW, M, P, after, db, ins, run_ob1

from nasaq.ir import Area, MemoryIndirect, Register, RegisterIndirect, Width


def test_lar_tar_car_and_add() -> None:
    cpu = after(ins("LAR1", P(4, 0)), ins("+AR1", P(2, 1)), ins("TAR1"))
    assert cpu.accu1 == (6 << 3) | 1
    cpu = after(ins("L", DINT(0x84000010)), ins("LAR2"), ins("LAR1", Register("AR2")), ins("TAR1"))
    assert cpu.accu1 == 0x84000010
    cpu = after(
        ins("LAR1", P(1, 0)), ins("LAR2", P(2, 0)), ins("CAR"), ins("TAR1"), ins("TAR2", MD(0))
    )
    assert cpu.accu1 == 16
    assert cpu.read(MD(0)) == 8
    cpu = after(ins("LAR1", P(10, 0, Area.M)), ins("L", INT(-8)), ins("+AR1"), ins("TAR1"))
    assert cpu.accu1 == 0x83000000 | (9 << 3)


def test_register_indirect_area_internal() -> None:
    cpu = after(
        ins("LAR1", P(20, 0)),
        ins("L", INT(0x4242)),
        ins("T", RegisterIndirect(Width.WORD, Area.M, 1, 16)),
        ins("L", MW(22)),
        ins("SET"),
        ins("=", RegisterIndirect(Width.BIT, Area.M, 1, 3)),
    )
    assert cpu.accu1 == 0x4242
    assert cpu.read(M(20, 3)) == 1


def test_register_indirect_area_crossing() -> None:
    cpu = after(
        ins("LAR1", P(30, 0, Area.M)),
        ins("L", INT(77)),
        ins("T", RegisterIndirect(Width.WORD, None, 1, 16)),
        ins("L", DINT(0x84000000)),
        ins("LAR2"),
        ins(
            "OPN",
            __import__("nasaq.ir", fromlist=["BlockRef"]).BlockRef(
                __import__("nasaq.ir", fromlist=["BlockKind"]).BlockKind.DB, 2
            ),
        ),
        ins("L", INT(5)),
        ins("T", RegisterIndirect(Width.BYTE, None, 2, 8 * 3)),
        extra=(db(2, 8),),
    )
    assert cpu.read(MW(32)) == 77
    assert cpu.db_bytes(2) == bytes([0, 0, 0, 5, 0, 0, 0, 0])


def test_memory_indirect() -> None:
    cpu = after(
        ins("L", P(40, 0)),
        ins("T", MD(4)),
        ins("L", INT(1234)),
        ins("T", MemoryIndirect(Width.WORD, Area.M, MD(4))),
        ins("L", P(40, 2)),
        ins("T", MD(4)),
        ins("A", MemoryIndirect(Width.BIT, Area.M, MD(4))),
        ins("=", M(50, 0)),
    )
    assert cpu.read(MW(40)) == 1234
    assert cpu.read(M(50, 0)) == (1234 >> 8 >> 2) & 1


def test_memory_indirect_alignment_error() -> None:
    cpu = run_ob1(
        ins("L", P(40, 1)), ins("T", MD(4)), ins("L", MemoryIndirect(Width.WORD, Area.M, MD(4)))
    )
    assert cpu.stop_code == "SIM520"


def test_indirect_area_length_error_names_the_address() -> None:
    cpu = run_ob1(ins("LAR1", P(3000, 0)), ins("L", RegisterIndirect(Width.WORD, Area.M, 1, 0)))
    assert cpu.stop_code == "SIM503"
    assert "MW 3000" in (cpu.stop_reason or "")

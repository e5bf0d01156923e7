"""Shifts and rotates, with the count from the operand or from ACCU2-LL."""

from __future__ import annotations

from builder import DINT, INT, after, ins, stw_bits


def test_word_shifts() -> None:
    cpu = after(ins("L", DINT(0x1234F001)), ins("SLW", INT(4)))
    assert cpu.accu1 == 0x12340010
    assert stw_bits(cpu.stw)["CC1"] == 1
    cpu = after(ins("L", DINT(0x1234000F)), ins("SRW", INT(2)))
    assert cpu.accu1 == 0x12340003
    assert stw_bits(cpu.stw)["CC1"] == 1
    cpu = after(ins("L", DINT(0x8000)), ins("SSI", INT(3)))
    assert cpu.accu1 == 0xF000
    cpu = after(ins("L", DINT(0xFFFF)), ins("SLW", INT(17)))
    assert cpu.accu1 == 0
    assert stw_bits(cpu.stw)["CC1"] == 0


def test_double_shifts_and_rotates() -> None:
    assert after(ins("L", DINT(0x80000001)), ins("SLD", INT(1))).accu1 == 2
    assert after(ins("L", DINT(0x80000001)), ins("SRD", INT(1))).accu1 == 0x40000000
    assert after(ins("L", DINT(-8)), ins("SSD", INT(2))).accu1 == 0xFFFFFFFE
    cpu = after(ins("L", DINT(0x80000001)), ins("RLD", INT(4)))
    assert cpu.accu1 == 0x00000018
    assert stw_bits(cpu.stw)["CC1"] == 0
    cpu = after(ins("L", DINT(0x80000001)), ins("RRD", INT(1)))
    assert cpu.accu1 == 0xC0000000
    assert stw_bits(cpu.stw)["CC1"] == 1


def test_shift_count_from_accu2() -> None:
    cpu = after(ins("L", INT(3)), ins("L", DINT(1)), ins("SLD"))
    assert cpu.accu1 == 8
    cpu = after(ins("L", INT(0)), ins("L", DINT(0xF)), ins("SLD"))
    assert cpu.accu1 == 0xF  # count 0: nothing happens


def test_rotate_through_cc1() -> None:
    cpu = after(ins("L", DINT(0x80000000)), ins("RLDA"))
    assert cpu.accu1 == 0
    assert stw_bits(cpu.stw)["CC1"] == 1
    cpu = after(ins("L", DINT(0x80000000)), ins("RLDA"), ins("RRDA"))
    assert cpu.accu1 == 0x80000000

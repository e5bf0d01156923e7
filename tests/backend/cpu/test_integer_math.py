"""INT and DINT arithmetic: results and CC1 CC0 OV OS as in the S7 manual tables."""

from __future__ import annotations

import pytest
from builder import DINT, INT, MD, MW, after, ins, status

from nasaq.cpu import Profile


def int_op(op: str, x: int, y: int) -> tuple[int, dict[str, int]]:
    cpu = after(ins("L", INT(x)), ins("L", INT(y)), ins(op))
    from builder import stw_bits

    return cpu.accu1, stw_bits(cpu.stw)


def signed16(value: int) -> int:
    return ((value & 0xFFFF) ^ 0x8000) - 0x8000


@pytest.mark.parametrize(
    ("x", "y", "result", "cc1", "cc0", "ov"),
    [
        (3, 4, 7, 1, 0, 0),
        (3, -4, -1, 0, 1, 0),
        (5, -5, 0, 0, 0, 0),
        (32767, 1, -32768, 0, 1, 1),  # 32767 < sum: CC1 0 CC0 1 OV 1
        (-32768, -1, 32767, 1, 0, 1),  # sum < -32768: CC1 1 CC0 0
        (-32768, -32768, 0, 0, 0, 1),  # sum = -65536
    ],
)
def test_add_int(x: int, y: int, result: int, cc1: int, cc0: int, ov: int) -> None:
    accu1, s = int_op("+I", x, y)
    assert signed16(accu1) == result
    assert (s["CC1"], s["CC0"], s["OV"], s["OS"]) == (cc1, cc0, ov, ov)


def test_add_int_keeps_accu1_high_word() -> None:
    cpu = after(ins("L", DINT(0x00010003)), ins("L", DINT(0xABCD0004)), ins("+I"))
    assert cpu.accu1 == 0xABCD0007


def test_subtract_is_accu2_minus_accu1() -> None:
    accu1, s = int_op("-I", 10, 3)
    assert accu1 & 0xFFFF == 7
    assert (s["CC1"], s["CC0"]) == (1, 0)
    accu1, s = int_op("-I", -32768, 1)
    assert signed16(accu1) == 32767
    assert s["OV"] == 1
    assert s["CC1"] == 1


def test_multiply_int_gives_32_bit_product() -> None:
    accu1, s = int_op("*I", 300, 300)
    assert accu1 == 90000
    assert (s["CC1"], s["CC0"], s["OV"], s["OS"]) == (1, 0, 1, 1)
    accu1, s = int_op("*I", -300, 300)
    assert accu1 == (-90000) & 0xFFFFFFFF
    assert (s["CC1"], s["CC0"], s["OV"]) == (0, 1, 1)
    accu1, s = int_op("*I", -3, 4)
    assert accu1 == (-12) & 0xFFFFFFFF
    assert (s["CC1"], s["CC0"], s["OV"]) == (0, 1, 0)


def test_divide_int_quotient_and_remainder() -> None:
    accu1, s = int_op("/I", -7, 2)
    assert signed16(accu1) == -3
    assert signed16(accu1 >> 16) == -1
    assert (s["CC1"], s["CC0"], s["OV"]) == (0, 1, 0)
    accu1, s = int_op("/I", 7, -2)
    assert signed16(accu1) == -3
    assert signed16(accu1 >> 16) == 1
    accu1, s = int_op("/I", -32768, -1)
    assert s["OV"] == 1
    assert s["OS"] == 1


def test_division_by_zero_sets_bits_and_does_not_stop() -> None:
    cpu = after(ins("L", INT(5)), ins("L", INT(0)), ins("/I"), ins("T", MW(0)))
    from builder import stw_bits

    s = stw_bits(cpu.stw)
    assert cpu.mode == "RUN"
    assert (s["CC1"], s["CC0"], s["OV"], s["OS"]) == (1, 1, 1, 1)
    assert cpu.accu1 == 0  # ACCU1 unchanged (it held the divisor)
    cpu = after(ins("L", DINT(5)), ins("L", DINT(0)), ins("MOD"))
    assert stw_bits(cpu.stw)["OV"] == 1


def test_os_is_sticky_and_ov_is_not() -> None:
    s = status(
        ins("L", INT(32767)),
        ins("L", INT(1)),
        ins("+I"),
        ins("L", INT(1)),
        ins("L", INT(1)),
        ins("+I"),
    )
    assert (s["OV"], s["OS"]) == (0, 1)


def test_dint_arithmetic() -> None:
    cpu = after(ins("L", DINT(100000)), ins("L", DINT(-300000)), ins("+D"), ins("T", MD(0)))
    assert cpu.read(MD(0)) == (-200000) & 0xFFFFFFFF
    cpu = after(ins("L", DINT(0x7FFFFFFF)), ins("L", DINT(1)), ins("+D"))
    from builder import stw_bits

    s = stw_bits(cpu.stw)
    assert cpu.accu1 == 0x80000000
    assert (s["CC1"], s["CC0"], s["OV"]) == (0, 1, 1)
    cpu = after(ins("L", DINT(-100000)), ins("L", DINT(7)), ins("/D"))
    assert cpu.accu1 == (-14285) & 0xFFFFFFFF
    cpu = after(ins("L", DINT(-100000)), ins("L", DINT(7)), ins("MOD"))
    assert cpu.accu1 == (-5) & 0xFFFFFFFF
    cpu = after(ins("L", DINT(70000)), ins("L", DINT(70000)), ins("*D"))
    assert stw_bits(cpu.stw)["OV"] == 1
    cpu = after(ins("L", DINT(-7)), ins("L", DINT(3)), ins("-D"))
    assert cpu.accu1 == (-10) & 0xFFFFFFFF


def test_four_accumulators_pop_after_arithmetic() -> None:
    cpu = after(
        ins("L", INT(1)),
        ins("L", INT(2)),
        ins("ENT"),
        ins("L", INT(3)),
        ins("L", INT(4)),
        ins("+I"),
        profile=Profile.S7_400,
    )
    # ENT copied ACCU2 (1) into ACCU3; before +I: ACCU1 4, ACCU2 3, ACCU3 1, ACCU4 0
    assert (cpu.accu1, cpu.accu2, cpu.accu3, cpu.accu4) == (7, 1, 0, 0)


def test_add_constant_and_inc_dec() -> None:
    cpu = after(ins("L", DINT(0x0001FFFF)), ins("+", INT(1)))
    assert cpu.accu1 == 0x00010000  # 16-bit addition, high word kept
    cpu = after(ins("L", DINT(0x0001FFFF)), ins("+", DINT(1)))
    assert cpu.accu1 == 0x00020000
    cpu = after(ins("L", DINT(0x12FF)), ins("INC", INT(1)))
    assert cpu.accu1 == 0x1200
    cpu = after(ins("L", DINT(0x1200)), ins("DEC", INT(1)))
    assert cpu.accu1 == 0x12FF
    s = status(ins("CLR"), ins("L", INT(32767)), ins("+", INT(1)))
    assert s["OV"] == 0
    assert s["CC1"] == 0

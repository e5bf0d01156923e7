"""BCD and number conversions, complements, negation and rounding."""

from __future__ import annotations

import pytest
from builder import DINT, INT, REAL, WORD, after, ins, run_ob1, stw_bits


def test_bcd_to_int_and_back() -> None:
    assert after(ins("L", WORD(0x0123)), ins("BTI")).accu1 == 123
    assert after(ins("L", WORD(0x8123)), ins("BTI")).accu1 & 0xFFFF == (-123) & 0xFFFF
    assert after(ins("L", INT(-123)), ins("ITB")).accu1 & 0xFFFF == 0xF123
    assert after(ins("L", INT(999)), ins("ITB")).accu1 & 0xFFFF == 0x0999
    assert after(ins("L", DWORD_(0x01234567)), ins("BTD")).accu1 == 1234567
    assert after(ins("L", DINT(-1234567)), ins("DTB")).accu1 == 0xF1234567


def DWORD_(value: int) -> object:  # noqa: N802
    from builder import DWORD

    return DWORD(value)


def test_itb_overflow_keeps_accu1() -> None:
    cpu = after(ins("L", INT(1000)), ins("ITB"))
    s = stw_bits(cpu.stw)
    assert cpu.accu1 == 1000
    assert (s["OV"], s["OS"]) == (1, 1)
    cpu = after(ins("L", DINT(10000000)), ins("DTB"))
    assert stw_bits(cpu.stw)["OV"] == 1


def test_invalid_bcd_is_a_programming_error() -> None:
    cpu = run_ob1(ins("L", WORD(0x00A1)), ins("BTI"))
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM512"


def test_int_to_dint_and_complements() -> None:
    assert after(ins("L", INT(-2)), ins("ITD")).accu1 == 0xFFFFFFFE
    assert after(ins("L", DINT(0x12340F0F)), ins("INVI")).accu1 == 0x1234F0F0
    assert after(ins("L", DINT(0x12340F0F)), ins("INVD")).accu1 == 0xEDCBF0F0


def test_negation_status() -> None:
    cpu = after(ins("L", INT(5)), ins("NEGI"))
    s = stw_bits(cpu.stw)
    assert cpu.accu1 & 0xFFFF == (-5) & 0xFFFF
    assert (s["CC1"], s["CC0"], s["OV"]) == (0, 1, 0)
    cpu = after(ins("L", INT(-32768)), ins("NEGI"))
    s = stw_bits(cpu.stw)
    assert cpu.accu1 & 0xFFFF == 0x8000
    assert (s["CC1"], s["CC0"], s["OV"], s["OS"]) == (0, 1, 1, 1)
    cpu = after(ins("L", DINT(0)), ins("NEGD"))
    assert (stw_bits(cpu.stw)["CC1"], stw_bits(cpu.stw)["CC0"]) == (0, 0)


@pytest.mark.parametrize(
    ("value", "rnd", "up", "down", "trunc"),
    [
        (2.5, 2, 3, 2, 2),
        (3.5, 4, 4, 3, 3),
        (-2.5, -2, -2, -3, -2),
        (-1.2, -1, -1, -2, -1),
        (7.0, 7, 7, 7, 7),
    ],
)
def test_rounding(value: float, rnd: int, up: int, down: int, trunc: int) -> None:
    for op, expected in (("RND", rnd), ("RND+", up), ("RND-", down), ("TRUNC", trunc)):
        cpu = after(ins("L", REAL(value)), ins(op))
        assert cpu.accu1 == expected & 0xFFFFFFFF, op


def test_rounding_out_of_range() -> None:
    cpu = after(ins("L", REAL(3e9)), ins("RND"))
    s = stw_bits(cpu.stw)
    assert (s["OV"], s["OS"]) == (1, 1)

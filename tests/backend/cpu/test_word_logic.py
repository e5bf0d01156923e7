"""AW OW XOW AD OD XOD."""

from __future__ import annotations

from builder import DINT, DWORD, WORD, after, ins, stw_bits


def test_word_logic_with_accu2_and_constant() -> None:
    cpu = after(ins("L", DINT(0xAAAA0F0F)), ins("L", DINT(0x5555F0FF)), ins("AW"))
    assert cpu.accu1 == 0x55550000 | (0x0F0F & 0xF0FF)
    assert after(ins("L", DINT(0x12340F0F)), ins("OW", WORD(0xF000))).accu1 == 0x1234FF0F
    assert after(ins("L", DINT(0x12340F0F)), ins("XOW", WORD(0x0F0F))).accu1 == 0x12340000
    assert after(ins("L", DINT(0xF0F0F0F0)), ins("AD", DWORD(0xFF00FF00))).accu1 == 0xF000F000
    assert after(ins("L", DINT(0xF0F0F0F0)), ins("OD", DWORD(0x0F000000))).accu1 == 0xFFF0F0F0
    cpu = after(ins("L", DINT(0xF0F0F0F0)), ins("L", DINT(0xF0F0F0F0)), ins("XOD"))
    assert cpu.accu1 == 0


def test_word_logic_status() -> None:
    s = stw_bits(after(ins("L", DINT(0x10000)), ins("AW", WORD(0xFFFF))).stw)
    assert (s["CC1"], s["CC0"], s["OV"]) == (0, 0, 0)
    s = stw_bits(after(ins("L", DINT(1)), ins("OD", DWORD(0))).stw)
    assert (s["CC1"], s["CC0"], s["OV"]) == (1, 0, 0)

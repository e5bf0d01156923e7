"""Comparisons: RLO, CC1/CC0 (ACCU2 relative to ACCU1), OV, /FC, OR, STA."""

from __future__ import annotations

import pytest
from builder import DINT, INT, REAL, after, ins, stw_bits


def compare(op: str, x: object, y: object) -> dict[str, int]:
    return stw_bits(after(ins("L", x), ins("L", y), ins(op)).stw)


@pytest.mark.parametrize(
    ("x", "y", "eq", "ne", "gt", "lt", "ge", "le", "cc1", "cc0"),
    [
        (3, 3, 1, 0, 0, 0, 1, 1, 0, 0),
        (5, 3, 0, 1, 1, 0, 1, 0, 1, 0),
        (-5, 3, 0, 1, 0, 1, 0, 1, 0, 1),
        (-1, -32768, 0, 1, 1, 0, 1, 0, 1, 0),
    ],
)
def test_integer_compare(
    x: int, y: int, eq: int, ne: int, gt: int, lt: int, ge: int, le: int, cc1: int, cc0: int
) -> None:
    for kind, make in (("I", INT), ("D", DINT)):
        expected = {"==": eq, "<>": ne, ">": gt, "<": lt, ">=": ge, "<=": le}
        for rel, rlo in expected.items():
            s = compare(rel + kind, make(x), make(y))
            assert (s["RLO"], s["STA"]) == (rlo, rlo), (rel, kind)
            assert (s["CC1"], s["CC0"], s["OV"], s["OR"], s["FC"]) == (cc1, cc0, 0, 0, 1)


def test_int_compare_ignores_high_word() -> None:
    s = compare("==I", DINT(0x00010005), DINT(0x00020005))
    assert s["RLO"] == 1


def test_real_compare_and_nan() -> None:
    s = compare(">R", REAL(2.5), REAL(-1.0))
    assert (s["RLO"], s["CC1"], s["CC0"]) == (1, 1, 0)
    s = compare("==R", REAL(float("nan")), REAL(1.0))
    assert (s["RLO"], s["CC1"], s["CC0"], s["OV"], s["OS"]) == (0, 1, 1, 1, 1)


def test_compare_starts_a_new_chain() -> None:
    s = stw_bits(after(ins("CLR"), ins("L", INT(1)), ins("L", INT(1)), ins("==I")).stw)
    assert s["RLO"] == 1

"""REAL arithmetic and functions: IEEE single results and the status bits table."""

from __future__ import annotations

import math

import pytest
from builder import DINT, REAL, after, ins, real_of, stw_bits


def real_op(op: str, x: float, y: float | None = None) -> tuple[float, dict[str, int]]:
    code = [ins("L", REAL(x))]
    if y is not None:
        code.append(ins("L", REAL(y)))
    cpu = after(*code, ins(op))
    return real_of(cpu.accu1), stw_bits(cpu.stw)


def flags(s: dict[str, int]) -> tuple[int, int, int, int]:
    return s["CC1"], s["CC0"], s["OV"], s["OS"]


def test_basic_arithmetic() -> None:
    assert real_op("+R", 1.5, 2.25)[0] == 3.75
    assert real_op("-R", 1.5, 2.25)[0] == -0.75
    assert real_op("*R", 1.5, -2.0)[0] == -3.0
    assert real_op("/R", 1.0, 4.0)[0] == 0.25
    assert flags(real_op("+R", 1.5, 2.25)[1]) == (1, 0, 0, 0)
    assert flags(real_op("-R", 1.5, 2.25)[1]) == (0, 1, 0, 0)
    assert flags(real_op("-R", 2.0, 2.0)[1]) == (0, 0, 0, 0)


def test_single_precision_rounding() -> None:
    value, _ = real_op("+R", 0.1, 0.2)
    assert value == pytest.approx(0.3, rel=1e-7)
    assert value != 0.1 + 0.2


def test_overflow_underflow_and_invalid() -> None:
    assert flags(real_op("*R", 3e38, 10.0)[1]) == (1, 0, 1, 1)  # +inf
    assert flags(real_op("*R", -3e38, 10.0)[1]) == (0, 1, 1, 1)  # -inf
    assert flags(real_op("*R", 1e-30, 1e-10)[1]) == (0, 0, 1, 1)  # denormal
    value, s = real_op("/R", 0.0, 0.0)
    assert math.isnan(value)
    assert flags(s) == (1, 1, 1, 1)
    value, s = real_op("/R", 1.0, 0.0)
    assert value == math.inf
    assert flags(s) == (1, 0, 1, 1)


@pytest.mark.parametrize(
    ("op", "x", "expected"),
    [
        ("ABS", -2.5, 2.5),
        ("SQR", 3.0, 9.0),
        ("SQRT", 16.0, 4.0),
        ("EXP", 0.0, 1.0),
        ("LN", 1.0, 0.0),
        ("SIN", 0.0, 0.0),
        ("COS", 0.0, 1.0),
        ("TAN", 0.0, 0.0),
        ("ASIN", 1.0, math.pi / 2),
        ("ACOS", 1.0, 0.0),
        ("ATAN", 1.0, math.pi / 4),
    ],
)
def test_functions(op: str, x: float, expected: float) -> None:
    assert real_op(op, x)[0] == pytest.approx(expected, rel=1e-6)


@pytest.mark.parametrize(("op", "x"), [("SQRT", -1.0), ("LN", -1.0), ("ASIN", 2.0), ("ACOS", -2.0)])
def test_invalid_functions_give_nan_and_uo(op: str, x: float) -> None:
    value, s = real_op(op, x)
    assert math.isnan(value)
    assert flags(s) == (1, 1, 1, 1)


def test_dint_to_real() -> None:
    cpu = after(ins("L", DINT(-7)), ins("DTR"))
    assert real_of(cpu.accu1) == -7.0
    cpu = after(ins("L", DINT(16777217)), ins("DTR"))
    assert real_of(cpu.accu1) == 16777216.0


def test_negr_and_abs_touch_only_the_sign() -> None:
    cpu = after(ins("L", REAL(2.0)), ins("NEGR"))
    assert real_of(cpu.accu1) == -2.0


def test_nan_results_are_all_ones() -> None:
    for code in (
        [ins("L", REAL(0.0)), ins("L", REAL(0.0)), ins("/R")],
        [ins("L", REAL(-1.0)), ins("SQRT")],
        [ins("L", REAL(math.inf)), ins("L", REAL(math.inf)), ins("-R")],
    ):
        assert after(*code).accu1 == 0xFFFFFFFF


def test_a_result_that_underflows_to_zero_reports_underflow() -> None:
    value, s = real_op("*R", 1e-30, 1e-30)
    assert value == 0.0
    assert flags(s) == (0, 0, 1, 1)
    assert flags(real_op("-R", 1e-30, 1e-30)[1]) == (0, 0, 0, 0)  # an exact zero is no underflow

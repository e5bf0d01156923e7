"""The Python bodies of the S7-1200/1500 types' hidden library FCs (``nasaq.cpu.long_library``):
results, wrap-around, rounding and the BR (ENO) they leave, on references into a buffer as the
CPU passes them."""

from __future__ import annotations

import math
import struct

import pytest

from nasaq.cpu.iec_library import BODIES, REACHING
from nasaq.lang.iec_library import FUNCTIONS
from nasaq.lang.long_library import BASE
from nasaq.lang.s7_1500_values import decode, encode

_SIZE = {
    "SINT": 1,
    "USINT": 1,
    "INT": 2,
    "UINT": 2,
    "DINT": 4,
    "UDINT": 4,
    "REAL": 4,
    "TIME": 4,
}


def _pack(kind: str, value: float) -> bytes:
    if kind == "REAL":
        return struct.pack(">f", value)
    size = _SIZE.get(kind)
    if size is None:
        return encode(kind, value)
    return (int(value) & ((1 << 8 * size) - 1)).to_bytes(size, "big")


def _call(name: str, *values: float) -> tuple[int | float | bool, int]:
    """Runs the FC ``name`` on ``values``; (RET_VAL, BR)."""
    function = FUNCTIONS[name]
    buffer = bytearray(64)
    refs = []
    at = 0
    for (_formal, data_type), value in zip(function.inputs, values, strict=True):
        data = _pack(data_type.name, value)
        buffer[at : at + len(data)] = data
        refs.append((buffer, at, 0))
        at += 8
    refs.append((buffer, at, 0))
    br = BODIES[name](refs)
    kind = function.result.name
    if kind == "BOOL":
        return bool(buffer[at] & 1), br
    if kind in ("LINT", "ULINT", "LREAL", "LWORD", "LTIME"):
        return decode(kind, bytes(buffer[at : at + 8])), br
    size = _SIZE.get(kind, {"BYTE": 1, "WORD": 2, "DWORD": 4}.get(kind, 4))
    raw = bytes(buffer[at : at + size])
    if kind == "REAL":
        return struct.unpack(">f", raw)[0], br
    signed = kind in ("SINT", "INT", "DINT", "TIME")
    return int.from_bytes(raw, "big", signed=signed), br


def test_every_function_has_a_body_and_a_number_from_the_base() -> None:
    ours = [f for f in FUNCTIONS.values() if f.number >= BASE]
    assert len(ours) > 200
    assert all(f.name in BODIES or f.name in REACHING for f in ours)  # (Strg_TO_Chars ...)
    assert len({f.number for f in FUNCTIONS.values()}) == len(FUNCTIONS)


@pytest.mark.parametrize(
    ("name", "values", "expected"),
    [
        ("ADD_LINT", (2**63 - 1, 1), (-(2**63), 1)),
        ("MUL_ULINT", (2**63, 2), (0, 1)),
        ("DIV_LINT", (-7, 2), (-3, 1)),
        ("MOD_LINT", (-7, 2), (-1, 1)),
        ("DIV_LINT", (5, 0), (0, 0)),
        ("DIV_UDINT", (4_000_000_000, 7), (571_428_571, 1)),
        ("MOD_UDINT", (4_000_000_000, 7), (3, 1)),
        ("NEG_LINT", (-(2**63),), (-(2**63), 1)),
        ("MUL_LTIME", (1_500_000, 3), (4_500_000, 1)),
        ("NOT_LWORD", (0,), (2**64 - 1, 1)),
        ("GT_ULINT", (2**64 - 1, 1), (True, 1)),
        ("LT_LINT", (-1, 1), (True, 1)),
    ],
)
def test_integer_operations_wrap_and_divide_toward_zero(
    name: str, values: tuple[int, ...], expected: tuple[int | bool, int]
) -> None:
    assert _call(name, *values) == expected


def test_lreal_is_a_double_and_dividing_by_zero_clears_eno() -> None:
    assert _call("ADD_LREAL", 0.1, 0.2) == (0.1 + 0.2, 1)
    assert _call("DIV_LREAL", 1.0, 0.0) == (math.inf, 0)
    value, br = _call("DIV_LREAL", 0.0, 0.0)
    assert math.isnan(value)
    assert br == 0
    assert _call("EQ_LREAL", math.nan, math.nan) == (False, 1)


@pytest.mark.parametrize(
    ("name", "value", "expected"),
    [
        ("LREAL_TO_DINT", 2.5, (2, 1)),  # a half to the even neighbour
        ("LREAL_TO_DINT", 3.5, (4, 1)),
        ("LREAL_TO_DINT", -2.5, (-2, 1)),
        ("LREAL_TO_DINT", 3e10, (round(3e10) % 2**32 - 2**32, 0)),
        ("LREAL_TO_DINT", math.inf, (0, 0)),
        ("LREAL_TO_REAL", 1e300, (math.inf, 0)),
        ("LREAL_TO_REAL", 2.5, (2.5, 1)),
        ("UINT_TO_INT", 65535, (-1, 0)),  # the bits, ENO FALSE: the value does not fit
        ("INT_TO_UINT", 5, (5, 1)),
        ("DINT_TO_UDINT", -1, (4_294_967_295, 0)),
        ("SINT_TO_USINT", -1, (255, 0)),
        ("UDINT_TO_REAL", 4_000_000_000, (4e9, 1)),
        ("LINT_TO_LWORD", -1, (2**64 - 1, 1)),
        ("LWORD_TO_LREAL", 0x3FF0000000000000, (1.0, 1)),
        ("LTIME_TO_TIME", 1_500_999_999, (1500, 1)),
        (
            "LTIME_TO_TIME",
            3_000_000_000_000_000,
            (3_000_000_000 - 2**32, 0),
        ),  # beyond TIME
        ("TIME_TO_LTIME", -3, (-3_000_000, 1)),
    ],
)
def test_conversions(name: str, value: float, expected: tuple[int | float, int]) -> None:
    assert _call(name, value) == expected

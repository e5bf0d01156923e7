"""The catalogue of LAD/FBD boxes: their pins (direction, S7 type), whether they have EN/ENO,
and what they lower to.

A box sits in series in a rung: the power flow into it feeds its *flow pin* (``EN``, or the
first Boolean input of a timer, counter or flip-flop) and the flow out of it is its *flow out*
(``ENO`` or ``Q``). Timers, counters, flip-flops and the POS/NEG edge boxes also have an operand
written above the box (the timer, the counter, the bit): the model holds it in ``Box.instance``.
Calls of FC/FB/SFC/SFB are not catalogued here: their pins are the called block's parameters
(see :func:`call_target`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal

Family = Literal[
    "compare", "move", "math", "convert", "word", "shift", "timer", "counter", "flipflop", "edge"
]
Direction = Literal["in", "out"]


@dataclass(frozen=True, slots=True)
class Pin:
    name: str
    direction: Direction
    type: str  # the S7 type: BOOL, INT, DINT, REAL, WORD, DWORD, S5TIME, ANY


@dataclass(frozen=True, slots=True)
class BoxSpec:
    """One box: ``op`` is its STL operation (``+I``, ``SD``, ``==I`` ...; empty for MOVE);
    ``can_fail`` boxes clear ENO on overflow (``AN OV; SAVE; CLR``); ``address`` names the operand
    kind written above the box (``timer``, ``counter``, ``bit``) or is None."""

    name: str
    family: Family
    pins: tuple[Pin, ...]
    en_eno: bool
    op: str
    can_fail: bool = False
    flow_pin: str | None = None
    flow_out: str | None = None
    address: Literal["timer", "counter", "bit"] | None = None

    def pin(self, name: str) -> Pin | None:
        return next((pin for pin in self.pins if pin.name == name), None)

    @property
    def inputs(self) -> tuple[Pin, ...]:
        return tuple(pin for pin in self.pins if pin.direction == "in")

    @property
    def outputs(self) -> tuple[Pin, ...]:
        return tuple(pin for pin in self.pins if pin.direction == "out")


def _p(name: str, type_: str, direction: Direction = "in") -> Pin:
    return Pin(name, direction, type_)


_EN, _ENO = _p("EN", "BOOL"), _p("ENO", "BOOL", "out")
_TYPES = {"I": "INT", "DI": "DINT", "R": "REAL"}
_COMPARES = ("==", "<>", ">", "<", ">=", "<=")


def _en_box(
    name: str, family: Family, op: str, pins: tuple[Pin, ...], can_fail: bool = False
) -> BoxSpec:
    return BoxSpec(name, family, (_EN, *pins, _ENO), True, op, can_fail, "EN", "ENO")


def _two(name: str, family: Family, op: str, type_: str, can_fail: bool) -> BoxSpec:
    pins = (_p("IN1", type_), _p("IN2", type_), _p("OUT", type_, "out"))
    return _en_box(name, family, op, pins, can_fail)


def _one(
    name: str, family: Family, op: str, type_in: str, type_out: str, can_fail: bool
) -> BoxSpec:
    return _en_box(name, family, op, (_p("IN", type_in), _p("OUT", type_out, "out")), can_fail)


def _catalogue() -> dict[str, BoxSpec]:
    boxes: list[BoxSpec] = []
    for suffix, type_ in (("I", "INT"), ("D", "DINT"), ("R", "REAL")):
        for relation in _COMPARES:
            pins = (_p("IN1", type_), _p("IN2", type_))
            boxes.append(
                BoxSpec(f"CMP{relation}{suffix}", "compare", pins, False, relation + suffix)
            )
    boxes.append(_en_box("MOVE", "move", "", (_p("IN", "ANY"), _p("OUT", "ANY", "out"))))
    for suffix, type_ in _TYPES.items():
        letter = "D" if suffix == "DI" else suffix
        for name, sign in (("ADD", "+"), ("SUB", "-"), ("MUL", "*"), ("DIV", "/")):
            boxes.append(_two(f"{name}_{suffix}", "math", sign + letter, type_, True))
    boxes.append(_two("MOD_DI", "math", "MOD", "DINT", True))
    boxes.append(_one("ABS", "math", "ABS", "REAL", "REAL", False))
    for name in ("SQR", "SQRT", "EXP", "LN", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN"):
        boxes.append(_one(name, "math", name, "REAL", "REAL", True))
    for name, op, type_in, type_out, can_fail in (
        ("BCD_I", "BTI", "WORD", "INT", False),
        ("I_BCD", "ITB", "INT", "WORD", True),
        ("I_DI", "ITD", "INT", "DINT", False),
        ("DI_R", "DTR", "DINT", "REAL", False),
        ("BCD_DI", "BTD", "DWORD", "DINT", False),
        ("DI_BCD", "DTB", "DINT", "DWORD", True),
        ("ROUND", "RND", "REAL", "DINT", True),
        ("TRUNC", "TRUNC", "REAL", "DINT", True),
        ("CEIL", "RND+", "REAL", "DINT", True),
        ("FLOOR", "RND-", "REAL", "DINT", True),
        ("INV_I", "INVI", "INT", "INT", False),
        ("INV_DI", "INVD", "DINT", "DINT", False),
        ("NEG_I", "NEGI", "INT", "INT", True),
        ("NEG_DI", "NEGD", "DINT", "DINT", True),
        ("NEG_R", "NEGR", "REAL", "REAL", False),
    ):
        boxes.append(_one(name, "convert", op, type_in, type_out, can_fail))
    for name, op in (("WAND", "A"), ("WOR", "O"), ("WXOR", "XO")):
        boxes.append(_two(f"{name}_W", "word", op + "W", "WORD", False))
        boxes.append(_two(f"{name}_DW", "word", op + "D", "DWORD", False))
    for name, op, type_ in (
        ("SHL_W", "SLW", "WORD"),
        ("SHR_W", "SRW", "WORD"),
        ("SHL_DW", "SLD", "DWORD"),
        ("SHR_DW", "SRD", "DWORD"),
        ("SHR_I", "SSI", "INT"),
        ("SHR_DI", "SSD", "DINT"),
        ("ROL_DW", "RLD", "DWORD"),
        ("ROR_DW", "RRD", "DWORD"),
    ):
        shift_pins = (_p("IN", type_), _p("N", "WORD"), _p("OUT", type_, "out"))
        boxes.append(_en_box(name, "shift", op, shift_pins))
    timer_pins = (
        _p("S", "BOOL"),
        _p("TV", "S5TIME"),
        _p("R", "BOOL"),
        _p("BI", "WORD", "out"),
        _p("BCD", "WORD", "out"),
        _p("Q", "BOOL", "out"),
    )
    for name, op in (
        ("S_PULSE", "SP"),
        ("S_PEXT", "SE"),
        ("S_ODT", "SD"),
        ("S_ODTS", "SS"),
        ("S_OFFDT", "SF"),
    ):
        boxes.append(BoxSpec(name, "timer", timer_pins, False, op, False, "S", "Q", "timer"))
    tail = (
        _p("S", "BOOL"),
        _p("PV", "WORD"),
        _p("R", "BOOL"),
        _p("CV", "WORD", "out"),
        _p("CV_BCD", "WORD", "out"),
        _p("Q", "BOOL", "out"),
    )
    cu, cd = _p("CU", "BOOL"), _p("CD", "BOOL")
    boxes.append(BoxSpec("S_CU", "counter", (cu, *tail), False, "CU", False, "CU", "Q", "counter"))
    boxes.append(BoxSpec("S_CD", "counter", (cd, *tail), False, "CD", False, "CD", "Q", "counter"))
    boxes.append(
        BoxSpec("S_CUD", "counter", (cu, cd, *tail), False, "CU", False, "CU", "Q", "counter")
    )
    q = _p("Q", "BOOL", "out")
    boxes.append(
        BoxSpec(
            "SR",
            "flipflop",
            (_p("S", "BOOL"), _p("R1", "BOOL"), q),
            False,
            "S",
            False,
            "S",
            "Q",
            "bit",
        )
    )
    boxes.append(
        BoxSpec(
            "RS",
            "flipflop",
            (_p("R", "BOOL"), _p("S1", "BOOL"), q),
            False,
            "R",
            False,
            "R",
            "Q",
            "bit",
        )
    )
    for name, op in (("POS", "FP"), ("NEG", "FN")):
        boxes.append(
            BoxSpec(name, "edge", (_p("M_BIT", "BOOL"), q), False, op, False, None, "Q", "bit")
        )
    return {box.name: box for box in boxes}


CATALOGUE: dict[str, BoxSpec] = _catalogue()

_CALL = re.compile(r'^\s*(?:(FC|FB|SFC|SFB)\s*(\d+)|("[^"]+"))\s*$', re.IGNORECASE)


def box_spec(name: str) -> BoxSpec | None:
    """The catalogued box ``name`` (spaces and case ignored: ``cmp >=i`` is ``CMP>=I``)."""
    return CATALOGUE.get(re.sub(r"\s+", "", name).upper())


def call_target(name: str) -> tuple[str, bool] | None:
    """For a call box (``FC 10``, ``FB 5``, ``SFB 4``, ``"Motor"``): its name as STL writes it
    and whether it needs an instance DB (FB/SFB; a symbol may be either, so it does not)."""
    found = _CALL.match(name)
    if found is None:
        return None
    if found.group(3):
        return found.group(3), False
    kind = found.group(1).upper()
    return f"{kind} {int(found.group(2))}", kind in ("FB", "SFB")

"""The box catalogue: every family the course uses, pins with direction and S7 type, EN/ENO."""

from __future__ import annotations

import pytest

from nasaq.lang.lad.boxes import CATALOGUE, Pin, box_spec, call_target


def test_every_family_is_catalogued() -> None:
    families = {spec.family for spec in CATALOGUE.values()}
    assert families == {
        "compare",
        "move",
        "math",
        "convert",
        "word",
        "shift",
        "timer",
        "counter",
        "flipflop",
        "edge",
    }
    assert len(CATALOGUE) == 18 + 1 + 24 + 15 + 6 + 8 + 5 + 3 + 2 + 2


def test_en_eno_boxes_have_en_first_and_eno_last() -> None:
    for spec in CATALOGUE.values():
        if spec.en_eno:
            assert spec.pins[0] == Pin("EN", "in", "BOOL")
            assert spec.pins[-1] == Pin("ENO", "out", "BOOL")
            assert spec.pin("OUT") is not None
        else:
            assert spec.pin("EN") is None
            assert spec.pin("ENO") is None


@pytest.mark.parametrize(
    ("name", "op", "pins", "can_fail"),
    [
        ("ADD_DI", "+D", ["EN", "IN1:DINT", "IN2:DINT", "OUT:DINT", "ENO"], True),
        ("DIV_R", "/R", ["EN", "IN1:REAL", "IN2:REAL", "OUT:REAL", "ENO"], True),
        ("I_BCD", "ITB", ["EN", "IN:INT", "OUT:WORD", "ENO"], True),
        ("I_DI", "ITD", ["EN", "IN:INT", "OUT:DINT", "ENO"], False),
        ("CEIL", "RND+", ["EN", "IN:REAL", "OUT:DINT", "ENO"], True),
        ("WXOR_DW", "XOD", ["EN", "IN1:DWORD", "IN2:DWORD", "OUT:DWORD", "ENO"], False),
        ("SHR_I", "SSI", ["EN", "IN:INT", "N:WORD", "OUT:INT", "ENO"], False),
        ("S_OFFDT", "SF", ["S", "TV:S5TIME", "R", "BI:WORD", "BCD:WORD", "Q"], False),
        ("S_CUD", "CU", ["CU", "CD", "S", "PV:WORD", "R", "CV:WORD", "CV_BCD:WORD", "Q"], False),
        ("SR", "S", ["S", "R1", "Q"], False),
        ("NEG", "FN", ["M_BIT", "Q"], False),
        ("CMP<>R", "<>R", ["IN1:REAL", "IN2:REAL"], False),
    ],
)
def test_box_details(name: str, op: str, pins: list[str], can_fail: bool) -> None:
    spec = box_spec(name)
    assert spec is not None
    shown = [p.name if p.type == "BOOL" else f"{p.name}:{p.type}" for p in spec.pins]
    assert (spec.op, shown, spec.can_fail) == (op, pins, can_fail)


def test_flow_pins_and_addresses() -> None:
    timer, counter, flip, edge = (box_spec(n) for n in ("S_ODT", "S_CD", "RS", "POS"))
    assert timer
    assert (timer.flow_pin, timer.flow_out, timer.address) == ("S", "Q", "timer")
    assert counter
    assert (counter.flow_pin, counter.address) == ("CD", "counter")
    assert flip
    assert (flip.flow_pin, flip.address) == ("R", "bit")
    assert edge
    assert (edge.flow_pin, edge.address) == (None, "bit")
    assert [p.name for p in timer.outputs] == ["BI", "BCD", "Q"]


def test_names_ignore_case_and_spaces() -> None:
    assert box_spec("cmp >= i") is CATALOGUE["CMP>=I"]
    assert box_spec("move") is CATALOGUE["MOVE"]
    assert box_spec("ADD_X") is None


def test_call_targets() -> None:
    assert call_target("fc10") == ("FC 10", False)
    assert call_target("FB 5") == ("FB 5", True)
    assert call_target("SFB  4") == ("SFB 4", True)
    assert call_target("SFC 20") == ("SFC 20", False)
    assert call_target('"Motor"') == ('"Motor"', False)
    assert call_target("MOVE") is None
    assert call_target("DB 5") is None

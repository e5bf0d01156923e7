"""P22 pneumatic cylinders: spring-return strokes, end switches, counted and short strokes, and
the paper's program 5 (seed 001) driving clamp / bend / bend 5, 7 and 4 times."""

from __future__ import annotations

import pytest
from plant_driver import CourseLoop

from nasaq.plants.base import PlantError
from nasaq.plants.cylinders import Cylinders


def run(plant: Cylinders, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_a_valve_pulse_extends_the_cylinder_and_the_spring_returns_it() -> None:
    bank = Cylinders()
    assert bank.sensors()["c1_home"] == 1
    run(bank, 490, v1=1)
    assert bank.sensors()["c1_end"] == 0
    run(bank, 10)
    assert bank.sensors()["c1_end"] == 1
    assert bank.state()["c1_strokes"] == 1
    run(bank, 500, v1=0)
    assert bank.sensors()["c1_home"] == 1
    assert bank.sensors()["c2_home"] == 1  # the others stayed in


def test_a_pulse_too_short_for_the_stroke_counts_as_short() -> None:
    bank = Cylinders()
    run(bank, 200, v2=1)
    run(bank, 500, v2=0)
    assert bank.state()["c2_strokes"] == 0
    assert bank.state()["c2_short"] == 1


def test_missing_cylinders_read_nothing_and_ignore_their_valves() -> None:
    bank = Cylinders({"count": 1})
    run(bank, 1000, v1=1, v3=1)
    assert bank.sensors() == {
        "c1_home": 0,
        "c1_end": 1,
        "c2_home": 0,
        "c2_end": 0,
        "c3_home": 0,
        "c3_end": 0,
    }
    assert bank.state()["c3_strokes"] == 0


def test_a_fractional_count_is_refused() -> None:
    with pytest.raises(PlantError):
        Cylinders({"count": 1.5})


def test_paper_program_5_pulses_the_three_cylinders_5_7_and_4_times() -> None:
    """The corrected program counts 7 pulses of P014, but its first one is the remainder of a
    2 s clock phase already running (the scenario's note: "a short remainder"): the plant shows
    that this bend stroke does not reach its end."""
    loop = CourseLoop("ar_001/p5_three_outputs_jump", "cylinders")
    loop.run(100)
    loop.press("start")
    loop.run(120_000)
    state = loop.plant.state()
    assert (state["c1_strokes"], state["c2_strokes"], state["c3_strokes"]) == (5, 6, 4)
    assert (state["c1_short"], state["c2_short"], state["c3_short"]) == (0, 1, 0)
    assert loop.plant.sensors()["c1_home"] == loop.plant.sensors()["c2_home"] == 1
    assert loop.plant.sensors()["c3_home"] == 1


def test_paper_program_1_pushes_six_times() -> None:
    loop = CourseLoop(
        "ar_001/p1_repeat_n_times",
        "cylinders",
        params={"count": 1},
        wiring={"start": "I0.0", "v1": "Q0.0", "c1_end": "I1.1"},
    )
    loop.press("start")
    loop.run(130_000)
    assert loop.plant.state()["c1_strokes"] == 6
    assert loop.plant.state()["c1_short"] == 0

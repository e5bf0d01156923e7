"""P12 hydraulic cylinder: stroke and end switches, holding with both valves off, the pressure
that builds when the ram is blocked (clamp, press-fit), and the course's press and clamp."""

from __future__ import annotations

import pytest
from plant_driver import CourseLoop

from nasaq.plants.base import PlantError
from nasaq.plants.cylinder import Cylinder


def run(plant: Cylinder, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_a_full_stroke_takes_two_seconds_each_way() -> None:
    ram = Cylinder()
    assert ram.sensors() == {"rest": 1, "end": 0, "pressure_ok": 0}
    run(ram, 100, extend=1)
    assert ram.sensors()["rest"] == 0
    run(ram, 1850)
    assert ram.sensors()["end"] == 0
    run(ram, 50)
    assert ram.sensors()["end"] == 1
    assert ram.state()["strokes"] == 1
    run(ram, 2000, extend=0, retract=1)
    assert ram.sensors()["rest"] == 1


def test_both_valves_off_hold_the_ram_where_it_is() -> None:
    ram = Cylinder()
    run(ram, 1000, extend=1)
    run(ram, 5000, extend=0)
    assert ram.state()["position"] == pytest.approx(50)


def test_pressure_builds_only_when_the_ram_is_blocked() -> None:
    ram = Cylinder()
    run(ram, 1500, extend=1)
    assert ram.state()["pressure"] == 5  # moving freely
    run(ram, 510)  # at the end
    run(ram, 360)
    assert ram.sensors()["pressure_ok"] == 0
    run(ram, 20)
    assert ram.sensors()["pressure_ok"] == 1  # from 5 to 20 bar at 40 bar/s
    run(ram, 200, extend=0)
    assert ram.sensors()["pressure_ok"] == 0


def test_press_fit_stops_on_the_work_piece_and_never_reaches_s5() -> None:
    ram = Cylinder({"work_at": 80})
    run(ram, 3000, extend=1)
    assert ram.state()["position"] == 80
    assert ram.sensors()["end"] == 0
    assert ram.sensors()["pressure_ok"] == 1
    assert ram.state()["strokes"] == 1


def test_both_valves_together_is_a_fault() -> None:
    ram = Cylinder()
    run(ram, 10, extend=1, retract=1)
    assert ram.active_faults == {"both_valves"}


def test_a_start_position_beyond_the_work_piece_is_refused() -> None:
    with pytest.raises(PlantError):
        Cylinder({"work_at": 50, "start_position": 60})


def test_course_press_extends_returns_and_stops_on_s3() -> None:
    loop = CourseLoop(
        "vi_004/e13_hydraulic_press", "cylinder", wiring=dict(Cylinder.default_wiring)
    )
    loop.press("s1")
    loop.run_until(lambda: loop.plant.sensors()["end"] == 1, 3000)
    loop.run_until(lambda: loop.plant.sensors()["rest"] == 1, 3000)
    loop.run(500)
    assert loop.plant.state()["strokes"] == 1
    assert loop.plant.actuators == {"extend": 0, "retract": 0, "lamp": 0}
    loop.press("s1")
    loop.run(500)
    loop.press("s3")
    held = loop.plant.state()["position"]
    loop.run(2000)
    assert loop.plant.state()["position"] == held
    assert 10 < held < 90
    loop.press("s2")
    loop.run_until(lambda: loop.plant.sensors()["rest"] == 1, 3000)
    assert loop.runtime.faults() == []


def test_course_clamp_keeps_pressing_for_fifteen_seconds_after_ls2() -> None:
    wiring = {
        "s1": "I0.0",
        "rest": "I0.1",
        "end": "I0.2",
        "extend": "Q0.0",
        "retract": "Q0.1",
    }
    loop = CourseLoop("vi_004/e31_hydraulic_clamp", "cylinder", wiring=wiring)
    loop.press("s1")
    loop.run_until(lambda: loop.plant.sensors()["end"] == 1, 3000)
    loop.run(14_800)
    assert loop.plant.actuators["extend"] == 1
    assert loop.plant.state()["pressure"] == 60  # clamped at the supply pressure
    loop.run(400)
    assert loop.plant.actuators["extend"] == 0


def test_a_stuck_pressure_switch_never_trips() -> None:
    ram = Cylinder({"work_at": 80})
    ram.inject("pressure_switch_stuck")
    run(ram, 5000, extend=1)
    assert ram.state()["pressure"] == 60
    assert ram.sensors()["pressure_ok"] == 0

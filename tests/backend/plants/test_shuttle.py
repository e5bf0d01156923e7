"""P14 motor shuttle: travel between LS1 and LS2, overtravel, both directions, and the course's
corrected E-vi-33 program shuttling the carriage with its 10 s wait at LS2."""

from __future__ import annotations

import pytest
from plant_driver import CourseLoop

from nasaq.plants.base import PlantError
from nasaq.plants.shuttle import Shuttle


def run(plant: Shuttle, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_the_carriage_starts_home_and_reaches_ls2_after_about_five_seconds() -> None:
    shuttle = Shuttle()
    assert shuttle.sensors() == {"ls1": 1, "ls2": 0}
    run(shuttle, 100, right=1)
    assert shuttle.sensors() == {"ls1": 0, "ls2": 0}
    assert shuttle.state()["direction"] == "right"
    run(shuttle, 4800)
    assert shuttle.sensors()["ls2"] == 0
    run(shuttle, 100)
    assert shuttle.sensors()["ls2"] == 1
    assert shuttle.active_faults == set()


def test_driving_into_the_buffer_is_overtravel() -> None:
    shuttle = Shuttle()
    run(shuttle, 5200, right=1)  # 40 mm past LS2: still short of the buffer
    assert shuttle.active_faults == set()
    run(shuttle, 100)
    assert shuttle.active_faults == {"overtravel"}
    assert shuttle.state()["position"] == 1050


def test_both_directions_at_once_is_a_fault_and_nothing_moves() -> None:
    shuttle = Shuttle({"start_position": 500})
    run(shuttle, 50, right=1, left=1)
    assert shuttle.active_faults == {"both_directions"}
    assert shuttle.state()["position"] == 500


def test_a_cycle_and_the_wait_at_ls2_are_measured() -> None:
    shuttle = Shuttle()
    run(shuttle, 4950, right=1)
    run(shuttle, 3000, right=0)
    assert shuttle.state()["wait_ms"] == 3000
    run(shuttle, 4950, left=1)
    assert shuttle.state()["last_wait_ms"] == 3000
    assert shuttle.state()["cycles"] == 1
    assert shuttle.sensors()["ls1"] == 1


def test_a_start_position_outside_the_track_is_refused() -> None:
    with pytest.raises(PlantError):
        Shuttle({"start_position": 2000})


def test_course_program_shuttles_with_a_ten_second_wait() -> None:
    loop = CourseLoop("vi_004/e33_motor_shuttle", "shuttle")
    loop.run(500)
    assert loop.plant.state()["direction"] == "stopped"
    loop.press("start")
    reached = loop.run_until(lambda: loop.plant.sensors()["ls2"] == 1, 10_000)
    assert 4700 <= reached <= 5000
    loop.run_until(lambda: loop.plant.state()["cycles"] == 1, 20_000)
    loop.run(1000)
    state = loop.plant.state()
    assert 9900 <= state["last_wait_ms"] <= 10_200
    assert state["direction"] == "stopped"
    assert loop.plant.sensors()["ls1"] == 1
    assert loop.runtime.faults() == []  # the motor stops one scan after LS1, inside the band


def test_a_broken_ls2_sends_the_course_carriage_into_the_buffer() -> None:
    loop = CourseLoop("vi_004/e33_motor_shuttle", "shuttle")
    loop.runtime.inject("ls2_broken")
    loop.press("start")
    loop.run(6000)
    assert loop.runtime.faults() == ["ls2_broken", "overtravel"]

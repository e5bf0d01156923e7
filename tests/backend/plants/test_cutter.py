"""P10 cut-to-length machine: feeding, braking distance, the knife stroke and its sensors, and
the course's E-vi-7 program cutting pieces of the right length."""

from __future__ import annotations

from plant_driver import CourseLoop

from nasaq.plants.cutter import Cutter


def run(plant: Cutter, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_the_bar_reaches_the_dimension_sensor_at_the_feed_speed() -> None:
    cutter = Cutter()
    run(cutter, 2500, wheel=1)  # 0.2 s to accelerate: 480 mm
    assert cutter.sensors()["dimension_eye"] == 0
    run(cutter, 200)
    assert cutter.sensors()["dimension_eye"] == 1
    assert cutter.state()["bar_speed"] == 200


def test_the_brake_stops_the_bar_within_a_few_millimetres_coasting_does_not() -> None:
    braked = Cutter()
    run(braked, 1000, wheel=1)
    at = braked.state()["bar_position"]
    run(braked, 500, wheel=0, brake=1)
    assert braked.state()["bar_position"] - at < 6
    coasting = Cutter()
    run(coasting, 1000, wheel=1)
    run(coasting, 2000, wheel=0)
    assert coasting.state()["bar_position"] - at > 90


def test_the_knife_stroke_and_its_sensors() -> None:
    cutter = Cutter()
    assert cutter.sensors()["knife_home"] == 1
    run(cutter, 10, knife=1)
    assert cutter.sensors()["knife_home"] == 0
    run(cutter, 480)
    assert cutter.sensors()["cut_done"] == 0
    run(cutter, 10)
    assert cutter.sensors()["cut_done"] == 1
    run(cutter, 500, knife=0)
    assert cutter.sensors() == {"dimension_eye": 0, "cut_done": 0, "knife_home": 1}


def test_a_piece_cut_without_braking_is_too_long() -> None:
    cutter = Cutter()
    run(cutter, 2700, wheel=1)
    run(cutter, 500, wheel=0, knife=1)  # no brake: the bar coasts under the knife
    assert cutter.state()["pieces"] == 1
    assert cutter.active_faults >= {"wrong_length", "knife_collision"}


def test_driving_against_the_brake() -> None:
    cutter = Cutter()
    run(cutter, 10, wheel=1, brake=1)
    assert cutter.active_faults == {"brake_drag"}
    assert cutter.state()["bar_position"] == 0


def test_course_program_cuts_pieces_of_the_set_length() -> None:
    loop = CourseLoop("vi_004/e07_cut_to_length", "cutter")
    for _ in range(3):
        loop.press("start")
        pieces = loop.plant.state()["pieces"]
        loop.run_until(lambda p=pieces: loop.plant.state()["pieces"] == p + 1, 5000)
        loop.run(600)  # the knife goes back up
        assert loop.plant.sensors()["knife_home"] == 1
    state = loop.plant.state()
    assert state["pieces"] == 3
    assert state["wrong_pieces"] == 0
    assert 500 <= state["last_length"] <= 510
    assert loop.runtime.faults() == []
    loop.run(3000)  # no automatic restart
    assert loop.plant.state()["bar_position"] == 0

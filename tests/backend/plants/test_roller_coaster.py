"""P13 roller coaster: the train leaves only after 15 s of siren, rides its loop, and the
course's E-vi-29 program warns long enough."""

from __future__ import annotations

from plant_driver import CourseLoop

from nasaq.plants.roller_coaster import RollerCoaster


def run(plant: RollerCoaster, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_starting_without_the_siren_is_no_warning() -> None:
    train = RollerCoaster()
    run(train, 10, drive=1)
    assert train.active_faults == {"no_warning"}


def test_a_warning_shorter_than_fifteen_seconds_is_no_warning() -> None:
    train = RollerCoaster()
    run(train, 14_000, siren=1)
    run(train, 10, siren=0, drive=1)
    assert train.active_faults == {"no_warning"}


def test_a_warning_that_ended_long_ago_does_not_count() -> None:
    train = RollerCoaster()
    run(train, 15_000, siren=1)
    run(train, 5000, siren=0)
    run(train, 10, drive=1)
    assert train.active_faults == {"no_warning"}


def test_fifteen_seconds_of_siren_then_the_train_rides_its_loop() -> None:
    train = RollerCoaster()
    assert train.sensors()["station"] == 1
    run(train, 15_000, siren=1)
    run(train, 4000, siren=0, drive=1)  # 16 m: out of the station
    assert train.active_faults == set()
    assert train.state()["warned"] is True
    assert train.sensors()["station"] == 0
    run(train, 45_000)  # 400 m at 10 m/s, plus 1 s to accelerate
    assert train.state()["laps"] == 1
    run(train, 5000, drive=0)  # brakes to a stop
    assert train.state()["speed"] == 0


def test_course_program_warns_fifteen_seconds_before_the_train_leaves() -> None:
    loop = CourseLoop("vi_004/e29_roller_coaster", "roller_coaster")
    loop.press("start", 300)
    left = loop.run_until(lambda: loop.plant.state()["speed"] > 0, 20_000)
    assert 14_600 <= left <= 15_200
    loop.run(45_000)
    assert loop.runtime.faults() == []
    assert loop.plant.state()["laps"] == 1

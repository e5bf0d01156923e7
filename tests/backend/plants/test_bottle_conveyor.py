"""P04 bottle conveyor: bottles move with the belt and cover the eyes where the layout says, the
filler judges each bottle (full, part-filled, over-full), the pusher rejects, a stuck eye, and
the course's bottle filling program (E-vi-25) filling bottle after bottle in closed loop."""

from __future__ import annotations

from plant_driver import COURSE, ClosedLoop, hold

from nasaq.plants.bottle_conveyor import BottleConveyor
from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import PlantConfig


def test_the_first_bottle_reaches_the_eyes_at_belt_speed() -> None:
    belt = BottleConveyor()  # 100 mm/s, bottles 60 mm, count eye at 150, filler at 600
    assert belt.sensors() == {"bottle_eye": 0, "exit_eye": 0, "count_eye": 0}
    hold(belt, 1200, conveyor=1)  # front edge at 150 mm
    assert belt.sensors()["count_eye"] == 1
    hold(belt, 4500)  # centre at 570 mm: its front edge is at the filler's eye
    assert belt.sensors()["bottle_eye"] == 1
    hold(belt, 2000, conveyor=0)
    assert belt.sensors()["bottle_eye"] == 1  # stands with the belt
    assert belt.state()["bottles"] == 3  # one set on every 250 mm


def bottle_at_filler() -> BottleConveyor:
    belt = BottleConveyor()
    hold(belt, 5700, conveyor=1)
    assert belt.sensors()["bottle_eye"] == 1
    belt.set_actuators({"conveyor": 0})
    return belt


def test_a_bottle_filled_for_the_fill_time_leaves_full() -> None:
    belt = bottle_at_filler()
    hold(belt, 12_000, fill_valve=1)
    assert belt.state()["fill"] == 100.0
    hold(belt, 1000, fill_valve=0, conveyor=1)
    assert belt.state()["filled_ok"] == 1
    assert belt.active_faults == set()


def test_part_filled_and_over_filled_bottles_are_faults() -> None:
    short = bottle_at_filler()
    hold(short, 6000, fill_valve=1)
    hold(short, 1000, fill_valve=0, conveyor=1)
    assert short.active_faults == {"underfill"}
    assert short.state()["underfilled"] == 1
    long = bottle_at_filler()
    hold(long, 13_000, fill_valve=1)
    hold(long, 1000, fill_valve=0, conveyor=1)
    assert long.active_faults == {"overfill"}


def test_empty_bottles_are_counted_not_faults_and_the_valve_without_a_bottle_spills() -> None:
    belt = BottleConveyor()
    hold(belt, 12_000, conveyor=1)
    assert belt.state()["passed_empty"] >= 2
    assert belt.active_faults == set()
    hold(belt, 100, conveyor=0, fill_valve=1)
    if belt.sensors()["bottle_eye"] == 0:
        assert belt.state()["spilled"] > 0


def test_the_pusher_rejects_the_bottle_at_the_exit_eye() -> None:
    belt = BottleConveyor()
    hold(belt, 9800, conveyor=1)  # the first bottle at the exit eye
    assert belt.sensors()["exit_eye"] == 1
    bottles = belt.state()["bottles"]
    hold(belt, 10, conveyor=0, pusher=1)
    assert belt.state()["rejected"] == 1
    assert belt.state()["bottles"] == bottles - 1
    assert belt.sensors()["exit_eye"] == 0


def test_a_dirty_eye_reads_covered() -> None:
    belt = BottleConveyor()
    belt.inject("eye_stuck")
    assert belt.sensors()["bottle_eye"] == 1


def test_the_course_filling_program_fills_bottle_after_bottle() -> None:
    base = COURSE / "vi_004" / "e25_bottle_filling"
    config = PlantConfig(
        kind="bottle_conveyor",
        wiring=dict(plant_class("bottle_conveyor").default_wiring),
        params={"fill_ms": 30_000},  # the book's program fills for 30 s
    )
    loop = ClosedLoop([base.with_suffix(".awl"), base.with_suffix(".sdf")], config)
    loop.runtime.operate("start", 1)
    loop.run(100)
    loop.runtime.operate("start", 0)
    loop.run(120_000)
    state = loop.plant.state()
    assert state["filled_ok"] >= 3
    assert state["underfilled"] == 0
    assert state["overfilled"] == 0
    assert loop.plant.active_faults == set()

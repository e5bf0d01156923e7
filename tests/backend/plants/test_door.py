"""P11 door: travel between the limit switches, overtravel, crush, the boiler door's closing
pressure, and the course's E-vi-12 program opening the warehouse door for a truck."""

from __future__ import annotations

import pytest
from plant_driver import CourseLoop

from nasaq.plants.base import PlantError
from nasaq.plants.door import Door


def run(plant: Door, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_the_door_opens_in_ten_seconds_between_its_limit_switches() -> None:
    door = Door()
    assert door.sensors() == {"ls_open": 0, "ls_closed": 1, "pressure_ok": 0}
    run(door, 100, open=1)
    assert door.sensors()["ls_closed"] == 0
    run(door, 9800)
    assert door.sensors()["ls_open"] == 0
    run(door, 100)
    assert door.sensors()["ls_open"] == 1
    assert door.state()["position"] == pytest.approx(100)
    run(door, 10_000, open=0, close=1)
    assert door.sensors()["ls_closed"] == 1
    assert door.active_faults == set()


def test_driving_on_past_a_limit_switch_is_overtravel() -> None:
    door = Door()
    run(door, 10_100, open=1)
    assert door.active_faults == set()  # within the margin: a scan late is fine
    run(door, 200)
    assert door.active_faults == {"overtravel"}
    assert door.state()["position"] == pytest.approx(102)


def test_open_and_close_together() -> None:
    door = Door({"start_position": 50})
    run(door, 10, open=1, close=1)
    assert door.active_faults == {"both_directions"}
    assert door.state()["position"] == 50


def test_closing_while_a_truck_is_in_the_doorway_crushes_it() -> None:
    door = Door({"start_position": 100})
    door.operate("inside", 1)
    run(door, 10, close=1)
    assert door.active_faults == {"crush"}


def test_a_simulated_truck_waits_outside_until_the_door_is_open() -> None:
    door = Door()
    door.operate("truck", 1)
    run(door, 1990)
    assert door.inputs()["outside"] == 0  # still on its way
    run(door, 20)
    assert door.inputs()["outside"] == 1
    assert door.state()["truck"] == "waiting"
    run(door, 5000)
    assert door.state()["truck"] == "waiting"
    run(door, 10_000, open=1)
    assert door.state()["truck"] == "passing"
    assert door.inputs()["inside"] == 1
    assert door.inputs()["outside"] == 0
    run(door, 3000, open=0)
    assert door.state()["truck"] == "none"
    assert door.state()["trucks_passed"] == 1
    assert door.inputs()["inside"] == 0


def test_a_truck_passing_under_a_closing_door_is_crushed() -> None:
    door = Door({"start_position": 100, "approach_ms": 0})
    door.operate("truck", 1)
    run(door, 20)
    assert door.state()["truck"] == "passing"
    run(door, 10, close=1)
    assert "crush" in door.active_faults


def test_boiler_door_builds_pressure_after_the_closed_limit() -> None:
    door = Door({"boiler": 1, "start_position": 10})
    run(door, 1000, close=1)
    assert door.sensors()["ls_closed"] == 1
    assert door.sensors()["pressure_ok"] == 0
    run(door, 1990)
    assert door.sensors()["pressure_ok"] == 0
    run(door, 20)
    assert door.sensors()["pressure_ok"] == 1  # 100 bar at 50 bar/s
    run(door, 5000, close=0)
    assert door.sensors()["pressure_ok"] == 1  # held with the valve closed
    assert door.active_faults == set()


def test_boiler_door_pressed_on_past_the_maximum_pressure() -> None:
    door = Door({"boiler": 1})
    run(door, 2700, close=1)
    assert door.active_faults == {"overpressure"}


def test_opening_a_boiler_door_releases_the_pressure_first() -> None:
    door = Door({"boiler": 1})
    run(door, 2000, close=1)
    run(door, 10, close=0, open=1)
    assert door.state()["pressure"] == 0
    assert door.state()["position"] == 0
    run(door, 100)
    assert door.state()["position"] > 0


def test_parameters_out_of_range_are_refused() -> None:
    with pytest.raises(PlantError) as caught:
        Door({"start_position": 120})
    assert caught.value.code == "PLT009"


def test_course_program_opens_the_door_for_a_truck_and_closes_it_behind() -> None:
    loop = CourseLoop("vi_004/e12_warehouse_door", "door")
    loop.run(500)
    assert loop.plant.state()["position"] == 0
    loop.press("truck")
    opened = loop.run_until(lambda: loop.plant.sensors()["ls_open"] == 1, 20_000)
    assert 11_000 <= opened <= 12_500  # 2 s to arrive, 10 s to open
    loop.run_until(lambda: loop.plant.state()["truck"] == "none", 5000)
    assert loop.plant.state()["trucks_passed"] == 1
    loop.run_until(lambda: loop.plant.sensors()["ls_closed"] == 1, 11_000)
    loop.run(2000)
    assert loop.plant.state()["position"] == pytest.approx(0, abs=0.5)
    assert loop.runtime.faults() == []


def test_book_wiring_with_swapped_limit_switches_never_opens() -> None:
    """The book's description (LS2 upper, LS1 lower): network 2 stops the door at once."""
    wiring = dict(Door.default_wiring, ls_open="I0.3", ls_closed="I0.2")
    loop = CourseLoop("vi_004/e12_warehouse_door", "door", wiring=wiring)
    loop.press("truck")
    loop.run(15_000)
    assert loop.plant.state()["position"] < 1
    assert loop.plant.state()["truck"] == "waiting"


def test_a_broken_open_limit_switch_drives_the_course_door_into_overtravel() -> None:
    loop = CourseLoop("vi_004/e12_warehouse_door", "door")
    loop.runtime.inject("ls_open_broken")
    loop.press("truck")
    loop.run(13_000)
    assert loop.plant.sensors()["ls_open"] == 0
    assert loop.runtime.faults() == ["ls_open_broken", "overtravel"]

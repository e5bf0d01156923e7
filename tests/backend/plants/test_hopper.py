"""P15 weighing hopper: the load-cell scaling the book uses (264.6 per kg), filling and
discharging, overflow, and the course's E-vi-17 program weighing 25 kg batches in closed loop."""

from __future__ import annotations

import pytest
from plant_driver import CourseLoop

from nasaq.plants.base import PlantError
from nasaq.plants.hopper import Hopper


def run(plant: Hopper, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_the_empty_hopper_reads_1323_and_30_kg_read_7938() -> None:
    hopper = Hopper()
    assert hopper.sensors() == {"weight": 1323}
    run(hopper, 25_000)
    assert hopper.sensors() == {"weight": 7938}
    assert hopper.state()["weight_kg"] == 30


def test_an_open_door_empties_the_hopper_and_stops_the_inflow() -> None:
    hopper = Hopper({"start_flour": 20})
    run(hopper, 2000, discharge=1)
    assert hopper.state()["flour"] == pytest.approx(10)
    run(hopper, 3000)
    assert hopper.sensors() == {"weight": 1323}
    assert hopper.state()["batches"] == 1
    assert hopper.state()["last_batch"] == 20


def test_a_door_that_never_opens_overflows() -> None:
    hopper = Hopper({"capacity": 30})
    run(hopper, 30_000)
    assert hopper.active_faults == set()
    run(hopper, 100)
    assert hopper.active_faults == {"overflow"}


def test_a_hopper_heavier_than_the_load_cell_is_refused() -> None:
    with pytest.raises(PlantError):
        Hopper({"tare": 70, "capacity": 40})


def test_course_program_discharges_25_kg_batches() -> None:
    loop = CourseLoop("vi_004/e17_flour_weighing", "hopper")
    loop.run(60_000)
    state = loop.plant.state()
    assert state["batches"] == 2
    assert state["last_batch"] == pytest.approx(25, abs=0.05)
    assert loop.runtime.faults() == []


def test_a_load_cell_wire_break_reads_32767() -> None:
    hopper = Hopper()
    hopper.inject("load_cell_wire_break")
    assert hopper.sensors() == {"weight": 32767}
    hopper.inject("load_cell_wire_break", on=False)
    assert hopper.sensors() == {"weight": 1323}

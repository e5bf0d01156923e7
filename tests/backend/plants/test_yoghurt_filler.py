"""P19 yoghurt filler: cups stop at SS1, the 5/2 valve opens the hopper, SS2 says full, LS says
closed; overflow, spill and underfill are caught. The controller here is Bài 9's sequence."""

from __future__ import annotations

import pytest

from nasaq.plants.base import PlantError
from nasaq.plants.yoghurt_filler import YoghurtFiller


def run(plant: YoghurtFiller, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def bai9(plant: YoghurtFiller, ms: int) -> None:
    """Start -> conveyor; SS1 rises -> conveyor off, Sol a on; SS2 -> Sol a off; LS -> conveyor
    on. Outputs come from the inputs of the step before, as a PLC scan sees them."""
    conveyor, sol_a, filling, cup_was = 1, 0, False, 0
    for _ in range(ms // 10):
        seen = plant.inputs()
        if seen["cup"] and not cup_was:
            conveyor, sol_a, filling = 0, 1, True
        elif filling and sol_a and seen["full"]:
            sol_a = 0
        elif filling and not sol_a and seen["piston_left"]:
            conveyor, filling = 1, False
        cup_was = seen["cup"]
        plant.set_actuators({"conveyor": conveyor, "sol_a": sol_a})
        plant.advance(10)


def test_the_first_cup_reaches_the_nozzle_after_about_a_second() -> None:
    plant = YoghurtFiller()
    run(plant, 840, conveyor=1)
    assert plant.sensors()["cup"] == 0
    run(plant, 20)
    assert plant.sensors()["cup"] == 1


def test_the_piston_opens_and_springs_back_with_the_solenoid() -> None:
    plant = YoghurtFiller()
    run(plant, 1000, conveyor=1)
    assert plant.sensors()["piston_left"] == 1
    run(plant, 10, conveyor=0, sol_a=1)
    assert plant.sensors()["piston_left"] == 0
    run(plant, 190)
    assert plant.state()["piston"] == 100
    run(plant, 200, sol_a=0)
    assert plant.sensors()["piston_left"] == 1


def test_the_bai9_sequence_fills_every_cup() -> None:
    plant = YoghurtFiller()
    bai9(plant, 30_000)
    state = plant.state()
    assert state["cups_good"] >= 6
    assert state["cups_bad"] == 0
    assert plant.active_faults == set()


def test_keeping_the_hopper_open_overflows_the_cup() -> None:
    plant = YoghurtFiller()
    run(plant, 1000, conveyor=1)
    run(plant, 2200, conveyor=0, sol_a=1)
    assert plant.sensors()["full"] == 1
    assert plant.active_faults == set()
    run(plant, 400)
    assert plant.active_faults == {"overflow"}


def test_opening_with_no_cup_spills() -> None:
    plant = YoghurtFiller()
    run(plant, 50, sol_a=1)
    assert plant.active_faults == {"spill"}


def test_a_cup_that_passes_unfilled_is_underfill() -> None:
    plant = YoghurtFiller()
    run(plant, 2000, conveyor=1)
    assert plant.active_faults == {"underfill"}
    assert plant.state()["cups_bad"] == 1


def test_an_sensor_window_wider_than_the_nozzle_is_refused() -> None:
    with pytest.raises(PlantError):
        YoghurtFiller({"window": 40, "catch": 25})


def test_a_stuck_full_sensor_makes_the_bai9_sequence_overflow() -> None:
    plant = YoghurtFiller()
    plant.inject("full_sensor_stuck")
    bai9(plant, 5000)
    assert "overflow" in plant.active_faults

"""P02 motor: run-up and coasting, the NC contacts at rest, the jam that trips the thermal relay
after 5 s, the winding that burns when the program ignores the trip, and the course's
motor start/stop project driving it."""

from __future__ import annotations

import pytest
from plant_driver import EXAMPLES, ClosedLoop, hold

from nasaq.plants.motor import Motor
from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import PlantConfig


def test_at_rest_the_nc_contacts_read_one() -> None:
    motor = Motor()
    assert motor.inputs() == {"start": 0, "stop": 1, "overload": 1, "running": 0}


def test_the_motor_runs_up_in_a_second_and_coasts_down_in_three() -> None:
    motor = Motor()
    hold(motor, 500, contactor=1)
    assert motor.state()["speed"] == pytest.approx(50.0)
    assert motor.sensors()["running"] == 1
    hold(motor, 600)
    assert motor.state()["speed"] == 100.0
    hold(motor, 1500, contactor=0)
    assert motor.state()["speed"] == pytest.approx(50.0)
    assert motor.sensors()["running"] == 1  # still turning
    hold(motor, 1500)
    assert motor.state()["speed"] == 0.0
    assert motor.sensors()["running"] == 0
    assert motor.state()["run_ms"] == 4100


def test_a_jam_trips_the_relay_after_five_seconds() -> None:
    motor = Motor()
    motor.inject("jam")
    hold(motor, 4990, contactor=1)
    assert motor.sensors()["overload"] == 1
    assert motor.state()["speed"] == 0.0  # blocked rotor
    hold(motor, 10)
    assert motor.sensors()["overload"] == 0
    hold(motor, 100, contactor=0)  # the program reacted: no damage
    assert motor.active_faults == {"jam"}
    motor.inject("jam", on=False)  # the fitter freed the rotor and reset the relay
    hold(motor, 10)
    assert motor.sensors()["overload"] == 1


def test_a_motor_kept_on_after_the_trip_burns() -> None:
    motor = Motor()
    motor.inject("jam")
    hold(motor, 5000, contactor=1)
    assert motor.sensors()["overload"] == 0
    hold(motor, 2000)
    assert "burnt" not in motor.active_faults
    hold(motor, 10)
    assert motor.active_faults == {"jam", "burnt"}
    motor.inject("jam", on=False)
    hold(motor, 2000, contactor=1)
    assert motor.state()["speed"] == 0.0  # a burnt motor stays dead until the plant is reset


def test_the_motor_start_stop_project_drives_the_motor_and_stops_on_the_trip() -> None:
    project = EXAMPLES / "motor-start-stop"
    config = PlantConfig(kind="motor", wiring=dict(plant_class("motor").default_wiring))
    loop = ClosedLoop([project / "OB1.awl", project / "symbols.sdf"], config)
    loop.run(100)
    assert loop.plant.state()["speed"] == 0.0
    loop.runtime.operate("start", 1)
    loop.run(100)
    loop.runtime.operate("start", 0)
    loop.run(1500)
    assert loop.plant.state()["speed"] == 100.0
    assert loop.plant.actuators["run_lamp"] == 1
    loop.runtime.inject("jam")
    loop.run(5100)
    # The program saw the overload contact open: contactor off, fault lamp on, nothing burnt.
    assert loop.plant.actuators == {"contactor": 0, "run_lamp": 0, "fault_lamp": 1}
    assert loop.plant.active_faults == {"jam"}
    loop.runtime.inject("jam", on=False)
    loop.runtime.operate("stop", 0)  # pressing stop opens the NC contact
    loop.run(100)
    loop.runtime.operate("stop", 1)
    assert loop.plant.actuators["fault_lamp"] == 0

"""P09 car park: one car per press, the sensor pulses it makes, the full sign that turns cars
away, a car that drives into a full car park, the gate, arrivals by chance that are the same
every run, and the course's corrected car park counter (E-vi-20) agreeing with the real count."""

from __future__ import annotations

from plant_driver import COURSE, ClosedLoop, hold

from nasaq.ir import Area, Direct, Width
from nasaq.plants.car_park import CarPark
from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import PlantConfig


def car(park: CarPark, control: str = "arrive") -> None:
    """The operator sends one car (a press and a release)."""
    park.operate(control, 1)
    hold(park, 10)
    park.operate(control, 0)
    hold(park, 10)


def test_a_car_covers_the_entry_sensor_for_a_second_then_is_inside() -> None:
    park = CarPark()
    car(park)  # the car reached the sensor 20 ms ago
    assert park.sensors()["entry"] == 1
    hold(park, 970)
    assert park.sensors()["entry"] == 1
    hold(park, 20)
    assert park.sensors()["entry"] == 0
    assert park.state()["cars"] == 1
    car(park, "leave")
    assert park.sensors()["exit"] == 1
    assert park.state()["cars"] == 0  # counted out as it drives over the exit sensor
    hold(park, 1000)
    assert park.sensors()["exit"] == 0
    assert park.state()["left"] == 1


def test_cars_pass_one_after_the_other() -> None:
    park = CarPark()
    car(park)
    car(park)
    hold(park, 1000)
    assert park.sensors()["entry"] == 0  # the gap between the two cars
    hold(park, 500)
    assert park.sensors()["entry"] == 1
    hold(park, 1000)
    assert park.state()["cars"] == 2


def test_the_full_sign_turns_cars_away_and_without_it_the_car_park_overfills() -> None:
    park = CarPark({"capacity": 2, "initial": 2})
    park.set_actuators({"full_sign": 1})
    car(park)
    hold(park, 2000)
    assert park.state()["refused"] == 1
    assert park.state()["cars"] == 2
    park.set_actuators({"full_sign": 0})
    car(park)
    hold(park, 2000)
    assert park.state()["cars"] == 3
    assert park.active_faults == {"over_capacity"}


def test_with_a_gate_a_car_waits_on_the_sensor_until_it_opens() -> None:
    park = CarPark({"gate": 1})
    car(park)
    hold(park, 3000)
    assert park.sensors()["entry"] == 1
    assert park.state()["cars"] == 0
    hold(park, 1000, gate=1)
    assert park.state()["cars"] == 1


def test_cars_that_come_by_chance_come_the_same_way_every_run() -> None:
    def run() -> dict[str, object]:
        park = CarPark({"arrive_every_ms": 3000, "leave_every_ms": 5000, "seed": 7})
        hold(park, 120_000)
        return dict(park.state())

    first = run()
    assert first == run()
    assert int(str(first["entered"])) > 20
    assert int(str(first["left"])) > 10


def test_the_course_counter_agrees_with_the_real_count_and_lights_the_sign_at_twelve() -> None:
    base = COURSE / "vi_004" / "e20_car_park"
    config = PlantConfig(kind="car_park", wiring=dict(plant_class("car_park").default_wiring))
    loop = ClosedLoop([base.with_suffix(".awl"), base.with_suffix(".sdf")], config)
    count = Direct(Area.M, Width.WORD, 0)
    for _ in range(14):
        loop.runtime.operate("arrive", 1)
        loop.run(20)
        loop.runtime.operate("arrive", 0)
        loop.run(1600)
    state = loop.plant.state()
    assert state["cars"] == 12
    assert state["refused"] == 2
    assert loop.cpu.read(count) == 12
    assert loop.plant.actuators["full_sign"] == 1
    for _ in range(3):
        loop.runtime.operate("leave", 1)
        loop.run(20)
        loop.runtime.operate("leave", 0)
        loop.run(1600)
    assert loop.plant.state()["cars"] == 9
    assert loop.cpu.read(count) == 9
    assert loop.plant.actuators["full_sign"] == 0
    assert loop.plant.active_faults == set()

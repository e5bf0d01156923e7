"""P06 traffic lights: what counts as a conflict (two flows given way at once) and as dark, cars
that pass on green, and the course's corrected E-vi-44 junction running 3 cycles without fault."""

from __future__ import annotations

from plant_driver import COURSE, ClosedLoop, hold

from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import PlantConfig
from nasaq.plants.traffic_light import TrafficLight


def test_green_against_green_or_running_yellow_is_a_conflict() -> None:
    light = TrafficLight()
    hold(light, 10, green1=1, red2=1)
    assert light.active_faults == set()
    hold(light, 10, green1=0, red1=1, yellow1=0, yellow2=1, red2=1)  # red+yellow: get ready
    assert light.active_faults == set()
    hold(light, 10, red1=0, yellow1=1, yellow2=1, red2=0)  # amber both ways: both still go
    assert light.active_faults == {"conflict"}


def test_pedestrians_on_green_while_direction_1_goes_is_a_conflict() -> None:
    light = TrafficLight()
    hold(light, 10, red1=1, red2=1, ped_green=1)
    assert light.active_faults == set()
    hold(light, 10, red1=0, green1=1)
    assert light.active_faults == {"conflict"}


def test_a_direction_in_service_without_a_lamp_goes_dark_after_the_grace() -> None:
    light = TrafficLight()
    light.operate("run", 1)
    hold(light, 100, red1=1)  # direction 2 shows nothing for 100 ms: still allowed
    assert light.active_faults == set()
    hold(light, 10)
    assert light.active_faults == {"dark"}
    single = TrafficLight({"directions": 1})
    single.operate("run", 1)
    hold(single, 1000, red1=1)
    assert single.active_faults == set()
    out_of_service = TrafficLight()
    hold(out_of_service, 1000)  # run off: a dark (flashing) junction is allowed
    assert out_of_service.active_faults == set()


def test_cars_queue_on_red_and_pass_on_green() -> None:
    light = TrafficLight()
    hold(light, 12000, red1=1, green2=1)
    assert light.state()["queue1"] == 3
    assert light.state()["passed2"] == 2  # 3 arrived at 4/8/12 s, passing takes 2 s each
    hold(light, 6000, red1=0, green1=1, green2=0, red2=1)
    assert light.state()["queue1"] == 1  # one more came, three passed
    assert light.state()["passed1"] == 3


def test_the_corrected_course_junction_runs_three_cycles_without_a_fault() -> None:
    config = PlantConfig(
        kind="traffic_light", wiring=dict(plant_class("traffic_light").default_wiring)
    )
    loop = ClosedLoop([COURSE / "vi_004" / "e44_traffic_light.awl"], config)
    loop.runtime.operate("run", 1)
    seen = set()
    for _ in range(270):
        loop.run(1000)
        a = loop.plant.actuators
        seen.add((a["red1"], a["yellow1"], a["green1"], a["red2"], a["yellow2"], a["green2"]))
    assert loop.plant.active_faults == set()
    assert (0, 0, 1, 1, 0, 0) in seen  # column 1 green, column 2 red
    assert (1, 0, 0, 0, 0, 1) in seen  # column 1 red, column 2 green
    assert loop.plant.state()["passed1"] > 0
    assert loop.plant.state()["passed2"] > 0

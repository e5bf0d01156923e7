"""P07 drilling station: feed speeds and limit switches, the spring-return head of the course's
hydraulic drilling head (E-vi-8) in closed loop, the bit that breaks when fed with the motor off,
and the clamp and coolant pressure switches with their injectable failures."""

from __future__ import annotations

from plant_driver import COURSE, ClosedLoop, hold

from nasaq.plants.drill import Drill
from nasaq.plants.runtime import PlantConfig


def test_the_head_feeds_down_to_the_depth_switch_and_returns_home() -> None:
    drill = Drill()
    assert drill.sensors()["home"] == 1
    hold(drill, 300, motor=1)
    assert drill.sensors()["motor_running"] == 1
    hold(drill, 4990, feed_down=1)  # 20 mm/s: 99.8 mm
    assert drill.sensors()["depth"] == 1  # within half a millimetre of the end
    assert drill.sensors()["home"] == 0
    hold(drill, 100)
    assert drill.state()["position"] == 100.0
    assert drill.state()["holes"] == 1
    hold(drill, 2000, feed_down=0, feed_up=1)  # 50 mm/s
    assert drill.sensors()["home"] == 1
    assert drill.active_faults == set()


def test_feeding_into_the_work_with_the_motor_off_breaks_the_bit() -> None:
    drill = Drill()
    hold(drill, 2000, feed_down=1)  # 40 mm: at the work piece's top
    assert drill.active_faults == set()
    hold(drill, 10)
    assert drill.active_faults == {"broken_bit"}
    hold(drill, 1000)
    assert drill.state()["position"] == 40.0  # it stops there


def test_clamp_and_coolant_pressure_build_unless_they_fail() -> None:
    drill = Drill()
    hold(drill, 290, clamp=1, coolant=1)
    assert drill.sensors()["clamp_ok"] == 0
    assert drill.sensors()["coolant_ok"] == 1
    hold(drill, 10)
    assert drill.sensors()["clamp_ok"] == 1
    drill.inject("clamp_fail")
    drill.inject("coolant_fail")
    assert drill.sensors()["clamp_ok"] == 0
    assert drill.sensors()["coolant_ok"] == 0


def test_the_course_drilling_head_drills_one_hole_per_start() -> None:
    wiring = {"start": "I0.0", "stop": "I0.1", "home": "I0.2", "depth": "I0.3", "feed_down": "Q0.0"}
    config = PlantConfig(kind="drill", wiring=wiring, params={"spring_return": 1, "motor_check": 0})
    base = COURSE / "vi_004" / "e08_drilling_head"
    loop = ClosedLoop([base.with_suffix(".awl"), base.with_suffix(".sdf")], config)
    loop.runtime.operate("start", 1)
    loop.run(200)
    loop.runtime.operate("start", 0)
    loop.run(4600)
    assert loop.plant.actuators["feed_down"] == 1
    loop.run(500)  # depth reached: 1Y resets, the spring lifts the head
    assert loop.plant.actuators["feed_down"] == 0
    loop.run(2100)
    assert loop.plant.inputs()["home"] == 1
    assert loop.plant.state()["holes"] == 1
    assert loop.plant.active_faults == set()

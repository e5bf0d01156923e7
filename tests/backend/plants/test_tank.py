"""P03 tank: the rates a learner computes with, the level switches, the analog word, overflow,
the injectable sensor faults, and the course's two-point level control in closed loop."""

from __future__ import annotations

import pytest
from plant_driver import EXAMPLES, ClosedLoop, hold

from nasaq.plants.base import PlantError
from nasaq.plants.runtime import PlantConfig
from nasaq.plants.tank import Tank


def test_the_pump_fills_at_its_rate_and_the_transmitter_reads_the_level() -> None:
    tank = Tank()  # 10 %, pump 5 %/s
    hold(tank, 4000, pump=1)
    assert tank.state()["level"] == pytest.approx(30.0)
    assert tank.sensors()["level"] == round(0.30 * 27648)
    hold(tank, 2000, pump=0, drain_valve=1)  # 4 %/s out
    assert tank.state()["level"] == pytest.approx(22.0)
    hold(tank, 1000, pump=1, fill_valve=1, drain_valve=1)  # 5 + 2.5 - 4
    assert tank.state()["level"] == pytest.approx(25.5)


def test_the_low_probe_closes_at_its_level_and_opens_below_the_hysteresis() -> None:
    tank = Tank({"initial": 15.0})
    hold(tank, 990, pump=1)  # 19.95 %
    assert tank.sensors()["ls_low"] == 0
    hold(tank, 10)  # 20 %
    assert tank.sensors()["ls_low"] == 1
    hold(tank, 200, pump=0, drain_valve=1)  # 19.2 %: inside the 1 % hysteresis
    assert tank.sensors()["ls_low"] == 1
    hold(tank, 100)  # 18.8 %
    assert tank.sensors()["ls_low"] == 0


def test_the_full_switch_trips_at_its_level_and_a_full_tank_overflows() -> None:
    tank = Tank({"initial": 85.0})
    hold(tank, 990, pump=1)
    assert tank.sensors()["ls_high"] == 0
    hold(tank, 10)  # 90 %
    assert tank.sensors()["ls_high"] == 1
    assert tank.active_faults == set()
    hold(tank, 3000)  # 100 % and still pumping for 1 s
    assert tank.state()["level"] == 100.0
    assert tank.active_faults == {"overflow"}
    assert tank.state()["spilled"] > 0
    hold(tank, 1000, pump=0)
    assert tank.active_faults == {"overflow"}  # water on the floor stays a fault
    tank.reset()
    tank.active_faults.clear()
    assert tank.state()["level"] == 85.0


def test_the_level_never_goes_below_empty() -> None:
    tank = Tank({"initial": 2.0})
    hold(tank, 3000, drain_valve=1)
    assert tank.state()["level"] == 0.0
    assert tank.sensors()["level"] == 0
    assert tank.state()["draining"] is False


def test_a_stuck_full_switch_and_a_broken_transmitter_wire() -> None:
    tank = Tank({"initial": 95.0})
    assert tank.sensors()["ls_high"] == 1
    tank.inject("ls_high_stuck")
    assert tank.sensors()["ls_high"] == 0
    tank.inject("level_wire_break")
    assert tank.sensors()["level"] == 32767
    tank.inject("level_wire_break", on=False)
    assert tank.sensors()["level"] == round(0.95 * 27648)
    with pytest.raises(PlantError) as raised:
        tank.inject("overflow")  # raised by the process, not injectable
    assert raised.value.code == "PLT010"


def test_parameters_are_checked() -> None:
    with pytest.raises(PlantError) as unknown:
        Tank({"size": 3})
    assert unknown.value.code == "PLT008"
    assert unknown.value.subject == ("params", "size")
    with pytest.raises(PlantError) as outside:
        Tank({"initial": 120})
    assert outside.value.code == "PLT009"


def test_the_example_two_point_control_cycles_the_level_between_its_limits() -> None:
    """examples/projects/tank-level (pump on below 20 %, off at 80 %) with consumers taking
    water: the level stays in the band, never overflows."""
    project = EXAMPLES / "tank-level"
    files = [project / n for n in ("OB1.awl", "TankSettings.awl", "LevelData.awl", "Scale.scl")]
    files += [project / "LevelControl.scl", project / "symbols.sdf"]
    wiring = {"auto": "I0.0", "level": "IW64", "pump": "Q4.0", "alarm": "Q4.1"}
    loop = ClosedLoop(files, PlantConfig(kind="tank", wiring=wiring, params={"use_rate": 2}))
    loop.runtime.operate("auto", 1)
    levels = []
    for _ in range(60):
        loop.run(1000)
        levels.append(loop.plant.state()["level"])
    assert min(levels[10:]) >= 19.0
    assert max(levels) <= 81.0
    assert max(levels) > 78.0  # it did fill up to the high limit
    assert loop.plant.active_faults == set()

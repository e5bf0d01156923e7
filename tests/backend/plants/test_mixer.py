"""P08 + P17 mixer with heating: filling and the level switches, the thermal model (heating rate,
losses, the thermostat and the analog temperature), the faults a check expects (dry heating,
overheat, a broken heater) and the course's paint stirrer mixing its batch in 2 min 30 s."""

from __future__ import annotations

import pytest
from plant_driver import COURSE, ClosedLoop, hold

from nasaq.plants.mixer import Mixer
from nasaq.plants.runtime import PlantConfig


def test_the_vessel_fills_and_drains_at_its_rates() -> None:
    mixer = Mixer()
    assert mixer.sensors()["empty"] == 1
    hold(mixer, 18_990, fill_valve=1)  # 5 %/s
    assert mixer.sensors()["full"] == 0
    hold(mixer, 10)  # 95 %
    assert mixer.sensors()["full"] == 1
    assert mixer.sensors()["empty"] == 0
    hold(mixer, 10_000, fill_valve=0, drain_valve=1)
    assert mixer.state()["volume"] == pytest.approx(45.0)


def test_a_full_vessel_heats_at_about_a_degree_a_second_and_reports_it() -> None:
    mixer = Mixer({"initial": 100, "loss": 0})
    hold(mixer, 30_000, heater=1)
    assert mixer.state()["temperature"] == pytest.approx(50.0)
    assert mixer.sensors()["temperature"] == round(0.5 * 27648)
    assert mixer.sensors()["hot"] == 0
    hold(mixer, 10_000)
    assert mixer.sensors()["hot"] == 1  # 60 °C setpoint
    half = Mixer({"initial": 50, "loss": 0})
    hold(half, 10_000, heater=1)
    assert half.state()["temperature"] == pytest.approx(40.0)  # half the liquid: twice as fast


def test_the_vessel_cools_towards_the_room() -> None:
    mixer = Mixer({"initial": 100})
    hold(mixer, 40_000, heater=1)
    hot = mixer.state()["temperature"]
    hold(mixer, 60_000, heater=0)
    cooled = mixer.state()["temperature"]
    assert 20.0 < cooled < hot


def test_heating_an_empty_vessel_and_boiling_are_faults() -> None:
    dry = Mixer()
    hold(dry, 10, heater=1)
    assert dry.active_faults == {"dry_heating"}
    boiling = Mixer({"initial": 100, "loss": 0})
    hold(boiling, 75_000, heater=1)
    assert boiling.active_faults == set()
    hold(boiling, 100)
    assert boiling.active_faults == {"overheat"}


def test_a_broken_heater_gives_no_heat() -> None:
    mixer = Mixer({"initial": 100})
    mixer.inject("heater_broken")
    hold(mixer, 10_000, heater=1)
    assert mixer.state()["temperature"] == 20.0
    assert mixer.state()["heating"] is False


def test_the_course_paint_stirrer_mixes_its_batch() -> None:
    base = COURSE / "vi_004" / "e27_paint_stirrer"
    config = PlantConfig(
        kind="mixer", wiring={"start": "I0.0", "stirrer": "Q0.0"}, params={"initial": 80}
    )
    loop = ClosedLoop([base.with_suffix(".awl"), base.with_suffix(".sdf")], config)
    loop.runtime.operate("start", 1)
    loop.run(200)
    loop.runtime.operate("start", 0)
    loop.run(140_000)
    assert loop.plant.actuators["stirrer"] == 1
    assert 90.0 < loop.plant.state()["mixed"] < 100.0
    loop.run(20_000)
    assert loop.plant.actuators["stirrer"] == 0
    assert loop.plant.state()["mixed"] == 100.0

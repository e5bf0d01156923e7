"""P01 push-button panel: NO and NC buttons, the contactor's pull-in delay and auxiliary contact,
the broken wire of S1, and the course's AND gate driving K1."""

from __future__ import annotations

from plant_driver import COURSE, ClosedLoop, hold

from nasaq.plants.panel import Panel
from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import PlantConfig


def test_buttons_are_no_unless_the_mask_makes_them_nc() -> None:
    panel = Panel({"nc_mask": 0b00010})  # S2 is NC
    assert panel.inputs()["s1"] == 0
    assert panel.inputs()["s2"] == 1
    panel.operate("s2", 0)  # pressed
    assert panel.state()["s2_pressed"] is True
    assert panel.state()["s1_pressed"] is False


def test_k1_pulls_in_after_its_delay_and_shows_on_its_auxiliary_contact() -> None:
    panel = Panel()
    hold(panel, 10, k1=1)
    assert panel.sensors()["k1_aux"] == 0
    hold(panel, 10)
    assert panel.sensors()["k1_aux"] == 1
    assert panel.state()["k1"] is True
    hold(panel, 10, k1=0)
    assert panel.sensors()["k1_aux"] == 1  # drops out as late
    hold(panel, 10)
    assert panel.sensors()["k1_aux"] == 0


def test_a_broken_wire_reads_zero_whatever_the_button_does() -> None:
    panel = Panel({"nc_mask": 1})  # S1 NC, as a stop button
    assert panel.inputs()["s1"] == 1
    panel.inject("wire_break")
    assert panel.inputs()["s1"] == 0  # looks pressed: the NC wiring fails safe
    assert panel.state()["s1_pressed"] is False


def test_the_and_gate_of_the_course_pulls_k1_in_only_with_all_three_buttons() -> None:
    config = PlantConfig(kind="panel", wiring=dict(plant_class("panel").default_wiring))
    loop = ClosedLoop([COURSE / "ar_000" / "e01_and_gate.awl"], config)
    loop.runtime.operate("s1", 1)
    loop.runtime.operate("s2", 1)
    loop.run(100)
    assert loop.plant.state()["k1"] is False
    loop.runtime.operate("s3", 1)
    loop.run(100)
    assert loop.plant.state()["k1"] is True
    assert loop.plant.inputs()["k1_aux"] == 1

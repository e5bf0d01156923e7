"""P20 shrink-wrap line: packs move conveyor to conveyor and queue where one stands, the tunnel
heats up, and the time in the hot tunnel decides raw, good or burnt packs."""

from __future__ import annotations

import pytest

from nasaq.plants.shrink_wrap import ShrinkWrap


def run(plant: ShrinkWrap, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_the_tunnel_heats_to_shrinking_temperature_in_about_thirteen_seconds() -> None:
    line = ShrinkWrap()
    run(line, 12_500, heater=1)  # 150 °C at 10 s x ln(180 / 50) = 12.8 s
    assert line.sensors()["tunnel_hot"] == 0
    run(line, 500)
    assert line.sensors()["tunnel_hot"] == 1
    run(line, 30_000, heater=0)
    assert line.sensors()["tunnel_hot"] == 0


def test_packs_queue_at_the_end_of_a_stopped_conveyor() -> None:
    line = ShrinkWrap()
    run(line, 20_000, conveyor_a=1)
    assert line.sensors()["eye_a"] == 1
    assert line.front[: line.count] == pytest.approx([1000, 800, 600, 400, 200, 0])
    run(line, 1000, conveyor_b=1)
    assert line.sensors()["eye_a"] == 1  # the next pack moved up to the eye
    assert line.state()["packs_on_line"] == 7  # and a new one came on at the start


def test_all_conveyors_running_with_a_hot_tunnel_make_good_packs() -> None:
    line = ShrinkWrap()
    run(line, 25_000, heater=1)
    run(line, 40_000, heater=1, conveyor_a=1, conveyor_b=1, conveyor_c=1)
    state = line.state()
    assert state["packs_done"] >= 8
    assert state["packs_good"] >= 8
    assert line.active_faults == set()


def test_packs_through_a_cold_tunnel_come_out_raw() -> None:
    line = ShrinkWrap()
    run(line, 12_000, conveyor_a=1, conveyor_b=1, conveyor_c=1)
    assert line.active_faults == {"raw_pack"}
    assert line.state()["packs_raw"] >= 1


def test_a_pack_left_standing_in_the_hot_tunnel_burns() -> None:
    line = ShrinkWrap()
    run(line, 25_000, heater=1)
    run(line, 7500, heater=1, conveyor_a=1, conveyor_b=1)  # first pack in the tunnel
    assert line.active_faults == set()
    run(line, 9000, conveyor_a=0, conveyor_b=0)
    assert line.active_faults == {"burnt_pack"}
    assert line.state()["packs_burnt"] == 1

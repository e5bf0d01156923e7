"""P05 packaging line: boxes stop at SS1, pieces fall through SS2 into them, and the course's
corrected E-vi-37 program fills boxes of ten in closed loop; the book's version overfills."""

from __future__ import annotations

from pathlib import Path

import pytest
from plant_driver import COURSE, CourseLoop

from nasaq.plants.base import PlantError
from nasaq.plants.packaging_line import PackagingLine


def run(plant: PackagingLine, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_a_box_reaches_the_box_sensor_after_two_seconds_of_belt() -> None:
    plant = PackagingLine()
    assert plant.sensors()["box_eye"] == 0
    run(plant, 1990, box_conveyor=1)
    assert plant.sensors()["box_eye"] == 0
    run(plant, 20)
    assert plant.sensors()["box_eye"] == 1


def test_a_piece_falls_through_the_eye_each_second_and_lands_in_the_box() -> None:
    plant = PackagingLine()
    run(plant, 2000, box_conveyor=1)
    run(plant, 990, box_conveyor=0, piece_conveyor=1)
    assert plant.sensors()["piece_eye"] == 0
    run(plant, 20)
    assert plant.sensors()["piece_eye"] == 1
    assert plant.state()["box_pieces"] == 0  # still falling
    run(plant, 200)
    assert plant.sensors()["piece_eye"] == 0
    assert plant.state()["box_pieces"] == 1
    assert plant.active_faults == set()


def test_a_piece_with_no_box_below_is_spilled() -> None:
    plant = PackagingLine()
    run(plant, 1300, piece_conveyor=1)
    assert plant.state()["pieces_spilled"] == 1
    assert plant.active_faults == {"spill"}


def test_an_eleventh_piece_overfills_the_box() -> None:
    plant = PackagingLine()
    run(plant, 2000, box_conveyor=1)
    run(plant, 10_300, box_conveyor=0, piece_conveyor=1)
    assert plant.state()["box_pieces"] == 10
    assert plant.active_faults == set()
    run(plant, 1000)
    assert plant.state()["box_pieces"] == 11
    assert plant.active_faults == {"overfill"}


def test_a_box_leaving_before_it_is_full_counts_short() -> None:
    plant = PackagingLine()
    run(plant, 4000, box_conveyor=1)
    assert plant.state()["boxes_short"] == 1
    assert plant.state()["boxes_full"] == 0


def test_deadlock_when_started_and_both_belts_stand_still() -> None:
    plant = PackagingLine()
    run(plant, 6000)  # not started: standing still is fine
    assert plant.active_faults == set()
    plant.operate("start", 1)
    run(plant, 100)
    plant.operate("start", 0)
    run(plant, 4800)  # 4.9 s since Start
    assert plant.active_faults == set()
    run(plant, 200)
    assert plant.active_faults == {"deadlock"}


def test_stop_ends_the_run_so_standing_still_is_no_deadlock() -> None:
    plant = PackagingLine()
    plant.operate("start", 1)
    run(plant, 100)
    plant.operate("start", 0)
    plant.operate("stop", 0)
    run(plant, 100)
    plant.operate("stop", 1)
    run(plant, 10_000)
    assert plant.active_faults == set()


def test_inconsistent_geometry_is_refused_naming_the_parameter() -> None:
    with pytest.raises(PlantError, match="box_pitch") as caught:
        PackagingLine({"box_pitch": 150})
    assert caught.value.subject == ("params", "box_pitch")  # a plant file can point at its line


def test_course_program_fills_boxes_of_ten_in_closed_loop() -> None:
    loop = CourseLoop("vi_004/e37_packaging_line", "packaging_line")
    loop.run(1000)
    assert loop.plant.state()["box_position"] == -200  # nothing runs before Start
    loop.press("start")
    loop.run(60_000)
    state = loop.plant.state()
    assert state["boxes_full"] >= 3
    assert state["boxes_short"] == 0
    assert state["pieces_spilled"] == 0
    assert loop.runtime.faults() == []
    loop.press("stop")
    landed = state["pieces_landed"]
    loop.run(5000)
    assert loop.plant.state()["pieces_landed"] <= landed + 1  # at most the piece in the air


def test_book_program_with_c12_overfills_the_box(tmp_path: Path) -> None:
    """The book's preset C#12 (L2258-2336) instead of C#10: the plant catches the 11th piece."""
    source = (COURSE / "vi_004/e37_packaging_line.awl").read_text(encoding="utf-8")
    wrong = tmp_path / "vi_004"
    wrong.mkdir()
    (wrong / "e37_c12.awl").write_text(source.replace("C#10", "C#12"), encoding="utf-8")
    (wrong / "e37_c12.sdf").write_text(
        (COURSE / "vi_004/e37_packaging_line.sdf").read_text(encoding="utf-8"),
        encoding="utf-8",
    )
    loop = CourseLoop(str(wrong / "e37_c12"), "packaging_line")
    loop.press("start")
    loop.run(30_000)
    assert "overfill" in loop.runtime.faults()


def test_a_blinded_piece_eye_lets_the_course_program_overfill() -> None:
    loop = CourseLoop("vi_004/e37_packaging_line", "packaging_line")
    loop.runtime.inject("piece_eye_stuck")
    loop.press("start")
    loop.run(16_000)
    assert loop.plant.sensors()["piece_eye"] == 0
    assert "overfill" in loop.runtime.faults()

"""P16 servo-valve piston: speed proportional to the analog output word (27648 = 10 V), signed
for both directions, the position word fed back, and an end hit at speed."""

from __future__ import annotations

from plant_driver import CourseLoop

from nasaq.ir import Area, Direct, Width
from nasaq.plants.servo_piston import ServoPiston


def run(plant: ServoPiston, ms: int, **actuators: int) -> None:
    plant.set_actuators(actuators)
    for _ in range(ms // 10):
        plant.advance(10)


def test_half_scale_moves_at_half_speed() -> None:
    piston = ServoPiston()
    run(piston, 2000, speed=13824)
    assert piston.state()["position"] == 100  # 50 mm/s for 2 s
    assert piston.state()["flow"] == 50  # l/min
    assert piston.sensors() == {"position": 5530}  # 100 of 500 mm


def test_a_negative_word_drives_the_piston_back() -> None:
    piston = ServoPiston({"start_position": 250})
    run(piston, 1000, speed=(-13824) & 0xFFFF)  # the PLC's INT as the output word holds it
    assert piston.state()["position"] == 200


def test_hitting_the_end_at_speed_is_a_fault_creeping_in_is_not() -> None:
    fast = ServoPiston({"start_position": 450})
    run(fast, 2000, speed=27648)
    assert fast.active_faults == {"end_stop"}
    assert fast.state()["position"] == 500
    slow = ServoPiston({"start_position": 495})
    run(slow, 2000, speed=2000)  # 7 mm/s
    assert slow.active_faults == set()
    assert slow.state()["at_end"] is True


def test_pushing_on_from_standstill_at_the_end_is_no_fault() -> None:
    piston = ServoPiston()
    run(piston, 1000, speed=(-27648) & 0xFFFF)
    assert piston.active_faults == set()
    assert piston.state()["position"] == 0


def test_course_program_moves_mw0_to_the_valve() -> None:
    loop = CourseLoop("vi_004/e15_servo_valve", "servo_piston")
    loop.cpu.write(Direct(Area.M, Width.WORD, 0, None), 13824)  # the keypad's value
    loop.run(2000)
    assert loop.plant.state()["speed"] == 50
    assert 95 <= loop.plant.state()["position"] <= 100

"""P18 sorting conveyor: objects ride past the eyes, the gate or the pusher decides their exit,
wrong exits are faults; the order of colours/heights is fixed by the seed."""

from __future__ import annotations

from nasaq.plants.sorter import Sorter


def colour_controller(plant: Sorter, ms: int) -> None:
    """Gate to exit 2 from a red ball at the eyes until a green one comes (one ball at a time
    rides between the eyes and the gate)."""
    plant.set_actuators({"conveyor": 1})
    for _ in range(ms // 10):
        eyes = plant.sensors()
        if eyes["red_eye"]:
            plant.set_actuators({"gate": 1})
        elif eyes["green_eye"]:
            plant.set_actuators({"gate": 0})
        plant.advance(10)


def height_controller(plant: Sorter, ms: int, delay_ms: int = 3900) -> None:
    """A low part (low eye without the high eye) is pushed ``delay_ms`` after it is seen."""
    plant.set_actuators({"conveyor": 1})
    seen_low = False
    push_at: list[int] = []
    for k in range(ms // 10):
        now = k * 10
        eyes = plant.sensors()
        low = bool(eyes["low_eye"] and not eyes["high_eye"])
        if low and not seen_low:
            push_at.append(now + delay_ms)
        seen_low = low if eyes["low_eye"] else False
        pushing = any(at <= now < at + 500 for at in push_at)
        plant.set_actuators({"pusher": int(pushing)})
        plant.advance(10)


def test_balls_sorted_by_colour_reach_their_exits() -> None:
    plant = Sorter()
    colour_controller(plant, 60_000)
    state = plant.state()
    assert state["good"] >= 10
    assert state["missorted"] == 0
    assert state["exit1"] > 0
    assert state["exit2"] > 0
    assert plant.active_faults == set()


def test_a_gate_that_never_turns_sends_red_balls_to_the_wrong_exit() -> None:
    plant = Sorter()
    plant.set_actuators({"conveyor": 1})
    for _ in range(6000):
        plant.advance(10)
    assert plant.state()["exit2"] == 0
    assert plant.state()["missorted"] > 0
    assert plant.active_faults == {"missorted"}


def test_eyes_see_balls_of_their_colour_only() -> None:
    plant = Sorter()
    plant.set_actuators({"conveyor": 1})
    seen = {"green_eye": 0, "red_eye": 0, "high_eye": 0, "low_eye": 0}
    for _ in range(3000):
        plant.advance(10)
        eyes = plant.sensors()
        assert not (eyes["green_eye"] and eyes["red_eye"])
        for name in seen:
            seen[name] += eyes[name]
    assert seen["green_eye"] > 0
    assert seen["red_eye"] > 0
    assert seen["high_eye"] == seen["low_eye"] == 0


def test_low_parts_pushed_off_in_time_high_parts_pass() -> None:
    plant = Sorter({"by_height": 1})
    height_controller(plant, 60_000)
    state = plant.state()
    assert state["good"] >= 10
    assert state["missorted"] == 0
    assert plant.active_faults == set()


def test_a_pusher_that_fires_too_late_misses_the_low_part() -> None:
    plant = Sorter({"by_height": 1})
    height_controller(plant, 30_000, delay_ms=4600)
    assert "missorted" in plant.active_faults


def test_the_order_of_objects_depends_only_on_the_seed() -> None:
    def order(seed: int) -> list[str]:
        plant = Sorter({"seed": seed})
        plant.set_actuators({"conveyor": 1})
        seen: list[str] = []
        for _ in range(10_000):
            plant.advance(10)
            if plant.state()["last"] and (not seen or plant.state()["last"] != seen[-1]):
                seen.append(str(plant.state()["last"]))
        return seen

    assert order(1) == order(1)
    assert order(1) != order(2)


def test_the_belt_stands_still_with_the_conveyor_off() -> None:
    plant = Sorter()
    for _ in range(1000):
        plant.advance(10)
    assert plant.state()["objects_in"] == 1
    assert plant.sensors()["exit_eye"] == 0

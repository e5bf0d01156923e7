"""P22 bank of one to three pneumatic cylinders (seed 001: the magazine pusher of program 1,
clamp / bend / bend of program 5).

Each cylinder has a single-solenoid valve with spring return: valve on -> the piston extends,
off -> it retracts, ``stroke_ms`` for a full stroke either way. ``cN_home`` reads 1 with the
piston fully in, ``cN_end`` with it fully out. A stroke counts once the piston reaches its end
(``cN_strokes``); a valve pulse too short for that is a ``cN_short`` stroke (the piece is not
pushed, bent or clamped). ``count`` says how many cylinders are fitted; the signals of missing
ones read 0 and their valves do nothing.

The default wiring is the three outputs of program 5 (P013-P015 -> Q0.3-Q0.5); program 1's
single pusher (P010) is wired ``v1: Q0.0`` with ``count: 1``. The end switches are not used by
the paper's programs and sit on I1.0-I1.5.
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Plant, PlantError, Signal, StateValue

_NAMES = ("c1", "c2", "c3")
_VALVES = ("v1", "v2", "v3")
_HOME = ("c1_home", "c2_home", "c3_home")
_END = ("c1_end", "c2_end", "c3_end")
_STATE = tuple((f"{n}_position", f"{n}_strokes", f"{n}_short") for n in _NAMES)


class Cylinders(Plant):
    kind = "cylinders"
    title = "Pneumatic cylinders"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("c1_home", "sensor", description="Cylinder 1 retracted"),
        Signal("c1_end", "sensor", description="Cylinder 1 extended"),
        Signal("c2_home", "sensor", description="Cylinder 2 retracted"),
        Signal("c2_end", "sensor", description="Cylinder 2 extended"),
        Signal("c3_home", "sensor", description="Cylinder 3 retracted"),
        Signal("c3_end", "sensor", description="Cylinder 3 extended"),
        Signal("v1", "actuator", description="Valve of cylinder 1 (spring return)"),
        Signal("v2", "actuator", description="Valve of cylinder 2 (spring return)"),
        Signal("v3", "actuator", description="Valve of cylinder 3 (spring return)"),
    )
    defaults: ClassVar[dict[str, float]] = {"count": 3, "stroke_ms": 500}
    limits: ClassVar[dict[str, tuple[float, float]]] = {"count": (1, 3), "stroke_ms": (10, 10000)}
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "v1": "Q0.3",
        "v2": "Q0.4",
        "v3": "Q0.5",
        "c1_home": "I1.0",
        "c1_end": "I1.1",
        "c2_home": "I1.2",
        "c2_end": "I1.3",
        "c3_home": "I1.4",
        "c3_end": "I1.5",
    }

    def reset(self) -> None:
        if self.params["count"] != int(self.params["count"]):
            raise PlantError("cylinders: count is 1, 2 or 3", "PLT020", ("params", "count"))
        self.count = int(self.params["count"])
        self.position = [0.0, 0.0, 0.0]  # 0 = in, 1 = out
        self.strokes = [0, 0, 0]
        self.short = [0, 0, 0]
        self.reached = [False, False, False]  # this stroke got to the end
        self.moving_out = [False, False, False]

    def step(self, dt_ms: int) -> None:
        delta = dt_ms / self.params["stroke_ms"]
        for i in range(self.count):
            position = self.position[i]
            if self.actuators[_VALVES[i]]:
                self.moving_out[i] = True
                position = min(1.0, position + delta)
                if position >= 1.0 and not self.reached[i]:
                    self.reached[i] = True
                    self.strokes[i] += 1
            else:
                if self.moving_out[i] and not self.reached[i]:
                    self.short[i] += 1
                self.moving_out[i] = False
                position = max(0.0, position - delta)
                if position <= 0.0:
                    self.reached[i] = False
            self.position[i] = position

    def sensors(self) -> dict[str, int]:
        values: dict[str, int] = {}
        for i in range(3):
            fitted = i < self.count
            values[_HOME[i]] = int(fitted and self.position[i] <= 0.0)
            values[_END[i]] = int(fitted and self.position[i] >= 1.0)
        return values

    def state(self) -> dict[str, StateValue]:
        values: dict[str, StateValue] = {"count": self.count}
        for i, (position, strokes, short) in enumerate(_STATE):
            values[position] = round(self.position[i] * 100)
            values[strokes] = self.strokes[i]
            values[short] = self.short[i]
        return values

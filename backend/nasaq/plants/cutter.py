"""P10 cut-to-length machine (seed 004, E-vi-7, Fig 3.3).

A friction wheel feeds a steel bar past a knife. ``bar_position`` is how far (mm) the bar's
front sticks out beyond the knife; the dimension sensor SS1 sits ``length`` mm beyond the knife
and reads 1 while the bar reaches it. The wheel accelerates the bar to ``feed_speed``; with the
wheel off the bar coasts (slowly, friction only) or, with the brake on, stops within a few mm.
That is why the book brakes: without the brake the pieces come out too long.

The knife moves down while its valve is on and back up while it is off, ``knife_ms`` per
stroke. It touches the bar at ``contact`` (0..1 of the stroke); at the bottom the piece is cut
off and SS2 (cut finished) reads 1. ``knife_home`` reads 1 with the knife fully up.

Faults: ``wrong_length`` a piece was cut more than ``tolerance`` mm off ``length``;
``knife_collision`` the bar moved while the knife was in it; ``brake_drag`` the wheel drove
against the applied brake.
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue


class Cutter(Plant):
    kind = "cutter"
    title = "Cut-to-length machine"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("dimension_eye", "sensor", description="SS1: the bar has reached the cut length"),
        Signal("cut_done", "sensor", description="SS2: the knife is at the bottom, cut finished"),
        Signal("knife_home", "sensor", description="The knife is fully up"),
        Signal("wheel", "actuator", description="Friction-wheel motor feeding the bar"),
        Signal("brake", "actuator", description="Motor brake"),
        Signal("knife", "actuator", description="Knife valve: 1 = knife moves down"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("wrong_length", description="A piece was cut too long or too short"),
        Fault("knife_collision", description="The bar moved while the knife was in it"),
        Fault("brake_drag", description="The wheel motor drove against the brake"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "length": 500.0,  # mm: where SS1 sits, the length the pieces must have
        "tolerance": 10.0,  # mm
        "feed_speed": 200.0,  # mm/s
        "accel": 1000.0,  # mm/s² while the wheel drives
        "coast_decel": 200.0,  # mm/s² with the wheel off and no brake
        "brake_decel": 5000.0,  # mm/s² with the brake on
        "knife_ms": 500,  # one knife stroke, down or up
        "contact": 0.6,  # part of the stroke where the knife touches the bar
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "length": (10, 10000),
        "tolerance": (0, 1000),
        "feed_speed": (1, 5000),
        "accel": (1, 100000),
        "coast_decel": (1, 100000),
        "brake_decel": (1, 100000),
        "knife_ms": (10, 10000),
        "contact": (0.05, 0.95),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "dimension_eye": "I0.1",
        "cut_done": "I0.2",
        "knife_home": "I0.3",
        "wheel": "Q0.0",
        "brake": "Q0.1",
        "knife": "Q0.2",
    }

    def reset(self) -> None:
        self.bar = 0.0  # mm beyond the knife
        self.speed = 0.0  # mm/s
        self.knife_pos = 0.0  # 0 = up, 1 = down
        self.cut_this_stroke = False
        self.pieces = 0
        self.wrong_pieces = 0
        self.last_length = 0.0

    def step(self, dt_ms: int) -> None:
        p = self.params
        act = self.actuators
        seconds = dt_ms / 1000
        if act["wheel"] and act["brake"]:
            self.raise_fault("brake_drag")
        if act["wheel"] and not act["brake"]:
            self.speed = min(p["feed_speed"], self.speed + p["accel"] * seconds)
        else:
            decel = p["brake_decel"] if act["brake"] else p["coast_decel"]
            self.speed = max(0.0, self.speed - decel * seconds)
        if self.speed > 0:
            self.bar += self.speed * seconds
            if self.knife_pos >= p["contact"] and self.bar > 0:
                self.raise_fault("knife_collision")
        stroke = dt_ms / p["knife_ms"]
        if act["knife"]:
            self.knife_pos = min(1.0, self.knife_pos + stroke)
            if self.knife_pos >= 1.0 and not self.cut_this_stroke:
                self.cut_this_stroke = True
                self._cut()
        else:
            self.knife_pos = max(0.0, self.knife_pos - stroke)
            if self.knife_pos <= 0.0:
                self.cut_this_stroke = False

    def _cut(self) -> None:
        if self.bar <= 0:
            return
        self.last_length = self.bar
        self.pieces += 1
        self.bar = 0.0
        if abs(self.last_length - self.params["length"]) > self.params["tolerance"]:
            self.wrong_pieces += 1
            self.raise_fault("wrong_length")

    def sensors(self) -> dict[str, int]:
        return {
            "dimension_eye": int(self.bar >= self.params["length"]),
            "cut_done": int(self.knife_pos >= 1.0),
            "knife_home": int(self.knife_pos <= 0.0),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "bar_position": round(self.bar, 1),
            "bar_speed": round(self.speed, 1),
            "knife_position": round(self.knife_pos * 100, 1),
            "pieces": self.pieces,
            "wrong_pieces": self.wrong_pieces,
            "last_length": round(self.last_length, 1),
        }

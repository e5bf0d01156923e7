"""P05 counting and packaging line (seed 004, E-vi-37, Fig 3.19).

The box conveyor BT1 brings empty boxes to the filling place, where the box sensor SS1 sees
them. The piece conveyor BT2 carries pieces at a fixed pitch; at its end a piece falls into the
box below, through the infrared piece sensor SS2 (1 while a piece is falling), so the sensor
counts what actually goes into the box. A box holds ``box_capacity`` pieces (10 in the book).

Geometry in mm along BT1, the box sensor at 0: a box covers the sensor while its front edge is
in [0, box_length); pieces land at ``-box_length / 2`` (the middle of a box that just stopped at
the sensor), so a box that stops one scan late still catches them. A box is gone once its front
passes ``box_length``; the next box follows ``box_pitch`` behind. Supply of boxes and pieces is
endless, as on the book's figure.

Faults: ``spill`` a piece landed where no box was; ``overfill`` a piece landed in a full box
(the book's C#12 and its interlock deadlock both end here); ``deadlock`` the line was started
and not stopped, yet both belts stood still for ``deadlock_ms`` (nothing can move any more).
Injectable: ``piece_eye_stuck`` (SS2 blinded: pieces fall uncounted, a box overfills unless the
program also watches the time).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue


class PackagingLine(Plant):
    kind = "packaging_line"
    title = "Counting and packaging line"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button (NO)"),
        Signal("stop", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("box_eye", "sensor", description="SS1: 1 while a box is at the filling place"),
        Signal("piece_eye", "sensor", description="SS2: 1 while a piece falls into the box"),
        Signal("box_conveyor", "actuator", description="BT1: box conveyor motor"),
        Signal("piece_conveyor", "actuator", description="BT2: piece conveyor motor"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("spill", description="A piece fell where there was no box"),
        Fault("overfill", description="A piece fell into a box that was already full"),
        Fault("deadlock", description="The line runs, but both conveyors stand still"),
        Fault("piece_eye_stuck", injectable=True, description="SS2 is blinded: it reads 0"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "box_capacity": 10,
        "box_speed": 100.0,  # mm/s
        "box_length": 200.0,  # mm
        "box_pitch": 400.0,  # mm from one box front to the next
        "piece_speed": 100.0,  # mm/s
        "piece_pitch": 100.0,  # mm between pieces on BT2: one piece a second
        "fall_ms": 200,  # a piece falls this long through SS2 before it lands
        "deadlock_ms": 5000,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "box_capacity": (1, 100),
        "box_speed": (1, 1000),
        "box_length": (10, 2000),
        "box_pitch": (20, 5000),
        "piece_speed": (1, 1000),
        "piece_pitch": (5, 2000),
        "fall_ms": (10, 2000),
        "deadlock_ms": (100, 600000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "box_eye": "I0.2",
        "piece_eye": "I0.3",
        "box_conveyor": "Q0.0",
        "piece_conveyor": "Q0.1",
    }

    def reset(self) -> None:
        p = self.params
        if p["box_pitch"] <= p["box_length"]:
            raise PlantError(
                "packaging_line: box_pitch must exceed box_length",
                "PLT020",
                ("params", "box_pitch"),
            )
        if p["piece_pitch"] / p["piece_speed"] * 1000 <= p["fall_ms"]:
            raise PlantError(
                "packaging_line: a piece must land before the next one falls",
                "PLT020",
                ("params", "fall_ms"),
            )
        self.capacity = int(p["box_capacity"])
        self.box_front = -p["box_pitch"] / 2  # the first box waits upstream
        self.box_pieces = 0
        self.piece_gap = p["piece_pitch"]  # mm until the next piece reaches the end of BT2
        self.fall_left_ms = 0.0  # > 0 while a piece is falling
        self.boxes_full = 0
        self.boxes_short = 0
        self.pieces_landed = 0
        self.pieces_spilled = 0
        self.running = False  # started from the panel and not stopped since
        self.idle_ms = 0.0

    def step(self, dt_ms: int) -> None:
        p = self.params
        act = self.actuators
        seconds = dt_ms / 1000
        if self.controls["stop"] == 0:
            self.running = False
        elif self.controls["start"]:
            self.running = True
        if self.fall_left_ms > 0:
            self.fall_left_ms -= dt_ms
            if self.fall_left_ms <= 0:
                self.fall_left_ms = 0.0
                self._land()
        if act["piece_conveyor"]:
            self.piece_gap -= p["piece_speed"] * seconds
            if self.piece_gap <= 0:
                self.piece_gap += p["piece_pitch"]
                self.fall_left_ms = p["fall_ms"]
        if act["box_conveyor"]:
            self.box_front += p["box_speed"] * seconds
            if self.box_front >= p["box_length"]:
                if self.box_pieces >= self.capacity:
                    self.boxes_full += 1
                else:
                    self.boxes_short += 1
                self.box_front -= p["box_pitch"]
                self.box_pieces = 0
        if self.running and not act["box_conveyor"] and not act["piece_conveyor"]:
            self.idle_ms += dt_ms
            if self.idle_ms >= p["deadlock_ms"]:
                self.raise_fault("deadlock")
        else:
            self.idle_ms = 0.0

    def _land(self) -> None:
        half = self.params["box_length"] / 2
        if -half < self.box_front < half:  # the box covers the landing point
            if self.box_pieces >= self.capacity:
                self.raise_fault("overfill")
            self.box_pieces += 1
            self.pieces_landed += 1
        else:
            self.pieces_spilled += 1
            self.raise_fault("spill")

    def sensors(self) -> dict[str, int]:
        front = self.box_front
        return {
            "box_eye": int(0 <= front < self.params["box_length"]),
            "piece_eye": int(self.fall_left_ms > 0 and "piece_eye_stuck" not in self.active_faults),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "box_position": round(self.box_front, 1),
            "box_pieces": self.box_pieces,
            "boxes_full": self.boxes_full,
            "boxes_short": self.boxes_short,
            "pieces_landed": self.pieces_landed,
            "pieces_spilled": self.pieces_spilled,
            "piece_falling": self.fall_left_ms > 0,
            "piece_gap": round(self.piece_gap, 1),
            "running": self.running,
        }

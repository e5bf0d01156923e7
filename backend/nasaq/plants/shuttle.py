"""P14 motor shuttle between two limit switches (seed 004, E-vi-33, Fig 3.16): a carriage
driven left -> right to LS2, waits there, and returns to LS1 (home).

``position`` is in mm from home (0) to the right end (``travel``), moved at ``speed`` mm/s.
LS1 reads 1 at or below ``switch_band`` mm, LS2 at or above ``travel - switch_band``. The
buffers stop the carriage ``overrun`` mm beyond the ends: a carriage still driven there is
``overtravel`` (the course program, which stops the motor one scan after LS1, stays clear).
Both motor contactors on at once is ``both_directions`` (a phase short: nothing moves).

``cycles`` counts returns to LS1 after a visit to LS2; ``last_wait_ms`` is how long the carriage
last stood at LS2 before it left (the SS timer's wait, 10 s in the corrected book program).
Injectable: ``ls2_broken`` (LS2 never makes: the carriage runs into the buffer).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue


class Shuttle(Plant):
    kind = "shuttle"
    title = "Motor shuttle"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("stop", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("ls1", "sensor", description="LS1: carriage at home (left)"),
        Signal("ls2", "sensor", description="LS2: carriage at the right end"),
        Signal("right", "actuator", description="Motor left -> right"),
        Signal("left", "actuator", description="Motor right -> left"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("both_directions", description="Both motor directions were on together"),
        Fault("overtravel", description="The carriage was driven into an end buffer"),
        Fault("ls2_broken", injectable=True, description="LS2 never makes"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "travel": 1000.0,  # mm between the limit switches
        "speed": 200.0,  # mm/s
        "switch_band": 10.0,  # mm
        "overrun": 50.0,  # mm from a limit switch to the buffer
        "start_position": 0.0,  # mm
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "travel": (50, 100000),
        "speed": (1, 10000),
        "switch_band": (1, 1000),
        "overrun": (1, 1000),
        "start_position": (0, 100000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "ls1": "I0.1",
        "ls2": "I0.2",
        "stop": "I0.3",
        "right": "Q0.0",
        "left": "Q0.1",
    }

    def reset(self) -> None:
        p = self.params
        if p["travel"] <= 2 * p["switch_band"]:
            raise PlantError(
                "shuttle: travel must exceed 2 x switch_band", "PLT020", ("params", "switch_band")
            )
        if p["start_position"] > p["travel"]:
            raise PlantError(
                "shuttle: start_position is beyond travel", "PLT020", ("params", "start_position")
            )
        self.position = p["start_position"]
        self.direction = 0  # -1 left, 0 standing, 1 right
        self.cycles = 0
        self.visited_right = False
        self.wait_ms = 0.0
        self.last_wait_ms = 0.0

    def step(self, dt_ms: int) -> None:
        p = self.params
        right = self.actuators["right"]
        left = self.actuators["left"]
        at_right = self.position >= p["travel"] - p["switch_band"]
        if right and left:
            self.raise_fault("both_directions")
            self.direction = 0
        else:
            self.direction = 1 if right else -1 if left else 0
        if at_right:
            if self.direction == 0:
                self.wait_ms += dt_ms
            elif self.direction < 0 and self.wait_ms:
                self.last_wait_ms = self.wait_ms
                self.wait_ms = 0.0
        if self.direction:
            self.position += self.direction * p["speed"] * dt_ms / 1000
            if self.position > p["travel"] + p["overrun"]:
                self.position = p["travel"] + p["overrun"]
                self.raise_fault("overtravel")
            elif self.position < -p["overrun"]:
                self.position = -p["overrun"]
                self.raise_fault("overtravel")
        if self.position >= p["travel"] - p["switch_band"]:
            self.visited_right = True
        elif self.position <= p["switch_band"] and self.visited_right:
            self.visited_right = False
            self.cycles += 1

    def sensors(self) -> dict[str, int]:
        p = self.params
        return {
            "ls1": int(self.position <= p["switch_band"]),
            "ls2": int(
                self.position >= p["travel"] - p["switch_band"]
                and "ls2_broken" not in self.active_faults
            ),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "position": round(self.position, 1),
            "direction": ("left", "stopped", "right")[self.direction + 1],
            "cycles": self.cycles,
            "wait_ms": int(self.wait_ms),
            "last_wait_ms": int(self.last_wait_ms),
        }

"""P16 hydraulic piston with a servo valve (seed 004, E-vi-15, Fig 3.8).

The PLC writes the valve setpoint to an analog output word (PQW272 in the book): 27648 = 10 V =
100 l/min, linear, as S7 analog outputs scale. The output is a signed INT (S7's -10..+10 V
range): negative values drive the piston back. The piston speed is proportional to the flow:
``max_speed`` mm/s at 27648. ``position`` runs from 0 to ``stroke`` mm and is fed back as a
word 0..27648 (an optional position transmitter).

``end_stop``: the piston hit an end of its stroke faster than ``end_speed`` mm/s (the servo
must slow it down first); it stops there in any case.
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue

_FULL_SCALE = 27648  # S7 analog nominal range


class ServoPiston(Plant):
    kind = "servo_piston"
    title = "Hydraulic piston with servo valve"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("position", "sensor", "word", description="Piston position: 0..stroke -> 0..27648"),
        Signal("speed", "actuator", "word", description="Valve setpoint: 27648 = 10 V = 100 l/min"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("end_stop", description="The piston hit the end of its stroke at speed"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "stroke": 500.0,  # mm
        "max_speed": 100.0,  # mm/s at 27648 (100 l/min)
        "end_speed": 10.0,  # mm/s: fastest safe arrival at an end
        "max_flow": 100.0,  # l/min at 27648
        "start_position": 0.0,  # mm
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "stroke": (1, 10000),
        "max_speed": (1, 10000),
        "end_speed": (0, 10000),
        "max_flow": (1, 10000),
        "start_position": (0, 10000),
    }
    default_wiring: ClassVar[dict[str, str]] = {"speed": "PQW272", "position": "PIW272"}

    def reset(self) -> None:
        p = self.params
        if p["start_position"] > p["stroke"]:
            raise PlantError(
                "servo_piston: start_position is beyond the stroke",
                "PLT020",
                ("params", "start_position"),
            )
        self.position = p["start_position"]
        self.velocity = 0.0

    def setpoint(self) -> int:
        """The output word as the signed INT the program wrote, limited to the 10 V range."""
        raw = self.actuators["speed"] & 0xFFFF
        value = raw - 0x10000 if raw & 0x8000 else raw
        return max(-_FULL_SCALE, min(_FULL_SCALE, value))

    def step(self, dt_ms: int) -> None:
        p = self.params
        self.velocity = self.setpoint() / _FULL_SCALE * p["max_speed"]
        was_inside = 0 < self.position < p["stroke"]
        self.position += self.velocity * dt_ms / 1000
        end = 0.0 if self.position <= 0 else p["stroke"] if self.position >= p["stroke"] else None
        if end is not None:
            if was_inside and abs(self.velocity) > p["end_speed"]:
                self.raise_fault("end_stop")  # pushing on from a standstill at the end is fine
            self.position = end
            self.velocity = 0.0

    def sensors(self) -> dict[str, int]:
        return {"position": round(self.position / self.params["stroke"] * _FULL_SCALE)}

    def state(self) -> dict[str, StateValue]:
        p = self.params
        stroke = p["stroke"]
        return {
            "position": round(self.position, 2),
            "speed": round(self.velocity, 2),
            "flow": round(self.setpoint() / _FULL_SCALE * p["max_flow"], 2),
            "at_end": self.position <= 0 or self.position >= stroke,
        }

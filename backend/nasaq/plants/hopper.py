"""P15 weighing hopper with a load cell (seed 004, E-vi-17, Fig 3.9).

The load cell weighs hopper and flour: 0..100 kg give 0..10 V, read as 0..26460 on PIW272
(264.6 per kg), so the empty hopper (``tare`` 5 kg) reads 1323 and a 25 kg batch 7938. Flour
runs in at ``fill_rate`` kg/s while the discharge door is shut and leaves at ``discharge_rate``
kg/s while it is open (nothing runs in then). More than ``capacity`` kg of flour is
``overflow``: the program did not open the door in time.

``batches`` counts openings of the door; ``last_batch`` is the flour (kg) in the hopper when the
door last opened. Injectable: ``load_cell_wire_break`` (the input reads 32767, as an S7
analog module reports an open loop: a program comparing >= 7938 opens the door for nothing).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue

_COUNTS_PER_KG = 264.6  # 26460 / 100 kg, as the book scales its load cell
_WIRE_BREAK = 32767  # what an S7 analog input reads with its loop open


class Hopper(Plant):
    kind = "hopper"
    title = "Weighing hopper"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("weight", "sensor", "word", description="Load cell: 0..100 kg -> 0..26460"),
        Signal("discharge", "actuator", description="1Y: air valve, discharge door open"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("overflow", description="The hopper overflowed: the door did not open in time"),
        Fault("load_cell_wire_break", injectable=True, description="PIW reads 32767"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "tare": 5.0,  # kg: hopper and frame
        "capacity": 40.0,  # kg of flour the hopper holds
        "fill_rate": 1.0,  # kg/s
        "discharge_rate": 5.0,  # kg/s
        "start_flour": 0.0,  # kg
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "tare": (0, 100),
        "capacity": (1, 100),
        "fill_rate": (0, 100),
        "discharge_rate": (0.1, 100),
        "start_flour": (0, 100),
    }
    default_wiring: ClassVar[dict[str, str]] = {"weight": "PIW272", "discharge": "Q1.0"}

    def reset(self) -> None:
        p = self.params
        if p["tare"] + p["capacity"] > 100:
            raise PlantError(
                "hopper: tare + capacity exceed the 100 kg load cell",
                "PLT020",
                ("params", "capacity"),
            )
        if p["start_flour"] > p["capacity"]:
            raise PlantError(
                "hopper: start_flour is more than capacity", "PLT020", ("params", "start_flour")
            )
        self.flour = p["start_flour"]
        self.door_was = 0
        self.batches = 0
        self.last_batch = 0.0

    def step(self, dt_ms: int) -> None:
        p = self.params
        seconds = dt_ms / 1000
        door = self.actuators["discharge"]
        if door and not self.door_was:
            self.batches += 1
            self.last_batch = self.flour
        self.door_was = door
        if door:
            self.flour = max(0.0, self.flour - p["discharge_rate"] * seconds)
        else:
            self.flour += p["fill_rate"] * seconds
            if self.flour > p["capacity"] + 1e-6:  # not float dust: 3000 x 0.01 kg > 30 kg
                self.flour = p["capacity"]
                self.raise_fault("overflow")

    def sensors(self) -> dict[str, int]:
        if "load_cell_wire_break" in self.active_faults:
            return {"weight": _WIRE_BREAK}
        return {"weight": round((self.params["tare"] + self.flour) * _COUNTS_PER_KG)}

    def state(self) -> dict[str, StateValue]:
        return {
            "flour": round(self.flour, 2),
            "weight_kg": round(self.params["tare"] + self.flour, 2),
            "door_open": bool(self.door_was),
            "batches": self.batches,
            "last_batch": round(self.last_batch, 2),
        }

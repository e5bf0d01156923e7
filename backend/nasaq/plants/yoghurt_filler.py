"""P19 yoghurt cup filler (seed 004, Bài 9, Fig 5).

A conveyor brings plastic cups, one every ``pitch`` mm, under the hopper's nozzle. The cup
sensor SS1 reads 1 while a cup's centre is within ``window`` mm of the nozzle. Piston A opens the
hopper: its valve "Sol a" is a 5/2 single-solenoid valve, so the piston moves right (opens) while
the solenoid is on and springs back left (closes) when it is off, ``piston_ms`` per stroke; the
magnetic switch LS reads 1 with the piston fully left. Yoghurt flows at ``flow`` % of a cup per
second times the opening; it goes into the cup if a cup's centre is within ``catch`` mm of the
nozzle. The capacitive sensor SS2 reads 1 once that cup holds ``full_at`` % or more.

Faults: ``overflow`` a cup filled past ``overflow_at`` %; ``spill`` yoghurt ran with no cup
under the nozzle; ``underfill`` a cup left the nozzle with less than ``underfill_at`` % (a cup
the program let pass unfilled counts too). Injectable: ``full_sensor_stuck`` (SS2 never
reports full: the cup overflows unless the program limits the filling time).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue


class YoghurtFiller(Plant):
    kind = "yoghurt_filler"
    title = "Yoghurt cup filler"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("stop", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("cup", "sensor", description="SS1: a cup is under the nozzle"),
        Signal("full", "sensor", description="SS2: capacitive sensor, the cup is full"),
        Signal("piston_left", "sensor", description="LS: piston A fully left (hopper closed)"),
        Signal("conveyor", "actuator", description="Cup conveyor motor"),
        Signal("sol_a", "actuator", description="Sol a: piston A moves right, hopper opens"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("overflow", description="A cup was filled until it ran over"),
        Fault("underfill", description="A cup left the filler not full"),
        Fault("spill", description="Yoghurt ran with no cup under the nozzle"),
        Fault("full_sensor_stuck", injectable=True, description="SS2 never reports full"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "speed": 100.0,  # mm/s
        "pitch": 200.0,  # mm between cups (L in the book)
        "window": 15.0,  # mm: SS1 sees a cup centre this close to the nozzle
        "catch": 25.0,  # mm: yoghurt lands in a cup whose centre is this close
        "piston_ms": 200,
        "flow": 50.0,  # % of a cup per second with the hopper fully open
        "full_at": 100.0,  # %
        "overflow_at": 115.0,  # %
        "underfill_at": 95.0,  # %
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "speed": (1, 1000),
        "pitch": (50, 2000),
        "window": (1, 100),
        "catch": (1, 100),
        "piston_ms": (10, 5000),
        "flow": (1, 1000),
        "full_at": (10, 200),
        "overflow_at": (10, 300),
        "underfill_at": (0, 200),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "cup": "I0.2",
        "full": "I0.3",
        "piston_left": "I0.4",
        "conveyor": "Q0.0",
        "sol_a": "Q0.1",
    }

    def reset(self) -> None:
        p = self.params
        if not p["window"] <= p["catch"] < p["pitch"] / 2:
            raise PlantError(
                "yoghurt_filler: window <= catch < pitch / 2", "PLT020", ("params", "catch")
            )
        if not p["underfill_at"] <= p["full_at"] < p["overflow_at"]:
            raise PlantError(
                "yoghurt_filler: underfill_at <= full_at < overflow_at",
                "PLT020",
                ("params", "full_at"),
            )
        self.cup_x = -p["pitch"] / 2  # centre of the next cup, mm from the nozzle
        self.fill = 0.0  # % of the cup at cup_x
        self.piston = 0.0  # 0 = left (closed), 1 = right (open)
        self.cups_good = 0
        self.cups_bad = 0

    def step(self, dt_ms: int) -> None:
        p = self.params
        act = self.actuators
        stroke = dt_ms / p["piston_ms"]
        if act["sol_a"]:
            self.piston = min(1.0, self.piston + stroke)
        else:
            self.piston = max(0.0, self.piston - stroke)
        if self.piston > 0:
            if abs(self.cup_x) <= p["catch"]:
                self.fill += p["flow"] * self.piston * dt_ms / 1000
                if self.fill > p["overflow_at"]:
                    self.raise_fault("overflow")
            else:
                self.raise_fault("spill")
        if act["conveyor"]:
            before = self.cup_x
            self.cup_x += p["speed"] * dt_ms / 1000
            if before <= p["catch"] < self.cup_x:  # the cup has left the nozzle
                if p["underfill_at"] <= self.fill <= p["overflow_at"]:
                    self.cups_good += 1
                else:
                    self.cups_bad += 1
                    if self.fill < p["underfill_at"]:
                        self.raise_fault("underfill")
            if self.cup_x >= p["pitch"] / 2:  # the next cup becomes the one at the nozzle
                self.cup_x -= p["pitch"]
                self.fill = 0.0

    def sensors(self) -> dict[str, int]:
        p = self.params
        at_nozzle = abs(self.cup_x) <= p["catch"]
        return {
            "cup": int(abs(self.cup_x) <= p["window"]),
            "full": int(
                at_nozzle
                and self.fill >= p["full_at"]
                and "full_sensor_stuck" not in self.active_faults
            ),
            "piston_left": int(self.piston <= 0.0),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "cup_position": round(self.cup_x, 1),
            "fill": round(self.fill, 1),
            "piston": round(self.piston * 100),
            "cups_good": self.cups_good,
            "cups_bad": self.cups_bad,
        }

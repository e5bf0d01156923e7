"""P09: a car park with an entry and an exit sensor, a "full" sign and an optional gate.

The operator makes cars come (``arrive``) and go (``leave``): each rising edge of the control is
one car (these controls need no wire; a scenario uses ``operate``). With ``arrive_every_ms`` /
``leave_every_ms`` cars also come and go by themselves, every period varied by up to half of it
from ``random.Random(seed)``, so a run is the same every time.

A car that arrives while the ``full_sign`` is lit drives away (``refused``). Otherwise it drives
over the entry sensor (``entry`` = 1 for ``pass_ms``) into the car park; with ``gate: 1`` it first
waits on the sensor until the ``gate`` output opens the barrier. A car that enters while the
car park is really full (``capacity`` cars inside) raises ``over_capacity``: the sign should
have been lit. A car leaves over the exit sensor (``exit``, ``pass_ms``) if there is one inside;
cars pass one after the other with ``gap_ms`` between them. ``cars`` is the real number of cars
inside, what a check compares the program's count with: a car counts in once it has passed the
entry sensor, and out as soon as it drives onto the exit sensor (it can no longer park).
``reset`` is only a panel control for the program's counter reset.
"""

from __future__ import annotations

import random
from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

MAX_WAITING = 50  # cars queued at a sensor


class CarPark(Plant):
    kind = "car_park"
    title = "Car park with entry and exit sensors"
    signals = (
        Signal("arrive", "control", description="operator: a car arrives (each rising edge)"),
        Signal("leave", "control", description="operator: a car leaves (each rising edge)"),
        Signal("reset", "control", description="counter reset push button"),
        Signal("entry", "sensor", description="entry sensor S1: a car drives in"),
        Signal("exit", "sensor", description="exit sensor S2: a car drives out"),
        Signal("full_sign", "actuator", description="sign: car park full"),
        Signal("gate", "actuator", description="entry barrier: 1 = open"),
    )
    faults = (Fault("over_capacity", description="a car drove into the full car park"),)
    defaults: ClassVar[dict[str, float]] = {
        "capacity": 12,
        "initial": 0,
        "pass_ms": 1000,
        "gap_ms": 500,
        "gate": 0,
        "arrive_every_ms": 0,
        "leave_every_ms": 0,
        "seed": 1,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "capacity": (1, 10_000),
        "initial": (0, 10_000),
        "pass_ms": (10, 60_000),
        "gap_ms": (0, 60_000),
        "gate": (0, 1),
        "arrive_every_ms": (0, 3_600_000),
        "leave_every_ms": (0, 3_600_000),
        "seed": (0, 2**31),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "entry": "I0.0",
        "exit": "I0.1",
        "reset": "I0.2",
        "full_sign": "Q0.0",
    }

    def reset(self) -> None:
        p = self.params
        self.cars = int(p["initial"])
        self.entered = 0
        self.left = 0
        self.refused = 0
        self.arriving = 0  # cars queued at the entry
        self.leaving = 0  # cars queued at the exit
        self.entry_ms = -1.0  # time on the entry sensor (-1: nobody on it)
        self.exit_ms = -1.0
        self.entry_gap = 0.0
        self.exit_gap = 0.0
        self.last_arrive = self.controls["arrive"]
        self.last_leave = self.controls["leave"]
        self.random = random.Random(int(p["seed"]))
        self.next_arrival = self._period("arrive_every_ms")
        self.next_departure = self._period("leave_every_ms")

    def _period(self, name: str) -> float:
        period = self.params[name]
        return period * (0.5 + self.random.random()) if period > 0 else -1.0

    def _arrives(self) -> None:
        if self.actuators["full_sign"] == 1:
            self.refused += 1  # the driver sees the sign and drives on
        else:
            self.arriving = min(self.arriving + 1, MAX_WAITING)

    def step(self, dt_ms: int) -> None:
        c = self.controls
        if c["arrive"] and not self.last_arrive:
            self._arrives()
        if c["leave"] and not self.last_leave:
            self.leaving = min(self.leaving + 1, MAX_WAITING)
        self.last_arrive, self.last_leave = c["arrive"], c["leave"]
        if self.next_arrival >= 0:
            self.next_arrival -= dt_ms
            if self.next_arrival < 0:
                self._arrives()
                self.next_arrival = self._period("arrive_every_ms")
        if self.next_departure >= 0:
            self.next_departure -= dt_ms
            if self.next_departure < 0:
                self.leaving = min(self.leaving + 1, MAX_WAITING)
                self.next_departure = self._period("leave_every_ms")
        self._entry(dt_ms)
        self._exit(dt_ms)

    def _entry(self, dt_ms: int) -> None:
        p = self.params
        if self.entry_ms < 0:
            self.entry_gap = max(0.0, self.entry_gap - dt_ms)
            if self.arriving and self.entry_gap == 0:
                self.arriving -= 1
                self.entry_ms = 0.0
            return
        if p["gate"] == 1 and self.actuators["gate"] == 0 and self.entry_ms == 0:
            return  # waiting at the closed barrier, on the sensor
        self.entry_ms += dt_ms
        if self.entry_ms >= p["pass_ms"]:
            if self.cars >= p["capacity"]:
                self.raise_fault("over_capacity")
            self.cars += 1
            self.entered += 1
            self.entry_ms = -1.0
            self.entry_gap = p["gap_ms"]

    def _exit(self, dt_ms: int) -> None:
        p = self.params
        if self.exit_ms < 0:
            self.exit_gap = max(0.0, self.exit_gap - dt_ms)
            if self.leaving and self.exit_gap == 0:
                self.leaving -= 1
                if self.cars > 0:
                    self.cars -= 1  # the car is on its way out
                    self.exit_ms = 0.0
            return
        self.exit_ms += dt_ms
        if self.exit_ms >= p["pass_ms"]:
            self.left += 1
            self.exit_ms = -1.0
            self.exit_gap = p["gap_ms"]

    def sensors(self) -> dict[str, int]:
        return {
            "entry": 1 if self.entry_ms >= 0 else 0,
            "exit": 1 if self.exit_ms >= 0 else 0,
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "cars": self.cars,
            "capacity": int(self.params["capacity"]),
            "entered": self.entered,
            "left": self.left,
            "refused": self.refused,
            "waiting": self.arriving,
        }

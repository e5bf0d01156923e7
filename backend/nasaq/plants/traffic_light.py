"""P06: a junction of two directions with three-lamp signal columns and a pedestrian crossing.

Direction 1 has lamps ``red1 yellow1 green1``, direction 2 ``red2 yellow2 green2``; pedestrians
cross direction 1's road on ``ped_red``/``ped_green`` after pressing ``ped`` (the button's demand
stays on the panel until they see green). The ``run`` switch puts the junction in service.

A direction lets traffic go while its green is lit, or its yellow without red (amber after green:
cars still cross); red with yellow is "get ready" and lets nobody go. ``conflict`` (raised) is two
flows at once: both directions going, or pedestrians on green while direction 1 goes. ``dark``
(raised) is a direction of the junction in service with no lamp lit for longer than
``dark_grace_ms`` (one scan of a phase change is not a fault). ``directions: 1`` makes a single
signal column (the course's four-phase light): direction 2 is then not checked.

Cars: one arrives at each direction every ``car_every_ms`` and one leaves the queue every
``car_pass_ms`` while its direction goes; ``queue1``/``queue2`` and ``passed1``/``passed2`` are
what the drawing animates.
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

MAX_QUEUE = 30  # cars the drawing shows waiting at one direction


class TrafficLight(Plant):
    kind = "traffic_light"
    title = "Traffic lights at a junction"
    signals = (
        Signal("run", "control", description="switch: 1 = in service"),
        Signal("ped", "control", description="pedestrian request button"),
        Signal("red1", "actuator", description="direction 1 red"),
        Signal("yellow1", "actuator", description="direction 1 yellow"),
        Signal("green1", "actuator", description="direction 1 green"),
        Signal("red2", "actuator", description="direction 2 red"),
        Signal("yellow2", "actuator", description="direction 2 yellow"),
        Signal("green2", "actuator", description="direction 2 green"),
        Signal("ped_red", "actuator", description="pedestrians red"),
        Signal("ped_green", "actuator", description="pedestrians green"),
    )
    faults = (
        Fault("conflict", description="two crossing flows were given way at the same time"),
        Fault("dark", description="a direction in service showed no lamp"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "directions": 2,
        "dark_grace_ms": 100,
        "car_every_ms": 4000,
        "car_pass_ms": 2000,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "directions": (1, 2),
        "dark_grace_ms": (0, 10_000),
        "car_every_ms": (100, 3_600_000),
        "car_pass_ms": (100, 3_600_000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "run": "I0.0",
        "red1": "Q4.0",
        "yellow1": "Q4.1",
        "green1": "Q4.2",
        "red2": "Q5.0",
        "yellow2": "Q5.1",
        "green2": "Q5.2",
    }

    def reset(self) -> None:
        self.dark_ms = [0.0, 0.0]
        self.queue = [0, 0]
        self.passed = [0, 0]
        self.arrive_ms = 0.0
        self.pass_ms = [0.0, 0.0]
        self.ped_waiting = False

    def _goes(self, n: int) -> bool:
        a = self.actuators
        green, yellow, red = a[f"green{n}"], a[f"yellow{n}"], a[f"red{n}"]
        return green == 1 or (yellow == 1 and red == 0)

    def step(self, dt_ms: int) -> None:
        a, p = self.actuators, self.params
        goes = (self._goes(1), self._goes(2))
        if (goes[0] and goes[1]) or (a["ped_green"] == 1 and goes[0]):
            self.raise_fault("conflict")
        running = self.controls["run"] == 1
        for n in range(int(p["directions"])):
            lit = a[f"red{n + 1}"] or a[f"yellow{n + 1}"] or a[f"green{n + 1}"]
            if running and not lit:
                self.dark_ms[n] += dt_ms
                if self.dark_ms[n] > p["dark_grace_ms"]:
                    self.raise_fault("dark")
            else:
                self.dark_ms[n] = 0.0
        if self.controls["ped"] == 1:
            self.ped_waiting = True
        if a["ped_green"] == 1:
            self.ped_waiting = False
        self.arrive_ms += dt_ms
        while self.arrive_ms >= p["car_every_ms"]:
            self.arrive_ms -= p["car_every_ms"]
            self.queue[0] = min(self.queue[0] + 1, MAX_QUEUE)
            if p["directions"] == 2:
                self.queue[1] = min(self.queue[1] + 1, MAX_QUEUE)
        for n in (0, 1):
            if goes[n] and self.queue[n] > 0:
                self.pass_ms[n] += dt_ms
                while self.pass_ms[n] >= p["car_pass_ms"] and self.queue[n] > 0:
                    self.pass_ms[n] -= p["car_pass_ms"]
                    self.queue[n] -= 1
                    self.passed[n] += 1
            else:
                self.pass_ms[n] = 0.0

    def sensors(self) -> dict[str, int]:
        return {}

    def state(self) -> dict[str, StateValue]:
        return {
            "go1": self._goes(1),
            "go2": self._goes(2),
            "queue1": self.queue[0],
            "queue2": self.queue[1],
            "passed1": self.passed[0],
            "passed2": self.passed[1],
            "ped_waiting": self.ped_waiting,
        }

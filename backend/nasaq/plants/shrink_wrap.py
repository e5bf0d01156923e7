"""P20 shrink-wrap packaging line (seed 004, Bài 10; the book's text breaks off, the rest of the
specification is the lesson's): conveyor A feeds packs into the heat-shrink tunnel, conveyor B
carries them through it, conveyor C takes them out.

Positions are a pack's front edge in mm along the line: A is [0, L), B (and the tunnel) [L, 2L),
C [2L, 3L), L = ``belt``. A pack moves with the conveyor under its front; it crosses onto the
next conveyor only while that one runs, and it never pushes into the pack ahead (they queue).
New packs are put on A every ``pitch`` mm while A runs; a pack whose front passes 3L drops into
the output bin. Each eye sits ``eye_back`` mm before the end of its conveyor and reads 1 while a
pack covers it (eye_c: a pack about to leave the line).

Tunnel: the heater drives the temperature towards ``heater_c`` with time constant ``tau_s``;
off, it falls back towards ``ambient_c``. ``tunnel_hot`` reads 1 from ``hot_c``. A pack whose
centre is in the tunnel collects exposure time while the tunnel is hot. When it leaves the
tunnel, less than ``min_s`` is ``raw_pack`` (the film has not shrunk); more than ``max_s``, even
while still inside, is ``burnt_pack``. ``packs_good`` counts packs that left the tunnel shrunk
and not burnt; ``packs_done`` packs that reached the output bin.
"""

from __future__ import annotations

import math
from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue

_SLOTS = 24


class ShrinkWrap(Plant):
    kind = "shrink_wrap"
    title = "Shrink-wrap packaging line"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("stop", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("eye_a", "sensor", description="A pack at the end of conveyor A"),
        Signal("eye_b", "sensor", description="A pack at the end of conveyor B (tunnel exit)"),
        Signal("eye_c", "sensor", description="A pack at the end of conveyor C"),
        Signal("tunnel_hot", "sensor", description="The tunnel is at shrinking temperature"),
        Signal("conveyor_a", "actuator", description="Conveyor A (infeed)"),
        Signal("conveyor_b", "actuator", description="Conveyor B (through the tunnel)"),
        Signal("conveyor_c", "actuator", description="Conveyor C (outfeed)"),
        Signal("heater", "actuator", description="Tunnel heater"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("burnt_pack", description="A pack stayed in the hot tunnel too long"),
        Fault("raw_pack", description="A pack left the tunnel with its film not shrunk"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "belt": 1000.0,  # mm per conveyor
        "speed": 200.0,  # mm/s, every conveyor
        "pack": 200.0,  # mm pack length
        "pitch": 600.0,  # mm between packs put on A
        "eye_back": 20.0,  # mm before the end of a conveyor
        "ambient_c": 20.0,
        "heater_c": 200.0,  # temperature the heater tends to
        "tau_s": 10.0,  # s
        "hot_c": 150.0,
        "min_s": 3.0,  # s of hot exposure a pack needs
        "max_s": 8.0,  # s of hot exposure that burns it
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "belt": (200, 10000),
        "speed": (1, 2000),
        "pack": (10, 2000),
        "pitch": (20, 10000),
        "eye_back": (1, 1000),
        "ambient_c": (-20, 60),
        "heater_c": (50, 400),
        "tau_s": (0.1, 600),
        "hot_c": (30, 400),
        "min_s": (0, 600),
        "max_s": (0, 600),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "eye_a": "I0.2",
        "eye_b": "I0.3",
        "eye_c": "I0.4",
        "tunnel_hot": "I0.5",
        "conveyor_a": "Q0.0",
        "conveyor_b": "Q0.1",
        "conveyor_c": "Q0.2",
        "heater": "Q0.3",
    }

    def reset(self) -> None:
        p = self.params
        if not p["pack"] < p["pitch"] or not p["eye_back"] < p["pack"] < p["belt"]:
            raise PlantError(
                "shrink_wrap: eye_back < pack < belt and pack < pitch", "PLT020", ("params", "pack")
            )
        if not p["ambient_c"] < p["hot_c"] < p["heater_c"] or not p["min_s"] < p["max_s"]:
            raise PlantError(
                "shrink_wrap: ambient_c < hot_c < heater_c and min_s < max_s",
                "PLT020",
                ("params", "hot_c"),
            )
        if 3 * p["belt"] / p["pack"] + 2 > _SLOTS:
            raise PlantError(
                "shrink_wrap: packs too short for the line (belt / pack <= 7)",
                "PLT020",
                ("params", "pack"),
            )
        # Packs in line order, the one furthest along first: plain lists, reused.
        self.front = [0.0] * _SLOTS
        self.exposure = [0.0] * _SLOTS  # s hot in the tunnel
        self.count = 0
        self.gap = 0.0  # A's travel until the next pack is put on
        self.temperature = p["ambient_c"]
        self._gain_dt = 0
        self._gain = 0.0
        self.packs_done = 0
        self.packs_good = 0
        self.packs_raw = 0
        self.packs_burnt = 0
        self.judged = [False] * _SLOTS  # the pack has left the tunnel, or burnt in it
        self.runs = [0, 0, 0, 1]  # conveyors A, B, C, and the output bin that always takes

    def step(self, dt_ms: int) -> None:
        p = self.params
        act = self.actuators
        seconds = dt_ms / 1000
        if dt_ms != self._gain_dt:  # the first-order step's gain, made once per scan time
            self._gain_dt = dt_ms
            self._gain = 1 - math.exp(-seconds / p["tau_s"])
        target = p["heater_c"] if act["heater"] else p["ambient_c"]
        self.temperature += (target - self.temperature) * self._gain
        hot = self.temperature >= p["hot_c"]
        belt = p["belt"]
        half = p["pack"] / 2
        runs = self.runs
        runs[0], runs[1], runs[2] = act["conveyor_a"], act["conveyor_b"], act["conveyor_c"]
        travel = p["speed"] * seconds
        limit = math.inf  # how far the pack ahead lets this one go
        i = 0
        while i < self.count:
            front = self.front[i]
            segment = int(front // belt)
            if runs[segment]:
                new = front + travel
                border = (segment + 1) * belt
                if new >= border and segment < 2 and not runs[segment + 1]:
                    new = border - 1e-6  # waits at the end until the next conveyor runs
                new = min(new, limit)
                front = max(front, new)
            self.front[i] = front
            limit = front - p["pack"]
            centre = front - half
            if belt <= centre < 2 * belt:
                if hot:
                    self.exposure[i] += seconds
                if self.exposure[i] > p["max_s"] and not self.judged[i]:
                    self.judged[i] = True
                    self.packs_burnt += 1
                    self.raise_fault("burnt_pack")
            elif centre >= 2 * belt and not self.judged[i]:
                self.judged[i] = True
                if self.exposure[i] < p["min_s"]:
                    self.packs_raw += 1
                    self.raise_fault("raw_pack")
                else:
                    self.packs_good += 1
            if front >= 3 * belt:
                self._finish(i)
                continue
            i += 1
        if act["conveyor_a"]:
            self.gap -= travel
            if self.gap <= 0 and self._room_at_start():
                self.front[self.count] = 0.0
                self.exposure[self.count] = 0.0
                self.judged[self.count] = False
                self.count += 1
                self.gap = p["pitch"]

    def _room_at_start(self) -> bool:
        return self.count < _SLOTS and (
            self.count == 0 or self.front[self.count - 1] >= self.params["pack"] - 1e-3
        )

    def _finish(self, i: int) -> None:
        self.packs_done += 1
        last = self.count - 1
        for k in range(i, last):  # keep line order; at most a handful of packs
            self.front[k] = self.front[k + 1]
            self.exposure[k] = self.exposure[k + 1]
            self.judged[k] = self.judged[k + 1]
        self.count = last

    def sensors(self) -> dict[str, int]:
        p = self.params
        length = p["pack"]
        belt = p["belt"]
        eye_a = belt - p["eye_back"]
        eye_b = eye_a + belt
        eye_c = eye_b + belt
        a = b = c = 0
        for i in range(self.count):
            front = self.front[i]
            back = front - length
            if front >= eye_a > back:
                a = 1
            elif front >= eye_b > back:
                b = 1
            elif front >= eye_c > back:
                c = 1
        return {
            "eye_a": a,
            "eye_b": b,
            "eye_c": c,
            "tunnel_hot": int(self.temperature >= p["hot_c"]),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "temperature": round(self.temperature, 1),
            "packs_on_line": self.count,
            "packs_done": self.packs_done,
            "packs_good": self.packs_good,
            "packs_raw": self.packs_raw,
            "packs_burnt": self.packs_burnt,
        }

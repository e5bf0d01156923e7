"""P18 sorting conveyor (seed 004, Bài 5a and Bài 6): balls sorted by colour with a rotary gate,
or parts sorted by height with pusher A (param ``by_height: 1``).

Objects enter the belt every ``pitch`` mm of belt travel, red or green (low or high) in an order
drawn from ``random.Random(seed)`` (``share`` = part of red / low ones), and ride at ``speed``
mm/s. Positions are the object's centre in mm from the belt's start.

Sensors at ``eye_at`` see an object while its centre is within half an object of them:
``green_eye``/``red_eye`` (SS1/SS2) see balls of their colour; ``low_eye`` sees every part (it is
mounted low), ``high_eye`` only high parts. ``exit_eye`` sees an object just past the gate or
pusher (``decide_at + size``), so a program knows when the object has gone by.

Colour: the gate (5/2 single-solenoid valve, ``gate_ms`` to swing) decides as a ball's centre
crosses ``decide_at``: gate on -> exit 2, off -> exit 1. Red belongs at exit 2, green at exit 1.
Height: pusher A (``pusher_ms`` per stroke) pushes a part off the belt if it is more than half
out while the part is in front of it; parts that reach the belt's end pass. Low parts belong
pushed off, high parts passed. A wrong exit is ``missorted``.
"""

from __future__ import annotations

import random
from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue


class Sorter(Plant):
    kind = "sorter"
    title = "Sorting conveyor"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("stop", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("green_eye", "sensor", description="SS1: a green ball at the colour sensors"),
        Signal("red_eye", "sensor", description="SS2: a red ball at the colour sensors"),
        Signal("high_eye", "sensor", description="Height sensor H1: a high part"),
        Signal("low_eye", "sensor", description="Height sensor H2: any part (mounted low)"),
        Signal("exit_eye", "sensor", description="An object has just passed the gate / pusher"),
        Signal("conveyor", "actuator", description="Conveyor motor"),
        Signal("gate", "actuator", description="Rotary gate valve: 1 = exit 2"),
        Signal("pusher", "actuator", description="Pusher A valve: 1 = push"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("missorted", description="An object left by the wrong exit"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "by_height": 0,  # 0: balls by colour (Bài 5a), 1: parts by height (Bài 6)
        "seed": 1,
        "share": 0.5,  # part of red balls / low parts
        "speed": 100.0,  # mm/s
        "pitch": 500.0,  # mm between objects: one at a time between the eyes and the gate
        "size": 50.0,  # mm
        "eye_at": 200.0,  # mm
        "decide_at": 600.0,  # mm: gate / pusher
        "belt_end": 900.0,  # mm
        "gate_ms": 200,
        "pusher_ms": 300,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "by_height": (0, 1),
        "seed": (0, 2**31 - 1),
        "share": (0, 1),
        "speed": (1, 2000),
        "pitch": (10, 10000),
        "size": (5, 1000),
        "eye_at": (1, 100000),
        "decide_at": (1, 100000),
        "belt_end": (1, 100000),
        "gate_ms": (10, 10000),
        "pusher_ms": (10, 10000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "green_eye": "I0.2",
        "red_eye": "I0.3",
        "high_eye": "I0.4",
        "low_eye": "I0.5",
        "exit_eye": "I0.6",
        "conveyor": "Q0.0",
        "gate": "Q0.1",
        "pusher": "Q0.2",
    }

    def reset(self) -> None:
        p = self.params
        if p["size"] >= p["pitch"]:
            raise PlantError(
                "sorter: objects must be shorter than their pitch", "PLT020", ("params", "size")
            )
        if not p["eye_at"] < p["decide_at"] < p["decide_at"] + p["size"] < p["belt_end"]:
            raise PlantError(
                "sorter: eye_at < decide_at < decide_at + size < belt_end",
                "PLT020",
                ("params", "decide_at"),
            )
        self.by_height = bool(p["by_height"])
        self.rng = random.Random(int(p["seed"]))
        slots = int(p["belt_end"] // p["pitch"]) + 3
        self.x = [0.0] * slots
        self.special = [False] * slots  # red ball / low part
        self.on_belt = [False] * slots
        self.gate_pos = 0.0
        self.pusher_pos = 0.0
        self.objects_in = 0
        self.good = 0
        self.bad = 0
        self.exit1 = 0
        self.exit2 = 0
        self.last = ""
        self._enter()
        self.gap = p["pitch"]

    def _enter(self) -> None:
        for i, used in enumerate(self.on_belt):
            if not used:
                self.on_belt[i] = True
                self.x[i] = 0.0
                self.special[i] = self.rng.random() < self.params["share"]
                self.objects_in += 1
                return
        raise PlantError("sorter: too many objects on the belt")  # cannot happen: slots >= belt

    def _judge(self, i: int, correct: bool, how: str) -> None:
        if self.by_height:
            name = "low" if self.special[i] else "high"
        else:
            name = "red" if self.special[i] else "green"
        self.last = f"{name}:{how}"
        if correct:
            self.good += 1
        else:
            self.bad += 1
            self.raise_fault("missorted")

    def step(self, dt_ms: int) -> None:
        p = self.params
        act = self.actuators
        swing = dt_ms / p["gate_ms"]
        if act["gate"]:
            self.gate_pos = min(1.0, self.gate_pos + swing)
        else:
            self.gate_pos = max(0.0, self.gate_pos - swing)
        push = dt_ms / p["pusher_ms"]
        if act["pusher"]:
            self.pusher_pos = min(1.0, self.pusher_pos + push)
        else:
            self.pusher_pos = max(0.0, self.pusher_pos - push)
        travel = p["speed"] * dt_ms / 1000 if act["conveyor"] else 0.0
        decide = p["decide_at"]
        half = p["size"] / 2
        end = p["belt_end"]
        for i, used in enumerate(self.on_belt):
            if not used:
                continue
            before = self.x[i]
            after = before + travel
            self.x[i] = after
            special = self.special[i]
            if self.by_height:
                if self.pusher_pos >= 0.5 and decide - half <= after <= decide + half:
                    self.on_belt[i] = False
                    self._judge(i, special, "pushed")
                elif after >= end:
                    self.on_belt[i] = False
                    self._judge(i, not special, "passed")
                continue
            if before < decide <= after:  # the gate decides; the ball rides on to its chute
                to_exit2 = self.gate_pos >= 0.5
                if to_exit2:
                    self.exit2 += 1
                else:
                    self.exit1 += 1
                self._judge(i, to_exit2 == special, "exit2" if to_exit2 else "exit1")
            if after >= end:
                self.on_belt[i] = False
        if travel:
            self.gap -= travel
            if self.gap <= 0:
                self.gap += p["pitch"]  # keeps the pitch exact, whatever the scan time
                self._enter()

    def _seen(self, at: float) -> tuple[bool, bool]:
        """(any object, a red/low object) with its centre within half an object of ``at``."""
        half = self.params["size"] / 2
        seen = special = False
        for i, used in enumerate(self.on_belt):
            if used and abs(self.x[i] - at) <= half:
                seen = True
                special = special or self.special[i]
        return seen, special

    def sensors(self) -> dict[str, int]:
        p = self.params
        seen, special = self._seen(p["eye_at"])
        passed, _ = self._seen(p["decide_at"] + p["size"])
        if self.by_height:
            high = seen and not special
            return {
                "green_eye": 0,
                "red_eye": 0,
                "high_eye": int(high),
                "low_eye": int(seen),
                "exit_eye": int(passed),
            }
        return {
            "green_eye": int(seen and not special),
            "red_eye": int(special),
            "high_eye": 0,
            "low_eye": 0,
            "exit_eye": int(passed),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "objects_in": self.objects_in,
            "good": self.good,
            "missorted": self.bad,
            "exit1": self.exit1,
            "exit2": self.exit2,
            "gate": round(self.gate_pos * 100),
            "pusher": round(self.pusher_pos * 100),
            "last": self.last,
        }

"""P04: a bottle conveyor with photo-eyes, a filling station and a reject pusher.

Positions are mm along the belt from the infeed. Bottles (``diameter`` mm) stand on the belt
``spacing`` mm apart, a new one set on at the infeed each time the last has moved on that far;
they move at ``speed`` mm/s while the ``conveyor`` runs and stand with it. A photo-eye reads 1
while a bottle covers it: ``count_eye`` at ``count_at`` (infeed counting), ``bottle_eye`` at the
filler (``fill_at``; the nozzle is above the eye, so a bottle that covers the eye is under the
nozzle), ``exit_eye`` at ``exit_at``. Bottles leave at the belt's end (``length``).

Filling: while the ``fill_valve`` is open, the bottle under the nozzle fills by 100 % in
``fill_ms``; with no bottle there the liquid runs onto the belt (``spilled``). When a filled
bottle moves on past the nozzle it is judged: under ``min_fill`` % is ``underfill`` (raised), over
``max_fill`` % ``overfill`` (raised); an empty bottle is only counted (``passed_empty``: a counting
lesson never fills). The ``pusher`` at the exit eye pushes a bottle that covers the eye off the
belt (``rejected``). Injectable: ``eye_stuck`` (dirt on the filler eye: it reads 1 always).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

MAX_BOTTLES = 64  # bottles on the belt at once (the belt is short; this is only a bound)


class BottleConveyor(Plant):
    kind = "bottle_conveyor"
    title = "Bottle conveyor with filling station"
    signals = (
        Signal("start", "control", description="start push button, NO"),
        Signal("stop", "control", normally_closed=True, description="stop push button, NC"),
        Signal("reset", "control", description="reset push button (counter reset)"),
        Signal("bottle_eye", "sensor", description="photo-eye at the filler: bottle in place"),
        Signal("exit_eye", "sensor", description="photo-eye at the exit"),
        Signal("count_eye", "sensor", description="photo-eye at the infeed: counts bottles"),
        Signal("conveyor", "actuator", description="conveyor motor"),
        Signal("fill_valve", "actuator", description="filling valve"),
        Signal("lamp", "actuator", description="signal lamp"),
        Signal("pusher", "actuator", description="reject pusher at the exit eye"),
    )
    faults = (
        Fault("overfill", description="a bottle left the filler over-full"),
        Fault("underfill", description="a bottle left the filler part-filled"),
        Fault("eye_stuck", injectable=True, description="the filler eye reads 1 always"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "speed": 100.0,  # mm/s
        "spacing": 250.0,  # mm between bottles
        "diameter": 60.0,  # mm
        "count_at": 150.0,
        "fill_at": 600.0,
        "exit_at": 1000.0,
        "length": 1100.0,
        "fill_ms": 12_000,  # time to fill one bottle
        "min_fill": 95.0,  # %
        "max_fill": 105.0,  # %
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "speed": (1, 10_000),
        "spacing": (10, 100_000),
        "diameter": (1, 1000),
        "count_at": (0, 100_000),
        "fill_at": (0, 100_000),
        "exit_at": (0, 100_000),
        "length": (10, 100_000),
        "fill_ms": (1, 3_600_000),
        "min_fill": (0, 1000),
        "max_fill": (0, 1000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "bottle_eye": "I0.1",
        "conveyor": "Q0.0",
        "fill_valve": "Q0.1",
    }

    def reset(self) -> None:
        self.positions: list[float] = [0.0]  # bottle centres, oldest (furthest) first
        self.fills: list[float] = [0.0]  # % of each bottle's volume
        self.judged: list[bool] = [False]  # the bottle has left the filler
        self.since_last = 0.0  # mm the newest bottle moved since it was set on
        self.delivered = 0
        self.rejected = 0
        self.filled_ok = 0
        self.underfilled = 0
        self.overfilled = 0
        self.passed_empty = 0
        self.spilled = 0.0  # % of a bottle's volume poured onto the belt

    def _covering(self, at: float) -> int:
        """The index of the bottle that covers position ``at`` (-1: none)."""
        half = self.params["diameter"] / 2.0
        for n, position in enumerate(self.positions):
            if abs(position - at) <= half:
                return n
        return -1

    def step(self, dt_ms: int) -> None:
        a, p = self.actuators, self.params
        if a["fill_valve"]:
            poured = 100.0 * dt_ms / p["fill_ms"]
            under = self._covering(p["fill_at"])
            if under >= 0:
                self.fills[under] += poured
            else:
                self.spilled += poured
        if a["pusher"]:
            out = self._covering(p["exit_at"])
            if out >= 0:
                self._judge(out)
                del self.positions[out], self.fills[out], self.judged[out]
                self.rejected += 1
        if a["conveyor"]:
            self._move(p["speed"] * dt_ms / 1000.0)

    def _move(self, distance: float) -> None:
        p = self.params
        leaving = p["fill_at"] + p["diameter"] / 2.0
        positions, fills, judged = self.positions, self.fills, self.judged
        for n, position in enumerate(positions):
            moved = position + distance
            if position <= leaving < moved:
                self._judge(n)
            positions[n] = moved
        while positions and positions[0] > p["length"]:
            del positions[0], fills[0], judged[0]
            self.delivered += 1
        self.since_last += distance
        while self.since_last >= p["spacing"] and len(positions) < MAX_BOTTLES:
            self.since_last -= p["spacing"]
            positions.append(self.since_last)
            fills.append(0.0)
            judged.append(False)

    def _judge(self, n: int) -> None:
        """A bottle leaves the filler: was it filled right?"""
        fill, p = self.fills[n], self.params
        if self.judged[n]:
            return
        self.judged[n] = True
        if fill == 0:
            self.passed_empty += 1
        elif fill < p["min_fill"]:
            self.underfilled += 1
            self.raise_fault("underfill")
        elif fill > p["max_fill"]:
            self.overfilled += 1
            self.raise_fault("overfill")
        else:
            self.filled_ok += 1

    def sensors(self) -> dict[str, int]:
        p = self.params
        stuck = "eye_stuck" in self.active_faults
        return {
            "bottle_eye": 1 if stuck or self._covering(p["fill_at"]) >= 0 else 0,
            "exit_eye": 1 if self._covering(p["exit_at"]) >= 0 else 0,
            "count_eye": 1 if self._covering(p["count_at"]) >= 0 else 0,
        }

    def state(self) -> dict[str, StateValue]:
        under = self._covering(self.params["fill_at"])
        return {
            "bottles": len(self.positions),
            "delivered": self.delivered,
            "rejected": self.rejected,
            "filled_ok": self.filled_ok,
            "underfilled": self.underfilled,
            "overfilled": self.overfilled,
            "passed_empty": self.passed_empty,
            "fill": round(self.fills[under], 1) if under >= 0 else 0.0,
            "spilled": round(self.spilled, 1),
            # The drawing's bottles: centre (mm) and fill (%) of each, "600:40,350:0".
            "bottle_list": ",".join(
                f"{x:.0f}:{f:.0f}" for x, f in zip(self.positions, self.fills, strict=True)
            ),
        }

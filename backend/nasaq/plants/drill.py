"""P07: an automatic drilling station: a drill head on a hydraulic feed, a clamp and coolant.

The head's position is 0 mm at home (top) and ``stroke_mm`` at the drilling depth; it moves down
at ``down_mm_s`` while ``feed_down`` is on and up at ``up_mm_s`` while ``feed_up`` is on (both on:
the valves fight and it stands). With ``spring_return: 1`` the head has one solenoid and a spring
(the course's hydraulic drilling head, solenoid 1Y): it rises whenever ``feed_down`` is off.
Limit switches: ``home`` at the top, ``depth`` at the bottom. The drill motor runs up in
``motor_run_up_ms`` (then ``motor_running``); the clamp's pressure switch closes
``clamp_ms`` after the clamp valve opens (``clamp_ok``) and the coolant pressure switch
``coolant_ms`` after the pump starts (``coolant_ok``).

The work piece's top is at ``work_mm``: feeding into it with the drill motor not running breaks
the bit (``broken_bit``, raised; the head stops there until the plant is reset). With
``motor_check: 0`` the motor is not modelled as wired (a lesson drives only the feed).
``holes`` counts the holes drilled to full depth. Injectable: ``clamp_fail`` (the clamp pressure
never builds), ``coolant_fail`` (no coolant pressure).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

AT_END_MM = 0.5  # a limit switch closes this close to its end


class Drill(Plant):
    kind = "drill"
    title = "Automatic drilling station"
    signals = (
        Signal("start", "control", description="start push button, NO"),
        Signal("stop", "control", normally_closed=True, description="stop push button, NC"),
        Signal("home", "sensor", description="top limit switch: head at home"),
        Signal("depth", "sensor", description="bottom limit switch: drilling depth reached"),
        Signal("clamp_ok", "sensor", description="clamp pressure switch"),
        Signal("motor_running", "sensor", description="drill motor up to speed"),
        Signal("coolant_ok", "sensor", description="coolant pressure switch"),
        Signal("feed_down", "actuator", description="feed valve: lower the head (1Y)"),
        Signal("feed_up", "actuator", description="feed valve: raise the head"),
        Signal("motor", "actuator", description="drill motor contactor"),
        Signal("coolant", "actuator", description="coolant pump"),
        Signal("clamp", "actuator", description="clamp valve"),
    )
    faults = (
        Fault("broken_bit", description="the head fed into the work piece with the motor off"),
        Fault("clamp_fail", injectable=True, description="the clamp pressure never builds"),
        Fault("coolant_fail", injectable=True, description="no coolant pressure"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "stroke_mm": 100.0,
        "work_mm": 40.0,
        "down_mm_s": 20.0,
        "up_mm_s": 50.0,
        "spring_return": 0,
        "motor_check": 1,
        "motor_run_up_ms": 200,
        "clamp_ms": 300,
        "coolant_ms": 200,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "stroke_mm": (1, 10_000),
        "work_mm": (0, 10_000),
        "down_mm_s": (0.1, 10_000),
        "up_mm_s": (0.1, 10_000),
        "spring_return": (0, 1),
        "motor_check": (0, 1),
        "motor_run_up_ms": (0, 60_000),
        "clamp_ms": (0, 60_000),
        "coolant_ms": (0, 60_000),
    }
    # Graph example 2 of the course (automatic drill): motor, coolant, lower, raise, clamp.
    default_wiring: ClassVar[dict[str, str]] = {
        "motor_running": "I0.0",
        "depth": "I0.2",
        "home": "I0.3",
        "clamp_ok": "I0.4",
        "coolant_ok": "I0.6",
        "start": "I0.7",
        "motor": "Q0.0",
        "coolant": "Q0.1",
        "feed_down": "Q0.2",
        "feed_up": "Q0.3",
        "clamp": "Q0.4",
    }

    def reset(self) -> None:
        self.position = 0.0  # mm below home
        self.motor_ms = 0.0
        self.clamp_ms = 0.0
        self.coolant_ms = 0.0
        self.holes = 0
        self.at_depth = False

    def step(self, dt_ms: int) -> None:
        a, p = self.actuators, self.params
        self.motor_ms = self.motor_ms + dt_ms if a["motor"] else 0.0
        self.clamp_ms = self.clamp_ms + dt_ms if a["clamp"] else 0.0
        self.coolant_ms = self.coolant_ms + dt_ms if a["coolant"] else 0.0
        if "broken_bit" in self.active_faults:
            return
        down = a["feed_down"] == 1
        up = a["feed_up"] == 1 or (p["spring_return"] == 1 and not down)
        seconds = dt_ms / 1000.0
        if down and not up:
            # Rounded to 1e-9 mm: sums of steps land on the positions one computes.
            position = min(p["stroke_mm"], round(self.position + p["down_mm_s"] * seconds, 9))
            spinning = p["motor_check"] == 0 or self.motor_ms >= p["motor_run_up_ms"]
            if position > p["work_mm"] and not spinning:
                self.position = max(self.position, p["work_mm"])
                self.raise_fault("broken_bit")
                return
            self.position = position
        elif up and not down:
            self.position = max(0.0, round(self.position - p["up_mm_s"] * seconds, 9))
        deep = self.position >= p["stroke_mm"] - AT_END_MM
        if deep and not self.at_depth:
            self.holes += 1
        self.at_depth = deep

    def sensors(self) -> dict[str, int]:
        p, faults = self.params, self.active_faults
        return {
            "home": 1 if self.position <= AT_END_MM else 0,
            "depth": 1 if self.position >= p["stroke_mm"] - AT_END_MM else 0,
            "clamp_ok": 1
            if self.clamp_ms >= p["clamp_ms"]
            and self.actuators["clamp"]
            and "clamp_fail" not in faults
            else 0,
            "motor_running": 1
            if self.actuators["motor"] and self.motor_ms >= p["motor_run_up_ms"]
            else 0,
            "coolant_ok": 1
            if self.coolant_ms >= p["coolant_ms"]
            and self.actuators["coolant"]
            and "coolant_fail" not in faults
            else 0,
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "position": round(self.position, 2),
            "depth_pct": round(100.0 * self.position / self.params["stroke_mm"], 1),
            "holes": self.holes,
            "spinning": self.actuators["motor"] == 1
            and self.motor_ms >= self.params["motor_run_up_ms"],
        }

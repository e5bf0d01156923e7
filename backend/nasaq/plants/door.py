"""P11 door with a motor (or hydraulics) and limit switches: the warehouse door of E-vi-12
(seed 004, Fig 3.6) and the pressure-boiler door of Bài 8 (param ``boiler: 1``).

``position`` is the opening in % (0 = closed, 100 = open), moved at ``100 / travel_s`` %/s while
``open`` or ``close`` is on. The limit switches ``ls_open``/``ls_closed`` operate at the ends;
the mechanism stops ``margin`` % beyond them: a door still driven there is ``overtravel`` (a
program that stops the motor the scan after its limit switch never gets there).

Trucks (warehouse): the panel's ``outside`` (SS1, ultrasonic, a truck waits outside) and
``inside`` (SS2, photo-eye, a truck is in the doorway) can be held by hand, or the ``truck``
button sends one simulated truck: after ``approach_ms`` it waits outside (``outside`` = 1) until
the door is fully open, passes through (``inside`` = 1 for ``pass_ms``) and leaves. Closing
while a truck is in the doorway is ``crush``, and so is a door that drops below ``clearance`` %
while the simulated truck passes under it.

Boiler (``boiler: 1``): closing on against the seal raises the closing pressure at
``pressure_rate`` bar/s; ``pressure_ok`` reads 1 from ``pressure_bar`` (100 bar). Pressure goes
on rising while ``close`` stays on; above ``max_bar`` it is ``overpressure``. Opening first
releases the pressure. There is no overtravel at the closed end of a boiler door.

``both_directions``: ``open`` and ``close`` on together (the motor or the valve is burnt).
Injectable: ``ls_open_broken`` (the open limit switch never makes: only a travel-time watchdog
in the program stops the door before it overtravels).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

_NO_TRUCK, _APPROACHING, _WAITING, _PASSING = 0, 1, 2, 3
_TRUCK_PHASES = ("none", "approaching", "waiting", "passing")


class Door(Plant):
    kind = "door"
    title = "Door with limit switches"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("open_pb", "control", description="Open push button"),
        Signal("close_pb", "control", description="Close push button"),
        Signal("stop_pb", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("outside", "control", description="SS1: a truck is waiting outside"),
        Signal("inside", "control", description="SS2: a truck is in the doorway"),
        Signal("truck", "control", description="Sends one simulated truck (rising edge)"),
        Signal("ls_open", "sensor", description="Limit switch: door fully open"),
        Signal("ls_closed", "sensor", description="Limit switch: door fully closed"),
        Signal("pressure_ok", "sensor", description="Pressure switch: door sealed (100 bar)"),
        Signal("open", "actuator", description="Motor up / hydraulic open"),
        Signal("close", "actuator", description="Motor down / hydraulic close"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("both_directions", description="Open and close were on together"),
        Fault("overtravel", description="The door was driven past a limit switch"),
        Fault("crush", description="The door closed on a truck"),
        Fault("overpressure", description="Boiler door: closing went on far above 100 bar"),
        Fault("ls_open_broken", injectable=True, description="The open limit switch never makes"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "boiler": 0,  # 1 = pressure-boiler door (Bài 8)
        "travel_s": 10.0,  # s from closed to open
        "margin": 2.0,  # % of travel beyond a limit switch before the mechanical end
        "start_position": 0.0,  # %
        "approach_ms": 2000,  # a simulated truck drives this long before it reaches the door
        "pass_ms": 3000,  # and this long through the doorway
        "clearance": 95.0,  # % opening a truck needs
        "pressure_rate": 50.0,  # bar/s while closing against the seal
        "pressure_bar": 100.0,  # the pressure switch
        "max_bar": 130.0,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "boiler": (0, 1),
        "travel_s": (0.5, 600),
        "margin": (0.1, 50),
        "start_position": (0, 100),
        "approach_ms": (0, 600000),
        "pass_ms": (100, 600000),
        "clearance": (1, 100),
        "pressure_rate": (1, 10000),
        "pressure_bar": (1, 1000),
        "max_bar": (1, 2000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "outside": "I0.0",
        "inside": "I0.1",
        "ls_open": "I0.2",
        "ls_closed": "I0.3",
        "open": "Q0.0",
        "close": "Q0.1",
    }

    def reset(self) -> None:
        p = self.params
        self.boiler = bool(p["boiler"])
        self.position = p["start_position"]
        self.pressure = 0.0
        self.truck_phase = _NO_TRUCK
        self.truck_ms = 0.0
        self.truck_button = 0
        self.trucks_passed = 0

    def step(self, dt_ms: int) -> None:
        p = self.params
        opening = self.actuators["open"]
        closing = self.actuators["close"]
        if opening and closing:
            self.raise_fault("both_directions")
        elif opening:
            if self.pressure > 0:  # the seal lets go before the door moves
                self.pressure = 0.0
            else:
                self._move(100 / p["travel_s"] * dt_ms / 1000)
        elif closing:
            if self.inside_now():
                self.raise_fault("crush")
            self._close(dt_ms)
        self._truck(dt_ms)

    def _move(self, delta: float) -> None:
        margin = self.params["margin"]
        self.position += delta
        for end in (0.0, 100.0):  # no float dust at the limit switches: 100 x 0.1 % is 10 %
            if abs(self.position - end) < 1e-6:
                self.position = end
        if self.position > 100 + margin:
            self.position = 100 + margin
            self.raise_fault("overtravel")
        elif self.position < -margin:
            self.position = -margin
            self.raise_fault("overtravel")

    def _close(self, dt_ms: int) -> None:
        p = self.params
        if self.boiler and self.position <= 0:
            self.position = 0.0
            self.pressure += p["pressure_rate"] * dt_ms / 1000
            if self.pressure > p["max_bar"]:
                self.pressure = p["max_bar"]
                self.raise_fault("overpressure")
            return
        self._move(-100 / p["travel_s"] * dt_ms / 1000)

    def _truck(self, dt_ms: int) -> None:
        p = self.params
        pressed = self.controls["truck"]
        if pressed and not self.truck_button and self.truck_phase == _NO_TRUCK:
            self.truck_phase = _APPROACHING
            self.truck_ms = 0.0
        self.truck_button = pressed
        phase = self.truck_phase
        if phase == _NO_TRUCK:
            return
        self.truck_ms += dt_ms
        if phase == _APPROACHING and self.truck_ms >= p["approach_ms"]:
            self.truck_phase = _WAITING
        elif phase == _WAITING and self.position >= 100:
            self.truck_phase = _PASSING
            self.truck_ms = 0.0
        elif phase == _PASSING:
            if self.position < p["clearance"]:
                self.raise_fault("crush")
            if self.truck_ms >= p["pass_ms"]:
                self.truck_phase = _NO_TRUCK
                self.trucks_passed += 1

    def inside_now(self) -> bool:
        return bool(self.controls["inside"]) or self.truck_phase == _PASSING

    def inputs(self) -> dict[str, int]:
        """The simulated truck drives SS1/SS2 as a held button would."""
        values = super().inputs()
        if self.truck_phase == _WAITING:
            values["outside"] = 1
        elif self.truck_phase == _PASSING:
            values["inside"] = 1
        return values

    def sensors(self) -> dict[str, int]:
        return {
            "ls_open": int(self.position >= 100 and "ls_open_broken" not in self.active_faults),
            "ls_closed": int(self.position <= 0),
            "pressure_ok": int(self.pressure >= self.params["pressure_bar"]),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "position": round(self.position, 2),
            "pressure": round(self.pressure, 1),
            "truck": _TRUCK_PHASES[self.truck_phase],
            "trucks_passed": self.trucks_passed,
            "boiler": self.boiler,
        }

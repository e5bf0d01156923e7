"""P02: a three-phase motor on a contactor, with a thermal overload relay (start/stop latch).

The course wires it as every contactor circuit: start NO, stop NC, the overload relay's
auxiliary contact NC (1 = healthy), so a broken wire stops the motor as the button does. The
model: the speed ramps 0 -> 100 % in ``ramp_up_ms`` while the contactor is on and coasts down in
``coast_ms`` when it drops out; ``running`` is a speed monitor (1 above 10 % speed). A ``jam``
(injectable) blocks the rotor: the motor draws locked-rotor current, the thermal relay trips after
``trip_ms`` (its NC contact opens, ``overload`` reads 0). The relay protects only through the PLC,
as the course wires it: if the program keeps the contactor on for more than ``burn_ms`` after the
trip, the winding burns (``burnt``, raised; the motor stays dead until the plant is reset).
Clearing the jam resets the relay (the fitter freed the rotor and pressed the relay's reset).
``run_ms`` counts the time the motor turned, for run-time meter lessons.
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

RUNNING_PCT = 10.0


class Motor(Plant):
    kind = "motor"
    title = "Motor with contactor and overload relay"
    signals = (
        Signal("start", "control", description="start push button, NO"),
        Signal("stop", "control", normally_closed=True, description="stop push button, NC"),
        Signal(
            "overload",
            "sensor",
            normally_closed=True,
            description="thermal overload relay contact, NC: 1 = healthy, 0 = tripped",
        ),
        Signal("running", "sensor", description="speed monitor: 1 while the motor turns"),
        Signal("contactor", "actuator", description="contactor coil: powers the motor"),
        Signal("run_lamp", "actuator", description="green lamp: running"),
        Signal("fault_lamp", "actuator", description="red lamp: fault"),
    )
    faults = (
        Fault("jam", injectable=True, description="the load jams: the relay trips after trip_ms"),
        Fault("burnt", description="kept on for more than burn_ms after the relay tripped"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "ramp_up_ms": 1000,
        "coast_ms": 3000,
        "trip_ms": 5000,
        "burn_ms": 2000,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "ramp_up_ms": (1, 600_000),
        "coast_ms": (1, 600_000),
        "trip_ms": (0, 600_000),
        "burn_ms": (0, 600_000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "overload": "I0.2",
        "contactor": "Q4.0",
        "run_lamp": "Q4.1",
        "fault_lamp": "Q4.2",
    }

    def reset(self) -> None:
        self.speed = 0.0  # % of nominal speed
        self.heat_ms = 0.0  # locked-rotor time the thermal relay has integrated
        self.tripped = False
        self.after_trip_ms = 0.0  # time powered since the trip
        self.run_ms = 0

    def step(self, dt_ms: int) -> None:
        on = self.actuators["contactor"] == 1
        jammed = "jam" in self.active_faults
        burnt = "burnt" in self.active_faults
        if not jammed and self.tripped:
            self.tripped = False  # the rotor was freed and the relay reset
            self.heat_ms = 0.0
        if on and not burnt and not jammed:
            self.speed = min(100.0, self.speed + 100.0 * dt_ms / self.params["ramp_up_ms"])
        elif jammed:
            self.speed = 0.0  # blocked rotor
        else:
            self.speed = max(0.0, self.speed - 100.0 * dt_ms / self.params["coast_ms"])
        was_tripped = self.tripped  # the time after the trip counts from the step after it
        if on and jammed and not burnt:
            self.heat_ms += dt_ms
            if self.heat_ms >= self.params["trip_ms"]:
                self.tripped = True
        if was_tripped and on and not burnt:
            self.after_trip_ms += dt_ms
            if self.after_trip_ms > self.params["burn_ms"]:
                self.raise_fault("burnt")
                self.speed = 0.0
        elif not on:
            self.after_trip_ms = 0.0
        if self.speed > 0:
            self.run_ms += dt_ms

    def sensors(self) -> dict[str, int]:
        return {
            "overload": 0 if self.tripped else 1,
            "running": 1 if self.speed > RUNNING_PCT else 0,
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "speed": round(self.speed, 1),
            "tripped": self.tripped,
            "run_ms": self.run_ms,
            "contactor": self.actuators["contactor"] == 1,
        }

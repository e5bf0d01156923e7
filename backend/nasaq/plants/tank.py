"""P03: a water tank with a filling pump, a fill valve, a drain valve and level sensors.

Levels are in % of the tank's height. The level changes at fixed rates (% per second): the pump
adds ``pump_rate``, the fill valve ``valve_rate``, the drain valve takes ``drain_rate`` and the
consumers take ``use_rate`` all the time; ``level' = inflow - outflow``, clamped to 0..100 %.
A tank that is full while water still comes in overflows (``overflow``, raised: water on the
floor; it stays until the plant is reset).

Sensors, as the course wires them: ``ls_low`` is the low probe (1 = water at the probe, so 0
means "nearly empty"), ``ls_high`` the full switch (1 = full); both switch with a small
hysteresis (``hysteresis`` %) as a float switch does. ``level`` is a 4-20 mA transmitter on an
analog input: 0..27648 for 0..100 %. Faults to inject: ``ls_high_stuck`` (the full switch's float
sticks: it never reports full), ``level_wire_break`` (the transmitter's loop is open: the input
reads 32767, S7's overflow value, as an analog module reports a wire break).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

FULL_SCALE = 27648  # S7 analog input: nominal range 0..27648
WIRE_BREAK = 32767  # S7 analog input: overflow / wire break


class Tank(Plant):
    kind = "tank"
    title = "Water tank with pump, valves and level sensors"
    signals = (
        Signal("pump_pb", "control", description="pump start push button, NO"),
        Signal("stop_pb", "control", normally_closed=True, description="stop push button, NC"),
        Signal("auto", "control", description="selector switch: 1 = automatic"),
        Signal("ls_low", "sensor", description="low level probe: 1 = water at the probe"),
        Signal("ls_high", "sensor", description="full switch: 1 = tank full"),
        Signal("level", "sensor", "word", description="level transmitter: 0..27648 = 0..100 %"),
        Signal("pump", "actuator", description="filling pump contactor"),
        Signal("fill_valve", "actuator", description="inlet valve solenoid"),
        Signal("drain_valve", "actuator", description="drain valve solenoid"),
        Signal("alarm", "actuator", description="alarm horn and lamp"),
    )
    faults = (
        Fault("overflow", description="water came in while the tank was full"),
        Fault("ls_high_stuck", injectable=True, description="the full switch never reports full"),
        Fault("level_wire_break", injectable=True, description="the level input reads 32767"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "initial": 10.0,  # % at the start and after a reset
        "pump_rate": 5.0,  # %/s while the pump runs (empty to full in 20 s)
        "valve_rate": 2.5,  # %/s while the fill valve is open
        "drain_rate": 4.0,  # %/s while the drain valve is open (and there is water)
        "use_rate": 0.0,  # %/s consumers take all the time
        "low": 20.0,  # % at the low probe
        "high": 90.0,  # % at the full switch
        "hysteresis": 1.0,  # % a switch needs to fall below its level to open again
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "initial": (0, 100),
        "pump_rate": (0, 100),
        "valve_rate": (0, 100),
        "drain_rate": (0, 100),
        "use_rate": (0, 100),
        "low": (0, 100),
        "high": (0, 100),
        "hysteresis": (0, 10),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "pump_pb": "I0.0",
        "stop_pb": "I0.1",
        "ls_low": "I0.2",
        "ls_high": "I0.3",
        "level": "IW64",
        "pump": "Q4.0",
        "alarm": "Q4.1",
        "drain_valve": "Q4.2",
    }

    def reset(self) -> None:
        self.level = float(self.params["initial"])
        self.low_on = self.level >= self.params["low"]
        self.high_on = self.level >= self.params["high"]
        self.spilled = 0.0  # % of the tank's volume that ran over

    def step(self, dt_ms: int) -> None:
        a, p = self.actuators, self.params
        inflow = a["pump"] * p["pump_rate"] + a["fill_valve"] * p["valve_rate"]
        outflow = a["drain_valve"] * p["drain_rate"] + p["use_rate"]
        # Rounded to 1e-9 %: a sum of steps lands exactly on the level a learner computes
        # (85 % + 1 s at 5 %/s is 90 %, not 89.999999...), so a switch trips when it should.
        level = round(self.level + (inflow - outflow) * dt_ms / 1000.0, 9)
        if level > 100.0:
            self.spilled += level - 100.0
            level = 100.0
        if level >= 100.0 and inflow > outflow:
            self.raise_fault("overflow")
        self.level = max(0.0, level)
        hysteresis = p["hysteresis"]
        if self.level >= p["low"]:
            self.low_on = True
        elif self.level < p["low"] - hysteresis:
            self.low_on = False
        if self.level >= p["high"]:
            self.high_on = True
        elif self.level < p["high"] - hysteresis:
            self.high_on = False

    def sensors(self) -> dict[str, int]:
        faults = self.active_faults
        return {
            "ls_low": 1 if self.low_on else 0,
            "ls_high": 1 if self.high_on and "ls_high_stuck" not in faults else 0,
            "level": WIRE_BREAK
            if "level_wire_break" in faults
            else round(self.level * FULL_SCALE / 100.0),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "level": round(self.level, 2),
            "spilled": round(self.spilled, 2),
            "filling": self.actuators["pump"] == 1 or self.actuators["fill_valve"] == 1,
            "draining": self.actuators["drain_valve"] == 1 and self.level > 0,
        }

"""P08 + P17: a mixing vessel with a stirrer, an electric heater, an inlet and a drain valve.

Volume in % of the vessel: the fill valve adds ``fill_rate`` %/s, the drain valve takes
``drain_rate`` %/s. ``full`` closes at ``full_level`` %, ``empty`` is 1 at or below
``empty_level`` % (its probe is dry).

Temperature, a first-order thermal model: the heater brings ``heat_power`` (°C per second for a
full vessel; a fuller vessel heats slower, in proportion to its volume), the vessel loses heat to
the room in proportion to the difference: ``T' = P * heater * 100/volume - loss * (T - ambient)``.
Liquid that flows in at ``inlet_temp`` mixes with what is there. ``temperature`` is a Pt100
transmitter on an analog input, 0..27648 for 0..100 °C; ``hot`` closes at ``setpoint`` °C (a
thermostat contact). Stirring for ``mix_ms`` mixes the batch completely (``mixed`` %, reset when
the vessel runs empty).

Faults: ``overheat`` (raised above 95 °C), ``dry_heating`` (raised: the heater is on while the
vessel is empty: the element burns), ``heater_broken`` (injectable: the heater gives no heat).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

FULL_SCALE = 27648
OVERHEAT_C = 95.0
MIN_HEATED_PCT = 5.0  # below this the heat capacity is taken as this much liquid


class Mixer(Plant):
    kind = "mixer"
    title = "Mixer with heating"
    signals = (
        Signal("start", "control", description="start push button, NO"),
        Signal("stop", "control", normally_closed=True, description="stop push button, NC"),
        Signal("temperature", "sensor", "word", description="temperature: 0..27648 = 0..100 °C"),
        Signal("hot", "sensor", description="thermostat: 1 at or above the setpoint"),
        Signal("full", "sensor", description="full level switch"),
        Signal("empty", "sensor", description="empty probe: 1 = vessel empty"),
        Signal("stirrer", "actuator", description="stirrer motor"),
        Signal("heater", "actuator", description="heating element contactor"),
        Signal("fill_valve", "actuator", description="inlet valve"),
        Signal("drain_valve", "actuator", description="drain valve"),
    )
    faults = (
        Fault("overheat", description="the liquid went above 95 °C"),
        Fault("dry_heating", description="the heater was on in an empty vessel"),
        Fault("heater_broken", injectable=True, description="the heater gives no heat"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "initial": 0.0,  # % volume at the start
        "fill_rate": 5.0,  # %/s
        "drain_rate": 5.0,  # %/s
        "full_level": 95.0,
        "empty_level": 2.0,
        "ambient": 20.0,  # °C: the room, the start temperature
        "inlet_temp": 20.0,  # °C of the liquid flowing in
        "heat_power": 1.0,  # °C/s for a full vessel
        "loss": 0.002,  # 1/s: heat lost per °C above the room
        "setpoint": 60.0,  # °C at which ``hot`` closes
        "mix_ms": 150_000,  # stirring time for a complete mix (2 min 30 s)
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "initial": (0, 100),
        "fill_rate": (0, 100),
        "drain_rate": (0, 100),
        "full_level": (1, 100),
        "empty_level": (0, 50),
        "ambient": (0, 100),
        "inlet_temp": (0, 100),
        "heat_power": (0, 100),
        "loss": (0, 1),
        "setpoint": (0, 100),
        "mix_ms": (1, 3_600_000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "full": "I0.2",
        "empty": "I0.3",
        "hot": "I0.4",
        "temperature": "IW64",
        "stirrer": "Q0.0",
        "heater": "Q0.1",
        "fill_valve": "Q0.2",
        "drain_valve": "Q0.3",
    }

    def reset(self) -> None:
        self.volume = float(self.params["initial"])
        self.temperature = float(self.params["ambient"])
        self.mixed = 0.0

    def step(self, dt_ms: int) -> None:
        a, p = self.actuators, self.params
        seconds = dt_ms / 1000.0
        volume = self.volume
        added = min(100.0 - volume, a["fill_valve"] * p["fill_rate"] * seconds)
        if added > 0:
            self.temperature = (self.temperature * volume + p["inlet_temp"] * added) / (
                volume + added
            )
        volume += added
        volume = max(0.0, volume - a["drain_valve"] * p["drain_rate"] * seconds)
        self.volume = round(volume, 9)  # sums of steps land on the levels one computes
        empty = volume <= p["empty_level"]
        heating = a["heater"] == 1 and "heater_broken" not in self.active_faults
        if a["heater"] == 1 and empty:
            self.raise_fault("dry_heating")
        power = p["heat_power"] * 100.0 / max(volume, MIN_HEATED_PCT) if heating else 0.0
        change = (power - p["loss"] * (self.temperature - p["ambient"])) * seconds
        self.temperature = round(self.temperature + change, 9)
        if self.temperature > OVERHEAT_C:
            self.raise_fault("overheat")
        self.temperature = min(self.temperature, 150.0)
        if empty:
            self.mixed = 0.0
        elif a["stirrer"] == 1:
            self.mixed = min(100.0, self.mixed + 100.0 * dt_ms / p["mix_ms"])

    def sensors(self) -> dict[str, int]:
        p = self.params
        raw = round(min(max(self.temperature, 0.0), 100.0) * FULL_SCALE / 100.0)
        return {
            "temperature": raw,
            "hot": 1 if self.temperature >= p["setpoint"] else 0,
            "full": 1 if self.volume >= p["full_level"] else 0,
            "empty": 1 if self.volume <= p["empty_level"] else 0,
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "volume": round(self.volume, 2),
            "temperature": round(self.temperature, 2),
            "mixed": round(self.mixed, 1),
            "stirring": self.actuators["stirrer"] == 1,
            "heating": self.actuators["heater"] == 1 and "heater_broken" not in self.active_faults,
        }

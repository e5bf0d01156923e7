"""P12 double-acting hydraulic cylinder: the press of E-vi-13, the clamp of E-vi-31 and the
press-fit of Bài 7 (seed 004), with valves 1Y1 (extend) and 1Y2 (retract).

``position`` is the ram's stroke in % (0 = at rest, 100 = end of stroke), moved at
``100 / stroke_s`` %/s while one valve is on. With both valves off the ram holds where it is (a
closed-centre valve), which is what "S3 stops the ram where it is" relies on. The rest switch S4
reads 1 at or below ``switch_band`` %, the end switch S5 at or above ``100 - switch_band`` %.

Pressure (bar) in the extend chamber: ``free_bar`` while the ram moves freely; when it is
blocked (at the end of the stroke, or on the work piece at ``work_at`` % for a press-fit) and
1Y1 stays on, it rises at ``rise_rate`` bar/s up to ``supply_bar``. The pressure switch
``pressure_ok`` reads 1 from ``switch_bar`` (20 bar in Bài 7). With 1Y1 off the pressure falls
at ``fall_rate``. This is how the clamp of E-vi-31 builds its clamping force after LS2.

``lamp`` (lamp H of Bài 7) is only drawn. ``both_valves``: 1Y1 and 1Y2 on together.
``strokes`` counts extensions that reached the work piece or the end switch. Injectable:
``pressure_switch_stuck`` (the 20-bar switch never trips: the press-fit never returns by itself).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue


class Cylinder(Plant):
    kind = "cylinder"
    title = "Hydraulic cylinder (press, clamp, press-fit)"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("s1", "control", description="S1: start push button"),
        Signal("s2", "control", description="S2: return push button"),
        Signal("s3", "control", description="S3: stop push button"),
        Signal("rest", "sensor", description="S4: ram at rest (retracted)"),
        Signal("end", "sensor", description="S5: ram at the end of the stroke"),
        Signal("pressure_ok", "sensor", description="Pressure switch (20 bar)"),
        Signal("extend", "actuator", description="1Y1: valve, ram extends"),
        Signal("retract", "actuator", description="1Y2: valve, ram retracts"),
        Signal("lamp", "actuator", description="Lamp H"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("both_valves", description="1Y1 and 1Y2 were on together"),
        Fault("pressure_switch_stuck", injectable=True, description="The switch never trips"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "stroke_s": 2.0,  # s for a full stroke either way
        "switch_band": 1.0,  # % of stroke where S4/S5 are made
        "work_at": 100.0,  # % where the ram meets the work piece (100: only the end stops it)
        "start_position": 0.0,  # %
        "free_bar": 5.0,
        "supply_bar": 60.0,
        "rise_rate": 40.0,  # bar/s while blocked
        "fall_rate": 200.0,  # bar/s with 1Y1 off
        "switch_bar": 20.0,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "stroke_s": (0.05, 600),
        "switch_band": (0.1, 20),
        "work_at": (1, 100),
        "start_position": (0, 100),
        "free_bar": (0, 1000),
        "supply_bar": (1, 1000),
        "rise_rate": (1, 100000),
        "fall_rate": (1, 100000),
        "switch_bar": (0, 1000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "s1": "I0.0",
        "s2": "I0.1",
        "s3": "I0.2",
        "rest": "I0.3",
        "end": "I0.4",
        "pressure_ok": "I0.5",
        "extend": "Q0.0",
        "retract": "Q0.1",
        "lamp": "Q0.2",
    }

    def reset(self) -> None:
        p = self.params
        if p["start_position"] > p["work_at"]:
            raise PlantError(
                "cylinder: start_position is beyond work_at", "PLT020", ("params", "start_position")
            )
        self.position = p["start_position"]
        self.pressure = 0.0
        self.peak_pressure = 0.0
        self.strokes = 0  # extensions that reached the work piece or the end switch
        self.counted = False  # this stroke is counted; cleared back at rest
        self.stroke_done = min(p["work_at"], 100 - p["switch_band"])

    def step(self, dt_ms: int) -> None:
        p = self.params
        extend = self.actuators["extend"]
        retract = self.actuators["retract"]
        seconds = dt_ms / 1000
        speed = 100 / p["stroke_s"] * seconds
        if extend and retract:
            self.raise_fault("both_valves")
        elif extend:
            stop = p["work_at"]
            if self.position < stop:
                self.position = min(stop, self.position + speed)
                self.pressure = p["free_bar"]
            else:
                self.pressure = min(p["supply_bar"], self.pressure + p["rise_rate"] * seconds)
            if self.position >= self.stroke_done and not self.counted:
                self.counted = True
                self.strokes += 1
        else:
            self.pressure = max(0.0, self.pressure - p["fall_rate"] * seconds)
            if retract:
                self.position = max(0.0, self.position - speed)
                if self.position <= p["switch_band"]:
                    self.counted = False
        self.peak_pressure = max(self.peak_pressure, self.pressure)

    def sensors(self) -> dict[str, int]:
        band = self.params["switch_band"]
        return {
            "rest": int(self.position <= band),
            "end": int(self.position >= 100 - band),
            "pressure_ok": int(
                self.pressure >= self.params["switch_bar"]
                and "pressure_switch_stuck" not in self.active_faults
            ),
        }

    def state(self) -> dict[str, StateValue]:
        return {
            "position": round(self.position, 2),
            "pressure": round(self.pressure, 1),
            "peak_pressure": round(self.peak_pressure, 1),
            "strokes": self.strokes,
            "lamp": bool(self.actuators["lamp"]),
        }

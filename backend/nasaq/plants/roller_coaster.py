"""P13 roller-coaster train (seed 004, E-vi-29): the siren must warn the passengers for 15 s
before the train leaves the station.

The train runs a closed track of ``track_m`` metres; it starts at the station (position 0). With
``drive`` on it accelerates at ``accel`` to ``top_speed``; with ``drive`` off it brakes at
``brake``. ``station`` reads 1 while the train is within ``station_m`` of the station (it also
does during a ride whenever the train passes through). ``laps`` counts passes of the station.

``no_warning`` is raised when the drive starts a standing train without a warning: the siren
must have sounded for at least ``warn_ms`` (less ``tolerance_ms`` for the timer's resolution),
and be sounding still or have stopped at most ``gap_ms`` earlier. The Stop push button of the
lesson exercise is wired NC (1 = not pressed), like every stop button of the course.
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, PlantError, Signal, StateValue


class RollerCoaster(Plant):
    kind = "roller_coaster"
    title = "Roller-coaster train"
    signals: ClassVar[tuple[Signal, ...]] = (
        Signal("start", "control", description="Start push button"),
        Signal("stop", "control", normally_closed=True, description="Stop push button (NC)"),
        Signal("station", "sensor", description="1 while the train is in the station"),
        Signal("drive", "actuator", description="Train drive"),
        Signal("siren", "actuator", description="Warning siren"),
    )
    faults: ClassVar[tuple[Fault, ...]] = (
        Fault("no_warning", description="The train left without 15 s of siren"),
    )
    defaults: ClassVar[dict[str, float]] = {
        "track_m": 400.0,
        "station_m": 10.0,
        "top_speed": 10.0,  # m/s
        "accel": 2.0,  # m/s²
        "brake": 3.0,  # m/s²
        "warn_ms": 15000,
        "tolerance_ms": 200,
        "gap_ms": 1000,
    }
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "track_m": (20, 10000),
        "station_m": (1, 1000),
        "top_speed": (0.1, 100),
        "accel": (0.1, 50),
        "brake": (0.1, 50),
        "warn_ms": (0, 600000),
        "tolerance_ms": (0, 10000),
        "gap_ms": (0, 60000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "start": "I0.0",
        "stop": "I0.1",
        "station": "I0.2",
        "drive": "Q0.0",
        "siren": "Q0.1",
    }

    def reset(self) -> None:
        p = self.params
        if p["track_m"] <= 2 * p["station_m"]:
            raise PlantError(
                "roller_coaster: the track must be longer than 2 x station_m",
                "PLT020",
                ("params", "station_m"),
            )
        self.position = 0.0
        self.speed = 0.0
        self.laps = 0
        self.siren_on_ms = 0.0  # length of the current (or last) siren sounding
        self.siren_off_ms = 0.0  # time since the siren went quiet
        self.drive_was = 0
        self.warned = False

    def step(self, dt_ms: int) -> None:
        p = self.params
        drive = self.actuators["drive"]
        if self.actuators["siren"]:
            if self.siren_off_ms > 0:
                self.siren_on_ms = 0.0
                self.siren_off_ms = 0.0
            self.siren_on_ms += dt_ms
        elif self.siren_on_ms > 0:
            self.siren_off_ms += dt_ms
        if drive and not self.drive_was and self.speed == 0:
            self.warned = (
                self.siren_on_ms >= p["warn_ms"] - p["tolerance_ms"]
                and self.siren_off_ms <= p["gap_ms"]
            )
            if not self.warned:
                self.raise_fault("no_warning")
        self.drive_was = drive
        seconds = dt_ms / 1000
        if drive:
            self.speed = min(p["top_speed"], self.speed + p["accel"] * seconds)
        else:
            self.speed = max(0.0, self.speed - p["brake"] * seconds)
        self.position += self.speed * seconds
        if self.position >= p["track_m"]:
            self.position -= p["track_m"]
            self.laps += 1

    def sensors(self) -> dict[str, int]:
        p = self.params
        at = self.position
        return {"station": int(at <= p["station_m"] or at >= p["track_m"] - p["station_m"])}

    def state(self) -> dict[str, StateValue]:
        return {
            "position": round(self.position, 2),
            "speed": round(self.speed, 2),
            "laps": self.laps,
            "siren": bool(self.actuators["siren"]),
            "warned": self.warned,
        }

"""P01: the relay-era wiring board of the first lessons: five push buttons, a contactor, lamps.

Push buttons S1..S5 go to 24 V inputs; each is NO unless the bit n of ``nc_mask`` makes S(n+1)
an NC contact (then its input reads 1 while it is not pressed, as the course's stop buttons).
The contactor K1 pulls in ``pull_in_ms`` after its coil (``k1``) is energised and drops out as
long after it is switched off; ``k1_aux`` is its auxiliary NO contact, so a program can see that
the contactor really closed. Lamps H1..H4 only light. The injectable ``wire_break`` cuts S1's
wire: its input reads 0 whatever the button does (an NC button then looks pressed: the fail-safe
reason for wiring stop buttons NC).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Fault, Plant, Signal, StateValue

BUTTONS = ("s1", "s2", "s3", "s4", "s5")


class Panel(Plant):
    kind = "panel"
    title = "Push-button, lamp and contactor panel"
    signals = (
        *(Signal(name, "control", description=f"push button {name.upper()}") for name in BUTTONS),
        Signal("k1_aux", "sensor", description="auxiliary contact of K1: 1 = contactor closed"),
        Signal("k1", "actuator", description="coil of contactor K1"),
        Signal("h1", "actuator", description="lamp H1"),
        Signal("h2", "actuator", description="lamp H2"),
        Signal("h3", "actuator", description="lamp H3"),
        Signal("h4", "actuator", description="lamp H4"),
    )
    faults = (
        Fault("wire_break", injectable=True, description="S1's wire is cut: its input reads 0"),
    )
    defaults: ClassVar[dict[str, float]] = {"nc_mask": 0, "pull_in_ms": 20}
    limits: ClassVar[dict[str, tuple[float, float]]] = {
        "nc_mask": (0, 31),
        "pull_in_ms": (0, 10_000),
    }
    default_wiring: ClassVar[dict[str, str]] = {
        "s1": "I0.0",
        "s2": "I0.1",
        "s3": "I0.2",
        "s4": "I0.3",
        "s5": "I0.4",
        "k1": "Q2.0",
        "h1": "Q2.1",
        "h2": "Q2.2",
        "h3": "Q2.3",
        "h4": "Q2.4",
    }

    def reset(self) -> None:
        mask = int(self.params["nc_mask"])
        self.nc = tuple(bool(mask >> n & 1) for n in range(len(BUTTONS)))
        for n, name in enumerate(BUTTONS):
            self.controls[name] = 1 if self.nc[n] else 0  # not pressed
        self.closed = False  # K1's contacts
        self.coil_ms = 0.0  # how long the coil has been in its present state

    def step(self, dt_ms: int) -> None:
        coil = self.actuators["k1"] == 1
        if coil == self.closed:
            self.coil_ms = 0.0
            return
        self.coil_ms += dt_ms
        if self.coil_ms >= self.params["pull_in_ms"]:
            self.closed = coil
            self.coil_ms = 0.0

    def sensors(self) -> dict[str, int]:
        return {"k1_aux": 1 if self.closed else 0}

    def inputs(self) -> dict[str, int]:
        found = {**self.controls, "k1_aux": 1 if self.closed else 0}
        if "wire_break" in self.active_faults:
            found["s1"] = 0
        return found

    def state(self) -> dict[str, StateValue]:
        found: dict[str, StateValue] = {"k1": self.closed, "nc_mask": int(self.params["nc_mask"])}
        for n, name in enumerate(BUTTONS):
            found[f"{name}_pressed"] = self.controls[name] != (1 if self.nc[n] else 0)
        for lamp in ("h1", "h2", "h3", "h4"):
            found[lamp] = self.actuators[lamp] == 1
        return found

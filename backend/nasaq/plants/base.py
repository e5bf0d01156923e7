"""The contract every virtual plant keeps: signals, parameters, a step in virtual time, faults.

A plant is a deterministic model of a process (a tank, a conveyor, a motor). The simulation
session and the scenario runner own the clock: between two scans they hand the plant the PLC's
outputs, call ``step(dt_ms)`` with the virtual time that passed, and write the plant's sensor
values into the PLC's peripheral inputs. Nothing here knows about the CPU or about addresses;
the wiring (signal name -> address) is the lesson's or the project's, see ``runtime.py``.

Signals have a direction seen from the PLC, as on a wiring diagram:
- ``sensor``: the plant drives a PLC input (a level switch, a photo-eye, an analog level).
- ``control``: the operator panel drives a PLC input (a push button, a selector switch); the
  learner presses it in the drawing, a scenario with ``operate``. A push button is momentary in
  the drawing; the model only keeps the value it was given. The value is the level the contact
  gives the PLC input, as on the wiring diagram: pressing an NC stop button is ``0``, releasing
  it ``1`` (``operate: {stop: 0}`` in a scenario presses stop).
- ``actuator``: a PLC output drives the plant (a pump contactor, a valve solenoid, an analog
  speed setpoint).
Kinds: ``bool`` (one bit) and ``word`` (an INT word, e.g. 0..27648 for an analog channel).

Determinism: a plant uses no wall clock and no global random state; ``random.Random(seed)``
from its parameters where it needs chance (cars arriving), so a check in the browser and in
``nasaq test`` agree exactly.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Literal

Direction = Literal["sensor", "control", "actuator"]
SignalKind = Literal["bool", "word"]
StateValue = int | float | bool | str


@dataclass(frozen=True, slots=True)
class Signal:
    """One terminal of the plant. ``normally_closed`` marks an NC contact (a stop button, an
    overload relay): its input is 1 while nothing happens, as the course books wire them."""

    name: str
    direction: Direction
    kind: SignalKind = "bool"
    normally_closed: bool = False
    description: str = ""


@dataclass(frozen=True, slots=True)
class Fault:
    """A fault the plant can raise by itself (``raised``: the tank overflowed, the motor burnt)
    or that a scenario or the learner injects (``injectable``: a sensor sticks, a wire breaks).
    ``code`` is the stable name checks and the drawing use."""

    code: str
    injectable: bool = False
    description: str = ""


class PlantError(ValueError):
    """Bad plant parameters, an unknown signal, control or fault; the message says which.

    ``code`` is the diagnostic (``PLT###``, ``diagnostics/plants.csv``) with ``params``;
    ``subject`` names the part of the configuration at fault (``("wiring", "pump")``,
    ``("params", "fill_rate")``, ``("faults", "jam")``, ``("kind",)``), so a plant file or a
    lesson's ``plant:`` block can point at its line."""

    def __init__(
        self,
        message: str,
        code: str = "PLT020",
        subject: tuple[str, ...] = (),
        **params: object,
    ) -> None:
        super().__init__(message)
        self.code = code
        self.subject = subject
        self.params: dict[str, object] = params or {"reason": message}


class Plant:
    """Base of every plant model. Subclasses set the class attributes and implement ``step``,
    ``sensors`` and ``state``; they keep their state in plain attributes (no per-step churn)."""

    kind: ClassVar[str]  # the id lessons and projects name: "tank", "motor", ...
    title: ClassVar[str]  # English name; the drawings translate by ``kind``
    signals: ClassVar[tuple[Signal, ...]]
    faults: ClassVar[tuple[Fault, ...]] = ()
    defaults: ClassVar[dict[str, float]] = {}  # parameters and their default values
    # The range a parameter must lie in, (low, high) inclusive; parameters not listed: any value.
    limits: ClassVar[dict[str, tuple[float, float]]] = {}
    default_wiring: ClassVar[dict[str, str]] = {}  # the course's usual I/O for this plant

    def __init__(self, params: dict[str, float] | None = None) -> None:
        given = dict(params or {})
        for name in sorted(given):
            if name not in self.defaults:
                known = ", ".join(sorted(self.defaults)) or "-"
                raise PlantError(
                    f"{self.kind}: no parameter '{name}' (known: {known})",
                    "PLT008",
                    ("params", name),
                    kind=self.kind,
                    param=name,
                    known=known,
                )
            low, high = self.limits.get(name, (float("-inf"), float("inf")))
            value = given[name]
            if (
                not isinstance(value, int | float)
                or isinstance(value, bool)
                or not low <= value <= high
            ):
                raise PlantError(
                    f"{self.kind}: {name} = {value} is outside {low:g} .. {high:g}",
                    "PLT009",
                    ("params", name),
                    param=name,
                    value=str(value),
                    low=f"{low:g}",
                    high=f"{high:g}",
                )
        self.params: dict[str, float] = {**self.defaults, **given}
        self.time_ms = 0
        self.active_faults: set[str] = set()  # raised and injected faults, by code
        self.controls: dict[str, int] = {
            s.name: (1 if s.normally_closed else 0)
            for s in self.signals
            if s.direction == "control"
        }
        self.actuators: dict[str, int] = {
            s.name: 0 for s in self.signals if s.direction == "actuator"
        }
        self.reset()

    # -- what subclasses implement ------------------------------------------------------------
    def reset(self) -> None:
        """Back to the initial state (called by ``__init__`` and on a plant reset)."""

    def step(self, dt_ms: int) -> None:
        """Advance the process by ``dt_ms`` of virtual time, reading ``self.actuators``."""
        raise NotImplementedError

    def sensors(self) -> dict[str, int]:
        """The value of every ``sensor`` signal now (bits 0/1, words as unsigned 16-bit)."""
        raise NotImplementedError

    def state(self) -> dict[str, StateValue]:
        """What the drawing animates and scenarios can expect (``plant.<name>``): levels,
        positions, counts. Plain numbers, booleans and short strings only."""
        raise NotImplementedError

    # -- shared behaviour ---------------------------------------------------------------------
    def advance(self, dt_ms: int) -> None:
        """The session's and the runner's entry point: step and count the time."""
        if dt_ms > 0:
            self.step(dt_ms)
            self.time_ms += dt_ms

    def inputs(self) -> dict[str, int]:
        """Every value the plant drives into PLC inputs: sensors and panel controls."""
        return {**self.sensors(), **self.controls}

    def set_actuators(self, values: dict[str, int]) -> None:
        for name, value in values.items():
            if name not in self.actuators:
                raise PlantError(
                    f"{self.kind}: no actuator '{name}'", "PLT003", kind=self.kind, signal=name
                )
            self.actuators[name] = int(value)

    def operate(self, control: str, value: int) -> None:
        """The operator presses, releases or turns a panel control: ``value`` is the level the
        PLC input sees (an NC button pressed is 0); a word control takes 0..65535 (or an INT,
        -32768..-1, as its two's complement)."""
        if control not in self.controls:
            known = ", ".join(self.controls) or "-"
            raise PlantError(
                f"{self.kind}: no control '{control}' (controls: {known})",
                "PLT014",
                kind=self.kind,
                control=control,
                known=known,
            )
        word = self.signal(control).kind == "word"
        low, high = (-32768, 65535) if word else (0, 1)
        if isinstance(value, bool):
            value = int(value)
        if not isinstance(value, int) or not low <= value <= high:
            raise PlantError(
                f"{self.kind}: {control} takes {low} .. {high}, not {value}",
                "PLT016",
                control=control,
                value=str(value),
                low=low,
                high=high,
            )
        self.controls[control] = value & 0xFFFF

    def inject(self, code: str, on: bool = True) -> None:
        """Inject (or clear) an injectable fault."""
        if code not in {f.code for f in self.faults if f.injectable}:
            known = ", ".join(f.code for f in self.faults if f.injectable) or "-"
            raise PlantError(
                f"{self.kind}: no injectable fault '{code}' (injectable: {known})",
                "PLT010",
                ("faults", code),
                kind=self.kind,
                fault=code,
                known=known,
            )
        if on:
            self.active_faults.add(code)
        else:
            self.active_faults.discard(code)

    def raise_fault(self, code: str) -> None:
        """For subclasses: the process did something that must not happen."""
        self.active_faults.add(code)

    def fault_active(self, code: str) -> bool:
        return code in self.active_faults

    @classmethod
    def signal(cls, name: str) -> Signal:
        for signal in cls.signals:
            if signal.name == name:
                return signal
        known = ", ".join(s.name for s in cls.signals)
        raise PlantError(
            f"{cls.kind}: no signal '{name}' (signals: {known})",
            "PLT003",
            ("wiring", name),
            kind=cls.kind,
            signal=name,
            known=known,
        )

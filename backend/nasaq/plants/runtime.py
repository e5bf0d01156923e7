"""A plant wired to a CPU: the one loop the simulation session and the scenario runner share.

Per scan: ``write_inputs(cpu)`` before it (sensors and panel controls into the peripheral
inputs, which the scan's PII update reads), ``read_outputs(cpu)`` after it (the PIQ the scan
wrote, or the peripheral outputs for ``PQW``), then ``advance(dt_ms)`` with the virtual time of
the scan. A check in ``nasaq test`` and the animation in the browser run this same code.

The configuration (``PlantConfig``) is what a lesson's ``plant:`` block and a project's
``<name>.plant`` file contain::

    kind: tank
    wiring: {pump: Q4.0, stop_pb: I0.1, ls_low: I0.2, level: PIW256}
    params: {fill_rate: 5}
    faults: [ls_high_stuck]          # injected from the start (find-the-fault lessons)

Sensors and controls are wired to inputs (``I``, ``E``, ``PI``), actuators to outputs (``Q``,
``A``, ``PQ``) or markers; bits for ``bool`` signals, words for ``word`` signals. A signal left
out of the wiring is not connected (its control still works in the drawing). Two signals may not
drive the same input bit; one output may drive several actuators.

Inputs go to the simulated input modules (the peripheral inputs), so the plant drives them as a
field device does: a value set by hand on a wired input is overwritten before the next scan,
and a force still wins at the PII update, as in PLCSIM. Outputs are read from the output modules
(``PQ``): what the scan's PIQ transfer put out, with forced outputs, and 0 in STOP, so a CPU
that stops switches the plant's pumps off as a real one does.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from nasaq.cpu import Cpu
from nasaq.headless.addresses import AddressError, parse_address
from nasaq.ir import Area, Direct, Width
from nasaq.plants.base import Plant, PlantError, StateValue
from nasaq.plants.registry import plant_class

MAX_STEP_MS = 100  # the longest single step of a plant model

# The smallest CPU's I, Q, M, PI and PQ areas (S7-300: 2048 bytes each); a wire beyond them would
# address nothing.
LAST_BYTE = 2047

_PERIPHERAL = re.compile(r"^P\s*(?P<io>[IEQA])\s*(?P<size>[BWD])\s*(?P<byte>\d+)$")


class PlantConfig(BaseModel):
    model_config = ConfigDict(extra="forbid")

    kind: str = Field(min_length=1, description="The plant's kind, e.g. tank, motor, conveyor")
    wiring: dict[str, str] = Field(default_factory=dict, description="signal name -> address")
    params: dict[str, float] = Field(default_factory=dict)
    faults: list[str] = Field(default_factory=list, description="Faults injected at the start")


@dataclass(frozen=True, slots=True)
class Wire:
    signal: str
    address: Direct
    text: str


def parse_wire_address(text: str) -> Direct:
    """``I0.2``, ``Q4.0``, ``IW64``, ``PIW256``, ``PQW272``, ``M10.0`` -> a direct address."""
    cleaned = text.strip().upper()
    if match := _PERIPHERAL.match(cleaned):
        area = Area.PI if match["io"] in "IE" else Area.PQ
        width = {"B": Width.BYTE, "W": Width.WORD, "D": Width.DWORD}[match["size"]]
        return Direct(area, width, int(match["byte"]), 0, None)
    found = parse_address(cleaned)
    if not isinstance(found, Direct) or found.area not in (Area.I, Area.Q, Area.M):
        raise AddressError(f"{text}: a plant is wired to inputs, outputs or markers")
    return found


def _input_bits(address: Direct) -> set[tuple[int, int]]:
    """The input bits a wire drives (I and PI are one space: an I wire drives the module)."""
    if address.width is Width.BIT:
        return {(address.byte, address.bit or 0)}
    return {(address.byte + k, bit) for k in range(int(address.width) // 8) for bit in range(8)}


def wires_of(plant_type: type[Plant], wiring: dict[str, str]) -> list[Wire]:
    """Checks every wire against the plant's signals; raises ``PlantError`` naming the wire
    (its ``subject`` is ``("wiring", <signal>)``)."""
    wires: list[Wire] = []
    driven: dict[tuple[int, int], str] = {}
    kind = plant_type.kind
    for name, text in wiring.items():
        signal = plant_type.signal(name)
        where = ("wiring", name)
        try:
            address = parse_wire_address(str(text))
        except AddressError:
            raise PlantError(
                f"{kind}: wire {name}: {text} is not an address a plant can be wired to",
                "PLT011",
                where,
                signal=name,
                address=str(text),
            ) from None
        drives_input = signal.direction in ("sensor", "control")
        if drives_input and address.area not in (Area.I, Area.PI):
            raise PlantError(
                f"{kind}: wire {name}: a {signal.direction} goes to an input, not {text}",
                "PLT004",
                where,
                signal=name,
                address=str(text),
            )
        if not drives_input and address.area in (Area.I, Area.PI):
            raise PlantError(
                f"{kind}: wire {name}: an actuator comes from an output or marker, not {text}",
                "PLT005",
                where,
                signal=name,
                address=str(text),
            )
        if signal.kind == "bool" and address.width is not Width.BIT:
            raise PlantError(
                f"{kind}: wire {name}: {name} needs a bit address, not {text}",
                "PLT006",
                where,
                signal=name,
                address=str(text),
            )
        if signal.kind == "word" and address.width is not Width.WORD:
            raise PlantError(
                f"{kind}: wire {name}: {name} needs a word address, not {text}",
                "PLT007",
                where,
                signal=name,
                address=str(text),
            )
        if address.byte + max(1, int(address.width) // 8) - 1 > LAST_BYTE:
            raise PlantError(
                f"{kind}: wire {name}: {text} is beyond the CPU's bytes 0 to {LAST_BYTE}",
                "PLT019",
                where,
                signal=name,
                address=str(text),
                last=LAST_BYTE,
            )
        if drives_input:
            for bit in _input_bits(address):
                other = driven.get(bit)
                if other is not None:
                    raise PlantError(
                        f"{kind}: wire {name}: {other} drives {text} already",
                        "PLT012",
                        where,
                        signal=name,
                        other=other,
                        address=str(text),
                    )
                driven[bit] = name
        wires.append(Wire(name, address, str(text)))
    return wires


def check_config(config: PlantConfig) -> PlantRuntime:
    """A runtime for ``config``, or ``PlantError`` (with ``subject``) for the first problem:
    the kind, a parameter, a wire or a fault. What a lesson lint and a plant file use."""
    return PlantRuntime(config)


class PlantRuntime:
    """One plant instance and its wires to one CPU."""

    def __init__(self, config: PlantConfig) -> None:
        plant_type = plant_class(config.kind)
        self.config = config
        self.plant: Plant = plant_type(config.params)
        wires = wires_of(plant_type, config.wiring)
        directions = {s.name: s.direction for s in plant_type.signals}
        # Inputs: the peripheral inputs the next scan's PII update reads. Outputs: what the
        # output modules put out (PQ, after the scan's PIQ transfer and the forces), a marker as
        # it is. Byte offsets and masks are worked out once here: a scan touches bytes only.
        inputs = [w for w in wires if directions[w.signal] != "actuator"]
        outputs = [w for w in wires if directions[w.signal] == "actuator"]
        self._bit_inputs = [
            (w.signal, w.address.byte, 1 << (w.address.bit or 0))
            for w in inputs
            if w.address.width is Width.BIT
        ]
        self._word_inputs = [
            (w.signal, w.address.byte) for w in inputs if w.address.width is not Width.BIT
        ]
        self._bit_outputs = [
            (w.signal, w.address.area is Area.M, w.address.byte, 1 << (w.address.bit or 0))
            for w in outputs
            if w.address.width is Width.BIT
        ]
        self._word_outputs = [
            (w.signal, w.address.area is Area.M, w.address.byte)
            for w in outputs
            if w.address.width is not Width.BIT
        ]
        self.wiring = {w.signal: w.text for w in wires}
        for code in config.faults:
            self.plant.inject(code)

    def write_inputs(self, cpu: Cpu) -> None:
        """Sensors and panel controls into the peripheral inputs (what ``Cpu.set_input`` does,
        without making an address per wire and scan)."""
        values = self.plant.inputs()
        pi = cpu.engine.memory.PI
        for name, byte, mask in self._bit_inputs:
            if values[name]:
                pi[byte] |= mask
            else:
                pi[byte] &= ~mask & 0xFF
        for name, byte in self._word_inputs:
            value = values[name] & 0xFFFF
            pi[byte] = value >> 8
            pi[byte + 1] = value & 0xFF

    def read_outputs(self, cpu: Cpu) -> None:
        """The actuators as the outputs drive them. Outside RUN the output modules are
        disabled (S7's BASP: a CPU in STOP puts out 0), so outputs read 0; markers keep theirs."""
        actuators = self.plant.actuators
        memory = cpu.engine.memory
        pq, m = memory.PQ, memory.M
        running = cpu.mode == "RUN"
        for name, marker, byte, mask in self._bit_outputs:
            if marker:
                actuators[name] = 1 if m[byte] & mask else 0
            else:
                actuators[name] = 1 if running and pq[byte] & mask else 0
        for name, marker, byte in self._word_outputs:
            area = m if marker else pq
            actuators[name] = (area[byte] << 8 | area[byte + 1]) if running or marker else 0

    def advance(self, dt_ms: int) -> None:
        """Steps the plant ``dt_ms`` of virtual time, in steps of at most ``MAX_STEP_MS`` (a long
        cycle or a jump of the clock in ``real`` mode must not let a bottle skip a photo-eye)."""
        plant = self.plant
        while dt_ms > MAX_STEP_MS:
            plant.advance(MAX_STEP_MS)
            dt_ms -= MAX_STEP_MS
        plant.advance(dt_ms)

    def operate(self, control: str, value: int) -> None:
        self.plant.operate(control, value)

    def inject(self, code: str, on: bool = True) -> None:
        self.plant.inject(code, on)

    def reset(self) -> None:
        plant = self.plant
        plant.time_ms = 0
        plant.active_faults.clear()
        plant.reset()
        for code in self.config.faults:
            plant.inject(code)

    def state(self) -> dict[str, StateValue]:
        return self.plant.state()

    def faults(self) -> list[str]:
        return sorted(self.plant.active_faults)

    def snapshot(self) -> dict[str, Any]:
        """What a frame carries for the drawing: kind, time, state, every signal's value, faults."""
        plant = self.plant
        return {
            "kind": plant.kind,
            "time_ms": plant.time_ms,
            "state": plant.state(),
            "signals": {**plant.inputs(), **plant.actuators},
            "faults": self.faults(),
            "wiring": dict(self.wiring),
        }

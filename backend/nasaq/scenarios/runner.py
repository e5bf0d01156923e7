"""Runs one scenario against a fresh CPU and collects every mismatch.

The sources' ``cpu.properties`` (``nasaq.headless.project_file``) sets the CPU; the scenario's
own ``profile`` and ``cycle_ms``, when the file names them, win over it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from nasaq.cpu import Cpu, Profile
from nasaq.headless import project_file
from nasaq.headless.addresses import (
    AddressError,
    CounterAddress,
    TimerAddress,
    address_text,
    as_real,
    encode_value,
    parse_address,
    parse_number,
    signed,
)
from nasaq.headless.sources import SourceError, compile_files, diagnostic_line
from nasaq.ir import Area, Direct, Width
from nasaq.scenarios.model import Scenario, ScenarioError, Step, load_scenario


@dataclass(frozen=True, slots=True)
class Failure:
    step: int  # 1-based, as the file lists them
    note: str | None
    address: str
    expected: str
    actual: str

    def describe(self) -> str:
        note = f" ({self.note})" if self.note else ""
        return f"step {self.step}{note}: {self.address} expected {self.expected}, got {self.actual}"


@dataclass(slots=True)
class ScenarioResult:
    path: Path
    name: str
    failures: list[Failure] = field(default_factory=list)
    error: str | None = None  # the scenario could not run: invalid file, compile errors
    diagnostics: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return self.error is None and not self.failures


def _shown(value: int, width: Width) -> str:
    if width is Width.BIT:
        return str(value)
    digits = int(width) // 4
    return f"{signed(value, width)} (16#{value:0{digits}X})"


def _check_direct(cpu: Cpu, address: Direct, expected: Any) -> tuple[str, str] | None:
    """None when ``address`` holds ``expected``, else (expected, actual) as text."""
    actual = cpu.read(address)
    tolerance: float | None = None
    if isinstance(expected, dict):
        if set(expected) - {"real", "tolerance"} or "real" not in expected:
            raise ScenarioError(f"{address_text(address)}: write {{real: x, tolerance: t}}")
        tolerance = float(expected.get("tolerance", 0.0))
        expected = float(expected["real"])
    if isinstance(expected, float):
        if address.width is not Width.DWORD:
            raise ScenarioError(f"{address_text(address)}: a real needs a doubleword address")
        if tolerance is None:
            tolerance = 1e-6 * max(1.0, abs(expected))
        real = as_real(actual)
        if math.isclose(real, expected, rel_tol=0.0, abs_tol=tolerance):
            return None
        return f"{expected} ± {tolerance}", repr(real)
    try:
        pattern = encode_value(
            address, expected if not isinstance(expected, bool) else int(expected)
        )
    except AddressError as exc:
        raise ScenarioError(str(exc)) from None
    if pattern == actual:
        return None
    return _shown(pattern, address.width), _shown(actual, address.width)


def _check(cpu: Cpu, key: str, expected: Any) -> tuple[str, str] | None:
    if key == "mode":
        return None if str(expected).upper() == cpu.mode else (str(expected).upper(), cpu.mode)
    address = parse_address(key)
    if isinstance(address, Direct):
        return _check_direct(cpu, address, expected)
    if not isinstance(expected, dict):
        raise ScenarioError(f"{key}: write e.g. {{q: 1}} or {{value: 3}} for timers and counters")
    if isinstance(address, TimerAddress):
        q, remaining, _running = cpu.timer(address.number)
        actual = {"q": int(q), "remaining_ms": int(remaining)}
    else:
        assert isinstance(address, CounterAddress)
        q, value = cpu.counter(address.number)
        actual = {"q": int(q), "value": int(value)}
    unknown = set(expected) - set(actual)
    if unknown:
        raise ScenarioError(f"{key}: unknown field(s) {', '.join(sorted(unknown))}")
    wanted = {name: int(expected[name]) for name in expected}
    got = {name: actual[name] for name in expected}
    return None if wanted == got else (str(wanted), str(got))


def _set(cpu: Cpu, key: str, value: Any) -> None:
    address = parse_address(key)
    if not isinstance(address, Direct):
        raise ScenarioError(f"{key}: timers and counters cannot be set")
    if isinstance(value, str):
        value = parse_number(value)
    pattern = encode_value(address, value)
    if address.area is Area.I:
        cpu.set_input(address, pattern)
    else:
        cpu.write(address, pattern)


def _do(
    cpu: Cpu, scenario: Scenario, index: int, step: Step, note: str | None, result: ScenarioResult
) -> None:
    if step.set_ is not None:
        for key, value in step.set_.items():
            _set(cpu, str(key), value)
    elif step.run is not None:
        for _ in range(step.scans(scenario.cycle_ms)):
            if cpu.mode != "RUN":
                break
            cpu.scan()
    elif step.expect is not None:
        for key, expected in step.expect.items():
            mismatch = _check(cpu, str(key), expected)
            if mismatch is not None:
                result.failures.append(Failure(index, note, str(key), *mismatch))


def run_scenario(path: Path) -> ScenarioResult:
    """Loads, compiles and runs one scenario file; never raises for a bad file or program."""
    try:
        scenario = load_scenario(path)
    except ScenarioError as exc:
        return ScenarioResult(path, path.stem, error=str(exc))
    result = ScenarioResult(path, scenario.name)
    try:
        compiled = compile_files(scenario.source_paths(), scenario.mnemonics)
    except SourceError as exc:
        result.error = str(exc)
        return result
    result.diagnostics = [diagnostic_line(d) for d in compiled.diagnostics]
    if not compiled.ok:
        result.error = "the sources do not compile"
        return result
    try:
        found = project_file.load(scenario.source_paths())
    except SourceError as exc:
        result.error = str(exc)
        return result
    cold = False
    options: dict[str, Any] = {}
    if found is not None:
        if not found.ok:
            result.diagnostics += project_file.problems(found)
            result.error = "the CPU properties file has errors"
            return result
        props = found.properties
        given = scenario.model_fields_set
        update: dict[str, Any] = {}
        if "profile" not in given:
            update["profile"] = props.profile.value
        if "cycle_ms" not in given:
            update["cycle_ms"] = float(props.cycle_ms)
        scenario = scenario.model_copy(update=update)
        options = props.cpu_options() | {"profile": Profile(scenario.profile)}
        cold = props.startup == "cold"
    options.setdefault("profile", Profile(scenario.profile))
    try:
        cpu = Cpu(compiled.program, cycle_ms=scenario.cycle_ms, **options)
    except ValueError as exc:  # e.g. retentive counts the scenario's profile does not have
        result.error = f"{path}: {exc}"
        return result
    cpu.start(cold=cold)
    note: str | None = None  # a note names the steps that follow it, until the next note
    try:
        for index, step in enumerate(scenario.steps, start=1):
            note = step.note or note
            _do(cpu, scenario, index, step, note, result)
    except (ScenarioError, AddressError) as exc:
        result.error = f"{path}: {exc}"
    return result

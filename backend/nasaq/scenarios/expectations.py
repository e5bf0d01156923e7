"""What an ``expect`` table asks, prepared once and checked as often as a step needs.

``during`` checks its table after every scan of its interval, so each key is parsed once into a
small function that reads the CPU (or the plant) and answers None (it holds) or the expected
and actual values as text.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from nasaq.cpu import Cpu
from nasaq.headless.addresses import (
    AddressError,
    CounterAddress,
    TimerAddress,
    address_text,
    as_real,
    encode_value,
    parse_address,
    signed,
)
from nasaq.ir import Direct, Width
from nasaq.plants.runtime import PlantRuntime
from nasaq.scenarios.members import is_member_key
from nasaq.scenarios.model import PLANT_KEY, ScenarioError

Mismatch = tuple[str, str] | None  # (expected, actual) as text, None when it holds
Check = Callable[[], Mismatch]


def _shown(value: int, width: Width) -> str:
    if width is Width.BIT:
        return str(value)
    digits = int(width) // 4
    return f"{signed(value, width)} (16#{value:0{digits}X})"


def _direct(cpu: Cpu, address: Direct, expected: Any) -> Check:
    tolerance: float | None = None
    if isinstance(expected, dict):
        if set(expected) - {"real", "tolerance"} or "real" not in expected:
            raise ScenarioError(f"{address_text(address)}: write {{real: x, tolerance: t}}")
        tolerance = float(expected.get("tolerance", 0.0))
        expected = float(expected["real"])
    if isinstance(expected, float):
        if address.width is not Width.DWORD:
            raise ScenarioError(f"{address_text(address)}: a real needs a doubleword address")
        real_wanted = expected
        margin = tolerance if tolerance is not None else 1e-6 * max(1.0, abs(expected))

        def real() -> Mismatch:
            got = as_real(cpu.read(address))
            if math.isclose(got, real_wanted, rel_tol=0.0, abs_tol=margin):
                return None
            return f"{real_wanted} ± {margin}", repr(got)

        return real
    try:
        pattern = encode_value(address, int(expected) if isinstance(expected, bool) else expected)
    except AddressError as exc:
        raise ScenarioError(str(exc)) from None
    width = address.width

    def exact() -> Mismatch:
        actual = cpu.read(address)
        if actual == pattern:
            return None
        return _shown(pattern, width), _shown(actual, width)

    return exact


def _timer_or_counter(
    cpu: Cpu, key: str, address: TimerAddress | CounterAddress, expected: Any
) -> Check:
    if not isinstance(expected, dict):
        raise ScenarioError(f"{key}: write e.g. {{q: 1}} or {{value: 3}} for timers and counters")
    fields = {"q", "remaining_ms"} if isinstance(address, TimerAddress) else {"q", "value"}
    unknown = set(expected) - fields
    if unknown:
        raise ScenarioError(f"{key}: unknown field(s) {', '.join(sorted(unknown))}")
    wanted = {name: int(expected[name]) for name in expected}
    number = address.number

    def check() -> Mismatch:
        if isinstance(address, TimerAddress):
            q, remaining, _running = cpu.timer(number)
            actual = {"q": int(q), "remaining_ms": int(remaining)}
        else:
            q, value = cpu.counter(number)
            actual = {"q": int(q), "value": int(value)}
        got = {name: actual[name] for name in wanted}
        return None if wanted == got else (str(wanted), str(got))

    return check


def _plant(runtime: PlantRuntime | None, key: str, expected: Any) -> Check:
    if runtime is None:
        raise ScenarioError(f"{key}: this scenario runs no plant")
    name = key[len(PLANT_KEY) :]
    if name == "faults":
        if not isinstance(expected, list):
            raise ScenarioError(f"{key}: write the list of active faults, e.g. [overflow] or []")
        wanted_faults = sorted(str(code) for code in expected)

        def faults() -> Mismatch:
            got = runtime.faults()
            return None if got == wanted_faults else (str(wanted_faults), str(got))

        return faults
    state = runtime.state()
    if name not in state:
        known = ", ".join(sorted(state))
        raise ScenarioError(
            f"{key}: the {runtime.config.kind} plant has no state '{name}' ({known})"
        )
    if isinstance(expected, dict):
        if not expected or set(expected) - {"min", "max"}:
            raise ScenarioError(f"{key}: write a value or {{min: a, max: b}}")
        low = float(expected["min"]) if "min" in expected else -math.inf
        high = float(expected["max"]) if "max" in expected else math.inf
        shown = f"{expected.get('min', '')}..{expected.get('max', '')}"

        def in_range() -> Mismatch:
            got = runtime.state()[name]
            if not isinstance(got, str) and low <= float(got) <= high:
                return None
            return shown, str(got)

        return in_range

    wanted = int(expected) if isinstance(expected, bool) else expected

    def equal() -> Mismatch:
        got = runtime.state()[name]
        value = int(got) if isinstance(got, bool) else got
        return None if value == wanted else (str(wanted), str(value))

    return equal


MemberCheck = Callable[[str, Any], Check]
"""Builds the check of a DB variable by name (``nasaq.scenarios.members``)."""


def prepare(
    cpu: Cpu,
    runtime: PlantRuntime | None,
    key: str,
    expected: Any,
    member: MemberCheck | None = None,
) -> Check:
    """The check of one ``expect`` entry; raises ScenarioError for an entry that cannot be
    checked (a real on a word, a state the plant does not have, an unknown DB variable)."""
    if member is not None and is_member_key(key):
        return member(key, expected)
    if key == "mode":
        wanted = str(expected).upper()
        return lambda: None if cpu.mode == wanted else (wanted, cpu.mode)
    if key.startswith(PLANT_KEY):
        return _plant(runtime, key, expected)
    address = parse_address(key)
    if isinstance(address, Direct):
        return _direct(cpu, address, expected)
    return _timer_or_counter(cpu, key, address, expected)


def prepare_all(
    cpu: Cpu, runtime: PlantRuntime | None, table: dict[str, Any], member: MemberCheck | None = None
) -> list[tuple[str, Check]]:
    return [
        (str(key), prepare(cpu, runtime, str(key), value, member)) for key, value in table.items()
    ]

"""DB variables by name in scenarios: ``DB1.S5.X``, ``DB1.S5.T``, ``IDB_Seq_drill.AUTO_ON``.

A scenario about an FB wants to read what its instance DB says (a Graph sequencer's active
steps, step times, mode outputs) and to write its members (the Control Sequencer mailbox) without
counting bytes. The file is validated before compilation, so such a key is only checked for its
shape there (:func:`is_member_key`); after compilation each key is resolved once, against the
compiled program's DB layout, by the monitor's resolver (``nasaq.monitor.targets``: the same
names, types and value spellings a watch table takes), and is then a typed address.

Values are those of a watch table: ``1``/``0``/``TRUE`` for BOOL, integers for INT/DINT/WORD,
``T#5S`` (or milliseconds) for TIME, a real for REAL (``{real: x, tolerance: t}`` too), and in
``expect`` a range ``{min: a, max: b}`` for anything numeric (a step time between two bounds).
The DB is its number or its symbol, quoted or not (YAML wants a quoted symbol inside quotes:
``'"IDB_Seq_drill".AUTO_ON': 1``). A key the program does not have is a scenario error with the
step number and the resolver's reason (code MON603; a value that does not fit, MON606).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any

from nasaq.cpu import Cpu
from nasaq.headless.addresses import AddressError, parse_address
from nasaq.ir import Program
from nasaq.monitor.targets import Target, TargetError, encode, read, resolve, write
from nasaq.monitor.values import Value, decode
from nasaq.scenarios.model import PLANT_KEY, ScenarioError

Mismatch = tuple[str, str] | None
Check = Callable[[], Mismatch]

# DB<n>, "<symbol>" or <symbol>, then one or more .member / [index] selectors.
_MEMBER = re.compile(
    r'^(?:DB\s*\d+|"[^"\r\n]+"|[A-Za-z_]\w*)(?:\s*(?:\.\s*(?:"[^"\r\n]+"|[A-Za-z_]\w*)|\[[^\]\r\n]*\]))+$',
    re.IGNORECASE,
)


def is_member_key(key: str) -> bool:
    """True for a key written as a DB variable (resolved once the program is compiled), False
    for an absolute address (``DB1.DBX0.0``), a plant's state (``plant.level``) and anything
    else."""
    if key.startswith(PLANT_KEY) or _MEMBER.match(key.strip()) is None:
        return False
    try:
        parse_address(key)
    except AddressError:
        return True
    return False


class Members:
    """The DB variables a scenario names, resolved against one compiled program."""

    def __init__(self, program: Program) -> None:
        self._program = program
        self._targets: dict[str, Target] = {}

    def target(self, key: str, step: int) -> Target:
        found = self._targets.get(key)
        if found is None:
            try:
                found = resolve(key, self._program)
            except TargetError as exc:
                raise _error(step, exc) from None
            if found.direct is None:
                raise ScenarioError(f"step {step}: {key}: name a DB variable, not a timer/counter")
            self._targets[key] = found
        return found

    def write(self, cpu: Cpu, key: str, value: Any, step: int) -> None:
        target = self.target(key, step)
        try:
            write(target, cpu, value)
        except TargetError as exc:
            raise _error(step, exc) from None

    def check(self, cpu: Cpu, key: str, expected: Any, step: int) -> Check:
        """The check of ``key: expected`` in an expect table."""
        target = self.target(key, step)
        kind = target.type
        if isinstance(expected, dict):
            if set(expected) <= {"min", "max"} and expected:
                return self._range(cpu, target, expected, step)
            if "real" in expected and set(expected) <= {"real", "tolerance"} and kind == "REAL":
                margin = float(expected.get("tolerance", 0.0))
                return _real(cpu, target, float(expected["real"]), margin)
            raise ScenarioError(
                f"step {step}: {key}: write a value, {{min: a, max: b}}"
                + (" or {real: x, tolerance: t}" if kind == "REAL" else "")
            )
        if kind == "REAL" and isinstance(expected, int | float) and not isinstance(expected, bool):
            wanted = float(expected)
            return _real(cpu, target, wanted, 1e-6 * max(1.0, abs(wanted)))
        try:
            pattern = encode(target, expected)
        except TargetError as exc:
            raise _error(step, exc) from None
        wanted_value = decode(kind, pattern)
        direct = target.direct
        assert direct is not None

        def exact() -> Mismatch:
            actual = cpu.read(direct)
            if actual == pattern:
                return None
            return _shown(kind, wanted_value), _shown(kind, decode(kind, actual))

        return exact

    def _range(self, cpu: Cpu, target: Target, bounds: dict[str, Any], step: int) -> Check:
        kind = target.type
        low = self._bound(target, bounds.get("min"), -math.inf, step)
        high = self._bound(target, bounds.get("max"), math.inf, step)
        shown = "..".join(
            _shown(kind, bound) if name in bounds else ""
            for name, bound in (("min", low), ("max", high))
        )

        def in_range() -> Mismatch:
            got = read(target, cpu)
            if isinstance(got, int | float) and low <= got <= high:
                return None
            return shown, _shown(kind, got)

        return in_range

    @staticmethod
    def _bound(target: Target, value: Any, default: float, step: int) -> float:
        if value is None:
            return default
        try:
            decoded = decode(target.type, encode(target, value))
        except TargetError as exc:
            raise _error(step, exc) from None
        if isinstance(decoded, bool) or not isinstance(decoded, int | float):
            raise ScenarioError(f"step {step}: {target.text}: a range needs a numeric variable")
        return decoded


def _real(cpu: Cpu, target: Target, wanted: float, margin: float) -> Check:
    def real() -> Mismatch:
        got = read(target, cpu)
        if isinstance(got, float) and math.isclose(got, wanted, rel_tol=0.0, abs_tol=margin):
            return None
        return f"{wanted} ± {margin}", repr(got)

    return real


def _shown(kind: str, value: Value | float) -> str:
    if isinstance(value, bool):
        return str(int(value))
    if kind == "TIME" and isinstance(value, int | float) and not math.isinf(value):
        return f"{value:g} ms" if isinstance(value, float) else f"{value} ms"
    return str(value)


def _error(step: int, exc: TargetError) -> ScenarioError:
    return ScenarioError(f"step {step}: {exc} ({exc.code})")

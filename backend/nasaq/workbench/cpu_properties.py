"""A project's CPU properties (STEP 7's HW Config "Properties - CPU", TIA Portal's device
properties) as a plain-text project file: ``cpu.properties``.

The file is UTF-8 text of ``key = value`` lines; ``#`` starts a comment (a whole line or the rest
of one), blank lines are ignored, keys are case-insensitive, a key left out keeps its default::

    # Nasaq CPU properties
    profile = S7-300              # S7-300, S7-400 or S7-1500 (the S7-1200/1500 family)
    cycle_monitoring_time = 150   # ms, 1 to 6000: the cycle watchdog (SIM501)
    cycle_time = 10               # ms, 1 to 6000: the virtual time of one scan
    clock_memory = MB100          # MB n, or none
    retentive_markers = 16        # MB 0 ... MB 15 keep their values over a warm restart
    retentive_timers = 0          # T 0 ... (none)
    retentive_counters = 8        # C 0 ... C 7
    startup = warm                # warm or cold
    cyclic_interrupt_OB35 = 100   # ms, 1 to 60000: the cycle time of a cyclic interrupt OB

- ``cycle_time`` is the simulator's scan period (what session options call ``cycle_ms``), as
  STEP 7's "minimum cycle time": like STEP 7, it must not exceed the cycle monitoring time.
- The clock memory bits toggle on the virtual clock at 10, 5, 2.5, 2, 1.25, 1, 0.625 and 0.5 Hz
  (bit 0 ... bit 7), as the S7-300/400 manuals list them.
- ``startup`` is the restart the CPU makes when it goes from STOP to RUN (RUN button, ``nasaq
  run``, ``nasaq test``); the toolbar's explicit warm/cold restart buttons still do what they
  say. ``hot`` (an S7-400's hot restart, OB101, resuming the interrupted scan) is refused with
  PRJ906: the simulator does not model it.
- ``cyclic_interrupt_OB<n>`` is the "cycle time" of cyclic interrupt OB n (default 100 ms):
  OB35 on S7-300/400 (the one the simulator runs there), OB30-OB38 and OB123 up on S7-1500
  (``nasaq.cpu.obs``). A number the profile has no cyclic interrupt for is PRJ902.
- Limits come from the profile (MB, T, C counts); the defaults are an S7-300's.

Reading never raises: a bad line gives one diagnostic (PRJ9xx, with its line and column) and
that key keeps its default, so a caller can show every problem at once. The compiler skips the
file; a project without it runs with the defaults.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Literal

from nasaq.cpu import Profile, Retentive
from nasaq.cpu.obs import MAX_PERIOD_MS, is_cyclic_number
from nasaq.diagnostics.catalogue import render
from nasaq.diagnostics.model import Diagnostic, Severity, Span

FILE_NAME = "cpu.properties"
SUFFIX = ".properties"
MAX_MS = 6000  # STEP 7's largest cycle monitoring time
Startup = Literal["warm", "cold"]
KEYS = (
    "profile",
    "cycle_monitoring_time",
    "cycle_time",
    "clock_memory",
    "retentive_markers",
    "retentive_timers",
    "retentive_counters",
    "startup",
)
_LINE = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*[=:]\s*(.*?)\s*")
_MS = re.compile(r"(\d+)\s*(?:ms)?", re.IGNORECASE)
_MARKER_BYTE = re.compile(r"(?:MB\s*)?(\d+)", re.IGNORECASE)
_CYCLIC_KEY = re.compile(r"cyclic_interrupt_ob(\d+)")  # matched on the lower-cased key
_CYCLIC_KEYS = {
    Profile.S7_1500: "cyclic_interrupt_OB30 … cyclic_interrupt_OB38, cyclic_interrupt_OB123 …"
}
# S7-1200 and "S7-1200/1500" name the one profile of that family (``nasaq.lang.profiles``).
_PROFILE_NAMES = {p.value.lower(): p for p in Profile} | {
    "s7-1200": Profile.S7_1500,
    "s7-1200/1500": Profile.S7_1500,
}
_PROFILE_CHOICES = " | ".join(p.value for p in Profile)


@dataclass(frozen=True, slots=True)
class CpuProperties:
    profile: Profile = Profile.S7_300
    cycle_monitoring_ms: int = 150
    cycle_ms: int = 10
    clock_memory: int | None = None
    retentive: Retentive = field(default_factory=Retentive)
    startup: Startup = "warm"
    cyclic_periods: tuple[tuple[int, int], ...] = ()  # (OB number, ms) of the lines that set one

    def cpu_options(self) -> dict[str, Any]:
        """Keyword arguments of :class:`nasaq.cpu.Cpu` (besides program and cycle time)."""
        return {
            "profile": self.profile,
            "watchdog_ms": self.cycle_monitoring_ms,
            "clock_memory_byte": self.clock_memory,
            "retentive": self.retentive,
            "cyclic_periods": dict(self.cyclic_periods),
        }

    def as_json(self) -> dict[str, Any]:
        return {
            "profile": self.profile.value,
            "cycle_monitoring_time": self.cycle_monitoring_ms,
            "cycle_time": self.cycle_ms,
            "clock_memory": self.clock_memory,
            "retentive_markers": self.retentive.markers,
            "retentive_timers": self.retentive.timers,
            "retentive_counters": self.retentive.counters,
            "startup": self.startup,
        }


@dataclass(slots=True)
class ReadProperties:
    properties: CpuProperties
    diagnostics: list[Diagnostic]

    @property
    def ok(self) -> bool:
        return not any(d.severity is Severity.ERROR for d in self.diagnostics)


def is_properties_file(name: str) -> bool:
    return name.rsplit("/", 1)[-1].lower() == FILE_NAME


def find(files: Iterable[tuple[str, str]]) -> tuple[str, str] | None:
    """The project's CPU properties file (name, text) among ``files``, or None."""
    return next(((n, t) for n, t in files if is_properties_file(n)), None)


def read_properties(text: str, file: str = FILE_NAME) -> ReadProperties:
    """Parses the file; every problem is a diagnostic and never an exception."""
    values: dict[str, Any] = {}
    lines: dict[str, int] = {}
    columns: dict[str, int] = {}  # where each value starts
    key_columns: dict[str, int] = {}
    problems: list[Diagnostic] = []

    def problem(code: str, line: int, column: int, **params: Any) -> None:
        span = Span(file=file, line=line, column=column)
        problems.append(render(code, span, **params))

    for number, raw in enumerate(text.splitlines(), start=1):
        body = raw.split("#", 1)[0]
        if not body.strip():
            continue
        column = len(body) - len(body.lstrip()) + 1
        match = _LINE.fullmatch(body)
        if match is None:
            problem("PRJ901", number, column, text=body.strip())
            continue
        key, value = match.group(1).lower(), match.group(2)
        if key not in KEYS and _CYCLIC_KEY.fullmatch(key) is None:
            problem("PRJ902", number, column, key=match.group(1), keys=", ".join(KEYS))
            continue
        if key in lines:
            problem("PRJ903", number, column, key=key, first=lines[key])
            continue
        lines[key] = number
        key_columns[key] = column
        value_column = columns[key] = match.start(2) + 1
        parsed = _value(key, value)
        if isinstance(parsed, tuple):
            code, params = parsed
            problem(code, number, value_column, key=key, value=value, **params)
        else:
            values[key] = parsed

    profile = values.get("profile", Profile.S7_300)
    limits = {
        "retentive_markers": profile.marker_bytes,
        "retentive_timers": profile.timers,
        "retentive_counters": profile.counters,
        "clock_memory": profile.marker_bytes - 1,
    }
    for key, limit in limits.items():
        if key in values and values[key] is not None and values[key] > limit:
            value = values.pop(key)
            problem("PRJ905", lines[key], columns[key], key=key, value=value, low=0, high=limit)
    periods: list[tuple[int, int]] = []
    for key in [k for k in values if _CYCLIC_KEY.fullmatch(k)]:
        ms = values.pop(key)
        number = int(key.removeprefix("cyclic_interrupt_ob"))
        if is_cyclic_number(number, profile):
            periods.append((number, ms))
            continue
        known = ", ".join((*KEYS, _CYCLIC_KEYS.get(profile, "cyclic_interrupt_OB35")))
        problem("PRJ902", lines[key], key_columns[key], key=key, keys=known)
    monitoring = values.get("cycle_monitoring_time", 150)
    if values.get("cycle_time", 10) > monitoring:
        key = "cycle_time" if "cycle_time" in lines else "cycle_monitoring_time"
        cycle = values.pop("cycle_time", 10)
        problem("PRJ907", lines[key], columns[key], key=key, cycle=cycle, limit=monitoring)
    properties = CpuProperties(
        profile=profile,
        cycle_monitoring_ms=monitoring,
        cycle_ms=values.get("cycle_time", 10),
        clock_memory=values.get("clock_memory"),
        retentive=Retentive(
            values.get("retentive_markers", Retentive().markers),
            values.get("retentive_timers", Retentive().timers),
            values.get("retentive_counters", Retentive().counters),
        ),
        startup=values.get("startup", "warm"),
        cyclic_periods=tuple(sorted(periods)),
    )
    return ReadProperties(properties, problems)


def _value(key: str, text: str) -> Any:
    """The value of ``key`` written as ``text``, or (code, params) of the problem."""
    word = text.strip()
    if key == "profile":
        found = _PROFILE_NAMES.get(word.lower().replace(" ", ""))
        return found if found is not None else ("PRJ904", {"expected": _PROFILE_CHOICES})
    if key == "startup":
        lowered = word.lower().removesuffix(" restart")
        if lowered in ("warm", "cold"):
            return lowered
        if lowered == "hot":
            return ("PRJ906", {})
        return ("PRJ904", {"expected": "warm | cold"})
    if key == "clock_memory":
        if word.lower() in ("none", "off", "no", ""):
            return None
        match = _MARKER_BYTE.fullmatch(word)
        return int(match.group(1)) if match else ("PRJ904", {"expected": "MB n | none"})
    if _CYCLIC_KEY.fullmatch(key):
        match = _MS.fullmatch(word)
        if match is None:
            return ("PRJ904", {"expected": f"1 … {MAX_PERIOD_MS}"})
        ms = int(match.group(1))
        return ms if 1 <= ms <= MAX_PERIOD_MS else ("PRJ905", {"low": 1, "high": MAX_PERIOD_MS})
    if key in ("cycle_monitoring_time", "cycle_time"):
        match = _MS.fullmatch(word)
        if match is None:
            return ("PRJ904", {"expected": f"1 … {MAX_MS}"})
        ms = int(match.group(1))
        return ms if 1 <= ms <= MAX_MS else ("PRJ905", {"low": 1, "high": MAX_MS})
    if not word.isdigit():  # the retentive counts
        return ("PRJ904", {"expected": "0, 1, 2 …"})
    return int(word)


def properties_of(files: Iterable[tuple[str, str]]) -> ReadProperties:
    """The CPU properties ``files`` (a project's, a download's) carry; the defaults without
    the file."""
    found = find(files)
    if found is None:
        return ReadProperties(CpuProperties(), [])
    return read_properties(found[1], found[0])

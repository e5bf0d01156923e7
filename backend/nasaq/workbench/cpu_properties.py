"""A project's CPU properties (STEP 7's HW Config "Properties - CPU", TIA Portal's device
properties) as a plain-text project file: ``cpu.properties``.

The file is UTF-8 text of ``key = value`` lines; ``#`` starts a comment (a whole line or the rest
of one), blank lines are ignored, keys are case-insensitive, a key left out keeps its default::

    # Nasaq CPU properties
    profile = S7-300              # S7-300 or S7-400
    cycle_monitoring_time = 150   # ms, 1 to 6000: the cycle watchdog (SIM501)
    cycle_time = 10               # ms, 1 to 6000: the virtual time of one scan
    clock_memory = MB100          # MB n, or none
    retentive_markers = 16        # MB 0 ... MB 15 keep their values over a warm restart
    retentive_timers = 0          # T 0 ... (none)
    retentive_counters = 8        # C 0 ... C 7
    startup = warm                # warm or cold

- ``cycle_time`` is the simulator's scan period (what session options call ``cycle_ms``), as
  STEP 7's "minimum cycle time": like STEP 7, it must not exceed the cycle monitoring time.
- The clock memory bits toggle on the virtual clock at 10, 5, 2.5, 2, 1.25, 1, 0.625 and 0.5 Hz
  (bit 0 ... bit 7), as the S7-300/400 manuals list them.
- ``startup`` is the restart the CPU makes when it goes from STOP to RUN (RUN button, ``nasaq
  run``, ``nasaq test``); the toolbar's explicit warm/cold restart buttons still do what they
  say. ``hot`` (an S7-400's hot restart, OB101, resuming the interrupted scan) is refused with
  PRJ906: the simulator does not model it.
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


@dataclass(frozen=True, slots=True)
class CpuProperties:
    profile: Profile = Profile.S7_300
    cycle_monitoring_ms: int = 150
    cycle_ms: int = 10
    clock_memory: int | None = None
    retentive: Retentive = field(default_factory=Retentive)
    startup: Startup = "warm"

    def cpu_options(self) -> dict[str, Any]:
        """Keyword arguments of :class:`nasaq.cpu.Cpu` (besides program and cycle time)."""
        return {
            "profile": self.profile,
            "watchdog_ms": self.cycle_monitoring_ms,
            "clock_memory_byte": self.clock_memory,
            "retentive": self.retentive,
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
        if key not in KEYS:
            problem("PRJ902", number, column, key=match.group(1), keys=", ".join(KEYS))
            continue
        if key in lines:
            problem("PRJ903", number, column, key=key, first=lines[key])
            continue
        lines[key] = number
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
    )
    return ReadProperties(properties, problems)


def _value(key: str, text: str) -> Any:
    """The value of ``key`` written as ``text``, or (code, params) of the problem."""
    word = text.strip()
    if key == "profile":
        found = {p.value.lower(): p for p in Profile}.get(word.lower().replace(" ", ""))
        return found if found is not None else ("PRJ904", {"expected": "S7-300 | S7-400"})
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

"""``nasaq run``: download sources into a fresh CPU, run N scans, print the final state as JSON.

The JSON object is a fixed contract that outside checks rely on: ``cycles``, ``time_ms``, ``mode``,
``stop_reason``, ``I``/``Q``/``M`` (nonzero bytes by decimal offset), ``DB`` (by DB number, then
offset), ``T`` (running or set timers), ``C`` (nonzero counters), ``ACCU1``, ``ACCU2`` and ``STW``.
Exit status: 0 when the scans ran (or the program stopped the CPU with SFC 46), 1 when the CPU went
to STOP on an error, 2 when the sources do not compile.

A ``cpu.properties`` among the sources or beside the first one (``nasaq.headless.project_file``)
sets the profile, cycle time, cycle monitoring time, clock memory, retentive ranges and startup;
the options named in ``RunOptions.explicit`` (those given on the command line) win over it.
"""

from __future__ import annotations

import json
import sys
import traceback
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, TextIO

from nasaq.cpu import Cpu, Profile, Retentive
from nasaq.cpu.errors import sentence_part
from nasaq.cpu.pacing import Pacer, TimeMode
from nasaq.diagnostics import render
from nasaq.headless import project_file
from nasaq.headless.addresses import (
    AddressError,
    address_text,
    encode_value,
    parse_address,
    parse_number,
)
from nasaq.headless.sources import SourceError, compile_files, diagnostic_line
from nasaq.ir import Area, Direct, Program

TIMERS = 256
COUNTERS = 256


@dataclass(frozen=True, slots=True)
class Assignment:
    """``ADDR=VALUE`` from ``--set``, or ``K:ADDR=VALUE`` from ``--at`` (scan K, 1-based)."""

    address: Direct
    pattern: int
    scan: int = 0


@dataclass(slots=True)
class RunOptions:
    sources: list[Path]
    cycles: int = 1
    cycle_ms: float = 10.0
    sets: list[Assignment] = field(default_factory=list)
    at: list[Assignment] = field(default_factory=list)
    mnemonics: str = "auto"
    test_ops: bool = False
    profile: Profile = Profile.S7_300
    time_mode: TimeMode = TimeMode.VIRTUAL
    cold_restart: bool = False  # start with a cold restart (OB102) instead of a warm one (OB100)
    clock_memory: int | None = None  # the clock memory byte (MB n), None for none
    watchdog_ms: int = 150  # the cycle monitoring time
    retentive: Retentive | None = None  # None: MB 0-15, C 0-7
    cyclic_periods: dict[int, int] = field(default_factory=dict)  # OB number: ms (cpu.properties)
    # Options the user gave (cycle_ms, profile, cold_restart, clock_memory): a cpu.properties
    # file does not override them.
    explicit: frozenset[str] = frozenset()


def _with_project_file(options: RunOptions, err: TextIO) -> RunOptions | None:
    """``options`` completed from the sources' cpu.properties; None (problems printed) if the
    file has errors. A file that cannot be read raises ``SourceError``."""
    found = project_file.load(options.sources)
    if found is None:
        return options
    if not found.ok:
        for line in project_file.problems(found):
            print(line, file=err)
        return None
    props = found.properties
    given = options.explicit
    return replace(
        options,
        cycle_ms=options.cycle_ms if "cycle_ms" in given else props.cycle_ms,
        profile=options.profile if "profile" in given else props.profile,
        cold_restart=options.cold_restart if "cold_restart" in given else props.startup == "cold",
        clock_memory=options.clock_memory if "clock_memory" in given else props.clock_memory,
        watchdog_ms=props.cycle_monitoring_ms,
        retentive=props.retentive,
        cyclic_periods=dict(props.cyclic_periods),
    )


def parse_assignment(text: str, with_scan: bool = False) -> Assignment:
    """Reads ``I0.0=1`` (or ``3:I0.0=1`` with ``with_scan``); raises AddressError."""
    scan = 0
    if with_scan:
        head, sep, text = text.partition(":")
        if not sep or not head.strip().isdigit() or int(head) < 1:
            raise AddressError(f"--at needs K:ADDR=VALUE with K a scan number from 1, not {head!r}")
        scan = int(head)
    target, sep, value = text.partition("=")
    if not sep:
        raise AddressError(f"{text!r}: write ADDR=VALUE, e.g. I0.0=1 or MW10=16#FF")
    address = parse_address(target)
    if not isinstance(address, Direct):
        raise AddressError(f"{target.strip()}: timers and counters cannot be set")
    return Assignment(address, encode_value(address, parse_number(value)), scan)


def _apply(cpu: Cpu, assignment: Assignment) -> None:
    if assignment.address.area is Area.I:
        cpu.set_input(assignment.address, assignment.pattern)
    else:
        cpu.write(assignment.address, assignment.pattern)


def _bytes_map(data: bytes | None) -> dict[str, int]:
    return {str(offset): value for offset, value in enumerate(data or b"") if value}


def snapshot(cpu: Cpu, cycles: int) -> dict[str, Any]:
    """The final state in the fixed JSON shape."""
    timers: dict[str, dict[str, int]] = {}
    for number in range(TIMERS):
        q, remaining, running = cpu.timer(number)
        if running or q:
            timers[str(number)] = {"q": int(q), "remaining_ms": int(remaining)}
    counters: dict[str, dict[str, int]] = {}
    for number in range(COUNTERS):
        q, value = cpu.counter(number)
        if value or q:
            counters[str(number)] = {"q": int(q), "value": int(value)}
    dbs = {str(n): _bytes_map(cpu.db_bytes(n)) for n in sorted(cpu.db_numbers())}
    return {
        "cycles": cycles,
        "time_ms": cpu.time_ms,
        "mode": cpu.mode,
        "stop_reason": cpu.stop_reason,
        "I": _bytes_map(cpu.area_bytes(Area.I)),
        "Q": _bytes_map(cpu.area_bytes(Area.Q)),
        "M": _bytes_map(cpu.area_bytes(Area.M)),
        "DB": {n: values for n, values in dbs.items() if values},
        "T": timers,
        "C": counters,
        "ACCU1": cpu.accu1 & 0xFFFFFFFF,
        "ACCU2": cpu.accu2 & 0xFFFFFFFF,
        "STW": cpu.stw,
    }


def execute(options: RunOptions, out: TextIO, err: TextIO) -> int:
    """Runs the whole command; returns the exit status of every ``nasaq`` command
    (``nasaq.cli``): 0 the scans ran, 1 the program has errors (it does not compile, its
    cpu.properties has errors, or the CPU went to STOP on an error), 2 a usage error (a file
    that cannot be read, an address or option the CPU does not have)."""
    try:
        completed = _with_project_file(options, err)
    except SourceError as exc:
        print(f"nasaq run: {exc}", file=err)
        return 2
    if completed is None:
        return 1
    options = completed
    try:
        result = compile_files(
            options.sources, options.mnemonics, options.test_ops, options.profile.value
        )
    except SourceError as exc:
        print(f"nasaq run: {exc}", file=err)
        return 2
    for diagnostic in result.diagnostics:
        print(diagnostic_line(diagnostic), file=err)
    if not result.ok:
        return 1  # as nasaq compile: the program has errors
    try:
        return _simulate(options, result.program, out, err)
    except Exception as exc:  # a simulator bug: STOP SIM500 in the usual shape, never a traceback
        traceback.print_exception(exc, file=err)
        message = sentence_part(render("SIM500").message)
        state: dict[str, Any] = {"cycles": 0, "time_ms": 0, "mode": "STOP"}
        state["stop_reason"] = f"{message} (SIM500)"
        state |= {key: {} for key in ("I", "Q", "M", "DB", "T", "C")}
        state |= {"ACCU1": 0, "ACCU2": 0, "STW": 0}
        json.dump(state, out, indent=None, separators=(",", ":"))
        out.write("\n")
        return 1


def _simulate(options: RunOptions, program: Program, out: TextIO, err: TextIO) -> int:
    try:
        cpu = Cpu(
            program,
            profile=options.profile,
            cycle_ms=options.cycle_ms,
            test_ops=options.test_ops,
            clock_memory_byte=options.clock_memory,
            watchdog_ms=options.watchdog_ms,
            retentive=options.retentive,
            cyclic_periods=options.cyclic_periods,
        )
    except ValueError as exc:  # a clock memory byte or a cyclic interrupt OB the CPU lacks
        print(f"nasaq run: {exc}", file=err)
        return 2
    for assignment in (*options.sets, *options.at):
        try:
            cpu.read(assignment.address)
        except (KeyError, IndexError, ValueError) as exc:
            reason = exc.args[0] if isinstance(exc, KeyError) and exc.args else "out of range"
            print(f"nasaq run: {address_text(assignment.address)}: {reason}", file=err)
            return 2
    for assignment in options.sets:
        if assignment.address.area is Area.I:
            _apply(cpu, assignment)
    cpu.start(cold=options.cold_restart)
    for assignment in options.sets:
        if assignment.address.area is not Area.I:
            _apply(cpu, assignment)

    def before_scan(scan: int) -> None:
        for assignment in options.at:
            if assignment.scan == scan:
                _apply(cpu, assignment)

    ran = Pacer(options.time_mode).run(cpu, options.cycles, before_scan)
    json.dump(snapshot(cpu, ran), out, indent=None, separators=(",", ":"))
    out.write("\n")
    if cpu.mode == "STOP" and not cpu.stopped_by_program:
        return 1
    return 0


def main(options: RunOptions) -> int:
    return execute(options, sys.stdout, sys.stderr)


def options_from_args(
    sources: Sequence[str],
    cycles: int,
    cycle_ms: float | None,
    sets: Sequence[str],
    at: Sequence[str],
    mnemonics: str,
    test_ops: bool,
    profile: str | None,
    time_mode: str = "virtual",
    restart: str | None = None,
    clock_memory: str | None = None,
) -> RunOptions:
    """Builds options from command-line strings (None: not given, the project file or the
    default decides); raises AddressError for a bad --set/--at."""
    given = {"cycle_ms": cycle_ms, "profile": profile, "cold_restart": restart}
    given["clock_memory"] = clock_memory
    return RunOptions(
        explicit=frozenset(name for name, value in given.items() if value is not None),
        sources=[Path(source) for source in sources],
        cycles=cycles,
        cycle_ms=10.0 if cycle_ms is None else cycle_ms,
        sets=[parse_assignment(text) for text in sets],
        at=[parse_assignment(text, with_scan=True) for text in at],
        mnemonics=mnemonics,
        test_ops=test_ops,
        profile=Profile(profile or "S7-300"),
        time_mode=TimeMode(time_mode),
        cold_restart=restart == "cold",
        clock_memory=None if clock_memory is None else parse_marker_byte(clock_memory),
    )


def parse_marker_byte(text: str) -> int:
    """``100`` or ``MB100`` / ``MB 100`` (the clock memory byte); raises AddressError."""
    digits = text.strip()
    if digits[:2].upper() == "MB":
        digits = digits[2:].strip()
    if not digits.isdigit():
        raise AddressError(
            f"--clock-memory needs a marker byte number like 100 or MB100, not {text!r}"
        )
    return int(digits)

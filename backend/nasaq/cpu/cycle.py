"""The scan cycle, restart, error OBs and STOP: the CPU's operating system.

Warm restart clears the non-retentive state and runs OB100; cold restart clears everything, gives
the data blocks their downloaded values back and runs OB102. Each scan copies the peripheral
inputs into the PII (forced inputs win), runs the cyclic interrupt OBs that are due (OB35 every
100 ms), runs OB1 (on S7-1200/1500 then the further program-cycle OBs: ``nasaq.cpu.obs``),
copies the PIQ to the peripheral outputs (forced outputs win) and advances the virtual clock by
the cycle time. The clock memory byte (if one is configured) follows the
virtual clock from the restart on; it is written at the restart and at the start of every scan.
Runtime errors are entered in the diagnostic buffer and call OB121/OB122 if loaded, otherwise the
CPU goes to STOP with the location. Without OB1 the CPU
still goes to RUN and its cycles run no program, as a real S7-300/400 does. Nothing a user program
does lets a Python exception out of ``start()`` or ``scan()``: an internal error is STOP SIM500.
"""

from __future__ import annotations

import logging
import traceback
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import TracebackType
from typing import Any

from nasaq.cpu.calls import Calls
from nasaq.cpu.codegen.compiler import Compiled, EmitterError
from nasaq.cpu.counters import Counters
from nasaq.cpu.errors import (
    FAULT_IDS,
    CpuError,
    CpuStopError,
    ErrorClass,
    error_class,
    location,
    sentence_part,
)
from nasaq.cpu.loader import Loader
from nasaq.cpu.machine import Machine
from nasaq.cpu.memory import Memory
from nasaq.cpu.obs import EVENT_STARTUP, plan
from nasaq.cpu.profile import Profile
from nasaq.cpu.timers import Timers
from nasaq.diagnostics import render
from nasaq.ir import BlockKind, Program

log = logging.getLogger(__name__)

RETENTIVE_MARKER_BYTES = 16  # STEP 7 default: MB 0..15 keep their value over a warm restart
RETENTIVE_COUNTERS = 8  # C 0..7
CLOCK_STEP_MS = 50
NEVER = 1 << 62  # the due time of a cyclic interrupt a program does not have
# Half periods of the clock memory bits in 50 ms steps: bit 0 = 0.1 s (10 Hz) ... bit 7 = 2 s.
CLOCK_HALF_PERIODS = (1, 2, 4, 5, 8, 10, 16, 20)


@dataclass(frozen=True, slots=True)
class DiagnosticEntry:
    time_ms: int
    code: str
    message: str  # English; ``key`` and ``params`` let a client say it in its own language
    block: str | None
    network: int | None
    line: int | None
    key: str = ""
    params: dict[str, str | int | float | bool | None] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class Retentive:
    """How many marker bytes, timers and counters from MB 0, T 0 and C 0 keep their values over
    a warm restart (the "Retentive memory" tab of an S7-300's CPU properties; its defaults)."""

    markers: int = RETENTIVE_MARKER_BYTES
    timers: int = 0
    counters: int = RETENTIVE_COUNTERS


class Engine:
    def __init__(
        self,
        program: Program,
        profile: Profile,
        cycle_ms: float,
        watchdog_ms: int,
        test_ops: bool,
        clock_memory_byte: int | None = None,
        retentive: Retentive | None = None,
        cyclic_periods: Mapping[int, int] | None = None,
    ) -> None:
        self.program = program
        self.obs = plan(program, profile, cyclic_periods or {})
        self.cyclic_due = [0] * len(self.obs.cyclic)  # virtual time each cyclic OB is due
        self.next_cyclic = 0  # the earliest of them (a scan without a due OB checks only this)
        self.retentive = retentive or Retentive()
        self.profile = profile
        self.cycle_ms = cycle_ms
        self.watchdog_ms = watchdog_ms
        self.memory = Memory(
            program, profile.process_image_bytes, profile.peripheral_bytes, profile.marker_bytes
        )
        self.m = Machine()
        self.timers = Timers(profile.timers, self.m)
        self.counters = Counters(profile.counters)
        self.clock_memory_byte = clock_memory_byte
        self.clock_origin = 0  # virtual time at which the clock memory bits were last all 0
        self.calls = Calls(
            self.m,
            self.memory,
            profile,
            self._compiled,
            self.handle,
            test_ops=test_ops,
            clock_reset=self.restart_clock_memory,
        )
        self.loader = Loader(
            program,
            profile,
            self.m,
            self.memory,
            self.timers,
            self.counters,
            self.calls,
            test_ops,
            self.handle,
            self._watchdog,
        )
        self.mode = "STOP"
        self.stop_reason: str | None = None
        self.stop_code: str | None = None
        self.stopped_by_program = False
        self.diagnostic_buffer: list[DiagnosticEntry] = []
        self.diagnostic_count = 0  # entries ever made (the buffer keeps the last 1000)
        self.forced_inputs: dict[tuple[int, int], int] = {}
        self.forced_outputs: dict[tuple[int, int], int] = {}
        self.scans = 0
        self.first_scan = True
        self.cold_start = False
        self._clock_fraction = 0.0
        self._in_error_ob = False
        self.last_registers: tuple[object, ...] = self.m.save()

    def _compiled(self, kind: BlockKind, number: int) -> Compiled | None:
        return self.loader.get(kind, number)

    # -- operating modes ------------------------------------------------------------------------
    def start(self, cold: bool = False) -> None:
        """Warm restart (OB100) or, with ``cold``, cold restart (OB102)."""
        try:
            self._start(cold)
        except Exception as exc:  # a simulator bug: STOP SIM500, never an exception
            self._internal_error(exc, exc.__traceback__)

    def _start(self, cold: bool) -> None:
        mem = self.memory
        mem.I[:] = bytes(len(mem.I))
        mem.Q[:] = bytes(len(mem.Q))
        mem.PQ[:] = bytes(len(mem.PQ))
        kept = Retentive(0, 0, 0) if cold else self.retentive
        kept_markers = min(kept.markers, len(mem.M))
        mem.M[kept_markers:] = bytes(len(mem.M) - kept_markers)
        self.timers.clear(keep=kept.timers)
        self.counters.clear(keep=kept.counters)
        if cold:
            mem.reload_dbs()
        self.m.reset_registers()
        self.mode = "RUN"
        self.stop_reason = self.stop_code = None
        self.stopped_by_program = False
        for k, (_number, period) in enumerate(self.obs.cyclic):
            self.cyclic_due[k] = self.m.now + period
        self.next_cyclic = min(self.cyclic_due, default=NEVER)
        self.first_scan = True
        self.cold_start = cold
        self.restart_clock_memory()
        self.calls.comm.restart()  # a restart ends the connections (``cpu.tia_comm``)
        if self.loader.get(BlockKind.OB, 1) is None:
            self._diagnose(CpuError("SIM524"))  # information only: the cycles run no program
        self.m.lim = self.m.n + self._budget()
        for number in self.obs.cold if cold else self.obs.warm:
            if self.mode == "RUN":
                self._run_ob(number)

    def scan(self) -> None:
        if self.mode != "RUN":
            return
        try:
            self._scan()
        except Exception as exc:  # a simulator bug: STOP SIM500, never an exception
            self._internal_error(exc, exc.__traceback__)

    def _scan(self) -> None:
        mem, m = self.memory, self.m
        count = min(len(mem.I), len(mem.PI))
        mem.I[:count] = mem.PI[:count]
        for (byte, bit), value in self.forced_inputs.items():
            _put_bit(mem.I, byte, bit, value)
        if self.clock_memory_byte is not None:
            mem.M[self.clock_memory_byte] = clock_memory_value(m.now - self.clock_origin)
        m.lim = m.n + self._budget()
        if m.now >= self.next_cyclic:
            due = self.cyclic_due
            for k, (number, period) in enumerate(self.obs.cyclic):
                while self.mode == "RUN" and m.now >= due[k]:
                    due[k] += period
                    self._run_ob(number)
            self.next_cyclic = min(due, default=NEVER)
        for number in self.obs.cycle:
            if self.mode == "RUN":
                self._run_ob(number)
        if self.mode == "RUN":
            count = min(len(mem.Q), len(mem.PQ))
            mem.PQ[:count] = mem.Q[:count]
            for (byte, bit), value in self.forced_outputs.items():
                _put_bit(mem.PQ, byte, bit, value)
        self.first_scan = False
        self.scans += 1
        self._clock_fraction += self.cycle_ms
        whole = int(self._clock_fraction)
        self._clock_fraction -= whole
        m.now += whole

    def restart_clock_memory(self) -> None:
        """The clock memory bits start from 0 now (at a restart; awlsim's SFC -4)."""
        self.clock_origin = self.m.now
        if self.clock_memory_byte is not None:
            self.memory.M[self.clock_memory_byte] = 0

    def _budget(self) -> int:
        return self.watchdog_ms * 1_000_000 // self.profile.ns_per_instruction

    # -- running organisation blocks ------------------------------------------------------------
    def _run_ob(self, number: int) -> bool:
        compiled = self.loader.get(BlockKind.OB, number)
        if compiled is None:
            return False
        m = self.m
        frame = bytearray(max(compiled.frame_size, 20))
        event, priority = self.obs.start_info.get(number, (0x11, 1))
        frame[0], frame[2], frame[3] = event, priority, number & 0xFF
        if priority == 1 and event == 0x11:  # OB1_SCAN_1: 1st cycle after warm (1)/cold (4), else 3
            frame[1] = (0x04 if self.cold_start else 0x01) if self.first_scan else 0x03
        elif event == EVENT_STARTUP:  # OB100_STRTUP: manual warm (16#81) or cold (16#85) restart
            frame[1] = 0x85 if self.cold_start else 0x81
        self.calls.comm.ob_started(frame, event == EVENT_STARTUP)  # RD_SINFO reads it
        m.depth, m.lstack, m.priority = 1, len(frame), priority
        m.fc = m.orb = m.os = 0
        m.sta = 1
        m.db = m.di = bytearray()
        m.dbno = m.dino = 0
        self._execute(compiled, frame)
        self.last_registers = m.save()
        return True

    def _execute(
        self, compiled: Compiled, frame: bytearray, params: list[object] | None = None
    ) -> None:
        try:
            compiled.function(self.m, frame, bytearray(), params or [])
        except CpuStopError as stop:
            self._stop(stop)
        except CpuError as error:  # a recoverable error that escaped its handler
            self._stop(error)
        except RecursionError:
            self._stop(CpuError("SIM508", limit=self.profile.nesting_depth, block="?"))
        except Exception as exc:
            self._internal_error(exc, exc.__traceback__)

    def _internal_error(self, exc: BaseException, tb: TracebackType | None) -> None:
        log.error("simulator internal error\n%s", "".join(traceback.format_exception(exc)))
        error = CpuError("SIM500")
        where: tuple[Any, int] | None = None
        for frame, lineno in traceback.walk_tb(tb):
            compiled = self.loader.by_filename.get(frame.f_code.co_filename)
            if compiled is not None and lineno in compiled.line_map:
                where = (compiled, compiled.line_map[lineno])
        failure = exc if isinstance(exc, EmitterError) else exc.__cause__
        if isinstance(failure, EmitterError):
            where = (failure, failure.index)
        if where is not None:
            error.where = location(*where)
        self._stop(error)

    # -- errors --------------------------------------------------------------------------------
    def handle(self, error: CpuError, compiled: Compiled, index: int) -> int:
        """Report ``error`` at instruction ``index`` of ``compiled``; run OB121/OB122 and
        return 0 (the value a failed read yields), or raise CpuStopError."""
        if error.where is None:
            error.where = location(compiled, index)
        self._diagnose(error)
        kind = error_class(error.code)
        if kind is ErrorClass.FATAL or self._in_error_ob:
            raise CpuStopError(error.code, **error.params).located(error.where)
        ob = 121 if kind is ErrorClass.PROGRAMMING else 122
        handler = self.loader.get(BlockKind.OB, ob)
        if handler is None:
            raise CpuStopError(error.code, **error.params).located(error.where)
        m = self.m
        saved = m.save()
        frame = bytearray(max(handler.frame_size, 20))
        event, _priority = self.obs.start_info[ob]
        frame[0], frame[1], frame[2], frame[3] = event, FAULT_IDS.get(error.code, 0), m.priority, ob
        m.depth, m.lstack = 1, len(frame)
        self._in_error_ob = True
        try:
            handler.function(m, frame, bytearray(), [])
        finally:
            self._in_error_ob = False
            m.restore(saved)
        return 0

    def _watchdog(self, compiled: Compiled, index: int) -> None:
        error = CpuStopError("SIM501", limit_ms=self.watchdog_ms)
        error.where = location(compiled, index)
        raise error

    def _diagnose(self, error: CpuError) -> None:
        block, network, line = error.where or (None, None, None)
        found = render(error.code, None, **error.params)
        params = {
            name: value if value is None or isinstance(value, str | int | float) else str(value)
            for name, value in error.params.items()
        }
        self.diagnostic_buffer.append(
            DiagnosticEntry(
                self.m.now, error.code, found.message, block, network, line, found.key, params
            )
        )
        self.diagnostic_count += 1
        del self.diagnostic_buffer[:-1000]

    def _stop(self, error: CpuError) -> None:
        if self.mode == "STOP" and self.stop_code is not None:
            return
        self.mode = "STOP"
        self.stop_code = error.code
        self.stopped_by_program = error.code == "SIM502"
        if not self.diagnostic_buffer or self.diagnostic_buffer[-1].code != error.code:
            self._diagnose(error)
        place = format_location(error.where)
        text = f"{sentence_part(error.message)} ({error.code})"
        self.stop_reason = f"{place}: {text}" if place else text
        self.memory.PQ[:] = bytes(len(self.memory.PQ))  # outputs are disabled in STOP


def clock_memory_value(elapsed_ms: int) -> int:
    """The clock memory byte ``elapsed_ms`` after its bits were all 0: bit k is a square wave
    (half the period 1, half 0) with the period of ``CLOCK_HALF_PERIODS[k]`` × 100 ms."""
    steps = max(0, elapsed_ms) // CLOCK_STEP_MS
    value = 0
    for bit, half in enumerate(CLOCK_HALF_PERIODS):
        value |= ((steps // half) & 1) << bit
    return value


def _put_bit(buf: bytearray, byte: int, bit: int, value: int) -> None:
    if 0 <= byte < len(buf):
        if value:
            buf[byte] |= 1 << bit
        else:
            buf[byte] &= ~(1 << bit) & 0xFF


def format_location(where: tuple[str, int | None, int | None] | None) -> str:
    if where is None:
        return ""
    block, network, line = where
    parts = [block]
    if network is not None:
        parts.append(f" network {network}")
    if line is not None:
        parts.append(f"{',' if network is not None else ''} line {line}")
    return "".join(parts)

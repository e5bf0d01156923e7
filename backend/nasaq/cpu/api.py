"""The public face of the simulator: ``Cpu`` (what the CLI, the tests and the server use)."""

from __future__ import annotations

from nasaq.cpu.codegen.test_ops import feature_profile
from nasaq.cpu.cycle import DiagnosticEntry, Engine, Retentive
from nasaq.cpu.memory import read_bytes, write_bytes
from nasaq.cpu.obs import check_periods
from nasaq.cpu.profile import Profile
from nasaq.cpu.status_word import pack
from nasaq.ir import Area, Direct, Program, Width

_REGISTER_INDEX = {"a1": 0, "a2": 1, "a3": 2, "a4": 3, "ar1": 4, "ar2": 5}
_STATUS = ("fc", "rlo", "sta", "orb", "os", "ov", "cc0", "cc1", "br")


class Cpu:
    """An S7-300/400 CPU running ``program`` in virtual time.

    >>> cpu = Cpu(program); cpu.start(); cpu.run(10)  # doctest: +SKIP
    """

    def __init__(
        self,
        program: Program,
        profile: Profile = Profile.S7_300,
        cycle_ms: float = 10,
        watchdog_ms: int = 150,
        test_ops: bool = False,
        clock_memory_byte: int | None = None,
        retentive: Retentive | None = None,
        cyclic_periods: dict[int, int] | None = None,
    ) -> None:
        """``clock_memory_byte``: the marker byte the CPU uses as clock memory (the CPU
        properties' "clock memory" in STEP 7), or None for none; ``retentive``: the MB, T and C
        ranges a warm restart keeps (default MB 0-15, no timers, C 0-7); ``cyclic_periods``: the
        cycle time in ms of cyclic interrupt OBs (default 100 ms each; ``nasaq.cpu.obs``). Raises
        ValueError if the profile has no such marker byte, fewer markers, timers or counters than
        retentive, or no such cyclic interrupt OB."""
        if test_ops:  # a self-checking test program may ask for 4 accumulators (__FEATURE 0, 4)
            profile = feature_profile(program, profile)
        if clock_memory_byte is not None and not 0 <= clock_memory_byte < profile.marker_bytes:
            raise ValueError(
                f"clock memory MB {clock_memory_byte}: the {profile.value} has MB 0 to "
                f"MB {profile.marker_bytes - 1}"
            )
        kept = retentive or Retentive()
        for what, count, limit in (
            ("marker bytes", kept.markers, profile.marker_bytes),
            ("timers", kept.timers, profile.timers),
            ("counters", kept.counters, profile.counters),
        ):
            if not 0 <= count <= limit:
                raise ValueError(f"retentive {what}: the {profile.value} has 0 to {limit}")
        check_periods(cyclic_periods or {}, profile)
        self.profile = profile
        self._engine = Engine(
            program,
            profile,
            cycle_ms,
            watchdog_ms,
            test_ops,
            clock_memory_byte=clock_memory_byte,
            retentive=kept,
            cyclic_periods=cyclic_periods,
        )

    @property
    def engine(self) -> Engine:
        """The operating system under the API, for the monitor (instrumented blocks, holds)."""
        return self._engine

    # -- operation -----------------------------------------------------------------------------
    def start(self, cold: bool = False) -> None:
        """Warm restart: clear non-retentive data, run OB100 if loaded, go to RUN. With ``cold``,
        cold restart: clear all data, give the DBs their downloaded values, run OB102 if loaded.
        Without OB1 the CPU still goes to RUN (its cycles run no program)."""
        self._engine.start(cold)

    def scan(self) -> None:
        self._engine.scan()

    def run(self, scans: int) -> None:
        engine = self._engine
        for _ in range(scans):
            if engine.mode != "RUN":
                break
            engine.scan()

    def stop(self) -> None:
        """Mode switch to STOP (by the operator, not an error)."""
        self._engine.mode = "STOP"

    def memory_reset(self) -> None:
        """MRES: data blocks get their downloaded values back, everything else is cleared."""
        mem = self._engine.memory
        mem.reload_dbs()
        mem.M[:] = bytes(len(mem.M))
        self._engine.counters.clear()
        self._engine.timers.clear()

    # -- state ---------------------------------------------------------------------------------
    @property
    def mode(self) -> str:
        return self._engine.mode

    @property
    def stop_reason(self) -> str | None:
        return self._engine.stop_reason

    @property
    def stop_code(self) -> str | None:
        return self._engine.stop_code

    @property
    def stopped_by_program(self) -> bool:
        return self._engine.stopped_by_program

    @property
    def time_ms(self) -> int:
        return self._engine.m.now

    @property
    def cycle_ms(self) -> float:
        """Virtual time between scans; may be changed between scans (real-time pacing)."""
        return self._engine.cycle_ms

    @cycle_ms.setter
    def cycle_ms(self, value: float) -> None:
        self._engine.cycle_ms = max(0.0, value)

    @property
    def scans(self) -> int:
        return self._engine.scans

    @property
    def diagnostic_buffer(self) -> list[DiagnosticEntry]:
        return list(self._engine.diagnostic_buffer)

    @property
    def instructions_executed(self) -> int:
        return self._engine.m.n

    def _register(self, name: str) -> int:
        value = self._engine.last_registers[_REGISTER_INDEX[name]]
        assert isinstance(value, int)
        return value

    @property
    def accu1(self) -> int:
        return self._register("a1")

    @property
    def accu2(self) -> int:
        return self._register("a2")

    @property
    def accu3(self) -> int:
        return self._register("a3")

    @property
    def accu4(self) -> int:
        return self._register("a4")

    @property
    def ar1(self) -> int:
        return self._register("ar1")

    @property
    def ar2(self) -> int:
        return self._register("ar2")

    @property
    def stw(self) -> int:
        """The status word, all nine bits (bit 0 /FC ... bit 8 BR; an S7-300 program's ``L STW``
        sees /FC, STA and OR as 0)."""
        saved = self._engine.last_registers
        values = {name: int(saved[6 + k]) for k, name in enumerate(_STATUS)}  # type: ignore[call-overload]
        return pack(values)

    # -- memory --------------------------------------------------------------------------------
    def _buffer(self, direct: Direct) -> bytearray:
        mem = self._engine.memory
        if direct.area is Area.DB:
            number = direct.db if direct.db is not None else self._engine.m.dbno
            found = mem.dbs.get(number)
            if found is None:
                raise KeyError(f"DB {number} is not loaded")
            return found
        if direct.area in (Area.L, Area.V, Area.DI):
            raise ValueError(f"{direct.area.value} is only addressable inside a block")
        return mem.area(direct.area)

    def read(self, direct: Direct) -> int:
        """Unsigned value of a bit, byte, word or double word (I = PII, Q = PIQ, PI, PQ, M, DB)."""
        return read_bytes(self._buffer(direct), direct.byte, int(direct.width), direct.bit)

    def write(self, direct: Direct, value: int) -> None:
        write_bytes(self._buffer(direct), direct.byte, int(direct.width), value, direct.bit)

    def set_input(self, direct: Direct, value: int) -> None:
        """Drive a peripheral input; the next scan's PII update reads it."""
        target = Direct(Area.PI, direct.width, direct.byte, direct.bit)
        write_bytes(self._engine.memory.PI, target.byte, int(target.width), value, target.bit)

    def force(self, direct: Direct, value: int) -> None:
        """Force an input (wins over the process at every PII update) or output (at every
        PIQ output) bit by bit."""
        forced = self._forces(direct)
        width = int(direct.width)
        if width == Width.BIT:
            forced[(direct.byte, direct.bit)] = value & 1
            return
        for k in range(width):
            byte = direct.byte + (width - 1 - k) // 8
            forced[(byte, k % 8)] = (value >> k) & 1

    def unforce(self, direct: Direct | None = None) -> None:
        engine = self._engine
        if direct is None:
            engine.forced_inputs.clear()
            engine.forced_outputs.clear()
            return
        forced = self._forces(direct)
        width = int(direct.width)
        bits = (
            [(direct.byte, direct.bit)]
            if width == 1
            else [(direct.byte + k // 8, k % 8) for k in range(width)]
        )
        for key in bits:
            forced.pop(key, None)

    def _forces(self, direct: Direct) -> dict[tuple[int, int], int]:
        if direct.area in (Area.I, Area.PI):
            return self._engine.forced_inputs
        if direct.area in (Area.Q, Area.PQ):
            return self._engine.forced_outputs
        raise ValueError("only inputs and outputs can be forced")

    def area_bytes(self, area: Area | str) -> bytes:
        return bytes(self._engine.memory.area(Area(area)))

    def db_bytes(self, number: int) -> bytes | None:
        found = self._engine.memory.dbs.get(number)
        return bytes(found) if found is not None else None

    def db_numbers(self) -> list[int]:
        return sorted(self._engine.memory.dbs)

    def timer(self, number: int) -> tuple[int, int, bool]:
        """(Q, remaining ms, running) of timer ``number``."""
        timers = self._engine.timers
        q = timers.status(number)
        return q, timers.remaining_ms(number), timers.running[number]

    def counter(self, number: int) -> tuple[int, int]:
        counters = self._engine.counters
        return counters.status(number), counters.load(number)

"""The steps of a scenario on a running CPU, with its plant in closed loop.

Per scan, as the simulation session does it: the plant's sensors and panel controls go to the
peripheral inputs, the CPU scans, the plant reads the outputs and advances by the cycle time.
Virtual time (``at_ms`` of a failure) counts the scans run since the CPU started.

A CPU in STOP runs no scan: ``run``, ``during`` and ``within`` end there (``expect: {mode:
STOP}`` checks that it stopped). The plant does not reset on ``restart``: a real tank keeps its
water while the CPU restarts.
"""

from __future__ import annotations

from typing import Any

from nasaq.cpu import Cpu
from nasaq.headless.addresses import encode_value, parse_address, parse_number
from nasaq.ir import Area, Direct, Program
from nasaq.plants.runtime import PlantRuntime
from nasaq.scenarios.expectations import Check, prepare_all
from nasaq.scenarios.members import Members, is_member_key
from nasaq.scenarios.model import PLANT_KEY, Interval, Note, Scenario, ScenarioError, Step
from nasaq.scenarios.result import Failure, ScenarioResult
from nasaq.scenarios.where import Writers


class Execution:
    def __init__(
        self,
        cpu: Cpu,
        runtime: PlantRuntime | None,
        scenario: Scenario,
        program: Program,
        texts: dict[str, str],
        result: ScenarioResult,
    ) -> None:
        self.cpu = cpu
        self.runtime = runtime
        self.scenario = scenario
        self.result = result
        self.writers = Writers(program, texts)
        self.members = Members(program)
        self.cycle_ms = scenario.cycle_ms
        self.scans_run = 0
        self.stopped_at: int | None = None  # virtual time the CPU left RUN by an error
        self.index = 0
        self.note: Note | None = None  # names the steps that follow it, until the next note

    # -- time ---------------------------------------------------------------------------------
    @property
    def now_ms(self) -> int:
        return round(self.scans_run * self.cycle_ms)

    def scans(
        self, count: int, checks: list[tuple[str, Check]] | None = None, until: bool = False
    ) -> list[tuple[str, str, str]] | None:
        """Runs up to ``count`` scans, fewer when the CPU stops; the hot loop. With ``checks``,
        they are evaluated after every scan and the loop ends at the first scan where one fails
        (``until`` False: ``during``) or where all hold (``until`` True: ``within``); answers
        the failing checks of the last scan run (None when no scan ran)."""
        cpu = self.cpu
        engine = cpu.engine
        scan = engine.scan
        runtime = self.runtime
        failing: list[tuple[str, str, str]] | None = None
        done = 0
        if runtime is not None:
            dt = int(self.cycle_ms)
            write_inputs = runtime.write_inputs
            read_outputs = runtime.read_outputs
            advance = runtime.advance
        while done < count:
            if engine.mode != "RUN":
                break
            if runtime is not None:
                write_inputs(cpu)
                scan()
                read_outputs(cpu)
                advance(dt)
            else:
                scan()
            done += 1
            if checks is not None:
                failing = [
                    (key, *mismatch) for key, check in checks if (mismatch := check()) is not None
                ]
                if bool(failing) != until:
                    break
        self.scans_run += done
        if done < count and engine.mode != "RUN" and self.stopped_at is None:
            self.stopped_at = self.now_ms
        return failing

    def _count(self, ms: float) -> int:
        return int(-(-ms // self.cycle_ms))

    # -- failures -----------------------------------------------------------------------------
    def fail(self, key: str, expected: str, actual: str) -> None:
        where = None if key == "mode" or key.startswith(PLANT_KEY) else self.writers.of(key)
        self.result.failures.append(
            Failure(self.index, self.note, key, expected, actual, self.now_ms, where)
        )

    def _failing(self, checks: list[tuple[str, Check]]) -> list[tuple[str, str, str]]:
        found = []
        for key, check in checks:
            mismatch = check()
            if mismatch is not None:
                found.append((key, *mismatch))
        return found

    # -- steps --------------------------------------------------------------------------------
    def run_steps(self) -> None:
        for index, step in enumerate(self.scenario.steps, start=1):
            self.index = index
            self.note = step.note or self.note
            if step.checks():
                self.result.steps.append((index, self.note))
            self.do(step)

    def do(self, step: Step) -> None:
        cpu, runtime = self.cpu, self.runtime
        if step.set_ is not None:
            for key, value in step.set_.items():
                if is_member_key(str(key)):
                    self.members.write(cpu, str(key), value, self.index)
                else:
                    _set(cpu, str(key), value)
        elif step.run is not None:
            self.scans(step.scans(self.cycle_ms))
        elif step.expect is not None:
            checks = prepare_all(cpu, runtime, step.expect, self.member_check)
            for key, expected, actual in self._failing(checks):
                self.fail(key, expected, actual)
        elif step.operate is not None:
            plant = self._plant("operate")
            for control, value in step.operate.items():
                number = parse_number(value) if isinstance(value, str) else value
                plant.operate(str(control), int(number))
        elif step.fault is not None:
            plant = self._plant("fault")
            for code, on in step.fault.items():
                plant.inject(str(code), bool(on))
        elif step.during is not None:
            self._during(step.during)
        elif step.within is not None:
            self._within(step.within)
        elif step.restart is not None:
            cpu.stop()
            cpu.start(cold=step.restart == "cold")

    def member_check(self, key: str, expected: Any) -> Check:
        return self.members.check(self.cpu, key, expected, self.index)

    def _plant(self, what: str) -> PlantRuntime:
        if self.runtime is None:
            raise ScenarioError(f"step {self.index}: {what}: this scenario runs no plant")
        return self.runtime

    def _during(self, interval: Interval) -> None:
        checks = prepare_all(self.cpu, self.runtime, interval.expect, self.member_check)
        count = self._count(interval.ms)
        start = self.scans_run
        failing = self.scans(count, checks)
        if failing:
            for key, expected, actual in failing:
                self.fail(key, expected, actual)
            self.scans(count - (self.scans_run - start))  # time goes on; the step has failed

    def _within(self, interval: Interval) -> None:
        checks = prepare_all(self.cpu, self.runtime, interval.expect, self.member_check)
        failing = self._failing(checks)
        if failing:
            after = self.scans(self._count(interval.ms), checks, until=True)
            failing = after if after is not None else failing
        for key, expected, actual in failing:
            self.fail(key, f"{expected} within {interval.ms:g} ms", actual)

    def finish(self) -> None:
        """Reports a CPU that went to STOP by an error: its reason, and a failure unless a step
        expected the mode."""
        cpu = self.cpu
        if cpu.mode == "RUN" or cpu.stop_code is None:
            return
        self.result.stop = (cpu.stop_code, cpu.stop_reason or cpu.stop_code)
        entry = next((e for e in reversed(cpu.diagnostic_buffer) if e.code == cpu.stop_code), None)
        if entry is not None:
            self.result.stop_key, self.result.stop_params = entry.key, dict(entry.params)
        expects_mode = any(
            "mode" in (step.expect or {})
            or "mode" in (step.during.expect if step.during else {})
            or "mode" in (step.within.expect if step.within else {})
            for step in self.scenario.steps
        )
        if not expects_mode:
            at = self.stopped_at if self.stopped_at is not None else self.now_ms
            self.result.failures.append(
                Failure(self.index, self.note, "mode", "RUN", f"STOP ({cpu.stop_code})", at)
            )


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

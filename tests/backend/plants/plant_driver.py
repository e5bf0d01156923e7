"""Helpers of the plant tests: step a plant alone, or run it in closed loop with a program."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from nasaq.cpu import Cpu
from nasaq.headless.sources import compile_files
from nasaq.plants.base import Plant
from nasaq.plants.registry import plant_class
from nasaq.plants.runtime import PlantConfig, PlantRuntime

COURSE = Path(__file__).resolve().parents[2] / "scenarios" / "course"
EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "projects"


def hold(plant: Plant, ms: int, dt: int = 10, **actuators: int) -> Plant:
    """Sets ``actuators`` and steps the plant ``ms`` of virtual time in steps of ``dt``."""
    plant.set_actuators(actuators)
    for _ in range(ms // dt):
        plant.advance(dt)
    return plant


class ClosedLoop:
    """A program on a CPU wired to a plant, scanned as the session and the scenarios do."""

    def __init__(self, files: list[Path], config: PlantConfig, cycle_ms: int = 10) -> None:
        compiled = compile_files(files, "auto")
        assert compiled.ok, [d.message for d in compiled.diagnostics]
        self.cpu = Cpu(compiled.program, cycle_ms=cycle_ms)
        self.runtime = PlantRuntime(config)
        self.plant = self.runtime.plant
        self.cycle_ms = cycle_ms
        self.cpu.start()

    def scan(self) -> None:
        runtime = self.runtime
        runtime.write_inputs(self.cpu)
        self.cpu.scan()
        runtime.read_outputs(self.cpu)
        runtime.advance(self.cycle_ms)

    def run(self, ms: int) -> None:
        for _ in range(ms // self.cycle_ms):
            self.scan()

    def run_until(self, condition: Callable[[], bool], limit_ms: int) -> int:
        """Scans until ``condition`` holds; returns the virtual ms it took (fails at the limit)."""
        for k in range(limit_ms // self.cycle_ms):
            if condition():
                return k * self.cycle_ms
            self.scan()
        raise AssertionError(f"not reached within {limit_ms} ms: {self.plant.state()}")

    def press(self, control: str, ms: int = 100) -> None:
        """A push button held for ``ms`` and released (an NC button: opened, then closed)."""
        signal = self.plant.signal(control)
        self.runtime.operate(control, 0 if signal.normally_closed else 1)
        self.run(ms)
        self.runtime.operate(control, 1 if signal.normally_closed else 0)


class CourseLoop(ClosedLoop):
    """A course example of ``tests/scenarios/course`` (e.g. ``vi_004/e37_packaging_line``: its
    .awl and, if present, .sdf) driving a plant wired as given or as the plant usually is."""

    def __init__(
        self,
        example: str,
        kind: str,
        params: dict[str, float] | None = None,
        wiring: dict[str, str] | None = None,
        cycle_ms: int = 10,
    ) -> None:
        base = COURSE / example
        files = [base.with_suffix(".awl")]
        if base.with_suffix(".sdf").exists():
            files.append(base.with_suffix(".sdf"))
        config = PlantConfig(
            kind=kind,
            wiring=wiring if wiring is not None else dict(plant_class(kind).default_wiring),
            params=params or {},
        )
        super().__init__(files, config, cycle_ms)

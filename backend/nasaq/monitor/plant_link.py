"""The session's virtual plant: built from the project's ``<name>.plant`` file, stepped with the
CPU's clock between scans, shown to the clients in the frames.

Per scan (``Session._scan``): ``before_scan`` writes the plant's sensors and panel controls into
the peripheral inputs, which the scan's PII update reads; ``after_scan`` reads the output modules
(``PQ``) and advances the plant by the virtual time the scan took (the CPU clock's step, so
``real`` mode's jumps and ``fast`` mode's back-to-back scans move the plant exactly as the
program sees time move). In STOP no scan runs and the plant stands still with the clock, as a
check's plant does; the panel still works (an operated control reaches the inputs at once).

A download builds a new plant from the new sources: the process starts again from its initial
state, as a PLCSIM + process-simulation pair is reset with the program (decision of issue 17;
``plant_reset`` does the same without a download). A plant file with an error refuses the
session or the download with its ``PLT###`` diagnostic (file and line), as a ``cpu.properties``
with an error does, so the CPU never runs with a process the user did not describe.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from nasaq.cpu import Cpu
from nasaq.lang.stl import SourceFile
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import PlantFrame
from nasaq.plants.base import PlantError

if TYPE_CHECKING:
    from nasaq.plants.runtime import PlantRuntime

PLANT_SUFFIX = ".plant"  # nasaq.plants.plant_file.SUFFIX

# Codes of the plant file that mean something else when a socket command names the thing.
_COMMAND_CODES = {"PLT010": "PLT018"}


def _text(source: SourceFile) -> str:
    text = source.text
    return text if isinstance(text, str) else text.decode("utf-8", errors="replace")


def plant_of(sources: list[SourceFile]) -> PlantRuntime | None:
    """The plant the sources' ``.plant`` file describes (None: no plant file); MonitorError
    with the file's PLT diagnostic when it cannot run."""
    if not any(s.name.lower().endswith(PLANT_SUFFIX) for s in sources):
        return None  # most projects: the plant models are not even imported (worker start-up)
    from nasaq.plants.plant_file import PlantFileError, find_plant_file, read_plant_file
    from nasaq.plants.runtime import PlantRuntime

    try:
        found = find_plant_file([(s.name, _text(s)) for s in sources])
        if found is None:
            return None
        config = read_plant_file(*found)
        return PlantRuntime(config)
    except PlantFileError as error:
        raise MonitorError(error.code, **error.params) from None


class PlantLink:
    """One plant wired to the session's CPU, and the last view of it the frames carried."""

    def __init__(self, runtime: PlantRuntime, cpu: Cpu) -> None:
        self.runtime = runtime
        self.cpu = cpu
        self.clock_ms = cpu.time_ms  # the CPU time the plant has been advanced to
        self.view: PlantFrame | None = None
        self._shown: dict[str, Any] | None = None

    def before_scan(self, cpu: Cpu) -> None:
        self.runtime.write_inputs(cpu)

    def after_scan(self, cpu: Cpu) -> None:
        runtime = self.runtime
        runtime.read_outputs(cpu)
        now = cpu.time_ms
        if now > self.clock_ms:
            runtime.advance(now - self.clock_ms)
        self.clock_ms = now

    def frame_view(self) -> PlantFrame:
        """The plant as the frames show it; the same object while nothing changed, so each
        client's frame state sends it only when it changed."""
        if self.cpu.mode != "RUN":
            self.runtime.read_outputs(self.cpu)  # stopped: the outputs are off
        shown = self.runtime.snapshot()
        if shown != self._shown or self.view is None:
            self._shown = shown
            self.view = PlantFrame.model_validate(shown)
        return self.view

    # -- commands (run in the CPU thread) --------------------------------------------------------
    def operate(self, cpu: Cpu, control: str, value: int) -> None:
        try:
            self.runtime.operate(control, value)
        except PlantError as error:
            raise _command_error(error, self.runtime.plant.kind) from None
        self.runtime.write_inputs(cpu)  # the inputs show it at once, in STOP too

    def fault(self, code: str, on: bool) -> None:
        try:
            self.runtime.inject(code, on)
        except PlantError as error:
            raise _command_error(error, self.runtime.plant.kind) from None

    def reset(self, cpu: Cpu) -> None:
        self.runtime.reset()
        self.runtime.write_inputs(cpu)


def _command_error(error: PlantError, kind: str) -> MonitorError:
    """The socket's error for a plant command the plant refused."""
    try:
        return MonitorError(_COMMAND_CODES.get(error.code, error.code), **error.params)
    except KeyError:  # a message about a file's line: say it without one
        return MonitorError("PLT020", file=kind, line="-", reason=str(error))


def no_plant() -> MonitorError:
    return MonitorError("PLT017")

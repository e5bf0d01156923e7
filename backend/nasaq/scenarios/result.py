"""What a scenario run found: its failures, compile problems and the CPU's stop reason."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from nasaq.diagnostics import Diagnostic
from nasaq.scenarios.model import Note, note_text
from nasaq.scenarios.where import Where


@dataclass(frozen=True, slots=True)
class Failure:
    step: int  # 1-based, as the file lists them
    note: Note | None  # the note of the step or of the steps before it
    address: str
    expected: str
    actual: str
    at_ms: int | None = None  # virtual time since the CPU started
    where: Where | None = None  # the instruction that last writes the address

    def describe(self, language: str = "en") -> str:
        text = note_text(self.note, language)
        note = f" ({text})" if text else ""
        return f"step {self.step}{note}: {self.address} expected {self.expected}, got {self.actual}"

    def place(self) -> str:
        """When and where, for a report's second line: ``at 2030 ms, written at OB1.awl:11``."""
        parts = [f"at {self.at_ms} ms"] if self.at_ms is not None else []
        if self.where is not None:
            network = f" (network {self.where.network})" if self.where.network else ""
            parts.append(f"written at {self.where.file}:{self.where.line}{network}")
        return ", ".join(parts)


@dataclass(slots=True)
class ScenarioResult:
    path: Path
    name: str
    failures: list[Failure] = field(default_factory=list)
    error: str | None = None  # the scenario could not run: invalid file, compile errors
    diagnostics: list[str] = field(default_factory=list)
    problems: list[Diagnostic] = field(default_factory=list)  # the compiler's, structured
    compile_failed: bool = False  # the program under test does not compile
    stop: tuple[str, str] | None = None  # (code, reason) when the CPU went to STOP by an error
    stop_key: str = ""  # the stop's catalogue key and parameters, to translate the reason
    stop_params: dict[str, object] = field(default_factory=dict)
    steps: list[tuple[int, Note | None]] = field(default_factory=list)  # checking steps, note

    @property
    def passed(self) -> bool:
        return self.error is None and not self.failures

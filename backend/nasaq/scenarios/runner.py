"""Runs one scenario against a fresh CPU and collects every mismatch.

The sources' ``cpu.properties`` (``nasaq.headless.project_file``) sets the CPU; the scenario's
own ``profile`` and ``cycle_ms``, when the file names them, win over it.

A lesson runs its scenarios against the learner's project: ``run_scenario(path, sources=...,
plant=...)`` takes the project's files as (name, text) and the lesson's plant; a scenario that
names its own ``sources`` or ``plant`` keeps them. Failures on an address say where the program
last writes it (``where.py``); a CPU that went to STOP by an error fails the scenario with its
stop reason, unless a step expected the mode.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from nasaq.cpu import Cpu, Profile
from nasaq.diagnostics import Diagnostic
from nasaq.headless import project_file
from nasaq.headless.addresses import AddressError
from nasaq.headless.sources import SourceError, diagnostic_line, read_source
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.plants.base import PlantError
from nasaq.plants.runtime import PlantConfig, PlantRuntime
from nasaq.scenarios.model import Scenario, ScenarioError, load_scenario
from nasaq.scenarios.result import Failure, ScenarioResult
from nasaq.scenarios.steps import Execution
from nasaq.workbench.cpu_properties import ReadProperties, is_properties_file, read_properties
from nasaq.workbench.names import language_of

__all__ = ["Failure", "ScenarioResult", "run_loaded", "run_scenario"]

_COMPILED = frozenset({"stl", "scl", "lad", "fbd", "graph", "symbols"})


def _project_files(sources: Sequence[tuple[str, str]]) -> list[SourceFile]:
    """The files of a project the compiler reads (not ``.plant``, watch tables, properties)."""
    return [SourceFile(name, text) for name, text in sources if language_of(name) in _COMPILED]


def _project_properties(sources: Sequence[tuple[str, str]]) -> ReadProperties | None:
    for name, text in sources:
        if is_properties_file(name):
            return read_properties(text, name)
    return None


def run_scenario(
    path: Path,
    sources: Sequence[tuple[str, str]] | None = None,
    plant: PlantConfig | None = None,
) -> ScenarioResult:
    """Loads, compiles and runs one scenario file; never raises for a bad file or program.

    ``sources``: the project under test as (file name, text), for a scenario without its own
    ``sources``; ``plant``: the plant it runs with unless it names its own (or ``none``)."""
    try:
        scenario = load_scenario(path)
    except ScenarioError as exc:
        return ScenarioResult(path, path.stem, error=str(exc))
    return run_loaded(scenario, path, sources, plant)


def _sources_of(
    scenario: Scenario, path: Path, sources: Sequence[tuple[str, str]] | None
) -> tuple[list[SourceFile], ReadProperties | None]:
    if scenario.sources:
        files = [read_source(source) for source in scenario.source_paths()]
        return files, project_file.load(scenario.source_paths())
    if sources is None:
        raise SourceError(f"{path}: sources: name the program's files (a lesson gives them)")
    return _project_files(sources), _project_properties(sources)


def _file_of(problem: Diagnostic) -> str:
    return (problem.span.file or "") if problem.span is not None else ""


def _line_of(problem: Diagnostic) -> int | None:
    return problem.span.line if problem.span is not None else None


def _diagnostics_missing(scenario: Scenario, problems: list[Diagnostic]) -> list[Failure]:
    """``expect_diagnostics``: every listed code (at its line and file) must be reported."""
    failures: list[Failure] = []
    for wanted in scenario.expect_diagnostics or []:
        found = any(
            problem.code == wanted.code
            and wanted.line in (None, _line_of(problem))
            and (wanted.file is None or _file_of(problem).endswith(wanted.file))
            for problem in problems
        )
        if not found:
            place = f" at line {wanted.line}" if wanted.line is not None else ""
            got = ", ".join(sorted({p.code for p in problems})) or "no diagnostics"
            failures.append(Failure(0, None, wanted.code, f"{wanted.code}{place}", got))
    return failures


def run_loaded(
    scenario: Scenario,
    path: Path,
    sources: Sequence[tuple[str, str]] | None = None,
    plant: PlantConfig | None = None,
) -> ScenarioResult:
    """Runs an already loaded scenario (see ``run_scenario``)."""
    result = ScenarioResult(path, scenario.name)
    try:
        files, found = _sources_of(scenario, path, sources)
    except SourceError as exc:
        result.error = str(exc)
        return result
    profile = scenario.profile  # the scenario's own, else the properties file's, as below
    if found is not None and "profile" not in scenario.model_fields_set:
        profile = found.properties.profile.value
    compiled = compile_sources(files, mnemonics=scenario.mnemonics, profile=profile)
    result.problems = list(compiled.diagnostics)
    result.diagnostics = [diagnostic_line(d) for d in compiled.diagnostics]
    if scenario.expect_diagnostics is not None:
        result.failures = _diagnostics_missing(scenario, result.problems)
        if compiled.ok:
            result.failures.append(Failure(0, None, "compile", "diagnostics", "it compiles"))
        return result
    if not compiled.ok:
        result.error = "the sources do not compile"
        result.compile_failed = True
        return result
    cold = False
    options: dict[str, Any] = {}
    if found is not None:
        if not found.ok:
            result.diagnostics += project_file.problems(found)
            result.error = "the CPU properties file has errors"
            return result
        props = found.properties
        given = scenario.model_fields_set
        update: dict[str, Any] = {}
        if "profile" not in given:
            update["profile"] = props.profile.value
        if "cycle_ms" not in given:
            update["cycle_ms"] = float(props.cycle_ms)
        scenario = scenario.model_copy(update=update)
        options = props.cpu_options() | {"profile": Profile(scenario.profile)}
        cold = props.startup == "cold"
    options.setdefault("profile", Profile(scenario.profile))
    chosen = scenario.plant if scenario.plant is not None else plant
    runtime: PlantRuntime | None = None
    if isinstance(chosen, PlantConfig):
        try:
            runtime = PlantRuntime(chosen)
        except (PlantError, AddressError) as exc:
            result.error = f"{path}: plant: {exc}"
            return result
    try:
        cpu = Cpu(compiled.program, cycle_ms=scenario.cycle_ms, **options)
    except ValueError as exc:  # e.g. retentive counts the scenario's profile does not have
        result.error = f"{path}: {exc}"
        return result
    texts = {file.name: file.text if isinstance(file.text, str) else "" for file in files}
    execution = Execution(cpu, runtime, scenario, compiled.program, texts, result)
    cpu.start(cold=cold)
    try:
        execution.run_steps()
    except (ScenarioError, AddressError, PlantError) as exc:
        result.error = f"{path}: {exc}"
    execution.finish()
    return result

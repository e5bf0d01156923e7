"""The S7-Graph examples of the course (seeds-003c-graph.md §3, G1-G20) under
tests/scenarios/graph/: every example is there with its scenario, every source is used and
explained in the folder's README, and Example 1 (G3) compiles to the STL shape the book shows.

The scenarios themselves run, one test each, in ``test_course.py`` (every scenario below
tests/scenarios, ids ``graph/<file>``) and again instrumented in
``tests/backend/monitor/test_instrumented_semantics.py``.
"""

import re
from pathlib import Path

import pytest

from nasaq.lang.graph.compile import lower_file
from nasaq.scenarios.model import load_scenario

FOLDER = Path(__file__).resolve().parents[2] / "scenarios" / "graph"
SCENARIOS = sorted(FOLDER.glob("*.yaml"))
README = (FOLDER / "README.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("number", range(1, 21))
def test_every_example_of_the_digest_has_a_graph_source_and_a_scenario(number: int) -> None:
    prefix = f"g{number:02d}"
    scenarios = [path for path in SCENARIOS if path.name.startswith(prefix)]
    assert scenarios, f"G{number}: no scenario {prefix}*.yaml"
    sources = {
        source
        for path in scenarios
        for source in load_scenario(path).sources or []
        if source.endswith(".graph")
    }
    assert sources, f"G{number}: its scenarios run no .graph source"
    assert f"## G{number}." in README, f"G{number}: no README section"


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda path: path.name)
def test_each_scenario_names_existing_sources_and_the_readme_lists_it(path: Path) -> None:
    scenario = load_scenario(path)
    assert scenario.expect_diagnostics or any(step.checks() for step in scenario.steps)
    for source in scenario.source_paths():
        assert source.is_file(), f"{path.name}: {source.name} is missing"
    assert f"`{path.stem}`" in README, f"README does not list {path.stem}"


def test_every_source_file_is_used_by_a_scenario() -> None:
    used = {source for path in SCENARIOS for source in load_scenario(path).sources or []}
    files = {path.name for path in FOLDER.iterdir() if path.suffix in (".graph", ".awl", ".sdf")}
    assert files - used == set()


def test_example_1_compiles_to_a_network_per_transition_and_per_step() -> None:
    """G3: the book's listing (5604-5607) has one network per transition (``A I 0.0`` ...)
    and one per step (``A #G7S[k].X; = Q 0.0`` / ``S M 0.0`` / ``R Q 0.1``); each generated
    line keeps its origin: the step, its action row, the transition (SEMANTICS.md §5)."""
    text = (FOLDER / "g03_nsr.graph").read_text(encoding="utf-8")
    lowered = lower_file("g03_nsr.graph", text)
    assert [d for d in lowered.diagnostics if d.severity == "error"] == []
    lines = lowered.stl.splitlines()
    source = text.splitlines()
    by_element: dict[str, list[str]] = {}
    for line, element in zip(lines, lowered.elements, strict=False):
        if element is not None:
            by_element.setdefault(element, []).append(" ".join(line.split()))
    for number, contact in ((3, "A I 0.0"), (4, "A I 0.1"), (5, "A I 0.3")):
        assert by_element[f"T{number}/e1"] == [contact]
        assert any(line.startswith("TITLE = T") for line in by_element[f"T{number}"])
    for step, row, operation in (
        ("S5", "N Q 0.0;", "= Q 0.0"),
        ("S6", "S M 0.0;", "S M 0.0"),
        ("S7", "R Q 0.1;", "R Q 0.1"),
    ):
        assert any(line.startswith("TITLE = S") for line in by_element[step])
        assert operation in by_element[f"{step}/A1"]
        # the action's STL points back at its row of the .graph file
        index = next(
            k
            for k, line in enumerate(lines)
            if lowered.elements[k] == f"{step}/A1" and " ".join(line.split()) == operation
        )
        graph_line = lowered.origins[index][0]
        assert re.match(rf"\s*{re.escape(row)}", source[graph_line - 1])

"""The S7-SCL course examples in tests/scenarios/scl/ (seeds-003b-scl.md §3: E01-E76, X1-X10):
every source parses and type-checks without an error (with the symbol table its scenario or a
sibling ``.sdf`` names), every scenario file is valid, and the folder's README lists every
example exactly once."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from nasaq.diagnostics import Diagnostic
from nasaq.diagnostics.model import Severity
from nasaq.lang.scl import check_sources, parse_source
from nasaq.lang.stl.symbols import SYMBOL_TABLE_SUFFIXES, SymbolTable, read_symbol_table
from nasaq.scenarios.model import load_scenario

FOLDER = Path(__file__).resolve().parents[3] / "scenarios" / "scl"
SOURCES = sorted(FOLDER.glob("*.scl"))
SCENARIOS = sorted(FOLDER.glob("*.yaml"))
# Scenarios whose programs the SCL compiler cannot lower yet (STRING, DATE_AND_TIME ...): kept
# outside tests/scenarios, which `make test` runs whole, until it can (see the README there).
PENDING = sorted((FOLDER.parents[1] / "scenarios_pending" / "scl").glob("*.yaml"))
EXAMPLES = [f"E{n:02d}" for n in range(1, 77)] + [f"X{n}" for n in range(1, 11)]

# Correct S7-SCL that the checker rejects: file -> the (code, line) of every error it reports.
# Each entry is a checker problem to fix (say why in a comment); once it is fixed the test fails
# until the entry is removed. Found against the checker of commit 942ee98 and already fixed in
# the checker being written when these examples were added (so the list is empty):
# - e01_ok_flag.scl 18, 30; e65_en_call.scl 24; e66_eno_check.scl 22: SCL201 "OK/ENO is not
#   declared". OK and ENO are predefined in every S7-SCL block (the OK flag; ENO of the last
#   call, read with IF ENO THEN as the S7-SCL manual does).
# - e25_indexed_access.scl 39: SCL217 "I is not an array" for I[i, k]. With a variable i the
#   checker took I[...] as indexing i (names ignore case); i is an INT, so I[i, k] can only be
#   the input area, bit k of input byte i.
# - e67_counters.scl 15, 17: SCL213 for PV := 100 / PV := 120 (an INT constant to the WORD
#   input PV). The S7-SCL manual's own counter example passes these; they compile, and now give
#   the warning SCL247 (PV is read as BCD: 64 and 78).
KNOWN_CHECKER_PROBLEMS: dict[str, set[tuple[str, int]]] = {}


def _compile_set(source: Path) -> list[Path]:
    """The files checked together with ``source``: the sources and symbol tables of the first
    scenario that names it, else the source and a symbol table with the same stem."""
    for scenario in SCENARIOS:
        paths = load_scenario(scenario).source_paths()
        if any(path.resolve() == source.resolve() for path in paths):
            return paths
    tables = [source.with_suffix(suffix) for suffix in (".sdf", ".csv")]
    return [source, *(table for table in tables if table.exists())]


def _errors(source: Path) -> list[Diagnostic]:
    table: SymbolTable | None = None
    parsed = []
    found: list[Diagnostic] = []
    for path in _compile_set(source):
        text = path.read_text("utf-8")
        if path.suffix.lower() in SYMBOL_TABLE_SUFFIXES:
            table = table if table is not None else SymbolTable()
            found += read_symbol_table(path.name, text, table)
        else:
            result = parse_source(path.name, text)
            found += result.diagnostics
            parsed.append(result.source)
    _index, checked = check_sources(parsed, table)
    found += checked
    return [
        item
        for item in found
        if item.severity is Severity.ERROR
        and (item.span is None or item.span.file in (None, source.name))
    ]


@pytest.mark.parametrize("source", SOURCES, ids=[path.name for path in SOURCES])
def test_example_checks_without_errors(source: Path) -> None:
    errors = [
        (item.code, item.span.line if item.span else 0, item.message) for item in _errors(source)
    ]
    found = {(code, line) for code, line, _message in errors}
    known = KNOWN_CHECKER_PROBLEMS.get(source.name, set())
    messages = [f"{code} line {line}: {message}" for code, line, message in errors]
    if known and not found:
        pytest.fail(f"{source.name} checks cleanly now: remove it from KNOWN_CHECKER_PROBLEMS")
    assert found == known, messages


@pytest.mark.parametrize("scenario", SCENARIOS, ids=[path.name for path in SCENARIOS])
def test_scenario_file_is_valid(scenario: Path) -> None:
    paths = load_scenario(scenario).source_paths()
    assert all(path.exists() for path in paths), paths
    assert any(path.suffix == ".scl" for path in paths)


def _readme_rows() -> list[list[str]]:
    rows = []
    for line in (FOLDER / "README.md").read_text("utf-8").splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("|") and re.fullmatch(r"[EX]\d+", cells[0]):
            rows.append(cells)
    return rows


def test_readme_lists_every_example_once() -> None:
    listed = [cells[0] for cells in _readme_rows()]
    assert sorted(listed) == sorted(EXAMPLES), (
        sorted(set(EXAMPLES) - set(listed)),
        sorted({name for name in listed if listed.count(name) > 1}),
        sorted(set(listed) - set(EXAMPLES)),
    )


def test_readme_names_every_file_and_only_existing_ones() -> None:
    named = {
        name
        for cells in _readme_rows()
        for cell in cells[1:]
        for name in re.findall(r"[\w.-]+\.(?:scl|yaml)", cell)
    }
    present = {path.name for path in [*SOURCES, *SCENARIOS, *PENDING]}
    assert named == present, (sorted(named - present), sorted(present - named))


def test_pending_scenarios_are_listed_with_their_reason() -> None:
    text = (FOLDER / "README.md").read_text(encoding="utf-8")
    section = text.split("## Scenarios waiting for the compiler", 1)[1]
    listed = set(re.findall(r"[\w.-]+\.yaml", section))
    assert listed == {path.name for path in PENDING}

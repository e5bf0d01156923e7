"""The scenario format's lesson extensions: the project's files from the caller, a plant in
closed loop, operate/fault, during/within, restart, expected diagnostics, where a failure
points, and the stop reason of a CPU that stopped."""

from pathlib import Path

import pytest

from nasaq.plants.runtime import PlantConfig
from nasaq.scenarios.model import ScenarioError, load_scenario
from nasaq.scenarios.runner import run_scenario

LATCH = """ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = the pump holds itself until the tank is full
      A(
      O     I 0.0
      O     Q 4.0
      )
      A     I 0.1
      AN    I 0.2
      =     Q 4.0
END_ORGANIZATION_BLOCK
"""
NO_LEVEL_SWITCH = LATCH.replace("      AN    I 0.2\n", "")
TANK = PlantConfig(
    kind="tank",
    wiring={"pump_pb": "I0.0", "stop_pb": "I0.1", "ls_high": "I0.2", "pump": "Q4.0"},
    params={"initial": 10, "pump_rate": 10},
)
FILL = """name: fill
steps:
  - note: at rest
  - run: 5
  - expect: {Q4.0: 0, plant.faults: []}
  - note: one press starts the pump
  - operate: {pump_pb: 1}
  - run: 2
  - operate: {pump_pb: 0}
  - run: 2
  - expect: {Q4.0: 1, plant.filling: 1}
  - note: the tank fills and the pump stops
  - within: {ms: 15000, expect: {Q4.0: 0}}
  - expect: {plant.level: {min: 85, max: 100}}
  - during: {ms: 3000, expect: {Q4.0: 0, plant.faults: []}}
"""


def _scenario(tmp_path: Path, text: str, name: str = "check.yaml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_the_project_files_run_with_the_plant_in_closed_loop(tmp_path: Path) -> None:
    result = run_scenario(_scenario(tmp_path, FILL), [("OB1.awl", LATCH)], TANK)
    assert result.error is None, result.diagnostics
    assert result.failures == []
    assert [number for number, _note in result.steps] == [3, 9, 11, 12, 13]


def test_a_program_that_overfills_fails_when_and_where_it_broke(tmp_path: Path) -> None:
    result = run_scenario(_scenario(tmp_path, FILL), [("OB1.awl", NO_LEVEL_SWITCH)], TANK)
    assert not result.passed
    first = result.failures[0]
    assert (first.step, first.note, first.address) == (
        11,
        "the tank fills and the pump stops",
        "Q4.0",
    )
    assert first.expected == "0 within 15000 ms"
    assert first.at_ms == 15090  # 9 scans before, then 1500 scans of 10 ms
    assert first.where is not None
    assert (first.where.file, first.where.line, first.where.network) == (
        "OB1.awl",
        10,
        1,
    )
    broken = [f for f in result.failures if f.address == "plant.faults"]
    assert broken
    assert broken[0].actual == "['overflow']"


def test_during_reports_the_virtual_time_it_first_broke(tmp_path: Path) -> None:
    text = """name: during
steps:
  - operate: {pump_pb: 1}
  - during: {ms: 1000, expect: {Q4.0: 0}}
  - expect: {mode: RUN}
"""
    result = run_scenario(_scenario(tmp_path, text), [("OB1.awl", LATCH)], TANK)
    assert [(f.step, f.address, f.at_ms) for f in result.failures] == [(2, "Q4.0", 10)]


def test_an_injected_fault_and_the_plant_state_can_be_expected(tmp_path: Path) -> None:
    text = """name: stuck float
steps:
  - fault: {ls_high_stuck: 1}
  - operate: {pump_pb: 1}
  - run: {ms: 12000}
  - expect: {plant.faults: [ls_high_stuck, overflow], Q4.0: 1}
"""
    result = run_scenario(_scenario(tmp_path, text), [("OB1.awl", LATCH)], TANK)
    assert result.passed, [f.describe() for f in result.failures]


def test_a_scenario_may_name_its_own_plant_or_none(tmp_path: Path) -> None:
    own = """name: own plant
plant:
  kind: tank
  wiring: {pump_pb: I0.0, stop_pb: I0.1, pump: Q4.0}
steps:
  - operate: {pump_pb: 1}
  - run: 2
  - expect: {Q4.0: 1}
"""
    assert run_scenario(_scenario(tmp_path, own), [("OB1.awl", LATCH)]).passed
    none = "name: no plant\nplant: none\nsteps:\n  - operate: {pump_pb: 1}\n"
    result = run_scenario(_scenario(tmp_path, none, "none.yaml"), [("OB1.awl", LATCH)], TANK)
    assert result.error is not None
    assert "runs no plant" in result.error


def test_a_bad_wiring_is_an_error_naming_the_wire(tmp_path: Path) -> None:
    text = """name: bad wire
plant: {kind: tank, wiring: {ls_high: Q0.0}}
steps:
  - run: 1
"""
    result = run_scenario(_scenario(tmp_path, text), [("OB1.awl", LATCH)])
    assert result.error is not None
    assert "ls_high" in result.error


def test_restart_warm_keeps_retentive_markers_and_cold_clears_them(
    tmp_path: Path,
) -> None:
    program = """ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      L     MW 0
      L     1
      +I
      T     MW 0
END_ORGANIZATION_BLOCK
"""
    text = """name: restarts
steps:
  - run: 3
  - restart: warm
  - run: 1
  - expect: {MW0: 4}
  - restart: cold
  - run: 1
  - expect: {MW0: 1}
"""
    result = run_scenario(_scenario(tmp_path, text), [("OB1.awl", program)])
    assert result.passed, [f.describe() for f in result.failures]


def test_expected_diagnostics_pass_only_when_the_program_is_rejected(
    tmp_path: Path,
) -> None:
    text = "name: rejected\nexpect_diagnostics: [{code: STL106, line: 4}]\n"
    bad = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      A     I 9.9\nEND_ORGANIZATION_BLOCK\n"
    path = _scenario(tmp_path, text)
    assert run_scenario(path, [("OB1.awl", bad)]).passed
    elsewhere = run_scenario(
        _scenario(tmp_path, text.replace("4", "3"), "l3.yaml"), [("OB1.awl", bad)]
    )
    assert [(f.address, f.actual) for f in elsewhere.failures] == [("STL106", "STL106")]
    compiles = run_scenario(path, [("OB1.awl", LATCH)])
    assert not compiles.passed
    assert [f.actual for f in compiles.failures] == ["no diagnostics", "it compiles"]


def test_a_cpu_that_stops_fails_with_its_stop_reason(tmp_path: Path) -> None:
    runaway = """ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
LOOP: JU    LOOP
END_ORGANIZATION_BLOCK
"""
    text = "name: runs\nsteps:\n  - run: 3\n  - expect: {Q4.0: 0}\n"
    result = run_scenario(_scenario(tmp_path, text), [("OB1.awl", runaway)])
    assert result.stop is not None
    code, reason = result.stop
    assert code.startswith("SIM")
    assert reason
    assert [(f.address, f.expected) for f in result.failures] == [("mode", "RUN")]


def test_a_failing_lad_rung_points_at_its_network_and_element(tmp_path: Path) -> None:
    lad = """ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = first
RUNG
  Contact(I 0.3)
  Coil(Q 4.2)
END_RUNG
NETWORK
TITLE = the wrong one
RUNG
  Contact(I 0.3)
  Contact(I 0.4)
  Coil(Q 4.1)
END_RUNG
END_ORGANIZATION_BLOCK
"""
    text = "name: lad\nsteps:\n  - set: {I0.3: 1}\n  - run: 1\n  - expect: {Q4.1: 1}\n"
    result = run_scenario(_scenario(tmp_path, text), [("OB1.lad", lad)])
    [failure] = result.failures
    assert failure.where is not None
    assert (failure.where.file, failure.where.network, failure.where.line) == (
        "OB1.lad",
        2,
        9,
    )
    assert failure.where.element is not None


def test_a_lesson_scenario_alone_names_what_is_missing(tmp_path: Path) -> None:
    result = run_scenario(_scenario(tmp_path, "name: x\nsteps:\n  - run: 1\n"))
    assert result.error is not None
    assert "sources" in result.error


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("name: x\nsteps: [{expect: {plant.: 1}}]\n", "plant."),
        ("name: x\nsteps: [{during: {ms: 10}}]\n", "expect"),
        ("name: x\nsteps: [{within: {ms: 0, expect: {Q4.0: 1}}}]\n", "ms"),
        ("name: x\nsteps: [{restart: hot}]\n", "restart"),
        ("name: x\nsteps: [{operate: {start: 16#XY}}]\n", "operate start"),
        ("name: x\nsteps: [{operate: {start: 1}, run: 1}]\n", "one thing"),
        ("name: x\nplant: {wiring: {}}\nsteps: [{run: 1}]\n", "plant"),
        ("name: x\n", "steps"),
    ],
)
def test_invalid_extensions_name_file_and_problem(tmp_path: Path, text: str, message: str) -> None:
    with pytest.raises(ScenarioError, match=r"case\.yaml") as error:
        load_scenario(_scenario(tmp_path, text, "case.yaml"))
    assert message in str(error.value)

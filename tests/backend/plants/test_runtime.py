"""The plant runtime and plant files: every wiring mistake is named with its code and the line
of the wire; inputs reach the peripheral inputs, outputs are read from the output modules."""

from __future__ import annotations

import pytest

from nasaq.cpu import Cpu
from nasaq.ir import Area, Direct, Width
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.plants.base import PlantError
from nasaq.plants.plant_file import PlantFileError, find_plant_file, read_plant_file
from nasaq.plants.registry import plants
from nasaq.plants.runtime import PlantConfig, PlantRuntime


def error_of(**config: object) -> PlantError:
    with pytest.raises(PlantError) as raised:
        PlantRuntime(PlantConfig.model_validate(config))
    return raised.value


@pytest.mark.parametrize(
    ("wiring", "code", "signal"),
    [
        ({"pumpe": "Q4.0"}, "PLT003", "pumpe"),
        ({"ls_low": "Q0.2"}, "PLT004", "ls_low"),  # a sensor to an output
        ({"pump_pb": "M0.0"}, "PLT004", "pump_pb"),  # a control to a marker
        ({"pump": "I0.0"}, "PLT005", "pump"),  # an actuator from an input
        ({"pump": "QW4"}, "PLT006", "pump"),  # a bit signal to a word
        ({"level": "I0.5"}, "PLT007", "level"),  # a word signal to a bit
        ({"level": "ID64"}, "PLT007", "level"),
        ({"pump": "Q4.9"}, "PLT011", "pump"),
        ({"pump": "T1"}, "PLT011", "pump"),
        ({"pump": "Q2048.0"}, "PLT019", "pump"),  # beyond the CPU's outputs
        ({"level": "PIW2047"}, "PLT019", "level"),  # its low byte would be 2048
        ({"ls_low": "I0.2", "ls_high": "I0.2"}, "PLT012", "ls_high"),
        ({"level": "IW64", "ls_low": "I65.3"}, "PLT012", "ls_low"),  # a bit inside the word
    ],
)
def test_every_wiring_mistake_names_the_wire(
    wiring: dict[str, str], code: str, signal: str
) -> None:
    error = error_of(kind="tank", wiring=wiring)
    assert error.code == code
    assert error.subject == ("wiring", signal)
    assert error.params["signal"] == signal


def test_kind_parameter_and_fault_mistakes_are_named() -> None:
    kind = error_of(kind="boiler")
    assert (kind.code, kind.subject) == ("PLT002", ("kind",))
    assert "tank" in str(kind.params["known"])
    param = error_of(kind="tank", params={"pump_speed": 3})
    assert (param.code, param.subject) == ("PLT008", ("params", "pump_speed"))
    fault = error_of(kind="tank", faults=["overflow"])
    assert (fault.code, fault.subject) == ("PLT010", ("faults", "overflow"))


def test_one_output_may_drive_two_actuators() -> None:
    PlantRuntime(PlantConfig(kind="tank", wiring={"pump": "Q4.0", "alarm": "Q4.0"}))


def test_every_plant_runs_with_its_default_wiring_and_names_its_signals_once() -> None:
    assert {"panel", "motor", "tank", "bottle_conveyor", "traffic_light"} <= set(plants())
    assert {"drill", "mixer", "car_park", "bcd_panel"} <= set(plants())
    for kind, plant in plants().items():
        names = [s.name for s in plant.signals]
        assert len(names) == len(set(names)), kind
        runtime = PlantRuntime(PlantConfig(kind=kind, wiring=dict(plant.default_wiring)))
        runtime.advance(10)
        shown = runtime.snapshot()
        assert shown["kind"] == kind
        assert set(shown["signals"]) == set(names), kind
        assert shown["wiring"] == plant.default_wiring


PROGRAM = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     I      0.2;
      =     Q      4.0;
      =     M      1.0;
      L     PIW  256;
      T     MW    10;
END_ORGANIZATION_BLOCK
"""


def test_inputs_reach_the_peripheral_inputs_and_outputs_come_from_the_output_modules() -> None:
    result = compile_sources([SourceFile("OB1.awl", PROGRAM)])
    assert result.ok
    cpu = Cpu(result.program)
    wiring = {"ls_low": "I0.2", "level": "PIW256", "pump": "Q4.0", "alarm": "M1.0"}
    runtime = PlantRuntime(PlantConfig(kind="tank", wiring=wiring, params={"initial": 50}))
    cpu.start()
    runtime.write_inputs(cpu)
    cpu.scan()
    runtime.read_outputs(cpu)
    assert cpu.read(Direct(Area.M, Width.WORD, 10)) == 13824  # the transmitter: 50 %
    assert runtime.plant.actuators["pump"] == 1
    assert runtime.plant.actuators["alarm"] == 1
    cpu.force(Direct(Area.Q, Width.BIT, 4, 0), 0)  # a forced output reaches the plant
    cpu.scan()
    runtime.read_outputs(cpu)
    assert runtime.plant.actuators["pump"] == 0
    cpu.unforce()
    cpu.scan()
    runtime.read_outputs(cpu)
    assert runtime.plant.actuators["pump"] == 1
    cpu.stop()  # outputs are off in STOP: the pump stops with the CPU
    runtime.read_outputs(cpu)
    assert runtime.plant.actuators["pump"] == 0
    assert runtime.plant.actuators["alarm"] == 1  # a marker keeps its value


def test_a_long_step_is_taken_in_short_ones_so_no_bottle_skips_an_eye() -> None:
    runtime = PlantRuntime(PlantConfig(kind="bottle_conveyor", params={"fill_ms": 1000}))
    runtime.plant.set_actuators({"conveyor": 1, "fill_valve": 1})
    runtime.advance(12_000)  # one jump of the clock: the valve poured into each passing bottle
    assert runtime.plant.time_ms == 12_000
    assert runtime.plant.state()["delivered"] == 1
    assert runtime.plant.state()["spilled"] > 0


def test_reset_restores_the_start_and_the_faults_the_configuration_injects() -> None:
    runtime = PlantRuntime(
        PlantConfig(kind="tank", faults=["ls_high_stuck"], params={"initial": 99})
    )
    runtime.plant.set_actuators({"pump": 1})
    runtime.advance(1000)
    runtime.inject("level_wire_break")
    assert runtime.faults() == ["level_wire_break", "ls_high_stuck", "overflow"]
    runtime.reset()
    assert runtime.faults() == ["ls_high_stuck"]
    assert runtime.state()["level"] == 99.0
    assert runtime.plant.time_ms == 0


PLANT_FILE = """\
kind: tank
wiring:
  pump_pb: I0.0
  level: IW64
  pump: Q4.0
params:
  pump_rate: 5
faults: [ls_high_stuck]
"""


def file_error(text: str, name: str = "tank.plant") -> PlantFileError:
    with pytest.raises(PlantFileError) as raised:
        read_plant_file(name, text)
    return raised.value


def test_a_plant_file_reads_into_its_configuration() -> None:
    config = read_plant_file("tank.plant", PLANT_FILE)
    assert config.kind == "tank"
    assert config.wiring["level"] == "IW64"
    assert config.params == {"pump_rate": 5.0}
    assert config.faults == ["ls_high_stuck"]


@pytest.mark.parametrize(
    ("old", "new", "code", "line"),
    [
        ("kind: tank", "kind: boiler", "PLT002", 1),
        ("  level: IW64", "  level: I64.0", "PLT007", 4),
        ("  pump: Q4.0", "  pump: I4.0", "PLT005", 5),
        ("  pump_pb: I0.0", "  start: I0.0", "PLT003", 3),
        ("  pump_rate: 5", "  pump_rate: 500", "PLT009", 7),
        ("  pump_rate: 5", "  rate: 5", "PLT008", 7),
        ("faults: [ls_high_stuck]", "faults: [overflow]", "PLT010", 8),
        ("  pump_rate: 5", "  pump_rate: fast", "PLT013", 7),
        ("kind: tank", "kinds: tank", "PLT013", 1),
        ("  pump: Q4.0", "  pump: [Q4.0", "PLT001", 6),
    ],
)
def test_a_bad_plant_file_names_its_line(old: str, new: str, code: str, line: int) -> None:
    error = file_error(PLANT_FILE.replace(old, new))
    assert error.code == code
    assert error.params["file"] == "tank.plant"
    assert error.params["line"] == line
    assert error.diagnostic.span is not None
    assert error.diagnostic.span.line == line
    assert error.diagnostic.message.startswith(f"tank.plant line {line}:")


def test_a_file_that_is_no_mapping_and_a_second_plant_file_are_refused() -> None:
    assert file_error("- tank\n").code == "PLT013"
    with pytest.raises(PlantFileError) as two:
        find_plant_file([("a.plant", PLANT_FILE), ("OB1.awl", ""), ("b.plant", PLANT_FILE)])
    assert two.value.code == "PLT015"
    assert two.value.params["other"] == "a.plant"
    assert find_plant_file([("OB1.awl", "")]) is None


def test_the_compiler_skips_the_plant_file() -> None:
    result = compile_sources([SourceFile("OB1.awl", PROGRAM), SourceFile("tank.plant", PLANT_FILE)])
    assert result.ok, [d.message for d in result.diagnostics]

"""The OBs a TIA export names by event run on the S7-1500 profile as TIA runs them: every
program-cycle OB each scan in number order, each cyclic interrupt at its own period, every startup
OB once at the restart in number order (``nasaq.cpu.obs``)."""

from __future__ import annotations

import json
import struct
from pathlib import Path

import pytest

from nasaq.cli import main
from nasaq.cpu import Cpu, Profile
from nasaq.ir import BlockKind, Program
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.workbench.cpu_properties import read_properties

# As TIA's "Generate source from blocks" writes it: OBs by symbolic name only.
SOURCE = """\
DATA_BLOCK "Log"
{ S7_Optimized_Access := 'FALSE' }
VERSION : 0.1
NON_RETAIN
   VAR
      main : DInt;
      second : DInt;
      seenMain : DInt;
      fast : DInt;
      slow : DInt;
      startup : DInt;
      mainAtFirstScan : DInt;
   END_VAR
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    IF "Log".main = 0 THEN
        "Log".mainAtFirstScan := "Log".startup;
    END_IF;
    "Log".main := "Log".main + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Cyclic interrupt"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Log".slow := "Log".slow + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Cyclic interrupt_1"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Log".fast := "Log".fast + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Startup"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Log".startup := "Log".startup * 10 + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Startup_1"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Log".startup := "Log".startup * 10 + 2;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Conveyor"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Log".second := "Log".second + 1;
    "Log".seenMain := "Log".main;
END_ORGANIZATION_BLOCK
"""
FIELDS = ("main", "second", "seenMain", "fast", "slow", "startup", "mainAtFirstScan")


def _program(profile: str) -> Program:
    result = compile_sources([SourceFile("Program.scl", SOURCE)], profile=profile)
    assert [d.code for d in result.diagnostics] == []
    return result.program


def _log(cpu: Cpu) -> dict[str, int]:
    data = cpu.db_bytes(1)
    assert data is not None
    return dict(zip(FIELDS, struct.unpack(">7i", data[:28]), strict=True))


def test_tia_numbers_the_obs_by_event() -> None:
    obs = {
        block.name: number
        for (kind, number), block in _program("S7-1500").blocks.items()
        if kind is BlockKind.OB
    }
    assert obs == {
        "Main": 1,
        "Cyclic interrupt": 30,
        "Cyclic interrupt_1": 31,
        "Startup": 100,
        "Startup_1": 123,
        "Conveyor": 124,
    }


def test_every_ob_runs_as_tia_runs_it_in_virtual_time() -> None:
    cpu = Cpu(
        _program("S7-1500"),
        profile=Profile.S7_1500,
        cycle_ms=10,
        cyclic_periods={31: 20},
    )
    cpu.start()
    assert _log(cpu)["startup"] == 12  # OB100, then the startup OB123, once each
    cpu.run(100)  # the scans start at 0, 10 ... 990 ms
    log = _log(cpu)
    assert cpu.mode == "RUN"
    assert log["main"] == 100
    assert log["second"] == 100  # the further program-cycle OB124 runs every scan ...
    assert log["seenMain"] == 100  # ... after OB1 in the same scan
    assert log["mainAtFirstScan"] == 12  # the startup OBs ran before the first cycle
    assert log["slow"] == 9  # OB30: TIA's default 100 ms, due at 100 ... 900 ms
    assert log["fast"] == 49  # OB31 set to 20 ms: due at 20 ... 980 ms
    cpu.start()  # a restart runs them again (the DB keeps its values)
    assert _log(cpu)["startup"] == 1212


def test_a_cold_restart_runs_the_same_startup_obs() -> None:
    cpu = Cpu(_program("S7-1500"), profile=Profile.S7_1500)
    cpu.start(cold=True)
    cpu.run(1)
    assert _log(cpu)["startup"] == 12
    assert _log(cpu)["mainAtFirstScan"] == 12


def test_the_s7_300_profile_keeps_its_one_cyclic_interrupt() -> None:
    # S7-300/400 have no OB 123 up nor optimized blocks: the same program without them.
    # "Cyclic interrupt" is OB35
    # there, "Cyclic interrupt_1" OB30.
    classic = SOURCE.split('ORGANIZATION_BLOCK "Startup_1"')[0]
    classic = classic.replace("{ S7_Optimized_Access := 'TRUE' }\n", "")
    result = compile_sources([SourceFile("Program.scl", classic)], profile="S7-300")
    assert [d.code for d in result.diagnostics] == []
    assert result.program.get(BlockKind.OB, 30) is not None
    cpu = Cpu(result.program, profile=Profile.S7_300, cycle_ms=10)
    cpu.start()
    cpu.run(100)
    log = _log(cpu)
    assert log["slow"] == 9  # OB35 every 100 ms
    assert log["fast"] == 0  # OB30: not run by the S7-300/400 profiles


def test_a_cycle_time_for_an_ob_that_is_no_cyclic_interrupt_is_refused() -> None:
    program = _program("S7-1500")
    with pytest.raises(ValueError, match="OB 30 is no cyclic interrupt OB of the S7-300"):
        Cpu(program, profile=Profile.S7_300, cyclic_periods={30: 100})
    with pytest.raises(ValueError, match="1 to 60000 ms"):
        Cpu(program, profile=Profile.S7_1500, cyclic_periods={35: 0})


def test_cpu_properties_set_the_cycle_time_of_a_cyclic_interrupt_ob() -> None:
    text = "profile = S7-1500\ncycle_time = 10\ncyclic_interrupt_OB30 = 250 ms  # slow loop\n"
    read = read_properties(text)
    assert read.diagnostics == []
    props = read.properties
    cpu = Cpu(_program("S7-1500"), cycle_ms=props.cycle_ms, **props.cpu_options())
    cpu.start()
    cpu.run(100)
    assert _log(cpu)["slow"] == 3  # OB30 due at 250, 500 and 750 ms
    assert _log(cpu)["fast"] == 9  # OB31 keeps its 100 ms


@pytest.mark.parametrize(
    ("text", "code", "column"),
    [
        ("cyclic_interrupt_OB30 = 20\n", "PRJ902", 1),  # an S7-300 runs OB35 only
        ("profile = S7-1500\ncyclic_interrupt_OB40 = 20\n", "PRJ902", 1),
        ("profile = S7-1500\n  cyclic_interrupt_OB31 = 0\n", "PRJ905", 27),
        ("profile = S7-1500\ncyclic_interrupt_OB31 = fast\n", "PRJ904", 25),
    ],
)
def test_a_wrong_cyclic_interrupt_property_is_a_located_diagnostic(
    text: str, code: str, column: int
) -> None:
    read = read_properties(text)
    assert [(d.code, d.span.line, d.span.column) for d in read.diagnostics] == [
        (code, text.count("\n"), column)
    ]
    assert read.properties.cyclic_periods == ()


def test_nasaq_run_takes_the_cycle_times_from_cpu_properties(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "Program.scl").write_text(SOURCE, encoding="utf-8")
    (tmp_path / "cpu.properties").write_text(
        "profile = S7-1500\ncyclic_interrupt_OB31 = 50\n", encoding="utf-8"
    )
    code = main(["run", str(tmp_path / "Program.scl"), "--cycles", "100"])
    out, err = capsys.readouterr()
    assert code == 0, err
    log = json.loads(out)["DB"]["1"]  # the DInts' low bytes, by byte offset
    # second (OB124), fast (OB31 every 50 ms), slow (OB30 every 100 ms), startup (OB100, OB123)
    assert (log["7"], log["15"], log["19"], log["23"]) == (100, 19, 9, 12)

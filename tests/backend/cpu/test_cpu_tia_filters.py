"""TIA Portal's filter instructions on the CPU (``nasaq.cpu.tia_filters``): Filter_PT1,
Filter_DT1 and Filter_PT2 step responses over a fixed virtual cycle, the measured cycle time,
Reset and the substitute output, and the error bits of invalid parameters."""

from __future__ import annotations

import itertools
import struct

import pytest
from cpu_run import run

from nasaq.cpu import Cpu, iec_blocks
from nasaq.cpu.tia_filters import ERROR_CYCLE_TIME, ERROR_DAMPING, ERROR_LAG
from nasaq.headless.addresses import as_real, parse_address
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.tia_filters import FILTER_PT1

CYCLE_MS = 100  # Ts = 0.1 s once measured

# "Io" (DB1): u DBD0, sub DBD4, y DBD8, bits DBD12, reset DBX16.0, subst DBX16.1, error DBX16.2,
# eno DBX16.3, cycle DBD18.
IO = """
DATA_BLOCK "Io"
STRUCT
  u : REAL; sub : REAL; y : REAL; bits : DWORD;
  reset : BOOL; subst : BOOL; error : BOOL; eno : BOOL;
  cycle : REAL;
END_STRUCT
BEGIN
END_DATA_BLOCK
"""


def program(kind: str, start: str) -> str:
    """``kind`` in instance DB "F" with the start values ``start``, wired to "Io" in OB1."""
    return (
        IO
        + f"""
DATA_BLOCK "F" {kind}
BEGIN
{start}
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "F"(Input := "Io".u, SubstituteOutput := "Io".sub,
      SubstituteOutputActive := "Io".subst, Reset := "Io".reset);
  "Io".eno := ENO;
  "Io".y := "F".Output;
  "Io".bits := "F".ErrorBits;
  "Io".error := "F".Error;
  "Io".cycle := "F".CycleTime.Value;
END_ORGANIZATION_BLOCK
"""
    )


def build(source: str) -> Cpu:
    """The S7-1500 program started (OB100, RUN), no cycle run yet."""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    return run(result, scans=0, profile="S7-1500", cycle_ms=CYCLE_MS)


def scan(cpu: Cpu, count: int = 1) -> None:
    cpu.run(count)
    assert cpu.mode == "RUN", cpu.stop_reason


def _direct(text: str) -> Direct:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return address


def real(cpu: Cpu, text: str) -> float:
    return as_real(cpu.read(_direct(text)))


def put(cpu: Cpu, text: str, value: float | bool) -> None:
    if isinstance(value, bool):
        cpu.write(_direct(text), int(value))
    else:
        cpu.write(_direct(text), struct.unpack(">I", struct.pack(">f", value))[0])


def outputs(cpu: Cpu) -> tuple[float, int, int, int]:
    """Output, ErrorBits, Error, ENO of the last call."""
    return (
        real(cpu, "DB1.DBD8"),
        cpu.read(_direct("DB1.DBD12")),
        cpu.read(_direct("DB1.DBX16.2")),
        cpu.read(_direct("DB1.DBX16.3")),
    )


def responses(cpu: Cpu, count: int) -> list[float]:
    found = []
    for _ in range(count):
        scan(cpu)
        found.append(real(cpu, "DB1.DBD8"))
    return found


def test_pt1_step_response_follows_the_backward_euler_lag() -> None:
    cpu = build(program("Filter_PT1", "Gain := 2.0; Lag := 0.4;"))
    put(cpu, "DB1.DBD0", 1.0)
    # y := (Lag*y + Ts*Gain*u) / (Lag + Ts) with Ts = 0.1 s
    assert responses(cpu, 3) == pytest.approx([0.4, 0.72, 0.976], abs=1e-6)
    assert outputs(cpu)[1:] == (0, 0, 1)
    scan(cpu, 100)
    assert real(cpu, "DB1.DBD8") == pytest.approx(2.0, abs=1e-5)  # Gain * Input


def test_pt1_without_lag_passes_the_input_times_the_gain() -> None:
    cpu = build(program("Filter_PT1", "Gain := 3.0; Lag := 0.0;"))
    put(cpu, "DB1.DBD0", 1.5)
    assert responses(cpu, 1) == pytest.approx([4.5])


def test_the_cycle_time_is_measured_on_the_virtual_clock() -> None:
    # the first call has no previous one: it uses CycleTime.Value (0.5 s), then the 100 ms measured
    cpu = build(program("Filter_PT1", "Gain := 1.0; Lag := 0.5; CycleTime.Value := 0.5;"))
    put(cpu, "DB1.DBD0", 1.0)
    scan(cpu)
    assert real(cpu, "DB1.DBD8") == pytest.approx(0.5)
    assert real(cpu, "DB1.DBD18") == pytest.approx(0.5)
    scan(cpu)
    assert real(cpu, "DB1.DBD8") == pytest.approx((0.5 * 0.5 + 0.1) / 0.6)
    assert real(cpu, "DB1.DBD18") == pytest.approx(0.1)


def test_without_measurement_the_configured_cycle_time_is_used() -> None:
    start = "Lag := 0.5; CycleTime.Value := 0.5; CycleTime.EnableMeasurement := FALSE;"
    cpu = build(program("Filter_PT1", start))
    put(cpu, "DB1.DBD0", 1.0)
    assert responses(cpu, 2) == pytest.approx([0.5, 0.75])
    assert real(cpu, "DB1.DBD18") == pytest.approx(0.5)


def test_reset_sets_the_substitute_output_and_the_filter_continues_from_it() -> None:
    cpu = build(program("Filter_PT1", "Gain := 2.0; Lag := 0.4;"))
    put(cpu, "DB1.DBD0", 1.0)
    scan(cpu, 5)
    put(cpu, "DB1.DBD4", 1.5)
    put(cpu, "DB1.DBX16.0", True)
    scan(cpu, 2)
    assert outputs(cpu) == (pytest.approx(1.5), 0, 0, 1)
    put(cpu, "DB1.DBX16.0", False)
    put(cpu, "DB1.DBD0", 0.0)
    assert responses(cpu, 1) == pytest.approx([0.4 * 1.5 / 0.5])  # no jump back to the old state


def test_substitute_output_active_holds_the_output_then_continues_without_a_jump() -> None:
    cpu = build(program("Filter_DT1", "Gain := 1.0; Lag := 0.0;"))
    put(cpu, "DB1.DBD4", -3.0)
    put(cpu, "DB1.DBX16.1", True)
    put(cpu, "DB1.DBD0", 7.0)
    assert responses(cpu, 2) == pytest.approx([-3.0, -3.0])
    put(cpu, "DB1.DBX16.1", False)
    # the input did not change since the substitute took over: no derivative spike
    assert responses(cpu, 1) == pytest.approx([0.0])


def test_dt1_gives_the_slope_of_a_ramp() -> None:
    cpu = build(program("Filter_DT1", "Gain := 1.0; Lag := 0.0;"))
    found = []
    for step in range(1, 5):
        put(cpu, "DB1.DBD0", 10.0 + 0.5 * step)  # +0.5 per 0.1 s: slope 5 per second
        found.extend(responses(cpu, 1))
    # the first call takes the input over (no jump from the initial 0.0)
    assert found == pytest.approx([0.0, 5.0, 5.0, 5.0])


def test_dt1_with_lag_decays_after_a_step() -> None:
    cpu = build(program("Filter_DT1", "Gain := 2.0; Lag := 0.1;"))
    scan(cpu)
    put(cpu, "DB1.DBD0", 1.0)
    # y := (Lag*y + Gain*(u - u_old)) / (Lag + Ts)
    assert responses(cpu, 3) == pytest.approx([10.0, 5.0, 2.5])


def test_pt2_step_response() -> None:
    cpu = build(program("Filter_PT2", "Gain := 1.0; TimeConstant := 1.0; Damping := 1.0;"))
    put(cpu, "DB1.DBD0", 1.0)
    first = 0.1 * (0.1 / 1.21)  # slope (0 + Ts*(1 - 0)/T^2) / (1 + 2*D*Ts/T + Ts^2/T^2)
    assert responses(cpu, 1) == pytest.approx([first])
    found = responses(cpu, 200)
    assert all(b >= a for a, b in itertools.pairwise(found))  # critically damped: no overshoot
    assert found[-1] == pytest.approx(1.0, abs=1e-3)


def test_pt2_with_low_damping_overshoots() -> None:
    cpu = build(program("Filter_PT2", "Gain := 2.0; TimeConstant := 0.5; Damping := 0.2;"))
    put(cpu, "DB1.DBD0", 1.0)
    found = responses(cpu, 300)
    assert max(found) > 2.5
    assert found[-1] == pytest.approx(2.0, abs=1e-3)


@pytest.mark.parametrize(
    ("kind", "start", "bits"),
    [
        ("Filter_PT1", "Lag := -1.0;", ERROR_LAG),
        ("Filter_DT1", "Lag := -0.5;", ERROR_LAG),
        ("Filter_PT2", "TimeConstant := -2.0;", ERROR_LAG),
        ("Filter_PT2", "Damping := -0.1;", ERROR_DAMPING),
        (
            "Filter_PT1",
            "CycleTime.Value := 0.0; CycleTime.EnableMeasurement := FALSE;",
            ERROR_CYCLE_TIME,
        ),
    ],
)
def test_an_invalid_parameter_sets_the_error_bits_and_holds_the_output(
    kind: str, start: str, bits: int
) -> None:
    cpu = build(program(kind, start))
    put(cpu, "DB1.DBD0", 1.0)
    assert outputs(cpu)[0] == 0.0
    scan(cpu, 3)
    assert outputs(cpu) == (0.0, bits, 1, 0)


def test_a_corrected_lag_clears_the_error() -> None:
    cpu = build(program("Filter_PT1", "Gain := 2.0; Lag := -1.0;"))
    put(cpu, "DB1.DBD0", 1.0)
    scan(cpu)
    assert outputs(cpu)[1:] == (ERROR_LAG, 1, 0)
    lag = next(v for v in iec_blocks.INTERFACES[FILTER_PT1] if v.name == "Lag")
    put(cpu, f"DB2.DBD{lag.offset_bits // 8}", 0.4)  # "F" is DB2
    scan(cpu)
    assert outputs(cpu) == (pytest.approx(0.4), 0, 0, 1)

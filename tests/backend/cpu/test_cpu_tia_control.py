"""TIA Portal's control and timing system blocks on the CPU (``nasaq.cpu.tia_control``):
PID_Compact V1.x, RUNTIME, RESET_TIMER, PRESET_TIMER and CTRL_HSC without counter hardware."""

from __future__ import annotations

import pytest
from cpu_run import read, real, run

from nasaq.cpu import Cpu, iec_blocks
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.tia_control import PID_COMPACT

CYCLE_MS = 10


def build(source: str) -> Cpu:
    """The S7-1500 program started (OB100, RUN), no cycle run yet."""
    result = compile_sources([SourceFile("prog.scl", source)], profile="S7-1500")
    return run(result, scans=0, profile="S7-1500", cycle_ms=CYCLE_MS)


def scan(cpu: Cpu, count: int = 1) -> None:
    cpu.run(count)
    assert cpu.mode == "RUN", cpu.stop_reason


def write_real(cpu: Cpu, text: str, number: float) -> None:
    import struct

    address = parse_address(text)
    assert isinstance(address, Direct)
    cpu.write(address, struct.unpack(">I", struct.pack(">f", number))[0])


# The loop (instance DB 1): Setpoint, Input and ManualValue written into the instance; manual
# M8.0, Reset M8.1; Output MD20, State MW24, Error MD26, ScaledInput MD30 (their bits).
PID_PROGRAM = """
DATA_BLOCK "Loop" PID_Compact
BEGIN
  sPid_Cmpt.b_Input_PER_On := FALSE;
  sPid_Cmpt.r_Lmn_Hlm := 80.0;
  sPid_Cmpt.r_Lmn_Llm := 5.0;
  sRet.i_Mode := 3;
  sRet.r_Ctrl_Gain := 0.5;
  sRet.r_Ctrl_Ti := 2.0;
  sRet.r_Ctrl_B := 1.0;
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "Loop"(ManualEnable := M8.0, Reset := M8.1);  // Setpoint, Input ... kept in the instance
  MD20 := "Loop".Output;
  MW24 := "Loop".State;
  MD26 := "Loop".Error;
  MD30 := "Loop".ScaledInput;
END_ORGANIZATION_BLOCK
"""


def member(name: str) -> str:
    """The address of a REAL input of PID_Compact in instance DB 1."""
    found = next(v for v in iec_blocks.INTERFACES[PID_COMPACT] if v.name == name)
    return f"DB1.DBD{found.offset_bits // 8}"


def pid(setpoint: float, process: float) -> Cpu:
    cpu = build(PID_PROGRAM)
    write_real(cpu, member("Setpoint"), setpoint)
    write_real(cpu, member("Input"), process)
    return cpu


def test_pid_compact_starts_in_the_mode_of_its_instance_and_acts_on_the_error() -> None:
    cpu = pid(50.0, 40.0)
    scan(cpu)
    assert read(cpu, "MW24") == 3  # automatic (sb_RunModeByStartup is TRUE by default)
    assert read(cpu, "MD26") == 0
    assert real(cpu, "MD30") == pytest.approx(40.0)
    first = real(cpu, "MD20")
    # P = 0.5 * (50 - 40) = 5; I after the first sample (0.1 s, the initial cycle) = 0.25
    assert first == pytest.approx(5.25, abs=1e-4)
    scan(cpu, 10)
    later = real(cpu, "MD20")
    # integral action: + 0.5 * 0.01 s / 2 s * 10 per scan
    assert later == pytest.approx(first + 10 * 0.5 * 0.01 / 2.0 * 10.0, abs=1e-3)


def test_pid_compact_output_stays_within_its_limits_without_winding_up() -> None:
    cpu = pid(100.0, 0.0)
    scan(cpu, 300)
    assert real(cpu, "MD20") == pytest.approx(80.0)  # r_Lmn_Hlm
    write_real(cpu, member("Input"), 99.0)  # nearly there: the output must fall at once
    scan(cpu, 1)
    assert real(cpu, "MD20") < 80.0  # no integral wound up beyond the limit
    write_real(cpu, member("Setpoint"), 0.0)
    write_real(cpu, member("Input"), 100.0)
    scan(cpu, 300)
    assert real(cpu, "MD20") == pytest.approx(5.0)  # r_Lmn_Llm


def test_pid_compact_inverted_control_and_manual_mode() -> None:
    cpu = pid(50.0, 40.0)
    scan(cpu)
    write_real(cpu, member("ManualValue"), 33.0)
    cpu.write(parse_address("M8.0"), 1)  # type: ignore[arg-type]
    scan(cpu)
    assert read(cpu, "MW24") == 4
    assert real(cpu, "MD20") == pytest.approx(33.0)
    write_real(cpu, member("ManualValue"), 95.0)
    scan(cpu)
    assert real(cpu, "MD20") == pytest.approx(80.0)  # ManualValue within the limits too
    write_real(cpu, member("ManualValue"), 33.0)
    scan(cpu)
    cpu.write(parse_address("M8.0"), 0)  # type: ignore[arg-type]
    scan(cpu)
    assert read(cpu, "MW24") == 3  # back to automatic, bumplessly
    assert real(cpu, "MD20") == pytest.approx(33.0, abs=0.1)


def test_pid_compact_reset_and_process_value_limits() -> None:
    cpu = pid(50.0, 40.0)
    scan(cpu)
    cpu.write(parse_address("M8.1"), 1)  # type: ignore[arg-type]
    scan(cpu)
    assert read(cpu, "MW24") == 0
    assert real(cpu, "MD20") == 0.0
    cpu.write(parse_address("M8.1"), 0)  # type: ignore[arg-type]
    scan(cpu)
    assert read(cpu, "MW24") == 3  # the falling edge restarts in the mode of i_Mode
    write_real(cpu, member("Input"), 500.0)  # above r_Pv_Hlm (120.0)
    scan(cpu)
    assert read(cpu, "MD26") == 0x0001
    assert read(cpu, "MW24") == 0
    assert real(cpu, "MD20") == 0.0
    write_real(cpu, member("Input"), 40.0)
    scan(cpu)
    assert read(cpu, "MD26") == 0  # the error has gone, the controller stays inactive
    assert read(cpu, "MW24") == 0


def test_pid_compact_as_a_multi_instance_with_inverted_action() -> None:
    cpu = build(
        """
FUNCTION_BLOCK "Cooling"
VAR
  pid : PID_Compact;
END_VAR
BEGIN
  #pid.sPid_Cmpt.b_Input_PER_On := FALSE;
  #pid.sPid_Cmpt.b_InvCtrl := TRUE;
  #pid.sRet.r_Ctrl_Gain := 2.0;
  #pid.sRet.r_Ctrl_Ti := 0.0;
  #pid.sRet.r_Ctrl_B := 1.0;
  #pid.sRet.i_Mode := 3;
  #pid(Setpoint := 20.0, Input := 30.0);
  MD20 := #pid.Output;
  MW24 := #pid.State;
END_FUNCTION_BLOCK
DATA_BLOCK "Cool" "Cooling" BEGIN END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "Cooling"."Cool"();
END_ORGANIZATION_BLOCK
"""
    )
    scan(cpu, 3)
    assert read(cpu, "MW24") == 3
    assert real(cpu, "MD20") == pytest.approx(20.0)  # -2 * (20 - 30): cooling opens up


def test_runtime_measures_the_virtual_time_between_two_calls() -> None:
    cpu = build(
        """
FUNCTION_BLOCK "Meter"
VAR
  mem : LREAL;
  seconds : LREAL;
END_VAR
BEGIN
  #seconds := RUNTIME(#mem);
  MD40 := LREAL_TO_REAL(#seconds);
  MD44 := LREAL_TO_REAL(#mem);
END_FUNCTION_BLOCK
DATA_BLOCK "M" "Meter" BEGIN END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "Meter"."M"();
END_ORGANIZATION_BLOCK
"""
    )
    scan(cpu, 5)
    assert real(cpu, "MD40") == pytest.approx(CYCLE_MS / 1000.0)
    assert real(cpu, "MD44") == pytest.approx(4 * CYCLE_MS / 1000.0)


TIMER_PROGRAM = """
FUNCTION_BLOCK "Timers"
VAR
  t : TON_TIME;
  kept : STRUCT inner : IEC_TIMER; END_STRUCT;
  n : INT;
END_VAR
BEGIN
  #n := #n + 1;
  #t(IN := TRUE, PT := T#1S);
  IF #n = 20 THEN
    RESET_TIMER(#t);
  END_IF;
  IF #n = 3 THEN
    PRESET_TIMER(PT := T#250MS, TIMER := #kept.inner);
  END_IF;
  MD50 := TIME_TO_DINT(#t.ET);
  M54.0 := #t.Q;
  MD56 := TIME_TO_DINT(#kept.inner.PT);
END_FUNCTION_BLOCK
DATA_BLOCK "T" "Timers" BEGIN END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "Timers"."T"();
END_ORGANIZATION_BLOCK
"""


def test_reset_timer_clears_a_running_timer_and_preset_timer_sets_pt() -> None:
    cpu = build(TIMER_PROGRAM)
    scan(cpu, 19)
    assert read(cpu, "MD50") == 18 * CYCLE_MS
    assert read(cpu, "MD56") == 250  # PRESET_TIMER in a structure member
    scan(cpu)
    assert read(cpu, "MD50") == 0  # RESET_TIMER after the call at the 20th scan
    assert read(cpu, "M54.0") == 0
    scan(cpu, 2)
    assert read(cpu, "MD50") == CYCLE_MS  # IN still TRUE: the timer runs again


def test_ctrl_hsc_without_counter_hardware_answers_no_hsc() -> None:
    cpu = build(
        """
FUNCTION_BLOCK "Count"
VAR
  hsc : CTRL_HSC;
END_VAR
BEGIN
  #hsc(HSC := 16#0101, CV := TRUE, NEW_CV := 100, BUSY => M60.0, STATUS => MW62);
  M60.1 := ENO;
END_FUNCTION_BLOCK
DATA_BLOCK "C" "Count" BEGIN END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "Count"."C"();
END_ORGANIZATION_BLOCK
"""
    )
    scan(cpu)
    assert read(cpu, "MW62") & 0xFFFF == 0x80A1
    assert read(cpu, "M60.0") == 0


def test_reset_timer_on_a_single_instance_db_and_a_tp_time() -> None:
    cpu = build(
        """
DATA_BLOCK "Delay"
{InstructionName := 'IEC_TIMER'; LibVersion := '1.0'; S7_Optimized_Access := 'TRUE' }
IEC_TIMER
BEGIN
END_DATA_BLOCK
FUNCTION_BLOCK "Pulses"
VAR
  p : TP_TIME;
END_VAR
BEGIN
  #p(IN := TRUE, PT := T#1S);
  IF M70.0 THEN
    RESET_TIMER(#p);
  END_IF;
  MD74 := TIME_TO_DINT(#p.ET);
END_FUNCTION_BLOCK
DATA_BLOCK "P" "Pulses" BEGIN END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
BEGIN
  "Delay".TON(IN := TRUE, PT := T#1S);
  IF M70.0 THEN
    RESET_TIMER("Delay");
  END_IF;
  MD78 := TIME_TO_DINT("Delay".ET);
  "Pulses"."P"();
END_ORGANIZATION_BLOCK
"""
    )
    scan(cpu, 5)
    assert read(cpu, "MD78") == 4 * CYCLE_MS
    assert read(cpu, "MD74") == 4 * CYCLE_MS
    cpu.write(parse_address("M70.0"), 1)  # type: ignore[arg-type]
    scan(cpu)
    assert read(cpu, "MD78") == 0
    assert read(cpu, "MD74") == 0

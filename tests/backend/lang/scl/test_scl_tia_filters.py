"""TIA Portal's filter instructions (Filter_PT1, Filter_DT1, Filter_PT2) in SCL: multi-instances
with TIA's instruction attributes, the static parameters written as members (``#f.Lag := 2.0``),
a chain of filters compiled and run, and SCL500 on an S7-300/400."""

from __future__ import annotations

import pytest
from scl_run import build, read, real

from nasaq.lang.stl import SourceFile, compile_sources

OUT = """
DATA_BLOCK "Out"
STRUCT
  smooth : REAL; slope : REAL; second : REAL; lag : REAL; bad : BOOL;
END_STRUCT
BEGIN
END_DATA_BLOCK
"""

# A measured value smoothed, differentiated and filtered again, as a TIA block writes it.
SMOOTHER = (
    OUT
    + """
FUNCTION_BLOCK "Smoother"
{ S7_Optimized_Access := 'TRUE' }
VAR_INPUT
  raw : REAL;
  restart : BOOL;
END_VAR
VAR
  pt1 {InstructionName := 'Filter_PT1'; LibVersion := '1.0';
       ExternalAccessible := 'False'} : Filter_PT1;
  "rate/dt" {InstructionName := 'Filter_DT1'; LibVersion := '1.0'} : Filter_DT1;
  pt2 {InstructionName := 'Filter_PT2'; LibVersion := '1.0'} : Filter_PT2;
END_VAR
BEGIN
  #pt1.Lag := 2.0;
  #pt1.Gain := 1.0;
  #"rate/dt".Lag := 0.0;
  #pt2.TimeConstant := 0.0;
  #pt2.Gain := 3.0;
  IF #restart THEN
    #pt1.SubstituteOutput := #raw;
  END_IF;
  #pt1(Input := #raw, Reset := #restart, Output => "Out".smooth);
  #"rate/dt"(Input := #pt1.Output, Reset := #restart, Output => "Out".slope);
  #pt2(Input := "Out".smooth, SubstituteOutput := 0.0);
  "Out".second := #pt2.Output;
  "Out".lag := #pt1.Lag;
  "Out".bad := #pt1.Error OR #"rate/dt".Error OR #pt2.Error;
END_FUNCTION_BLOCK

DATA_BLOCK "SmootherDb" "Smoother"
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  "SmootherDb"(raw := 10.0, restart := FALSE);
END_ORGANIZATION_BLOCK
"""
)


def codes(source: str, profile: str = "S7-1500") -> list[str]:
    result = compile_sources([SourceFile("prog.scl", source)], profile=profile)
    return [d.code for d in result.diagnostics if d.severity == "error"]


def test_multi_instances_with_tia_attributes_compile_and_run() -> None:
    cpu = build(SMOOTHER, profile="S7-1500", scans=1)
    # first call: Ts = CycleTime.Value (0.1 s): (2.0*0 + 0.1*10) / 2.1
    smooth = 1.0 / 2.1
    assert real(cpu, "DB1.DBD0") == pytest.approx(smooth)
    assert real(cpu, "DB1.DBD4") == 0.0  # DT1's first call takes the input over
    assert real(cpu, "DB1.DBD8") == pytest.approx(3.0 * smooth)  # PT2 without lag: Gain*u
    assert real(cpu, "DB1.DBD12") == 2.0  # the member written before the call
    assert read(cpu, "DB1.DBX16.0") == 0  # no filter reports an error


def test_the_filters_keep_their_state_between_scans() -> None:
    cpu = build(SMOOTHER, profile="S7-1500", scans=20)
    smooth = real(cpu, "DB1.DBD0")
    assert 1.0 < smooth < 10.0  # rising towards 10.0
    assert real(cpu, "DB1.DBD4") > 0.0  # a rising input has a positive slope


def test_member_write_and_read_of_the_static_parameters() -> None:
    source = """
FUNCTION_BLOCK "F"
VAR
  f {InstructionName := 'Filter_PT1'; LibVersion := '1.0'} : Filter_PT1;
  d : Filter_DT1;
  x : REAL;
  on : BOOL;
END_VAR
BEGIN
  #f.Lag := 2.0;
  #f.Gain := #f.Lag * 0.5;
  #f.CycleTime.EnableMeasurement := FALSE;
  #f.CycleTime.Value := 0.01;
  #d.Lag := #f.Lag;
  #f(Input := #x, Reset := FALSE, Output => #x);
  #on := #f.Error OR #d.SubstituteOutputActive;
  #x := #f.SubstituteOutput + DWORD_TO_REAL(#f.ErrorBits);
END_FUNCTION_BLOCK
"""
    assert codes(source) == []


def test_an_instance_db_of_a_filter() -> None:
    source = """
DATA_BLOCK "Lag1" Filter_PT1
BEGIN
  Lag := 0.5;
END_DATA_BLOCK
ORGANIZATION_BLOCK OB1
VAR_TEMP
  y : REAL;
END_VAR
BEGIN
  "Lag1"(Input := 4.0, Output => #y);
END_ORGANIZATION_BLOCK
"""
    assert codes(source) == []


@pytest.mark.parametrize(
    ("wrong", "code"),
    [
        ("#f(Input := TRUE);", "SCL214"),  # a BOOL for a REAL
        ("#f(Gain := 2.0);", "SCL223"),  # a static member is no parameter
        ("#f.Lag := T#2s;", "SCL214"),
        ("#f.Unknown := 1.0;", "SCL222"),
    ],
)
def test_wrong_uses_are_errors(wrong: str, code: str) -> None:
    source = f"""
FUNCTION_BLOCK "F"
VAR
  f : Filter_PT1;
END_VAR
BEGIN
  {wrong}
END_FUNCTION_BLOCK
"""
    assert codes(source) == [code]


def test_on_an_s7_300_the_filters_are_s7_1500_only() -> None:
    result = compile_sources([SourceFile("prog.scl", SMOOTHER)], profile="S7-300")
    errors = [d for d in result.diagnostics if d.severity == "error"]
    assert {d.code for d in errors} == {"SCL500"}
    named = " ".join(d.message for d in errors)
    assert all(name in named for name in ("Filter_PT1", "Filter_DT1", "Filter_PT2"))

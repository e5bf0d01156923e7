"""TIA system blocks with structured interfaces in SCL (``nasaq.lang.system_types``,
``nasaq.lang.tia_control``): PID_Compact instances, multi-instances, ``.db`` instance files that
initialise static members, member access, RUNTIME/RESET_TIMER/PRESET_TIMER calls, and the
profile refusal."""

from __future__ import annotations

import pytest

from nasaq.lang import system_types
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.types import ArrayType, BlockType, Elementary, StringType


def codes(source: str, profile: str = "S7-1500", name: str = "prog.scl") -> list[str]:
    result = compile_sources([SourceFile(name, source)], profile=profile)
    return [d.code or "" for d in result.diagnostics if d.severity == "error"]


def test_the_one_parser_reads_every_kind_of_type_text() -> None:
    parse = system_types.parse
    assert parse("INT") == Elementary("INT")
    assert parse("STRING[10]") == StringType(10)
    assert parse("WSTRING[4]") == StringType(4, wide=True)
    assert parse("ARRAY[0..3, 1..2] OF BYTE") == ArrayType(((0, 3), (1, 2)), Elementary("BYTE"))
    assert parse("VARIANT") == Elementary("VARIANT")
    assert parse("HW_HSC") == Elementary("WORD")
    assert parse("IEC_TIMER") == BlockType("SFB", 4)
    assert parse("BOOL := TRUE") == Elementary("BOOL")
    assert system_types.initial("BOOL := TRUE") is True
    ret = parse("PID_Compact_Ret")
    assert [f.name for f in ret.fields][:2] == ["i_Mode", "r_Ctrl_Gain"]  # type: ignore[union-attr]
    with pytest.raises(ValueError, match="NO_SUCH_TYPE"):
        parse("NO_SUCH_TYPE")


INSTANCE_DB = """
DATA_BLOCK "Feeder_Pid"
{InstructionName := 'PID_Compact';
 LibVersion := '1.2';
 S7_Optimized_Access := 'TRUE' }
NON_RETAIN
PID_Compact

BEGIN
   sb_EnCyclEstimation := TRUE;
   sBackUp.r_Gain := 1.5;
   sPid_Calc.r_Cycle := 0.1;
   sPid_Cmpt.r_Sp_Hlm := 3.402822E+38;
   sPid_Cmpt.r_Lmn_Hlm := 100.0;
   sRet.i_Mode := 3;
   sRet.r_Ctrl_Gain := 0.25;
END_DATA_BLOCK
"""


def test_a_pid_compact_instance_db_file_initialises_its_static_members() -> None:
    assert codes(INSTANCE_DB, name="Feeder_Pid.db") == []


def test_an_unknown_member_of_pid_compact_is_named() -> None:
    wrong = INSTANCE_DB.replace("sRet.r_Ctrl_Gain", "sRet.r_No_Such")
    assert codes(wrong, name="Feeder_Pid.db")


def test_pid_compact_multi_instance_and_in_out_member_access() -> None:
    source = """
FUNCTION_BLOCK "Loop"
VAR_IN_OUT
   io_Pid : PID_Compact;
END_VAR
VAR
   own : PID_Compact;
   out : REAL;
   state : INT;
   fault : DWORD;
END_VAR
BEGIN
   #io_Pid.sRet.i_Mode := 3;
   #io_Pid.sRet.r_Ctrl_Gain := #own.sRet.r_Ctrl_Gain;
   #io_Pid.sPid_Cmpt.r_Lmn_Hlm := 80.0;
   #own(Setpoint := 10.0, Input := 5.0, Output => #out, State => #state, Error => #fault);
END_FUNCTION_BLOCK
"""
    assert codes(source) == []


def test_pid_compact_parameters_are_checked() -> None:
    source = """
FUNCTION_BLOCK "Loop"
VAR
   pid : PID_Compact;
END_VAR
BEGIN
   #pid(Setpoint := 10.0, Nonsense := 5.0);
END_FUNCTION_BLOCK
"""
    assert codes(source) == ["SCL223"]


def test_control_blocks_need_the_s7_1500_profile() -> None:
    source = """
FUNCTION_BLOCK "Loop"
VAR
   pid : PID_Compact;
   hsc : CTRL_HSC;
END_VAR
BEGIN
END_FUNCTION_BLOCK
"""
    assert codes(source, profile="S7-1500") == []
    assert codes(source, profile="S7-300") == ["SCL500", "SCL500"]


def test_timing_instructions_compile_and_take_variables() -> None:
    source = """
FUNCTION_BLOCK "Timing"
VAR
   mem : LREAL;
   seconds : REAL;
   t : TON_TIME;
   parts : STRUCT pause : IEC_TIMER; END_STRUCT;
END_VAR
BEGIN
   #seconds := LREAL_TO_REAL(RUNTIME(#mem));
   RESET_TIMER(#t);
   RESET_TIMER(TIMER := #parts.pause);
   PRESET_TIMER(PT := T#3S, TIMER := #t);
END_FUNCTION_BLOCK
"""
    assert codes(source) == []


def test_reset_timer_refuses_what_is_no_timer() -> None:
    source = """
FUNCTION_BLOCK "Timing"
VAR
   n : INT;
END_VAR
BEGIN
   RESET_TIMER(#n);
END_FUNCTION_BLOCK
"""
    assert codes(source)


def test_stl_calls_a_tia_control_block_on_the_s7_1500_profile_only() -> None:
    source = "FUNCTION_BLOCK FB 1\nVAR\n  p : SFB 1100;\nEND_VAR\nBEGIN\n"
    source += "  CALL #p (Setpoint := 1.0);\nEND_FUNCTION_BLOCK\n"
    assert codes(source, profile="S7-1500", name="prog.awl") == []
    assert codes(source, profile="S7-300", name="prog.awl") == ["STL500"]

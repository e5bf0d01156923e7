"""Test pseudo-ops: assertions stop with their line, __STWRST, register operands."""

from __future__ import annotations

from builder import INT, MW, REAL, ins, reg, run_ob1, sfc, stw_bits

from nasaq.cpu import Profile
from nasaq.ir import Instruction, Origin


def test_passing_assertions() -> None:
    cpu = run_ob1(
        ins("L", INT(5)),
        ins("T", MW(0)),
        Instruction("__ASSERT==", MW(0), operand2=INT(5)),
        Instruction("__ASSERT<", MW(0), operand2=INT(6)),
        Instruction("__ASSERT==", reg("ACCU1"), operand2=INT(5)),
        Instruction("__ASSERT==", reg("STW.RLO"), operand2=INT(0)),
    )
    assert cpu.mode == "RUN", cpu.stop_reason


def test_failed_assertion_stops_at_its_line() -> None:
    from nasaq.ir import Instruction

    cpu = run_ob1(
        ins("L", INT(5)),
        Instruction(
            "__ASSERT>=", reg("ACCU1"), origin=Origin("t.awl", 42, 1, network=3), operand2=INT(6)
        ),
    )
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM513"
    assert (
        cpu.stop_reason == "OB1 network 3, line 42: assertion failed: ACCU1 >= 6 is false (SIM513)"
    )


def test_real_assertion_and_stwrst() -> None:
    from nasaq.ir import Instruction

    cpu = run_ob1(
        ins("L", REAL(1.5)),
        ins("L", REAL(2.25)),
        ins("+R"),
        Instruction("__ASSERT==R", reg("ACCU1"), operand2=REAL(3.75)),
        ins("SET"),
        ins("__STWRST"),
        Instruction("__ASSERT==", reg("STW"), operand2=INT(0)),
    )
    assert cpu.mode == "RUN", cpu.stop_reason
    assert stw_bits(cpu.stw)["RLO"] == 0


def test_test_ops_need_the_flag() -> None:
    from nasaq.ir import Instruction

    cpu = run_ob1(Instruction("__ASSERT==", MW(0), operand2=INT(0)), test_ops=False)
    assert cpu.stop_code == "SIM522"


def test_accu3_register_on_400() -> None:
    from nasaq.ir import Instruction

    cpu = run_ob1(
        ins("L", INT(1)),
        ins("PUSH"),
        ins("PUSH"),
        Instruction("__ASSERT==", reg("ACCU3"), operand2=INT(1)),
        profile=Profile.S7_400,
    )
    assert cpu.mode == "RUN", cpu.stop_reason


def test_feature_zero_reports_and_selects_the_accumulators() -> None:
    """awlsim's ``__FEATURE 0[, n]``: ACCU1 := number of accumulators; asking for 4 makes the
    CPU an S7-400 (the only profile with 4), asking for 2 an S7-300."""
    from builder import ob1

    from nasaq.cpu import Cpu
    from nasaq.ir import Instruction

    cpu = run_ob1(ins("L", INT(7)), Instruction("__FEATURE", INT(0)))
    assert (cpu.accu1, cpu.accu2) == (2, 0)  # ACCU1 set, nothing pushed
    wants_four = ob1(Instruction("__FEATURE", INT(0), operand2=INT(4)), ins("ENT"))
    cpu = Cpu(wants_four, test_ops=True)
    assert cpu.profile is Profile.S7_400
    cpu.start()
    cpu.scan()
    assert (cpu.mode, cpu.accu1) == ("RUN", 4)
    assert Cpu(wants_four, test_ops=False).profile is Profile.S7_300
    wants_two = ob1(Instruction("__FEATURE", INT(0), operand2=INT(2)))
    assert Cpu(wants_two, profile=Profile.S7_400, test_ops=True).profile is Profile.S7_300
    cpu = run_ob1(Instruction("__FEATURE", INT(1)))
    assert cpu.accu1 == 1  # OB start information is always written
    cpu = run_ob1(Instruction("__FEATURE", INT(9)))
    assert cpu.stop_code == "SIM522"


def test_int_constants_in_assertions_are_16_bit_immediates() -> None:
    """``L -32768`` sign-extends into ACCU1-H; awlsim's INT immediates are 16 bits wide, so an
    assertion against an INT constant compares the low word."""
    from builder import DINT

    from nasaq.ir import Instruction

    cpu = run_ob1(
        ins("L", INT(-32768)),
        ins("L", INT(-1)),
        ins("+I"),
        Instruction("__ASSERT==", reg("ACCU1"), operand2=INT(32767)),
        Instruction("__ASSERT==", reg("ACCU1"), operand2=DINT(-32769)),  # 0xFFFF7FFF
    )
    assert cpu.mode == "RUN", cpu.stop_reason
    cpu = run_ob1(ins("L", INT(1)), Instruction("__ASSERT==", reg("ACCU1"), operand2=DINT(0x10001)))
    assert cpu.stop_code == "SIM513"


def test_assertions_on_status_conditions_end_the_logic_chain() -> None:
    from builder import M

    from nasaq.ir import Instruction, StatusCondition

    cpu = run_ob1(
        ins("L", INT(0)),
        ins("L", INT(1)),
        ins("-I"),
        Instruction("__ASSERT==", StatusCondition.LT0, operand2=INT(1)),
        Instruction("__ASSERT==", StatusCondition.BR, operand2=INT(0)),
        ins("SET"),
        ins("A", M(0, 0)),  # RLO 0, /FC 1
        Instruction("__ASSERT==", reg("STW.RLO"), operand2=INT(0)),
        ins("A", M(0, 0)),  # /FC is 0 after an assertion: a new chain
        ins("NOT"),
        ins("=", M(0, 1)),
    )
    assert cpu.mode == "RUN", cpu.stop_reason
    assert cpu.read(M(0, 1)) == 1


def test_failed_assertion_names_its_operands() -> None:
    from builder import M

    from nasaq.ir import Instruction

    cpu = run_ob1(
        ins("SET"), ins("=", M(1, 2)), Instruction("__ASSERT==", M(1, 2), operand2=M(1, 3))
    )
    assert "assertion failed: M 1.2 == M 1.3 is false" in (cpu.stop_reason or "")


def test_awlsim_sfc_minus_3_is_a_stop_requested_by_the_program() -> None:
    for kind in (1, 2):
        cpu = run_ob1(sfc(-3, SHUTDOWN_TYPE=INT(kind)), ins("L", INT(7)), ins("T", MW(0)))
        assert cpu.mode == "STOP"
        assert cpu.stopped_by_program
        assert cpu.stop_code == "SIM502"
        assert cpu.read(MW(0)) == 0
    cpu = run_ob1(ins("L", INT(1)), ins("T", MW(2)), sfc(-3, SHUTDOWN_TYPE=MW(2)))
    assert cpu.stopped_by_program
    cpu = run_ob1(sfc(-3, SHUTDOWN_TYPE=INT(3)))
    assert cpu.stop_code == "SIM526"
    assert not cpu.stopped_by_program
    assert "SHUTDOWN_TYPE" in (cpu.stop_reason or "")
    cpu = run_ob1(sfc(-3, SHUTDOWN_TYPE=INT(1)), test_ops=False)
    assert cpu.stop_code == "SIM506"
    assert not cpu.stopped_by_program

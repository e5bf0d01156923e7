"""Master control relay: with MCR dependency on and the MCR bit 0, = and T write 0."""

from __future__ import annotations

from builder import INT, MW, M, after, ins, run_ob1


def mcr_program(condition: int) -> list:
    return [
        ins("SET"),
        ins("=", M(5, 0)),
        ins("L", INT(7)),
        ins("T", MW(10)),
        ins("SET"),
        ins("S", M(5, 1)),
        ins("MCRA"),
        ins("SET" if condition else "CLR"),
        ins("MCR("),
        ins("SET"),
        ins("=", M(5, 0)),
        ins("L", INT(9)),
        ins("T", MW(10)),
        ins("SET"),
        ins("R", M(5, 1)),
        ins(")MCR"),
        ins("MCRD"),
    ]


def test_mcr_on_executes_normally() -> None:
    cpu = after(*mcr_program(1))
    assert cpu.read(M(5, 0)) == 1
    assert cpu.read(MW(10)) == 9
    assert cpu.read(M(5, 1)) == 0


def test_mcr_off_writes_zero_and_skips_set_reset() -> None:
    cpu = after(*mcr_program(0))
    assert cpu.read(M(5, 0)) == 0
    assert cpu.read(MW(10)) == 0
    assert cpu.read(M(5, 1)) == 1


def test_without_mcra_the_mcr_does_not_matter() -> None:
    code = [i for i in mcr_program(0) if i.op not in ("MCRA", "MCRD")]
    cpu = after(*code)
    assert cpu.read(M(5, 0)) == 1
    assert cpu.read(MW(10)) == 9


def test_mcr_stack_errors() -> None:
    assert run_ob1(ins(")MCR")).stop_code == "SIM511"
    assert run_ob1(*[ins("MCR(")] * 9).stop_code == "SIM510"

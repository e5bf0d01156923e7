"""Bit logic with the status word after every kind of check (S7-300 instruction list tables)."""

from __future__ import annotations

import pytest
from builder import I, M, Q, after, ins, run_ob1, status


def logic(code: list, **bits: int) -> int:
    """Run ``code`` (using M 50.x as inputs a..h) and return M 60.0 (the result)."""
    setup = []
    for k, name in enumerate("abcdefgh"):
        if name in bits:
            setup += [ins("SET" if bits[name] else "CLR"), ins("=", M(50, k))]
    cpu = after(*setup, *code, ins("=", M(60, 0)))
    return cpu.read(M(60, 0))


def a(k: int) -> object:
    return M(50, k)


@pytest.mark.parametrize(("x", "y"), [(0, 0), (0, 1), (1, 0), (1, 1)])
def test_and_or_xor(x: int, y: int) -> None:
    assert logic([ins("A", a(0)), ins("A", a(1))], a=x, b=y) == (x & y)
    assert logic([ins("A", a(0)), ins("AN", a(1))], a=x, b=y) == (x & (1 - y))
    assert logic([ins("A", a(0)), ins("O", a(1))], a=x, b=y) == (x | y)
    assert logic([ins("A", a(0)), ins("ON", a(1))], a=x, b=y) == (x | (1 - y))
    assert logic([ins("X", a(0)), ins("X", a(1))], a=x, b=y) == (x ^ y)
    assert logic([ins("X", a(0)), ins("XN", a(1))], a=x, b=y) == 1 - (x ^ y)
    assert logic([ins("AN", a(0)), ins("AN", a(1))], a=x, b=y) == ((1 - x) & (1 - y))


@pytest.mark.parametrize("bits", range(16))
def test_and_before_or(bits: int) -> None:
    x, y, z, w = (bits >> 0) & 1, (bits >> 1) & 1, (bits >> 2) & 1, (bits >> 3) & 1
    code = [ins("A", a(0)), ins("A", a(1)), ins("O"), ins("A", a(2)), ins("A", a(3))]
    assert logic(code, a=x, b=y, c=z, d=w) == ((x & y) | (z & w))
    # three groups, the middle one false
    code3 = [*code, ins("O"), ins("AN", a(0))]
    assert logic(code3, a=x, b=y, c=z, d=w) == ((x & y) | (z & w) | (1 - x))


@pytest.mark.parametrize("bits", range(16))
def test_nesting(bits: int) -> None:
    x, y, z, w = (bits >> 0) & 1, (bits >> 1) & 1, (bits >> 2) & 1, (bits >> 3) & 1
    v = {"a": x, "b": y, "c": z, "d": w}
    and_of_ors = [
        ins("A("),
        ins("O", a(0)),
        ins("O", a(1)),
        ins(")"),
        ins("A("),
        ins("O", a(2)),
        ins("O", a(3)),
        ins(")"),
    ]
    assert logic(and_of_ors, **v) == ((x | y) & (z | w))
    assert logic([ins("A", a(0)), ins("O("), ins("A", a(1)), ins("A", a(2)), ins(")")], **v) == (
        x | (y & z)
    )
    assert logic([ins("A", a(0)), ins("AN("), ins("O", a(1)), ins("O", a(2)), ins(")")], **v) == (
        x & (1 - (y | z))
    )
    assert logic([ins("A", a(0)), ins("X("), ins("A", a(1)), ins("A", a(3)), ins(")")], **v) == (
        x ^ (y & w)
    )
    assert logic([ins("A", a(0)), ins("ON("), ins("A", a(1)), ins(")")], **v) == (x | (1 - y))
    assert logic([ins("A", a(0)), ins("XN("), ins("A", a(1)), ins(")")], **v) == 1 - (x ^ y)
    deep = [
        ins("A("),
        ins("A("),
        ins("A("),
        ins("O", a(0)),
        ins("O", a(1)),
        ins(")"),
        ins("A", a(2)),
        ins(")"),
        ins("O", a(3)),
        ins(")"),
    ]
    assert logic(deep, **v) == (((x | y) & z) | w)


def test_nesting_with_and_before_or_inside() -> None:
    code = [ins("A("), ins("A", a(0)), ins("O"), ins("A", a(1)), ins(")"), ins("A", a(2))]
    for bits in range(8):
        x, y, z = bits & 1, bits >> 1 & 1, bits >> 2 & 1
        assert logic(code, a=x, b=y, c=z) == ((x | y) & z)


def test_nesting_stack_with_jumps_uses_the_dynamic_stack() -> None:
    code = [
        ins("A("),
        ins("O", a(0)),
        ins("JC", __import__("builder").lbl("X")),
        ins("O", a(1)),
        ins(")", label="X"),
        ins("A", a(2)),
    ]
    assert logic(code, a=0, b=1, c=1) == 1
    assert logic(code, a=0, b=0, c=1) == 0


def test_status_word_after_first_check() -> None:
    s = status(ins("SET"), ins("=", M(0, 0)), ins("A", M(0, 0)))
    assert (s["FC"], s["RLO"], s["STA"], s["OR"]) == (1, 1, 1, 0)
    s = status(ins("SET"), ins("=", M(0, 0)), ins("AN", M(0, 0)))
    assert (s["FC"], s["RLO"], s["STA"], s["OR"]) == (1, 0, 1, 0)  # STA is the signal state


def test_status_word_after_assign_set_reset() -> None:
    s = status(ins("A", M(0, 1)), ins("NOT"), ins("=", M(0, 0)))
    assert (s["FC"], s["RLO"], s["STA"], s["OR"]) == (0, 1, 1, 0)
    s = status(ins("CLR"))
    assert (s["FC"], s["RLO"], s["STA"], s["OR"]) == (0, 0, 0, 0)
    s = status(ins("SET"))
    assert (s["FC"], s["RLO"], s["STA"], s["OR"]) == (0, 1, 1, 0)
    s = status(ins("CLR"), ins("S", M(0, 0)))
    assert (s["FC"], s["RLO"], s["STA"], s["OR"]) == (0, 0, 0, 0)


def test_or_bit_between_and_groups() -> None:
    s = status(ins("SET"), ins("=", M(0, 0)), ins("A", M(0, 0)), ins("O"))
    assert (s["OR"], s["STA"], s["FC"]) == (1, 1, 1)
    s = status(ins("SET"), ins("=", M(0, 0)), ins("A", M(0, 0)), ins("O"), ins("A", M(0, 1)))
    assert (s["OR"], s["RLO"], s["STA"]) == (1, 1, 0)
    s = status(ins("A", M(0, 1)), ins("O"))
    assert (s["OR"], s["FC"]) == (0, 0)


def test_open_bracket_status() -> None:
    s = status(ins("SET"), ins("=", M(0, 0)), ins("A", M(0, 0)), ins("A("))
    assert (s["FC"], s["OR"], s["STA"], s["RLO"]) == (0, 0, 1, 1)


def test_not_and_save() -> None:
    s = status(ins("CLR"), ins("NOT"))
    assert (s["RLO"], s["STA"]) == (1, 1)
    s = status(ins("SET"), ins("SAVE"), ins("CLR"))
    assert s["BR"] == 1


def test_set_reset_bits() -> None:
    cpu = after(ins("SET"), ins("S", M(1, 3)), ins("S", Q(0, 7)), ins("CLR"), ins("S", M(1, 4)))
    assert cpu.read(M(1, 3)) == 1
    assert cpu.read(Q(0, 7)) == 1
    assert cpu.read(M(1, 4)) == 0
    cpu = after(ins("SET"), ins("S", M(1, 3)), ins("R", M(1, 3)))
    assert cpu.read(M(1, 3)) == 0


def test_edges() -> None:
    code = [
        ins("A", I(0, 0)),
        ins("FP", M(10, 0)),
        ins("=", M(10, 1)),
        ins("A", I(0, 0)),
        ins("FN", M(10, 2)),
        ins("=", M(10, 3)),
    ]
    from builder import ob1

    from nasaq.cpu import Cpu

    cpu = Cpu(ob1(*code))
    cpu.start()
    seen = []
    for value in (0, 1, 1, 0, 0, 1):
        cpu.set_input(I(0, 0), value)
        cpu.scan()
        seen.append((cpu.read(M(10, 1)), cpu.read(M(10, 3))))
    assert seen == [(0, 0), (1, 0), (0, 0), (0, 1), (0, 0), (1, 0)]


def test_fp_status() -> None:
    s = status(ins("SET"), ins("FP", M(10, 0)))
    assert (s["RLO"], s["STA"], s["FC"], s["OR"]) == (1, 1, 1, 0)


def test_status_conditions_as_operands() -> None:
    from builder import INT

    def cond(value: int, op: str, operand: object) -> int:
        cpu = run_ob1(
            ins("L", INT(value)), ins("L", INT(0)), ins("+I"), ins(op, operand), ins("=", M(9, 0))
        )
        return cpu.read(M(9, 0))

    from nasaq.ir import StatusCondition as S

    assert cond(0, "A", S.EQ0) == 1
    assert cond(5, "A", S.EQ0) == 0
    assert cond(5, "A", S.GT0) == 1
    assert cond(-5, "A", S.LT0) == 1
    assert cond(-5, "A", S.NE0) == 1
    assert cond(0, "A", S.GE0) == 1
    assert cond(0, "A", S.LE0) == 1
    assert cond(5, "A", S.LE0) == 0
    assert cond(5, "AN", S.OV) == 1
    assert cond(5, "A", S.UO) == 0


def test_nesting_overflow_stops_without_ob121() -> None:
    code = [ins("A(")] * 8 + [ins(")")] * 8
    cpu = run_ob1(*code)
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM514"


def test_mcr_free_chain_through_o_with_unknown_first_check() -> None:
    # after a jump target the /FC state is not known at compile time
    from builder import lbl

    code = [
        ins("A", M(50, 0)),
        ins("JC", lbl("L1")),
        ins("A", M(50, 1)),
        ins("A", M(50, 2), label="L1"),
        ins("=", M(60, 0)),
    ]
    assert logic(code, a=0, b=1, c=1) == 1
    assert logic(code, a=1, b=0, c=1) == 1  # JC jumped with RLO set to 1 and /FC 0
    assert logic(code, a=1, b=0, c=0) == 0

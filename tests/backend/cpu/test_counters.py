"""S5 counters: edges, limits, set with C#, enable, BCD load."""

from __future__ import annotations

from builder import MW, I, Q, ins, ob1

from nasaq.cpu import Cpu
from nasaq.ir import Constant, ConstType, CounterRef

C1 = CounterRef(1)


def counter_cpu() -> Cpu:
    cpu = Cpu(
        ob1(
            ins("A", I(0, 0)),
            ins("CU", C1),
            ins("A", I(0, 1)),
            ins("CD", C1),
            ins("A", I(0, 2)),
            ins("L", Constant(ConstType.COUNTER, 0x998, 998, "C#998")),
            ins("S", C1),
            ins("A", I(0, 3)),
            ins("R", C1),
            ins("A", I(0, 4)),
            ins("FR", C1),
            ins("A", C1),
            ins("=", Q(0, 0)),
            ins("L", C1),
            ins("T", MW(0)),
            ins("LC", C1),
            ins("T", MW(2)),
        )
    )
    cpu.start()
    return cpu


def pulse(cpu: Cpu, bit: int, times: int = 1) -> None:
    for _ in range(times):
        cpu.set_input(I(0, bit), 1)
        cpu.scan()
        cpu.set_input(I(0, bit), 0)
        cpu.scan()


def test_count_up_down_on_edges() -> None:
    cpu = counter_cpu()
    pulse(cpu, 0, 3)
    assert cpu.counter(1) == (1, 3)
    assert cpu.read(Q(0, 0)) == 1
    cpu.set_input(I(0, 0), 1)
    cpu.run(5)  # held: counts once
    assert cpu.counter(1) == (1, 4)
    pulse(cpu, 1, 10)
    assert cpu.counter(1) == (0, 0)
    assert cpu.read(Q(0, 0)) == 0


def test_set_limits_and_bcd() -> None:
    cpu = counter_cpu()
    pulse(cpu, 2)
    pulse(cpu, 0, 3)
    assert cpu.counter(1)[1] == 999
    assert cpu.read(MW(0)) == 999
    assert cpu.read(MW(2)) == 0x999
    pulse(cpu, 3)
    assert cpu.counter(1) == (0, 0)


def test_enable_recounts_a_held_input() -> None:
    cpu = counter_cpu()
    cpu.set_input(I(0, 0), 1)
    cpu.run(3)
    pulse(cpu, 4)
    assert cpu.counter(1)[1] == 2


def test_counters_0_to_7_are_retentive_over_a_warm_restart() -> None:
    cpu = counter_cpu()
    pulse(cpu, 0, 2)
    cpu.start()
    assert cpu.counter(1)[1] == 2

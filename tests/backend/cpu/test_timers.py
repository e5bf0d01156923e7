"""S5 timers in virtual time: the clock stands still in a scan and moves cycle_ms between scans."""

from __future__ import annotations

from builder import MW, S5T, I, M, Q, ins, ob1

from nasaq.cpu import Cpu
from nasaq.ir import TimerRef

T1 = TimerRef(1)


def timer_cpu(kind: str, ms: int = 2000) -> Cpu:
    cpu = Cpu(
        ob1(
            ins("A", I(0, 0)),
            ins("L", S5T(ms)),
            ins(kind, T1),
            ins("A", I(0, 1)),
            ins("R", T1),
            ins("A", T1),
            ins("=", Q(0, 0)),
            ins("L", T1),
            ins("T", MW(0)),
            ins("LC", T1),
            ins("T", MW(2)),
        )
    )
    cpu.start()
    return cpu


def q_trace(cpu: Cpu, inputs: list[int], scans: int = 1) -> list[int]:
    out = []
    for value in inputs:
        cpu.set_input(I(0, 0), value)
        cpu.run(scans)
        out.append(cpu.read(Q(0, 0)))
    return out


def test_on_delay_after_exactly_200_scans_of_10_ms() -> None:
    cpu = timer_cpu("SD")
    cpu.set_input(I(0, 0), 1)
    cpu.run(199)  # started at 0 ms; the clock now reads 1990 ms
    assert cpu.timer(1) == (0, 10, True)
    cpu.run(1)  # the 200th scan still runs at 1990 ms
    assert cpu.read(Q(0, 0)) == 0
    assert cpu.timer(1) == (1, 0, False)  # seen from 2000 ms
    cpu.run(1)
    assert cpu.read(Q(0, 0)) == 1
    cpu.set_input(I(0, 0), 0)
    cpu.run(1)
    assert cpu.read(Q(0, 0)) == 0


def test_timer_values_binary_and_bcd() -> None:
    cpu = timer_cpu("SD")
    cpu.set_input(I(0, 0), 1)
    cpu.run(51)  # 500 ms after the start
    assert cpu.read(MW(0)) == 150
    assert cpu.read(MW(2)) == 0x0150  # time base 10 ms (00) and BCD 150


def test_pulse() -> None:
    cpu = timer_cpu("SP", 100)
    assert q_trace(cpu, [1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1]) == [1] * 10 + [0, 0]
    cpu = timer_cpu("SP", 100)
    assert q_trace(cpu, [1, 1, 0, 1]) == [1, 1, 0, 1]


def test_extended_pulse_keeps_running_and_retriggers() -> None:
    cpu = timer_cpu("SE", 50)
    assert q_trace(cpu, [1, 0, 0, 0, 0, 0, 0]) == [1, 1, 1, 1, 1, 0, 0]
    cpu = timer_cpu("SE", 50)
    assert q_trace(cpu, [1, 0, 0, 1, 0, 0, 0, 0, 0]) == [1, 1, 1, 1, 1, 1, 1, 1, 0]


def test_retentive_on_delay_needs_reset() -> None:
    cpu = timer_cpu("SS", 30)
    assert q_trace(cpu, [1, 0, 0, 0, 0, 0]) == [0, 0, 0, 1, 1, 1]
    cpu.set_input(I(0, 1), 1)
    cpu.run(1)
    assert cpu.read(Q(0, 0)) == 0


def test_off_delay() -> None:
    cpu = timer_cpu("SF", 30)
    assert q_trace(cpu, [1, 1, 0, 0, 0, 0, 1]) == [1, 1, 1, 1, 1, 0, 1]


def test_reset_and_enable() -> None:
    cpu = Cpu(
        ob1(
            ins("A", I(0, 2)),
            ins("FR", T1),
            ins("A", I(0, 0)),
            ins("L", S5T(50)),
            ins("SE", T1),
            ins("A", T1),
            ins("=", Q(0, 0)),
        )
    )
    cpu.start()
    cpu.set_input(I(0, 0), 1)
    cpu.run(10)
    assert cpu.read(Q(0, 0)) == 0
    cpu.set_input(I(0, 2), 1)  # FR: a start with RLO still 1 restarts the timer
    cpu.run(1)
    assert cpu.read(Q(0, 0)) == 1


def test_sleep_advances_the_clock_mid_scan() -> None:
    from builder import run_ob1

    cpu = run_ob1(
        ins("SET"),
        ins("L", S5T(100)),
        ins("SD", T1),
        ins("__SLEEP", __import__("builder").INT(100)),
        ins("A", T1),
        ins("=", M(0, 0)),
    )
    assert cpu.read(M(0, 0)) == 1
    assert cpu.time_ms == 110


def test_timer_number_error() -> None:
    from builder import run_ob1

    cpu = run_ob1(ins("A", TimerRef(300)))
    assert cpu.stop_code == "SIM516"


def test_time_bases() -> None:
    cpu = timer_cpu("SD", 20000)
    cpu.set_input(I(0, 0), 1)
    cpu.run(101)  # 1 s after the start: S5T#20S is 200 × 100 ms
    assert cpu.read(MW(0)) == 190
    assert cpu.read(MW(2)) == 0x1190

"""Time modes: real time paces scans to the wall clock, virtual and fast never wait."""

from nasaq.cpu import Cpu
from nasaq.cpu.pacing import Pacer, TimeMode
from nasaq.ir import Block, BlockKind, Instruction, Program


class FakeClock:
    def __init__(self, scan_seconds: float = 0.0) -> None:
        self.now = 100.0
        self.scan_seconds = scan_seconds
        self.sleeps: list[float] = []

    def clock(self) -> float:
        return self.now

    def sleep(self, seconds: float) -> None:
        self.sleeps.append(round(seconds, 6))
        self.now += seconds


def _cpu(cycle_ms: float = 10) -> Cpu:
    program = Program()
    program.add(Block(BlockKind.OB, 1, code=[Instruction("NOP", None)]))
    cpu = Cpu(program, cycle_ms=cycle_ms)
    cpu.start()
    return cpu


def test_real_time_waits_for_each_cycle_slot() -> None:
    fake = FakeClock()
    pacer = Pacer(TimeMode.REAL, clock=fake.clock, sleep=fake.sleep)
    cpu = _cpu(cycle_ms=20)
    assert pacer.run(cpu, 4) == 4
    assert fake.sleeps == [0.02, 0.02, 0.02]
    assert cpu.time_ms == 80


def test_real_time_overrun_starts_the_next_scan_at_once() -> None:
    fake = FakeClock()
    pacer = Pacer(TimeMode.REAL, clock=fake.clock, sleep=fake.sleep)
    cpu = _cpu(cycle_ms=10)

    def slow_scan(number: int) -> None:
        fake.now += 0.025 if number == 2 else 0.0  # scan 2 is heavy

    pacer.run(cpu, 4, before_scan=slow_scan)
    assert fake.sleeps == [0.01, 0.01]  # before scans 2 and 4; none after the overrun


def test_virtual_and_fast_never_sleep_and_advance_by_the_cycle() -> None:
    for mode in (TimeMode.VIRTUAL, TimeMode.FAST):
        fake = FakeClock()
        cpu = _cpu(cycle_ms=10)
        assert Pacer(mode, clock=fake.clock, sleep=fake.sleep).run(cpu, 50) == 50
        assert fake.sleeps == []
        assert cpu.time_ms == 500


def test_before_scan_sees_one_based_scan_numbers() -> None:
    seen: list[int] = []
    Pacer(TimeMode.VIRTUAL).run(_cpu(), 3, before_scan=seen.append)
    assert seen == [1, 2, 3]

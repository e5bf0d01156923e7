"""The clock memory byte (a CPU property in STEP 7) and awlsim's SFC -4 that restarts it."""

from __future__ import annotations

import itertools

import pytest
from builder import INT, MB, MD, MW, M, ins, lbl, ob1, reg, run_ob1, sfc

from nasaq.cpu import Cpu, Profile
from nasaq.cpu.cycle import clock_memory_value

PERIODS_MS = (100, 200, 400, 500, 800, 1000, 1600, 2000)  # bit 0 ... bit 7


@pytest.mark.parametrize("bit", range(8))
def test_each_bit_is_a_square_wave_with_the_standard_period(bit: int) -> None:
    period = PERIODS_MS[bit]
    for t in range(0, 2 * 4000, 50):
        expected = 1 if t % period >= period // 2 else 0
        assert (clock_memory_value(t) >> bit) & 1 == expected, (bit, t)


def test_all_bits_start_at_zero_and_rise_after_half_a_period() -> None:
    assert clock_memory_value(0) == 0
    assert clock_memory_value(49) == 0
    assert clock_memory_value(50) == 0b0000_0001
    assert clock_memory_value(100) == 0b0000_0010
    assert clock_memory_value(1000) == 0b1100_0100  # 0.4 s, 1.6 s and 2 s bits high


def test_the_cpu_writes_the_byte_from_the_virtual_clock() -> None:
    cpu = Cpu(ob1(ins("L", MB(20)), ins("T", MB(21))), cycle_ms=10, clock_memory_byte=20)
    cpu.start()
    seen = []
    for _ in range(120):  # 1.2 s of virtual time
        cpu.scan()
        seen.append(cpu.read(MB(21)))
    assert cpu.mode == "RUN", cpu.stop_reason
    # The program sees the byte of the scan's start: scan k starts at (k - 1) * 10 ms.
    assert seen == [clock_memory_value(k * 10) for k in range(120)]
    falling = sum(1 for a, b in itertools.pairwise(seen) if a & 1 and not b & 1)
    assert falling == 11  # 10 Hz: falling edges at 0.1 s ... 1.1 s


def test_the_clock_restarts_with_the_cpu_and_without_it_nothing_is_written() -> None:
    cpu = Cpu(ob1(ins("NOP", INT(0))), clock_memory_byte=7)
    cpu.start()
    cpu.run(12)  # 120 ms
    assert cpu.read(MB(7)) == clock_memory_value(110)
    cpu.start()  # warm restart: the bits start from 0 again (MB 7 is retentive)
    assert cpu.read(MB(7)) == 0
    cpu.run(6)
    assert cpu.read(MB(7)) == clock_memory_value(50)
    plain = Cpu(ob1(ins("NOP", INT(0))))
    plain.start()
    plain.run(20)
    assert plain.area_bytes("M") == bytes(len(plain.area_bytes("M")))


def test_a_clock_memory_byte_outside_the_marker_area_is_refused() -> None:
    program = ob1(ins("NOP", INT(0)))
    with pytest.raises(ValueError, match="MB 2048"):
        Cpu(program, clock_memory_byte=Profile.S7_300.marker_bytes)
    with pytest.raises(ValueError, match="MB -1"):
        Cpu(program, clock_memory_byte=-1)
    assert Cpu(program, profile=Profile.S7_400, clock_memory_byte=2048).mode == "STOP"


def test_awlsim_sfc_minus_4_restarts_the_clock_and_the_system_time() -> None:
    """awlsim's __CLKRST: the clock memory bits restart at 0, TIME_TCK restarts 100 ms before
    it wraps round at 2**31 ms, BR = 1."""
    program = ob1(
        ins("A", M(50, 0)),  # the test sets M 50.0 for the scan that calls SFC -4
        ins("JCN", lbl("skip")),
        sfc(-4),
        ins("L", reg("STW")),
        ins("T", MW(40)),
        ins("NOP", INT(0), label="skip"),
        sfc(64, RET_VAL=MD(0)),
    )
    cpu = Cpu(program, clock_memory_byte=20, test_ops=True)
    cpu.start()
    cpu.run(9)
    assert cpu.read(MB(20)) == clock_memory_value(80)
    assert cpu.read(MD(0)) == 80
    cpu.write(M(50, 0), 1)
    cpu.run(1)  # SFC -4 at 90 ms
    cpu.write(M(50, 0), 0)
    assert cpu.mode == "RUN", cpu.stop_reason
    assert cpu.read(MB(20)) == 0
    assert cpu.read(MD(0)) == 0x7FFFFFFF - 100
    assert cpu.read(MW(40)) & 0x100  # BR
    cpu.run(11)  # 110 ms later: the clock memory follows the new origin, TIME_TCK wrapped
    assert cpu.read(MB(20)) == clock_memory_value(100)
    assert cpu.read(MD(0)) == 9


def test_negative_sfc_numbers_exist_only_with_test_ops() -> None:
    cpu = run_ob1(sfc(-4), test_ops=False)
    assert cpu.stop_code == "SIM506"
    assert "SFC -4" in (cpu.stop_reason or "")
    assert run_ob1(sfc(-4)).mode == "RUN"
    assert run_ob1(sfc(-2, REBOOT_TYPE=INT(1))).stop_code == "SIM506"  # not emulated

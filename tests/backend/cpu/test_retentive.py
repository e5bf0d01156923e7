"""Retentive ranges (the CPU properties' "Retentive memory" tab) over warm and cold restarts."""

from __future__ import annotations

import pytest
from builder import DBW, INT, MB, S5T, I, block, db, ins, program

from nasaq.cpu import Cpu, Profile, Retentive
from nasaq.ir import BlockKind, CounterRef, TimerRef


def _cpu(retentive: Retentive | None = None) -> Cpu:
    """OB1 writes MB 0-7 and DB1.DBW0, counts I0.0's rising edges in C 0-9 and starts the
    storing on-delay timers T 0-3 (SS) with I0.0."""
    code = [ins("L", INT(0x55))]
    code += [ins("T", MB(n)) for n in range(8)]
    code += [ins("L", INT(9)), ins("T", DBW(1, 0))]
    for n in range(10):
        code += [ins("A", I(0, 0)), ins("CU", CounterRef(n))]
    for n in range(4):
        code += [ins("A", I(0, 0)), ins("L", S5T(50)), ins("SS", TimerRef(n))]
    ob1 = block(BlockKind.OB, 1, code)
    return Cpu(program(ob1, db(1, 2, b"\x00\x03")), retentive=retentive)


def _fill(cpu: Cpu) -> None:
    cpu.start()
    cpu.set_input(I(0, 0), 1)
    cpu.run(10)  # 100 ms: the timers have elapsed, every counter is at 1
    cpu.stop()  # STOP: OB1 no longer runs, so what a restart keeps is what survives


def _state(cpu: Cpu) -> tuple[list[int], list[int], list[int], int]:
    markers = [cpu.read(MB(n)) for n in range(8)]
    counters = [cpu.counter(n)[1] for n in range(10)]
    timers = [cpu.timer(n)[0] for n in range(4)]
    return markers, counters, timers, cpu.read(DBW(1, 0))


def test_the_default_ranges_are_an_s7_300s_mb_0_to_15_and_c_0_to_7() -> None:
    cpu = _cpu()
    _fill(cpu)
    assert _state(cpu) == ([0x55] * 8, [1] * 10, [1] * 4, 9)
    cpu.start()
    markers, counters, timers, dbw = _state(cpu)
    assert markers == [0x55] * 8
    assert counters == [1] * 8 + [0, 0]
    assert timers == [0] * 4  # no retentive timers by default
    assert dbw == 9  # data blocks keep their values over a warm restart


def test_configured_ranges_keep_exactly_the_first_n_of_each_area() -> None:
    cpu = _cpu(Retentive(markers=3, timers=2, counters=9))
    _fill(cpu)
    cpu.start()  # warm restart
    markers, counters, timers, dbw = _state(cpu)
    assert markers == [0x55] * 3 + [0] * 5
    assert counters == [1] * 9 + [0]
    assert timers == [1, 1, 0, 0]
    assert dbw == 9


def test_no_retentive_memory_clears_all_markers_timers_and_counters() -> None:
    cpu = _cpu(Retentive(0, 0, 0))
    _fill(cpu)
    cpu.start()
    assert _state(cpu) == ([0] * 8, [0] * 10, [0] * 4, 9)


def test_cold_restart_clears_the_retentive_ranges_and_reloads_the_data_blocks() -> None:
    cpu = _cpu(Retentive(markers=8, timers=4, counters=10))
    _fill(cpu)
    cpu.start(cold=True)
    assert _state(cpu) == ([0] * 8, [0] * 10, [0] * 4, 3)


@pytest.mark.parametrize(
    ("retentive", "what"),
    [
        (Retentive(markers=2049), "marker bytes"),
        (Retentive(timers=257), "timers"),
        (Retentive(counters=-1), "counters"),
    ],
)
def test_ranges_beyond_the_profile_are_refused(retentive: Retentive, what: str) -> None:
    with pytest.raises(ValueError, match=what):
        _cpu(retentive)
    # the S7-400 has more of each: the same numbers fit there, except a negative count
    if retentive.counters >= 0:
        Cpu(program(block(BlockKind.OB, 1, [])), Profile.S7_400, retentive=retentive)

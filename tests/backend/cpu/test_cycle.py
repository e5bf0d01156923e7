"""Scan cycle: restart, process images, OB35, error OBs, watchdog, STOP, forcing, virtual time."""

from __future__ import annotations

import pytest
from builder import DBW, INT, MB, MD, MW, I, M, Q, block, db, ins, ob1, program, run_ob1

from nasaq.cpu import Cpu
from nasaq.ir import Area, BlockKind, Direct, Origin, Width


def counting_ob1() -> list:
    return [ins("L", MW(0)), ins("+", INT(1)), ins("T", MW(0))]


def test_ob100_runs_once_at_warm_restart() -> None:
    ob100 = block(BlockKind.OB, 100, [ins("L", INT(500)), ins("T", MW(10))])
    cpu = Cpu(program(block(BlockKind.OB, 1, counting_ob1()), ob100))
    cpu.start()
    assert cpu.mode == "RUN"
    assert cpu.read(MW(10)) == 500
    cpu.run(3)
    assert cpu.read(MW(0)) == 3
    assert cpu.time_ms == 30
    assert cpu.scans == 3


def test_process_images() -> None:
    cpu = Cpu(ob1(ins("A", I(0, 0)), ins("=", Q(0, 0)), ins("A", Q(0, 0)), ins("=", M(0, 0))))
    cpu.start()
    cpu.set_input(I(0, 0), 1)
    assert cpu.read(I(0, 0)) == 0  # the PII is read at the start of the next scan
    cpu.scan()
    assert cpu.read(I(0, 0)) == 1
    assert cpu.read(Q(0, 0)) == 1
    from nasaq.ir import Area, Direct, Width

    assert cpu.read(Direct(Area.PQ, Width.BIT, 0, 0)) == 1


def test_forcing_wins_over_the_process_and_the_program() -> None:
    cpu = Cpu(ob1(ins("A", I(0, 0)), ins("=", Q(0, 0)), ins("SET"), ins("=", Q(0, 1))))
    cpu.start()
    cpu.force(I(0, 0), 1)
    cpu.force(Q(0, 1), 0)
    cpu.scan()
    from nasaq.ir import Area, Direct, Width

    assert cpu.read(Q(0, 0)) == 1
    assert cpu.read(Direct(Area.PQ, Width.BIT, 0, 1)) == 0
    cpu.unforce()
    cpu.scan()
    assert cpu.read(Q(0, 0)) == 0
    assert cpu.read(Direct(Area.PQ, Width.BIT, 0, 1)) == 1


def test_cyclic_interrupt_every_100_ms() -> None:
    ob35 = block(BlockKind.OB, 35, [ins("L", MW(2)), ins("+", INT(1)), ins("T", MW(2))])
    cpu = Cpu(program(block(BlockKind.OB, 1, counting_ob1()), ob35))
    cpu.start()
    cpu.run(100)  # 0 .. 990 ms
    assert cpu.read(MW(2)) == 9
    cpu.cycle_ms = 250
    cpu.run(2)
    assert cpu.read(MW(2)) == 12


def area_error_program(with_ob121: bool) -> Cpu:
    ob1_code = [
        ins("L", INT(1), origin=Origin("ob1.awl", 10, 7, network=1)),
        ins("T", MW(0), origin=Origin("ob1.awl", 11, 7, network=1)),
        ins("L", MW(600 * 4), origin=Origin("ob1.awl", 14, 7, network=2)),
        ins("L", INT(2), origin=Origin("ob1.awl", 15, 7, network=2)),
        ins("T", MW(2), origin=Origin("ob1.awl", 16, 7, network=2)),
    ]
    blocks = [block(BlockKind.OB, 1, ob1_code)]
    if with_ob121:
        blocks.append(
            block(BlockKind.OB, 121, [ins("L", MW(4)), ins("+", INT(1)), ins("T", MW(4))])
        )
    cpu = Cpu(program(*blocks))
    cpu.start()
    cpu.scan()
    return cpu


def test_runtime_error_without_ob121_stops_with_the_location() -> None:
    cpu = area_error_program(False)
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM503"
    assert cpu.stop_reason == "OB1 network 2, line 14: area length error reading MW 2400 (SIM503)"
    entry = cpu.diagnostic_buffer[-1]
    assert (entry.code, entry.block, entry.network, entry.line) == ("SIM503", "OB1", 2, 14)
    assert cpu.read(MW(2)) == 0
    cpu.scan()  # no-op in STOP
    assert cpu.scans == 1


def test_ob121_handles_the_error_and_execution_continues() -> None:
    cpu = area_error_program(True)
    assert cpu.mode == "RUN"
    assert cpu.read(MW(4)) == 1
    assert cpu.read(MW(2)) == 2
    assert cpu.diagnostic_buffer[-1].code == "SIM503"


def test_ob122_for_io_access_errors() -> None:
    from nasaq.ir import Area, Direct, Width

    ob122 = block(BlockKind.OB, 122, [ins("SET"), ins("=", M(9, 0))])
    cpu = Cpu(program(block(BlockKind.OB, 1, [ins("L", Direct(Area.PI, Width.WORD, 5000))]), ob122))
    cpu.start()
    cpu.scan()
    assert cpu.mode == "RUN"
    assert cpu.read(M(9, 0)) == 1


def test_error_in_db_access_is_reported_per_instruction() -> None:
    cpu = run_ob1(ins("L", DBW(4, 10)), extra=(db(4, 4),))
    assert cpu.stop_reason == "OB1 network 1, line 1: area length error reading DB4.DBW 10 (SIM503)"


def test_without_ob1_the_cpu_runs_empty_cycles() -> None:
    """A real S7-300/400 goes to RUN without OB1; its cycles simply run no user program."""
    ob100 = block(BlockKind.OB, 100, [ins("L", INT(1)), ins("T", MW(0))])
    cpu = Cpu(program(ob100, db(1, 2)))
    cpu.start()
    assert cpu.mode == "RUN"
    assert cpu.read(MW(0)) == 1
    cpu.run(3)
    assert cpu.mode == "RUN"
    assert (cpu.scans, cpu.time_ms) == (3, 30)
    assert [entry.code for entry in cpu.diagnostic_buffer] == ["SIM524"]  # information only
    cpu = Cpu(program())
    cpu.start()
    cpu.run(2)
    assert cpu.mode == "RUN"


def test_cold_restart_runs_ob102_and_clears_everything() -> None:
    """Cold restart: all bit memory, timers, counters cleared, DBs back to their load values,
    OB102 (start event 16#13, OB102_STRTUP 16#85 manual cold restart); OB1_SCAN_1 is 16#04."""
    ob1_code = [
        ins("L", Direct(Area.L, Width.BYTE, 1)),
        ins("T", MB(20)),
        ins("L", INT(5)),
        ins("T", DBW(1, 0)),
        ins("T", MW(2)),
    ]
    ob100 = block(BlockKind.OB, 100, [ins("L", INT(100)), ins("T", MW(4))])
    ob102 = block(
        BlockKind.OB,
        102,
        [
            ins("L", Direct(Area.L, Width.DWORD, 0)),
            ins("T", MD(8)),
            ins("L", INT(102)),
            ins("T", MW(4)),
        ],
    )
    cpu = Cpu(program(block(BlockKind.OB, 1, ob1_code), ob100, ob102, db(1, 2, b"\x00\x07")))
    cpu.start(cold=True)
    assert cpu.read(MW(4)) == 102
    assert cpu.read(MD(8)) == 0x13_85_1B_66  # event class, startup, priority 27, OB 102
    cpu.scan()
    assert cpu.read(MB(20)) == 0x04
    cpu.scan()
    assert cpu.read(MB(20)) == 0x03
    assert (cpu.read(MW(2)), cpu.read(DBW(1, 0))) == (5, 5)  # MW 2 is retentive (MB 0-15)
    cpu.stop()
    cpu.start()  # warm: OB100, retentive markers and DBs keep their values
    assert (cpu.read(MW(4)), cpu.read(MW(2)), cpu.read(DBW(1, 0))) == (100, 5, 5)
    cpu.scan()
    assert cpu.read(MB(20)) == 0x01
    cpu.stop()
    cpu.start(cold=True)
    assert (cpu.read(MW(4)), cpu.read(MW(2)), cpu.read(DBW(1, 0))) == (102, 0, 7)


def test_ob100_start_information() -> None:
    ob100 = block(BlockKind.OB, 100, [ins("L", Direct(Area.L, Width.DWORD, 0)), ins("T", MD(8))])
    cpu = Cpu(program(block(BlockKind.OB, 1, []), ob100))
    cpu.start()
    assert cpu.read(MD(8)) == 0x13_81_1B_64  # event class, manual warm restart, 27, OB 100


def test_watchdog_counts_executed_work() -> None:
    import time

    from builder import lbl

    started = time.perf_counter()
    cpu = Cpu(
        ob1(ins("L", INT(0)), ins("T", MW(0), label="X"), ins("L", MW(0)), ins("LOOP", lbl("X"))),
        watchdog_ms=150,
    )
    cpu.start()
    cpu.run(5)
    assert time.perf_counter() - started < 1.0
    assert cpu.mode == "RUN"  # 65536 turns of 3 instructions: 19.7 ms nominal
    cpu = Cpu(
        ob1(ins("L", INT(0)), ins("T", MW(0), label="X"), ins("L", MW(0)), ins("LOOP", lbl("X"))),
        watchdog_ms=10,
    )
    cpu.start()
    cpu.scan()
    assert cpu.stop_code == "SIM501"
    assert "10 ms" in (cpu.stop_reason or "")


def test_internal_errors_never_escape(monkeypatch: pytest.MonkeyPatch) -> None:
    cpu = Cpu(ob1(ins("L", INT(1)), ins("DTR")))

    def broken(a1: int) -> int:
        raise ZeroDivisionError("boom")

    cpu.start()
    cpu._engine.loader.get(BlockKind.OB, 1).namespace["_DTR"] = broken  # type: ignore[union-attr]
    cpu.scan()
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM500"
    assert cpu.stop_reason == (
        "OB1 network 1, line 2: internal simulator error; the details are in the server log"
        " (SIM500)"
    )


def test_internal_error_while_compiling_is_a_stop(monkeypatch: pytest.MonkeyPatch) -> None:
    from nasaq.cpu.codegen.registry import EMITTERS

    def broken(ctx: object, instruction: object) -> None:
        raise KeyError("boom")

    monkeypatch.setitem(EMITTERS, "NOP", broken)
    cpu = Cpu(ob1(ins("L", INT(1)), ins("NOP", INT(0))))
    cpu.start()
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM500"
    assert (cpu.stop_reason or "").startswith("OB1 network 1, line 2: internal simulator error")
    cpu.scan()  # stays in STOP, no exception
    assert cpu.mode == "STOP"


def test_internal_error_outside_the_program_is_a_stop(monkeypatch: pytest.MonkeyPatch) -> None:
    from nasaq.cpu.cycle import Engine

    cpu = Cpu(ob1(ins("L", INT(1))))
    cpu.start()

    def broken(self: Engine) -> int:
        raise RuntimeError("boom")

    monkeypatch.setattr(Engine, "_budget", broken)
    cpu.scan()
    assert cpu.mode == "STOP"
    assert cpu.stop_code == "SIM500"


def test_restart_after_stop_clears_non_retentive_markers() -> None:
    cpu = Cpu(ob1(ins("L", INT(7)), ins("T", MW(100)), ins("T", MW(0))))
    cpu.start()
    cpu.scan()
    cpu.stop()
    cpu.write(MW(100), 9)
    cpu.start()
    assert cpu.read(MW(100)) == 0
    assert cpu.read(MW(0)) == 7


def test_api_reads_and_writes() -> None:
    cpu = Cpu(ob1(ins("L", DBW(2, 0)), ins("T", MW(0))), test_ops=False)
    cpu.start()
    from builder import db as make_db

    assert cpu.db_numbers() == []
    cpu = Cpu(
        program(block(BlockKind.OB, 1, [ins("L", DBW(2, 0)), ins("T", MW(0))]), make_db(2, 4))
    )
    cpu.start()
    cpu.write(DBW(2, 0), 0xBEEF)
    cpu.scan()
    assert cpu.read(MW(0)) == 0xBEEF
    assert cpu.db_bytes(2) == bytes([0xBE, 0xEF, 0, 0])
    assert cpu.db_numbers() == [2]
    assert cpu.db_bytes(3) is None
    assert len(cpu.area_bytes("M")) == 2048
    cpu.memory_reset()
    assert cpu.db_bytes(2) == bytes(4)

"""IEC counters and timers (SFB 0 CTU ... SFB 5 TOF) in STL programs, in virtual time.

A scan runs at ``cpu.time_ms`` (the clock stands still during it) and the clock moves on by the
cycle time afterwards; an input set with ``set_input`` is seen from the next scan on.
"""

from __future__ import annotations

import pytest
from builder import MD, MW, I, M, Q, block, db, ins

from nasaq.cpu import Cpu, iec_blocks
from nasaq.ir import (
    Area,
    BlockKind,
    BlockRef,
    CallInfo,
    Direct,
    Instruction,
    Program,
    Width,
)
from nasaq.lang.stl import SourceFile, compile_sources

# -- helpers --------------------------------------------------------------------------------------


def DBX(db: int, byte: int, bit: int) -> Direct:  # noqa: N802
    return Direct(Area.DB, Width.BIT, byte, bit, db=db)


def DBB(db: int, byte: int) -> Direct:  # noqa: N802
    return Direct(Area.DB, Width.BYTE, byte, db=db)


def DBW(db: int, byte: int) -> Direct:  # noqa: N802
    return Direct(Area.DB, Width.WORD, byte, db=db)


def DBD(db: int, byte: int) -> Direct:  # noqa: N802
    return Direct(Area.DB, Width.DWORD, byte, db=db)


def ob1(body: str) -> str:
    return f"ORGANIZATION_BLOCK OB 1\nBEGIN\n{body}\nEND_ORGANIZATION_BLOCK\n"


def program(source: str, test_ops: bool = False) -> Program:
    result = compile_sources([SourceFile("iec.awl", source)], test_ops=test_ops)
    errors = [f"{d.code} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    return result.program


def plc(source: str, cycle_ms: float = 10, test_ops: bool = False) -> Cpu:
    cpu = Cpu(program(source, test_ops), cycle_ms=cycle_ms, test_ops=test_ops)
    cpu.start()
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def scan(cpu: Cpu, count: int = 1) -> None:
    cpu.run(count)
    assert cpu.mode == "RUN", cpu.stop_reason


def trace(cpu: Cpu, scans: int, *outputs: Direct) -> list[tuple[int, ...]]:
    """For each of ``scans`` scans: the time it ran at, then ``outputs`` as it left them."""
    rows = []
    for _ in range(scans):
        at = cpu.time_ms
        scan(cpu)
        rows.append((at, *(signed(cpu.read(out), out) for out in outputs)))
    return rows


def signed(value: int, where: Direct) -> int:
    bits = int(where.width)
    return value - (1 << bits) if bits > 1 and value >> (bits - 1) else value


def pulse(cpu: Cpu, where: Direct, count: int = 1) -> None:
    """``count`` rising edges: the input 1 for one scan, then 0 for one scan."""
    for _ in range(count):
        cpu.set_input(where, 1)
        scan(cpu)
        cpu.set_input(where, 0)
        scan(cpu)


# -- the module ------------------------------------------------------------------------------------


def test_instance_layouts_are_those_of_the_s7_300_400() -> None:
    def offsets(number: int) -> dict[str, tuple[int, int]]:
        return {v.name: divmod(v.offset_bits, 8) for v in iec_blocks.INTERFACES[number]}

    iec = (0, 1, 2, 3, 4, 5, 1000, 1001)  # (the TIA system blocks have their own tests)
    classic = {n: size for n, size in iec_blocks.INSTANCE_BYTES.items() if n in iec}
    assert classic == {0: 10, 1: 10, 2: 10, 3: 22, 4: 22, 5: 22} | {
        1000: 6,  # R_TRIG and F_TRIG (issue 20): CLK, Q, M a word each
        1001: 6,
    }
    timer = {
        "IN": (0, 0),
        "PT": (2, 0),
        "Q": (6, 0),
        "ET": (8, 0),
        "STATE": (12, 0),
        "STIME": (14, 0),
        "ATIME": (18, 0),
    }
    assert offsets(3) == offsets(4) == offsets(5) == timer
    assert offsets(0) == {"CU": (0, 0), "R": (0, 1), "PV": (2, 0), "Q": (4, 0), "CV": (6, 0)} | {
        "CUO": (8, 0)
    }
    assert offsets(2) == {
        "CU": (0, 0),
        "CD": (0, 1),
        "R": (0, 2),
        "LOAD": (0, 3),
        "PV": (2, 0),
        "QU": (4, 0),
        "QD": (4, 1),
        "CV": (6, 0),
        "CUO": (8, 0),
        "CDO": (8, 1),
    }
    assert set(iec) <= set(iec_blocks.BODIES) <= set(iec_blocks.INSTANCE_BYTES)


def test_ton_measures_across_the_wrap_of_the_system_time() -> None:
    buf = bytearray(30)
    base = 4  # as in a multi-instance
    buf[base] = 1  # IN
    buf[base + 2 : base + 6] = (100).to_bytes(4, "big")  # PT
    start = iec_blocks.TIME_MASK - 63  # 64 ms before the system time wraps round to 0
    assert iec_blocks.ton(buf, base, start) == 1
    assert iec_blocks.ton(buf, base, 32) == 1  # 96 ms later
    assert (buf[base + 6], int.from_bytes(buf[base + 8 : base + 12], "big")) == (0, 96)
    iec_blocks.ton(buf, base, 36)
    assert (buf[base + 6], int.from_bytes(buf[base + 8 : base + 12], "big")) == (1, 100)
    assert buf[:base] == bytes(base)  # nothing outside the instance is touched
    assert buf[base + 22 :] == bytes(30 - base - 22)


# -- TON ------------------------------------------------------------------------------------------

TON = ob1(
    """
      CALL SFB 4, DB 1 (IN := I 0.0, PT := MD 100, Q := Q 0.0, ET := MD 10);
      A BR
      = M 0.1
    """
)


def test_ton_sets_q_when_in_has_been_1_for_pt() -> None:
    cpu = plc(TON)
    cpu.write(MD(100), 50)
    assert trace(cpu, 2, Q(0, 0), MD(10)) == [(0, 0, 0), (10, 0, 0)]
    cpu.set_input(I(0, 0), 1)
    assert trace(cpu, 7, Q(0, 0), MD(10)) == [
        (20, 0, 0),
        (30, 0, 10),
        (40, 0, 20),
        (50, 0, 30),
        (60, 0, 40),
        (70, 1, 50),  # exactly PT after the scan that saw IN = 1
        (80, 1, 50),  # ET stays at PT
    ]
    assert cpu.read(M(0, 1)) == 1  # BR (ENO) after the call
    cpu.set_input(I(0, 0), 0)
    assert trace(cpu, 1, Q(0, 0), MD(10)) == [(90, 0, 0)]


def test_ton_resets_when_in_falls_before_pt() -> None:
    cpu = plc(TON)
    cpu.write(MD(100), 50)
    cpu.set_input(I(0, 0), 1)
    assert trace(cpu, 4, Q(0, 0), MD(10))[-1] == (30, 0, 30)
    cpu.set_input(I(0, 0), 0)
    assert trace(cpu, 1, Q(0, 0), MD(10)) == [(40, 0, 0)]
    cpu.set_input(I(0, 0), 1)  # starts from 0 again
    assert trace(cpu, 6, Q(0, 0), MD(10))[-2:] == [(90, 0, 40), (100, 1, 50)]


def test_ton_to_the_millisecond_at_a_cycle_of_7_ms() -> None:
    cpu = plc(TON, cycle_ms=7)
    cpu.write(MD(100), 50)
    cpu.set_input(I(0, 0), 1)
    rows = trace(cpu, 10, Q(0, 0), MD(10))
    assert rows[0] == (0, 0, 0)
    assert rows[7] == (49, 0, 49)
    assert rows[8] == (56, 1, 50)  # the first scan at 50 ms or later


def test_ton_reads_pt_at_every_call() -> None:
    cpu = plc(TON)
    cpu.write(MD(100), 100)
    cpu.set_input(I(0, 0), 1)
    assert trace(cpu, 4, Q(0, 0), MD(10))[-1] == (30, 0, 30)
    cpu.write(MD(100), 200)  # longer: still counted from the same start
    rows = trace(cpu, 17, Q(0, 0), MD(10))
    assert rows[-2:] == [(190, 0, 190), (200, 1, 200)]
    cpu.set_input(I(0, 0), 0)
    scan(cpu)
    cpu.set_input(I(0, 0), 1)
    assert trace(cpu, 7, Q(0, 0), MD(10))[-1] == (280, 0, 60)
    cpu.write(MD(100), 40)  # shorter than what has elapsed: expires at the next call
    assert trace(cpu, 1, Q(0, 0), MD(10)) == [(290, 1, 40)]
    cpu.write(MD(100), 500)  # once expired, the outputs hold until IN falls
    assert trace(cpu, 1, Q(0, 0), MD(10)) == [(300, 1, 40)]


def test_negative_pt_resets_the_timer_and_clears_br() -> None:
    cpu = plc(TON)
    cpu.write(MD(100), 20)
    cpu.set_input(I(0, 0), 1)
    assert trace(cpu, 3, Q(0, 0), MD(10))[-1] == (20, 1, 20)
    cpu.write(MD(100), 0xFFFFFFFF)  # T#-1MS
    assert trace(cpu, 1, Q(0, 0), MD(10), M(0, 1)) == [(30, 0, 0, 0)]
    assert cpu.read(DBB(1, 12)) == 0  # STATE
    assert cpu.read(DBX(1, 0, 0)) == 1  # IN stays as passed


# -- TP -------------------------------------------------------------------------------------------

TP = ob1("CALL SFB 3, DB 2 (IN := I 0.1, PT := T#50MS, Q := Q 0.1, ET := MD 14);")


def test_tp_pulse_of_pt_from_a_short_rising_edge() -> None:
    cpu = plc(TP)
    cpu.set_input(I(0, 1), 1)
    scan(cpu)
    cpu.set_input(I(0, 1), 0)
    assert trace(cpu, 6, Q(0, 1), MD(14)) == [
        (10, 1, 10),
        (20, 1, 20),
        (30, 1, 30),
        (40, 1, 40),
        (50, 0, 0),  # the pulse is over and IN is 0: ET is reset at once
        (60, 0, 0),
    ]


def test_tp_is_not_retriggerable_and_keeps_et_while_in_is_1() -> None:
    cpu = plc(TP)
    cpu.set_input(I(0, 1), 1)
    scan(cpu, 2)
    cpu.set_input(I(0, 1), 0)
    scan(cpu)
    cpu.set_input(I(0, 1), 1)  # a new rising edge during the pulse
    assert trace(cpu, 4, Q(0, 1), MD(14)) == [
        (30, 1, 30),
        (40, 1, 40),
        (50, 0, 50),  # ends PT after the first edge; ET = PT while IN is 1
        (60, 0, 50),
    ]
    cpu.set_input(I(0, 1), 0)
    assert trace(cpu, 1, Q(0, 1), MD(14)) == [(70, 0, 0)]
    cpu.set_input(I(0, 1), 1)  # the next edge starts a new pulse
    assert trace(cpu, 1, Q(0, 1), MD(14)) == [(80, 1, 0)]


# -- TOF ------------------------------------------------------------------------------------------

TOF = ob1("CALL SFB 5, DB 3 (IN := I 0.2, PT := T#30MS, Q := Q 0.2, ET := MD 18);")


def test_tof_holds_q_for_pt_after_in_falls() -> None:
    cpu = plc(TOF)
    assert trace(cpu, 1, Q(0, 2), MD(18)) == [(0, 0, 0)]
    cpu.set_input(I(0, 2), 1)
    assert trace(cpu, 2, Q(0, 2), MD(18)) == [(10, 1, 0), (20, 1, 0)]
    cpu.set_input(I(0, 2), 0)
    assert trace(cpu, 5, Q(0, 2), MD(18)) == [
        (30, 1, 0),
        (40, 1, 10),
        (50, 1, 20),
        (60, 0, 30),  # PT after the falling edge
        (70, 0, 30),  # ET keeps PT until IN is 1 again
    ]
    cpu.set_input(I(0, 2), 1)
    assert trace(cpu, 1, Q(0, 2), MD(18)) == [(80, 1, 0)]


def test_tof_in_back_to_1_during_the_delay_keeps_q() -> None:
    cpu = plc(TOF)
    cpu.set_input(I(0, 2), 1)
    scan(cpu)
    cpu.set_input(I(0, 2), 0)
    assert trace(cpu, 3, Q(0, 2), MD(18))[-1] == (30, 1, 20)
    cpu.set_input(I(0, 2), 1)
    assert trace(cpu, 1, Q(0, 2), MD(18)) == [(40, 1, 0)]
    cpu.set_input(I(0, 2), 0)  # a new delay, from this falling edge
    assert trace(cpu, 4, Q(0, 2), MD(18)) == [(50, 1, 0), (60, 1, 10), (70, 1, 20), (80, 0, 30)]


# -- counters -------------------------------------------------------------------------------------

CTU = ob1("CALL SFB 0, DB 4 (CU := I 1.0, R := I 1.1, PV := 3, Q := Q 1.0, CV := MW 20);")


def test_ctu_counts_rising_edges_and_compares_with_pv() -> None:
    cpu = plc(CTU)
    pulse(cpu, I(1, 0), 2)
    assert (cpu.read(MW(20)), cpu.read(Q(1, 0))) == (2, 0)
    cpu.set_input(I(1, 0), 1)
    scan(cpu, 3)  # CU stays 1: one edge
    assert (cpu.read(MW(20)), cpu.read(Q(1, 0))) == (3, 1)
    assert cpu.read(DBX(4, 8, 0)) == 1  # CUO
    cpu.set_input(I(1, 0), 0)
    scan(cpu)
    pulse(cpu, I(1, 0))
    assert (cpu.read(MW(20)), cpu.read(Q(1, 0))) == (4, 1)


def test_ctu_reset_has_priority_and_the_count_stops_at_32767() -> None:
    cpu = plc(CTU)
    pulse(cpu, I(1, 0), 2)
    cpu.set_input(I(1, 1), 1)
    cpu.set_input(I(1, 0), 1)  # an edge together with R
    scan(cpu)
    assert (cpu.read(MW(20)), cpu.read(Q(1, 0))) == (0, 0)
    cpu.set_input(I(1, 1), 0)
    scan(cpu)  # CU still 1: the edge was taken while R was 1
    assert cpu.read(MW(20)) == 0
    cpu.set_input(I(1, 0), 0)
    cpu.write(DBW(4, 6), 32766)  # CV in the instance
    pulse(cpu, I(1, 0), 3)
    assert (cpu.read(MW(20)), cpu.read(Q(1, 0))) == (32767, 1)


CTD = ob1("CALL SFB 1, DB 5 (CD := I 2.0, LOAD := I 2.1, PV := 2, Q := Q 2.0, CV := MW 22);")


def test_ctd_loads_pv_and_counts_down_to_the_limit() -> None:
    cpu = plc(CTD)
    scan(cpu)
    assert (cpu.read(MW(22)), cpu.read(Q(2, 0))) == (0, 1)  # CV <= 0
    cpu.set_input(I(2, 1), 1)
    cpu.set_input(I(2, 0), 1)  # LOAD wins over an edge at CD
    scan(cpu)
    assert (cpu.read(MW(22)), cpu.read(Q(2, 0))) == (2, 0)
    cpu.set_input(I(2, 1), 0)
    cpu.set_input(I(2, 0), 0)
    scan(cpu)
    pulse(cpu, I(2, 0))
    assert (cpu.read(MW(22)), cpu.read(Q(2, 0))) == (1, 0)
    pulse(cpu, I(2, 0), 2)
    assert (signed(cpu.read(MW(22)), MW(22)), cpu.read(Q(2, 0))) == (-1, 1)
    cpu.write(DBW(5, 6), 0x8001)  # -32767
    pulse(cpu, I(2, 0), 3)
    assert cpu.read(MW(22)) == 0x8000  # -32768


CTUD = ob1(
    """
      CALL SFB 2, DB 6 (CU := I 3.0, CD := I 3.1, R := I 3.2, LOAD := I 3.3, PV := 2,
                        QU := Q 3.0, QD := Q 3.1, CV := MW 24);
    """
)


def ctud_state(cpu: Cpu) -> tuple[int, int, int]:
    return signed(cpu.read(MW(24)), MW(24)), cpu.read(Q(3, 0)), cpu.read(Q(3, 1))


def test_ctud_counts_both_ways() -> None:
    cpu = plc(CTUD)
    scan(cpu)
    assert ctud_state(cpu) == (0, 0, 1)
    pulse(cpu, I(3, 0), 2)
    assert ctud_state(cpu) == (2, 1, 0)
    pulse(cpu, I(3, 1), 3)
    assert ctud_state(cpu) == (-1, 0, 1)
    cpu.set_input(I(3, 0), 1)
    cpu.set_input(I(3, 1), 1)  # rising edges at CU and CD in one call: CV stays
    scan(cpu)
    assert ctud_state(cpu) == (-1, 0, 1)
    assert cpu.read(DBB(6, 8)) == 0b11  # CUO, CDO


def test_ctud_reset_wins_over_load_and_load_over_counting() -> None:
    cpu = plc(CTUD)
    cpu.set_input(I(3, 3), 1)
    cpu.set_input(I(3, 0), 1)
    scan(cpu)
    assert ctud_state(cpu) == (2, 1, 0)  # LOAD, the edge at CU is lost
    cpu.set_input(I(3, 2), 1)
    scan(cpu)
    assert ctud_state(cpu) == (0, 0, 1)  # R and LOAD: R
    cpu.set_input(I(3, 2), 0)
    cpu.set_input(I(3, 3), 0)
    cpu.set_input(I(3, 0), 0)
    cpu.write(DBW(6, 6), 32767)
    pulse(cpu, I(3, 0))
    assert ctud_state(cpu) == (32767, 1, 0)
    cpu.write(DBW(6, 6), 0x8000)
    pulse(cpu, I(3, 1))
    assert ctud_state(cpu) == (-32768, 0, 1)


# -- instances ------------------------------------------------------------------------------------


def test_two_instance_dbs_do_not_interfere() -> None:
    cpu = plc(
        ob1(
            """
      CALL SFB 4, DB 1 (IN := I 0.0, PT := T#30MS, Q := Q 0.0, ET := MD 10);
      CALL SFB 4, DB 2 (IN := I 0.1, PT := T#50MS, Q := Q 0.1, ET := MD 14);
    """
        )
    )
    cpu.set_input(I(0, 0), 1)
    scan(cpu, 2)
    cpu.set_input(I(0, 1), 1)
    assert trace(cpu, 5, Q(0, 0), MD(10), Q(0, 1), MD(14)) == [
        (20, 0, 20, 0, 0),
        (30, 1, 30, 0, 10),
        (40, 1, 30, 0, 20),
        (50, 1, 30, 0, 30),
        (60, 1, 30, 0, 40),
    ]
    cpu.set_input(I(0, 0), 0)
    assert trace(cpu, 1, Q(0, 0), MD(10), Q(0, 1), MD(14)) == [(70, 0, 0, 1, 50)]


DECLARED = """
DATA_BLOCK DB 3 SFB 4
BEGIN
  PT := T#40MS;
END_DATA_BLOCK
"""


def test_declared_instance_db_and_parameters_not_supplied() -> None:
    """``DATA_BLOCK DB 3 SFB 4``: PT comes from the instance, Q and ET are read from it; the
    call leaves DB 3 open and BR = 1, as an FB call does."""
    cpu = plc(
        DECLARED
        + ob1(
            """
      CLR
      SAVE
      CALL SFB 4, DB 3 (IN := I 0.0);
      A BR
      = M 0.1
      L DBNO
      T MW 2
      A DB3.Q
      = Q 0.0
      L DB3.ET
      T MD 10
    """
        )
    )
    cpu.set_input(I(0, 0), 1)
    rows = trace(cpu, 5, Q(0, 0), MD(10), M(0, 1), MW(2))
    assert rows[-2:] == [(30, 0, 30, 1, 3), (40, 1, 40, 1, 3)]
    cpu.set_input(I(0, 0), 0)
    scan(cpu)
    cpu.set_input(I(0, 0), 1)
    scan(cpu, 3)  # started at 60 ms
    cpu.write(DBD(3, 2), 100)  # a new PT written into the instance
    assert trace(cpu, 8, Q(0, 0), MD(10))[-2:] == [(150, 0, 90), (160, 1, 100)]


FB_WITH_TIMERS = """
FUNCTION_BLOCK FB 10
VAR_INPUT
  start : BOOL;
  reset : BOOL;
END_VAR
VAR_OUTPUT
  done : BOOL;
  elapsed : TIME;
  count : INT;
END_VAR
VAR
  delay : SFB 4;
  cycles : SFB 0;
END_VAR
BEGIN
  CALL #delay (IN := #start, PT := T#40MS);
  A #delay.Q
  = #done
  L #delay.ET
  T #elapsed
  CALL #cycles (CU := #delay.Q, R := #reset, PV := 2, CV := #count);
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 20
VAR_INPUT
  start : BOOL;
END_VAR
VAR_OUTPUT
  done : BOOL;
END_VAR
VAR
  spare : INT;
  inner : FB 10;
END_VAR
BEGIN
  CALL #inner (start := #start, done := #done);
END_FUNCTION_BLOCK

DATA_BLOCK DB 10 FB 10
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 11 FB 10
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 20 FB 20
BEGIN
END_DATA_BLOCK
"""


def test_multi_instances_inside_fbs() -> None:
    cpu = plc(
        FB_WITH_TIMERS
        + ob1(
            """
      CALL FB 10, DB 10 (start := I 4.0, reset := I 4.2, done := Q 4.0, elapsed := MD 30,
                         count := MW 34);
      CALL FB 10, DB 11 (start := I 4.1, reset := I 4.2, done := Q 4.1, elapsed := MD 40,
                         count := MW 44);
      CALL FB 20, DB 20 (start := I 4.3, done := Q 4.3);
    """
        )
    )
    cpu.set_input(I(4, 0), 1)
    scan(cpu, 2)
    cpu.set_input(I(4, 1), 1)
    cpu.set_input(I(4, 3), 1)
    rows = trace(cpu, 3, Q(4, 0), MD(30), Q(4, 1), MD(40), Q(4, 3))
    assert rows == [(20, 0, 20, 0, 0, 0), (30, 0, 30, 0, 10, 0), (40, 1, 40, 0, 20, 0)]
    assert (cpu.read(MW(34)), cpu.read(MW(44))) == (1, 0)
    # FB 10's instance: IN 0-1, OUT 2-9, delay (TON) at byte 10, cycles (CTU) at byte 32
    assert (cpu.read(DBX(10, 16, 0)), cpu.read(DBD(10, 18))) == (1, 40)  # delay.Q, delay.ET
    assert (cpu.read(DBX(10, 32, 0)), cpu.read(DBW(10, 38))) == (1, 1)  # cycles.CU, .CV
    assert cpu.read(DBD(11, 18)) == 20
    assert trace(cpu, 2, Q(4, 1), Q(4, 3)) == [(50, 0, 0), (60, 1, 1)]
    # FB 20: IN 0, OUT 2, spare 4, inner (FB 10) from byte 6: its delay at 16, ET at 24
    assert (cpu.read(DBX(20, 22, 0)), cpu.read(DBD(20, 24))) == (1, 40)
    assert cpu.read(DBW(20, 4)) == 0
    cpu.set_input(I(4, 0), 0)
    scan(cpu)
    cpu.set_input(I(4, 0), 1)
    scan(cpu, 5)
    assert (cpu.read(Q(4, 0)), cpu.read(MW(34)), cpu.read(MW(44))) == (1, 2, 1)
    cpu.set_input(I(4, 2), 1)
    scan(cpu)
    assert (cpu.read(MW(34)), cpu.read(MW(44))) == (0, 0)


def test_an_fb_calling_an_sfb_with_an_instance_db_keeps_its_own_instance() -> None:
    cpu = plc(
        """
FUNCTION_BLOCK FB 30
VAR_INPUT
  go : BOOL;
END_VAR
VAR_OUTPUT
  q : BOOL;
END_VAR
VAR
  calls : INT;
END_VAR
BEGIN
  CALL SFB 4, DB 7 (IN := #go, PT := T#20MS, Q := #q);
  L #calls
  + 1
  T #calls
END_FUNCTION_BLOCK

DATA_BLOCK DB 30 FB 30
BEGIN
END_DATA_BLOCK
"""
        + ob1("CALL FB 30, DB 30 (go := I 0.0, q := Q 0.0);")
    )
    cpu.set_input(I(0, 0), 1)
    assert trace(cpu, 3, Q(0, 0)) == [(0, 0), (10, 0), (20, 1)]
    assert cpu.read(DBW(30, 4)) == 3  # calls
    assert cpu.read(DBD(7, 8)) == 20  # ET in DB 7


# -- restarts, clock, errors ----------------------------------------------------------------------


def test_pt_0_in_ob100_initialises_the_instance_at_a_warm_restart() -> None:
    source = TON + (
        "ORGANIZATION_BLOCK OB 100\nBEGIN\n"
        "  CALL SFB 4, DB 1 (PT := T#0MS, Q := M 1.0);\n"
        "  A BR\n  = M 1.1\n"
        "END_ORGANIZATION_BLOCK\n"
    )
    for with_ob100 in (False, True):
        cpu = plc(source if with_ob100 else TON)
        cpu.write(MD(100), 30)
        cpu.set_input(I(0, 0), 1)
        assert trace(cpu, 4, Q(0, 0))[-1] == (30, 1)
        cpu.stop()
        cpu.start()  # warm restart: the instance DB keeps its data
        cpu.write(MD(100), 30)
        if with_ob100:  # Q = 0, ET = 0, STATE = 0 and IN = 0 in the instance: it starts again
            assert cpu.read(DBX(1, 0, 0)) == cpu.read(DBX(1, 6, 0)) == 0  # IN, Q
            assert cpu.read(DBD(1, 8)) == cpu.read(DBB(1, 12)) == 0  # ET, STATE
            assert (cpu.read(M(1, 1)), cpu.read(M(1, 0))) == (1, 0)
            assert trace(cpu, 4, Q(0, 0)) == [(40, 0), (50, 0), (60, 0), (70, 1)]
        else:
            assert trace(cpu, 1, Q(0, 0)) == [(40, 1)]


def test_a_cold_restart_resets_the_instances() -> None:
    cpu = plc(CTU)
    pulse(cpu, I(1, 0), 2)
    assert cpu.read(DBW(4, 6)) == 2
    cpu.stop()
    cpu.start(cold=True)
    assert cpu.db_bytes(4) == bytes(10)


def test_timers_run_across_the_wrap_of_the_system_time() -> None:
    """awlsim's SFC -4 moves the system time to 100 ms before it wraps round at 2**31 ms."""
    cpu = plc(
        ob1(
            """
      A M 50.0
      JCN skip
      CALL SFC -4
skip: CALL SFB 4, DB 1 (IN := I 0.0, PT := T#250MS, Q := Q 0.0, ET := MD 10);
      CALL SFC 64 (RET_VAL := MD 20);
    """
        ),
        test_ops=True,
    )
    cpu.write(M(50, 0), 1)
    scan(cpu)
    cpu.write(M(50, 0), 0)
    cpu.set_input(I(0, 0), 1)
    scan(cpu)  # starts at 2**31 - 1 - 90
    assert cpu.read(DBD(1, 14)) == 0x7FFFFFFF - 90
    rows = trace(cpu, 25, Q(0, 0), MD(10), MD(20))
    assert rows[9][1:] == (0, 100, 9)  # the system time has wrapped round
    assert rows[-2][1:] == (0, 240, 149)
    assert rows[-1][1:] == (1, 250, 159)


def test_a_short_instance_db_is_an_area_length_error() -> None:
    call = CallInfo(BlockRef(BlockKind.SFB, 4), BlockRef(BlockKind.DB, 5), ())
    blocks = [block(BlockKind.OB, 1, [Instruction("CALL", call=call)]), db(5, 12)]
    cpu = Cpu(Program({(b.kind, b.number): b for b in blocks}))
    cpu.start()
    cpu.run(1)
    assert (cpu.mode, cpu.stop_code) == ("STOP", "SIM503")
    assert "instance data of SFB 4" in (cpu.stop_reason or "")


@pytest.mark.parametrize("number", [6, 32])
def test_other_sfbs_are_still_not_loaded(number: int) -> None:
    call = CallInfo(BlockRef(BlockKind.SFB, number), BlockRef(BlockKind.DB, 5), ())
    blocks = [
        block(BlockKind.OB, 1, [ins("SET"), Instruction("CALL", call=call)]),
        db(5, 40),
    ]
    cpu = Cpu(Program({(b.kind, b.number): b for b in blocks}))
    cpu.start()
    cpu.run(1)
    assert (cpu.mode, cpu.stop_code) == ("STOP", "SIM506")

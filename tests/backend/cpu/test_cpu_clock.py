"""SFC 1 READ_CLK and the CPU's time-of-day clock (``nasaq.cpu.clock``): set from the PC's
local time at the first read, then running with the CPU's virtual clock."""

from __future__ import annotations

import datetime

from nasaq.cpu import Cpu
from nasaq.cpu.clock import Clock, pc_ms
from nasaq.cpu.iec_library import dt_ms
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources

PROGRAM = """ORGANIZATION_BLOCK OB 1
VAR_TEMP
  r : INT;
  dt : DATE_AND_TIME;
END_VAR
BEGIN
      L     1;
      T     #r;
      CALL SFC 1 (RET_VAL := #r, CDT := #dt);
      L     LD 2;
      T     MD 10;
      L     LD 6;
      T     MD 14;
      L     #r;
      T     MW 20;
      A     BR;
      =     M 22.0;
      L     MW 30;
      +     1;
      T     MW 30;
      L     MW 30;
      L     1;
      ==I;
      JCN   SKIP;
      L     MD 10;
      T     MD 40;
      L     MD 14;
      T     MD 44;
SKIP: NOP   0;
END_ORGANIZATION_BLOCK
"""


def _bytes(cpu: Cpu, first: str, second: str) -> bytes:
    def word(text: str) -> int:
        address = parse_address(text)
        assert isinstance(address, Direct)
        return cpu.read(address)

    return word(first).to_bytes(4, "big") + word(second).to_bytes(4, "big")


def test_read_clk_gives_the_pc_time_then_runs_with_the_cpu() -> None:
    result = compile_sources([SourceFile("clock.awl", PROGRAM)])
    assert [d.code for d in result.diagnostics] == []
    cpu = Cpu(result.program, cycle_ms=10)
    before = pc_ms()
    cpu.start()
    cpu.run(1)
    first = dt_ms(_bytes(cpu, "MD40", "MD44"))
    assert before - 1000 <= first <= pc_ms() + 1000  # the PC's local time
    cpu.run(50)
    latest = dt_ms(_bytes(cpu, "MD10", "MD14"))
    assert latest - first == 50 * 10  # 50 scans of the virtual clock, whatever the PC did
    address = parse_address("MW20")
    assert isinstance(address, Direct)
    assert cpu.read(address) == 0  # RET_VAL
    bit = parse_address("M22.0")
    assert isinstance(bit, Direct)
    assert cpu.read(bit) == 1  # BR


def test_the_clock_keeps_the_date_and_time_format() -> None:
    clock = Clock()
    clock.base = (datetime.date(2024, 2, 29) - datetime.date(1990, 1, 1)).days * 86_400_000
    data = clock.date_and_time(13 * 3_600_000 + 5 * 60_000 + 7_089)
    assert data == bytes([0x24, 0x02, 0x29, 0x13, 0x05, 0x07, 0x08, 0x95])  # Thursday = 5

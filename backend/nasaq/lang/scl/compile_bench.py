"""SCL speed, the two figures of issue 4: ``python -m nasaq.lang.scl.compile_bench``.

1. Compile: parse + type check + lowering (to STL, then to the CPU's IR) of the generated
   20,000-line source of ``nasaq.lang.scl.bench`` (FBs and FCs with every statement kind),
   in lines per second (target: 20,000).
2. Run: SCL statements per second of compiled code on a loop (target: 2 million). The loop body
   is four statements (an assignment with DINT arithmetic, an INT assignment with a bit
   operation, an IF with a comparison) plus the FOR step, counted as one statement.
"""

from __future__ import annotations

import sys
import time

from nasaq.cpu.api import Cpu
from nasaq.lang.scl.bench import program
from nasaq.lang.stl import SourceFile, compile_sources

LOOPS = 20_000
STATEMENTS_PER_LOOP = 5  # FOR step, three assignments / IF, counted as SCL does them
RUN_SOURCE = f"""
FUNCTION_BLOCK Work
VAR i : DINT; total : DINT; flags : WORD; END_VAR
BEGIN
  FOR i := 1 TO {LOOPS} DO
    total := total + i * 3;
    flags := flags XOR 16#0001 AND 16#00FF;
    IF total > 1000000 THEN
      total := total - 1000000;
    END_IF;
  END_FOR;
END_FUNCTION_BLOCK

ORGANIZATION_BLOCK Main
BEGIN
  Work.DB1();
END_ORGANIZATION_BLOCK
"""


def compile_speed(lines: int = 20_000) -> tuple[float, int]:
    """(lines per second, error count) of a whole compilation."""
    text = program(lines)
    compile_sources([SourceFile("warm.scl", "FUNCTION FC1 : VOID\nBEGIN\nEND_FUNCTION\n")])
    best = float("inf")
    errors = 0
    for _ in range(2):
        started = time.perf_counter()
        result = compile_sources([SourceFile("bench.scl", text)])
        best = min(best, time.perf_counter() - started)
        errors = sum(1 for item in result.diagnostics if item.severity == "error")
    return text.count("\n") / best, errors


def run_speed(seconds: float = 2.0) -> float:
    """SCL statements per second of the loop program."""
    result = compile_sources([SourceFile("loop.scl", RUN_SOURCE)])
    assert result.ok, result.diagnostics
    cpu = Cpu(result.program, watchdog_ms=60_000)
    cpu.start()
    scans = 0
    started = time.perf_counter()
    while time.perf_counter() - started < seconds:
        cpu.run(1)
        scans += 1
    elapsed = time.perf_counter() - started
    assert cpu.mode == "RUN", cpu.stop_reason
    return scans * LOOPS * STATEMENTS_PER_LOOP / elapsed


def main(argv: list[str]) -> int:
    lines = int(argv[1]) if len(argv) > 1 else 20_000
    speed, errors = compile_speed(lines)
    print(f"SCL compile (parse + check + lower), {lines} lines: {speed:,.0f} lines/s")
    print(f"SCL run, loop of {STATEMENTS_PER_LOOP} statements: {run_speed():,.0f} statements/s")
    return 1 if errors else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))

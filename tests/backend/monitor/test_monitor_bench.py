"""The monitoring benchmark's quick mode runs end to end and reports its three figures."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from nasaq.monitor.bench import executed_per_scan, program_source

BACKEND = Path(__file__).resolve().parents[3] / "backend"


def test_bench_program_executes_exactly_1000_instructions_per_scan() -> None:
    assert executed_per_scan(program_source(1000)) == 1000


def test_quick_bench_reports_the_three_figures() -> None:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(BACKEND), env.get("PYTHONPATH")) if p)
    done = subprocess.run(
        [sys.executable, "-m", "nasaq.monitor.bench", "--quick"],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        check=False,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    out = done.stdout
    assert "(a) set_input -> frame latency" in out
    assert "p95" in out
    assert "(b)" in out
    assert "scan rate" in out
    assert "frames" in out
    assert "(c) open-block monitoring slowdown" in out
    assert "OB1 monitored" in out
    assert "slowdown" in out
    verdicts = [line for line in out.splitlines() if line.rstrip().endswith(("PASS", "FAIL"))]
    assert len(verdicts) == 4, out
    assert "targets met" in out

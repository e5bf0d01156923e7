"""Helpers of the SCL tests that run compiled programs on the CPU."""

from __future__ import annotations

from cpu_run import read, real, run

from nasaq.cpu import Cpu
from nasaq.lang.stl import SourceFile, compile_sources

__all__ = ["build", "ob1", "read", "real"]


def build(source: str, *more: SourceFile, profile: str = "S7-300", scans: int = 1) -> Cpu:
    """The program compiled for ``profile`` without errors, started (OB100, RUN) and scanned
    ``scans`` times."""
    result = compile_sources([SourceFile("prog.scl", source), *more], profile=profile)
    return run(result, scans, profile)


def ob1(body: str, temps: str = "") -> str:
    declared = f"VAR_TEMP\n{temps}\nEND_VAR\n" if temps else ""
    return f"ORGANIZATION_BLOCK OB1\n{declared}BEGIN\n{body}\nEND_ORGANIZATION_BLOCK\n"

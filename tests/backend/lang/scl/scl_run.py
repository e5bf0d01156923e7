"""Helpers of the SCL tests that run compiled programs on the CPU."""

from __future__ import annotations

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import as_real, parse_address, signed
from nasaq.ir import Direct
from nasaq.lang.stl import SourceFile, compile_sources


def build(source: str, *more: SourceFile, profile: str = "S7-300", scans: int = 1) -> Cpu:
    """The program compiled for ``profile`` without errors, started (OB100, RUN) and scanned
    ``scans`` times."""
    result = compile_sources([SourceFile("prog.scl", source), *more], profile=profile)
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=10)
    cpu.start()
    assert cpu.mode == "RUN", cpu.stop_reason
    cpu.run(scans)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def read(cpu: Cpu, text: str) -> int:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return signed(cpu.read(address), address.width)


def real(cpu: Cpu, text: str) -> float:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return as_real(cpu.read(address))


def ob1(body: str, temps: str = "") -> str:
    declared = f"VAR_TEMP\n{temps}\nEND_VAR\n" if temps else ""
    return f"ORGANIZATION_BLOCK OB1\n{declared}BEGIN\n{body}\nEND_ORGANIZATION_BLOCK\n"

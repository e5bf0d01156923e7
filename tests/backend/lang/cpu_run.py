"""The one helper of the compiler tests that run a compiled program (STL, SCL or both) on the
CPU and read what it left: ``run`` starts it and scans, ``read``/``real`` look at an address."""

from __future__ import annotations

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import as_real, parse_address, signed
from nasaq.ir import Direct
from nasaq.lang.stl import CompileResult


def run(result: CompileResult, scans: int = 1, profile: str = "S7-300", cycle_ms: int = 10) -> Cpu:
    """The compiled program (no errors) on a CPU of ``profile`` with a virtual cycle of
    ``cycle_ms``: started (OB100, RUN) and ``scans`` cycles."""
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=cycle_ms)
    cpu.start()
    assert cpu.mode == "RUN", cpu.stop_reason
    cpu.run(scans)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def read(cpu: Cpu, text: str) -> int:
    """The signed value at an absolute address (``MW 20``, ``DB2.DBW 8``, ``Q 4.0``)."""
    address = parse_address(text)
    assert isinstance(address, Direct)
    return signed(cpu.read(address), address.width)


def real(cpu: Cpu, text: str) -> float:
    """The REAL at an absolute address (``MD 20``)."""
    address = parse_address(text)
    assert isinstance(address, Direct)
    return as_real(cpu.read(address))

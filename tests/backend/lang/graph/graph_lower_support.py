"""Helpers for the Graph → STL lowering tests: compile a ``.graph`` source with an OB 1 that
calls its FB, run scans on the CPU, read instance DB members by name."""

from __future__ import annotations

from pathlib import Path

from nasaq.cpu import Cpu
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct, Program
from nasaq.lang.stl import CompileResult, SourceFile, compile_sources
from nasaq.monitor.targets import read, resolve

SCENARIOS = Path(__file__).resolve().parents[3] / "scenarios" / "graph"
OB1 = "ORGANIZATION_BLOCK OB 1\nBEGIN\n      CALL  FB 1, DB 1\nEND_ORGANIZATION_BLOCK\n"


def compiled(text: str, *extra: SourceFile) -> CompileResult:
    return compile_sources([SourceFile("seq.graph", text), SourceFile("ob1.awl", OB1), *extra])


def errors(result: CompileResult) -> list[str]:
    return [f"{d.code} {d.message}" for d in result.diagnostics if d.severity == "error"]


class Plant:
    """A CPU running a compiled Graph FB called from OB 1."""

    def __init__(self, text: str, *extra: SourceFile) -> None:
        result = compiled(text, *extra)
        assert not errors(result), errors(result)
        self.program: Program = result.program
        self.cpu = Cpu(self.program)
        self.cpu.start()
        assert self.cpu.mode == "RUN", self.cpu.stop_reason

    def scan(self, count: int = 1, **inputs: int) -> None:
        """``inputs``: ``I0_1=1`` sets I 0.1 before the scans."""
        for name, value in inputs.items():
            address = parse_address(name.replace("_", "."))
            assert isinstance(address, Direct)
            self.cpu.set_input(address, value)
        for _ in range(count):
            self.cpu.scan()

    def db(self, path: str) -> object:
        """A member of DB 1 by name: ``Step5.X``, ``S_NO``."""
        return read(resolve(f"DB1.{path}", self.program), self.cpu)

    def set(self, address: str, value: int) -> None:
        found = parse_address(address)
        assert isinstance(found, Direct)
        self.cpu.write(found, value)

    def bit(self, address: str) -> int:
        found = parse_address(address)
        assert isinstance(found, Direct)
        return self.cpu.read(found)

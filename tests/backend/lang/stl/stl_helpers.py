"""Small helpers shared by the STL compiler tests."""

from __future__ import annotations

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.headless.addresses import as_real, parse_address, signed
from nasaq.ir import Block, BlockKind, Direct, Instruction
from nasaq.lang.stl import CompileResult, SourceFile, compile_sources


def compile_text(
    text: str, *extra: SourceFile, test_ops: bool = False, mnemonics: str = "auto"
) -> CompileResult:
    return compile_sources(
        [SourceFile("test.awl", text), *extra], mnemonics=mnemonics, test_ops=test_ops
    )


def ob1(body: str, **options: object) -> str:
    return f"ORGANIZATION_BLOCK OB 1\nBEGIN\n{body}\nEND_ORGANIZATION_BLOCK\n"


def codes(result: CompileResult) -> list[tuple[str, int, int]]:
    return [
        (item.code, item.span.line or 0, item.span.column or 0)
        for item in result.diagnostics
        if item.span is not None
    ]


def block(result: CompileResult, kind: str = "OB", number: int = 1) -> Block:
    found = result.program.get(BlockKind(kind), number)
    assert found is not None, f"{kind} {number} missing"
    return found


def code_of(result: CompileResult, kind: str = "OB", number: int = 1) -> list[Instruction]:
    return block(result, kind, number).code


def run(result: CompileResult, scans: int = 1, profile: str = "S7-300") -> Cpu:
    """The compiled program (no errors) on a CPU of ``profile``: started and ``scans`` cycles."""
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=10)
    cpu.start()
    assert cpu.mode == "RUN", cpu.stop_reason
    cpu.run(scans)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def value(cpu: Cpu, text: str) -> int:
    """The signed value at an absolute address (``MW 20``, ``DB2.DBW 8``, ``Q 4.0``)."""
    address = parse_address(text)
    assert isinstance(address, Direct)
    return signed(cpu.read(address), address.width)


def real_value(cpu: Cpu, text: str) -> float:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return as_real(cpu.read(address))

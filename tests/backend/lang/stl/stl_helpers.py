"""Small helpers shared by the STL compiler tests (running a program on the CPU: ``cpu_run``)."""

from __future__ import annotations

from nasaq.ir import Block, BlockKind, Instruction
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

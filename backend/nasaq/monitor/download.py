"""A download: compile the sources into a program, and what a new program keeps of the old CPU.

As in STEP 7, a download in STOP replaces the blocks; the CPU's memory stays. Markers, peripheral
inputs, the clock, the diagnostic buffer and the data blocks whose layout did not change keep their
values; new and changed DBs start from their initial values.
"""

from __future__ import annotations

from typing import Any

from nasaq.cpu import Cpu
from nasaq.diagnostics.phrases import phrase
from nasaq.ir import Area, BlockKind, Program
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.monitor.errors import MonitorError

MAX_DB_BYTES = 16 * 1024 * 1024


def compile_download(sources: list[SourceFile], profile: str = "S7-300") -> Program:
    """The program of a download, compiled for the CPU family ``profile``; MonitorError when
    it does not compile."""
    result = compile_sources(sources, profile=profile)
    errors = [d for d in result.diagnostics if d.severity.value == "error"]
    if errors:
        first = errors[0]
        where = f"{first.span.file}:{first.span.line}:{first.span.column}" if first.span else ""
        raise MonitorError(
            "MON611",
            count=len(errors),
            first=f"{where} {first.code} {first.message}".strip(),
            first_key=first.key,
            first_params=first.params,
            first_prefix=f"{where} {first.code}".strip(),
        )
    size = sum(len(b.data) for b in result.program.blocks.values())
    if size > MAX_DB_BYTES:
        raise MonitorError("MON616", reason=phrase("db_too_large", size=size, limit=MAX_DB_BYTES))
    return result.program


def carry_over(old_program: Program, old: Cpu, program: Program, cpu: Cpu) -> list[str]:
    """Copies what a download keeps from ``old`` into ``cpu``; the blocks the download changed."""
    for area in (Area.M, Area.PI):
        fresh = cpu.engine.memory.area(area)
        kept = old.engine.memory.area(area)[: len(fresh)]  # a new profile may be smaller or larger
        fresh[: len(kept)] = kept
    for number, data in old.engine.memory.dbs.items():
        new_block = program.get(BlockKind.DB, number)
        old_block = old_program.get(BlockKind.DB, number)
        target = cpu.engine.memory.dbs.get(number)
        if (
            target is not None
            and new_block is not None
            and old_block is not None
            and len(target) == len(data)
            and _same_layout(old_block, new_block, old_program, program)
        ):
            target[:] = data
    cpu.engine.m.now = old.engine.m.now
    cpu.engine.diagnostic_buffer = list(old.engine.diagnostic_buffer)
    cpu.engine.diagnostic_count = old.engine.diagnostic_count
    return _changed_blocks(old_program, program)


def _changed_blocks(old: Program, new: Program) -> list[str]:
    changed = []
    for key in sorted(set(old.blocks) | set(new.blocks), key=lambda k: (k[0].value, k[1])):
        a, b = old.blocks.get(key), new.blocks.get(key)
        if a is None or b is None or _content(a) != _content(b):
            changed.append(f"{key[0].value}{key[1]}")
    return changed


def _content(block: Any) -> tuple[object, ...]:
    """A block as the CPU sees it: its code without source positions, its data and layout."""
    code = [(i.op, i.operand, i.operand2, i.label, i.call) for i in block.code]
    return (code, block.labels, block.data, block.interface, block.instance_of, block.temp_bytes)


def _same_layout(old_block: Any, new_block: Any, old: Program, new: Program) -> bool:
    if old_block.interface != new_block.interface or old_block.instance_of != new_block.instance_of:
        return False
    if new_block.instance_of is None:
        return True
    a = old.get(BlockKind.FB, new_block.instance_of)
    b = new.get(BlockKind.FB, new_block.instance_of)
    return a is not None and b is not None and a.interface == b.interface

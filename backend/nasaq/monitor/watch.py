"""Watch entries: resolved once when subscribed, read at each snapshot.

An entry that cannot be resolved stays in the list with its error, so a watch table with one wrong
line still shows the others. ``#name`` is a local of the block the CPU holds in, read only then.
A forced output shows what its module gets (the forced value), marked forced.
"""

from __future__ import annotations

from nasaq.cpu import Cpu
from nasaq.ir import Area, Direct, Program
from nasaq.monitor import targets
from nasaq.monitor.block_info import read_slot
from nasaq.monitor.debugger import HoldContext, local_slot
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.protocol import Value, WatchValue
from nasaq.monitor.status import AR2, DI

LOCAL = "local"  # a resolved entry that names a local of the held block


def memory_target(text: str, program: Program, cpu: Cpu) -> targets.Target:
    """The target ``text`` names; MON603 also when this CPU has no such address."""
    target = targets.resolve(text, program)
    targets.read(target, cpu)  # raises for an address beyond the CPU's memory
    return target


def resolve_entries(
    entries: list[str], program: Program, cpu: Cpu
) -> tuple[dict[str, targets.Target | str], list[dict[str, object]]]:
    """Each entry's target (or ``LOCAL``, or its error text) and the report the ack carries."""
    resolved: dict[str, targets.Target | str] = {}
    report: list[dict[str, object]] = []
    for text in entries:
        if text.strip().startswith("#"):
            resolved[text] = LOCAL
            report.append({"entry": text, "type": LOCAL})
            continue
        try:
            target = memory_target(text, program, cpu)
        except targets.TargetError as error:
            resolved[text] = str(error)
            report.append(
                {
                    "entry": text,
                    "code": error.code,
                    "error": str(error),
                    # for the UI's language: the key and params of the problem (phrases inside)
                    "key": error.diagnostic.key,
                    "params": error.diagnostic.params,
                }
            )
            continue
        resolved[text] = target
        report.append({"entry": text, "type": target.type})
    return resolved, report


def watch_value(
    text: str, target: targets.Target | str, cpu: Cpu, held: HoldContext | None
) -> WatchValue:
    if isinstance(target, str):
        if target != LOCAL:
            return WatchValue(value=None, error=target)
        if held is None:
            return WatchValue(value=None, error="shown while the CPU holds in a block")
        try:
            slot = local_slot(held, text)
        except MonitorError as error:
            return WatchValue(value=None, error=str(error))
        regs = held.regs
        return WatchValue(value=read_slot(slot, held.frame, regs[DI], regs[AR2], held.params))
    is_forced = forced(target, cpu)
    if is_forced and targets.is_output(target) and target.direct is not None:
        direct = target.direct
        target = targets.Target(
            target.text, target.type, Direct(Area.PQ, direct.width, direct.byte, direct.bit)
        )
    try:
        return WatchValue(value=targets.read(target, cpu), forced=is_forced)
    except targets.TargetError as error:
        return WatchValue(value=None, error=str(error))


def forced(target: targets.Target, cpu: Cpu) -> bool:
    """Whether a force holds any bit of ``target``."""
    direct = target.direct
    if direct is None:
        return False
    engine = cpu.engine
    if targets.is_input(target):
        table = engine.forced_inputs
    elif targets.is_output(target):
        table = engine.forced_outputs
    else:
        return False
    width = int(direct.width)
    if width == 1:
        return (direct.byte, direct.bit) in table
    return any((direct.byte + k // 8, k % 8) in table for k in range(width))


def read_or_none(target: targets.Target, cpu: Cpu) -> Value:
    try:
        return targets.read(target, cpu)
    except targets.TargetError:
        return None

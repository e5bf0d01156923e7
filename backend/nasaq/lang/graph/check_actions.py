"""The rows of a step's action table: legal event × qualifier × C combinations, their
operands and values (GRA230–GRA247).

The legal combinations are the digest's §2.5.3 table with its notes, which follow Siemens'
own list where the course book over-generalises:

- Without an event: N, S, R, D, L, CALL (each with or without C), the arithmetic N[C].
- With an event: N, S, R, CALL, ON, OFF, CS, CU, CD, CR, TL, TD, TR and the arithmetic N.
- The C suffix only without an event or with S1, V1, A1, R1 (also for the arithmetic N:
  the book's ``N[C]`` for S0/V0/L0/L1 is the same over-generalisation as its counters table).
- D and L never with an event (they act on the step's time since its activation).
- ON, OFF, the counters and the timers only with an event (they act once).
- ``OFF S_ALL`` only with S1, V1 and L1; ``ON S_ALL`` never. ON/OFF name an existing step,
  by ``S<number>`` or by name.
- D/L need a time (``T#5S`` or an operand), CS a preset (``C#26`` or an operand; a bare
  number would be loaded as BCD garbage), TL/TD an S5 time (``S5T#8S`` or an operand); the
  other qualifiers take no value.
- CALL names a block (FC/FB/SFC/SFB by number or symbol, an FB with its instance DB);
  counters name a counter, timers a timer, bit actions a bit (not a timer, counter, block
  or S_ALL).
- An assignment (``A := expr``) is an arithmetic action and needs N.
- A C row in a step without an interlock: warning (C can never block, §2.5.1).
- A step without actions: info only (S7-Graph prints a warning, but a waiting step such as
  an idle initial step is normal and needs none; the info keeps the Problems list quiet).
- A transition without a condition (``None``): warning, it passes at once. An explicitly
  empty ``CONDITION END_CONDITION`` says "always" and is not reported.
"""

from __future__ import annotations

import re

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check_context import BlockContext, step_key, transition_key
from nasaq.lang.graph.model import Action, Step

C_EVENTS = frozenset({None, "S1", "V1", "A1", "R1"})
OFF_ALL_EVENTS = frozenset({"S1", "V1", "L1"})
WITHOUT_EVENT = frozenset({"D", "L"})
NEEDS_EVENT = frozenset({"ON", "OFF", "CS", "CU", "CD", "CR", "TL", "TD", "TR"})
COUNTERS = frozenset({"CS", "CU", "CD", "CR"})
TIMERS = frozenset({"TL", "TD", "TR"})
BITS = frozenset({"N", "S", "R", "D", "L"})

# The qualifiers that take a value after the comma: the constant prefixes that do not fit
# (an operand or the right constant does) and an example for the message.
_VALUES: dict[str, tuple[tuple[str, ...], str]] = {
    "D": (("S5T#", "S5TIME#", "C#"), "T#5S"),
    "L": (("S5T#", "S5TIME#", "C#"), "T#5S"),
    "CS": (("T#", "TIME#", "S5T#", "S5TIME#"), "C#10"),
    "TL": (("T#", "TIME#", "C#"), "S5T#5S"),
    "TD": (("T#", "TIME#", "C#"), "S5T#5S"),
}

_SYMBOL = r'"[^"]+"'
_LOCAL = r"#[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*"
_BLOCK = re.compile(
    rf"(?:(?:FC|FB|SFC|SFB)\s*\d+|{_SYMBOL})(?:\s*,\s*(?:DB\s*\d+|DI\s*\d+|{_SYMBOL}|{_LOCAL}))?",
    re.IGNORECASE,
)
_COUNTER = re.compile(rf"C\s*\d+|Z\s*\d+|{_SYMBOL}|{_LOCAL}", re.IGNORECASE)
_TIMER = re.compile(rf"T\s*\d+|{_SYMBOL}|{_LOCAL}", re.IGNORECASE)
_NOT_A_BIT = re.compile(
    r"(?:T|C|Z|FC|FB|SFC|SFB|DB|DI|OB|UDT)\s*\d+|S_ALL",
    re.IGNORECASE,
)
_NUMBER = re.compile(r"[+-]?\d+")


def check_actions(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    for _, step in ctx.steps:
        if not step.actions:
            found.append(ctx.problem("GRA244", step_key(step), step=step.name))
        for k, action in enumerate(step.actions, start=1):
            found += _row(ctx, step, action, f"{step_key(step)}/A{k}")
    for _, transition in ctx.transitions:
        if transition.condition is None:
            found.append(
                ctx.problem("GRA245", transition_key(transition), transition=transition.name)
            )
    return found


def written(action: Action) -> str:
    """The row's instruction as written: ``S1 NC``, ``D``."""
    qualifier = action.qualifier + ("C" if action.interlock else "")
    return f"{action.event} {qualifier}" if action.event else qualifier


def _row(ctx: BlockContext, step: Step, action: Action, key: str) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    qualifier, event, operand = action.qualifier, action.event, action.operand.strip()
    row = written(action)
    if not operand:
        return [ctx.problem("GRA247", key, action=row)]
    if action.interlock and event not in C_EVENTS:
        found.append(ctx.problem("GRA230", key, action=row, event=event))
    if event is not None and qualifier in WITHOUT_EVENT:
        found.append(ctx.problem("GRA231", key, action=row, qualifier=qualifier, event=event))
    if event is None and qualifier in NEEDS_EVENT:
        found.append(ctx.problem("GRA232", key, action=row, qualifier=qualifier))
    if action.interlock and step.interlock is None:
        found.append(ctx.problem("GRA243", key, action=row, step=step.name))
    arithmetic = ":=" in operand
    if arithmetic and qualifier != "N":
        found.append(ctx.problem("GRA242", key, action=row, operand=operand))
    found += _value(ctx, action, key, row)
    if arithmetic:
        return found
    if qualifier in ("ON", "OFF"):
        found += _step_control(ctx, action, key, row)
    elif qualifier == "CALL":
        if _BLOCK.fullmatch(operand) is None:
            found.append(ctx.problem("GRA239", key, action=row, operand=operand))
    elif qualifier in COUNTERS:
        if _COUNTER.fullmatch(operand) is None:
            found.append(ctx.problem("GRA240", key, action=row, operand=operand))
    elif qualifier in TIMERS:
        if _TIMER.fullmatch(operand) is None:
            found.append(ctx.problem("GRA241", key, action=row, operand=operand))
    elif qualifier in BITS and _NOT_A_BIT.fullmatch(operand) is not None:
        found.append(ctx.problem("GRA246", key, action=row, operand=operand))
    return found


def _step_control(ctx: BlockContext, action: Action, key: str, row: str) -> list[Diagnostic]:
    operand = action.operand.strip()
    if operand.upper() == "S_ALL":
        if action.qualifier == "ON":
            return [ctx.problem("GRA234", key, action=row)]
        if action.event is not None and action.event not in OFF_ALL_EVENTS:
            return [ctx.problem("GRA233", key, action=row, event=action.event)]
        return []
    if ctx.step_reference(operand) is None:
        return [ctx.problem("GRA235", key, action=row, step=operand)]
    return []


def _value(ctx: BlockContext, action: Action, key: str, row: str) -> list[Diagnostic]:
    """The value after the comma: present where needed, of the right kind, absent elsewhere."""
    value = (action.time or "").strip()
    expected = _VALUES.get(action.qualifier)
    operand = action.operand.strip()
    if expected is None:
        if value:
            return [ctx.problem("GRA237", key, action=row, value=value)]
        return []
    refused, example = expected
    if not value:
        return [ctx.problem("GRA236", key, action=row, operand=operand, example=example)]
    upper = value.upper().replace(" ", "")
    if upper.startswith(refused) or _NUMBER.fullmatch(upper):
        return [
            ctx.problem("GRA238", key, action=row, value=value, operand=operand, example=example)
        ]
    return []

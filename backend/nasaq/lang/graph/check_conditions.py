"""The LAD/FBD logic of transitions, interlocks, supervisions and permanent instructions
(GRA260–GRA265).

S7-Graph (digest §2.6) builds a condition from normally open and normally closed contacts,
AND/OR (series and parallel branches) and comparator boxes only, at most 32 elements per
condition. Decisions:

- ``NOT`` (the LAD ``--|NOT|--``) is refused with its own message: S7-Graph's condition
  toolbar has no NOT; a normally closed contact (``ContactNC``) inverts one operand and De
  Morgan the rest. Status bits, edge contacts, midline coils and every box but a comparator
  (``CMP==I`` … ``CMP<=R``) are refused too.
- The 32 elements count what a student sees as an element in LAD: contacts and boxes
  (coils and calls too in a permanent network); a parallel branch is wiring, not an element.
- A permanent instruction is a condition whose result goes to ``=``, ``S`` or ``R`` coils,
  or a block call (FC/FB/SFC/SFB box) as its final element; other coils, jumps, RET, OPN,
  other boxes and STL networks are refused. A permanent network without an output does
  nothing: warning. The 32-element limit applies to each permanent network.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import lru_cache

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check_context import BlockContext, step_key, transition_key
from nasaq.lang.lad.boxes import box_spec, call_target
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    Midline,
    Network,
    OpenDb,
    Parallel,
    Return,
    Series,
    StatusContact,
)

MAX_ELEMENTS = 32
_ALLOWED_COILS = frozenset({"=", "S", "R"})
_COIL_NAMES = {"SP": "SP", "SE": "SE", "SD": "SD", "SS": "SS", "SF": "SF", "SAVE": "Save"}


def check_conditions(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    for _, transition in ctx.transitions:
        if transition.condition is not None:
            found += _condition(ctx, transition.condition, transition_key(transition))
    for _, step in ctx.steps:
        for series, part in ((step.interlock, "C"), (step.supervision, "V")):
            if series is not None:
                found += _condition(ctx, series, f"{step_key(step)}/{part}")
    for prefix, networks in (("PRE", ctx.block.pre), ("POST", ctx.block.post)):
        for number, network in enumerate(networks, start=1):
            found += _permanent(ctx, network, f"{prefix}{number}")
    return found


def is_comparator(box: Box) -> bool:
    return _compares(box.name)


@lru_cache(maxsize=1024)
def _compares(name: str) -> bool:
    spec = box_spec(name)
    return spec is not None and spec.family == "compare"


def leaves(series: Series) -> Iterator[Element]:
    """Every element of ``series`` but the parallels (wiring), depth first, in reading order;
    the logic fed into a box's pins included."""
    for element in series.elements:
        if isinstance(element, Parallel):
            for branch in element.branches:
                yield from leaves(branch)
            continue
        yield element
        if isinstance(element, Box):
            for pin in element.inputs.values():
                if isinstance(pin, Series):
                    yield from leaves(pin)


def describe(element: Element | Final) -> str:
    """An element as the LAD text writes it, short: ``Box(MOVE)``, ``Edge(P, M 0.0)``."""
    match element:
        case Invert():
            return "NOT"
        case StatusContact(bit=bit, negated=negated):
            return f"{'StatusNC' if negated else 'Status'}({bit})"
        case EdgeContact(edge=edge, memory=memory):
            return f"Edge({edge}, {memory})"
        case Midline(operand=operand):
            return f"Midline({operand})"
        case Box(name=name):
            return f"Box({name})"
        case Coil(coil=coil, operand=operand):
            names = {"=": "Coil", "S": "SetCoil", "R": "ResetCoil"}
            return f"{names.get(coil, _COIL_NAMES.get(coil, coil))}({operand})"
        case Jump(negated=negated, label=label):
            return f"{'JumpN' if negated else 'Jump'}({label})"
        case Return():
            return "Return"
        case OpenDb(block=block):
            return f"Open({block})"
        case _:
            return type(element).__name__


def _element_problems(ctx: BlockContext, elements: list[Element], key: str) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    for element in elements:
        if isinstance(element, Contact):
            continue
        if isinstance(element, Box) and is_comparator(element):
            continue
        where = f"{key}/{element.id}" if element.id else key
        if isinstance(element, Invert):
            found.append(ctx.problem("GRA261", key, where))
        else:
            found.append(ctx.problem("GRA260", key, where, found=describe(element)))
    return found


def _condition(ctx: BlockContext, series: Series, key: str) -> list[Diagnostic]:
    elements = list(leaves(series))
    found = _element_problems(ctx, elements, key)
    if len(elements) > MAX_ELEMENTS:
        found.append(ctx.problem("GRA262", key, count=len(elements), limit=MAX_ELEMENTS))
    return found


def _permanent(ctx: BlockContext, network: Network, key: str) -> list[Diagnostic]:
    if network.stl is not None:
        return [ctx.problem("GRA264", key, network=key)]
    elements = list(leaves(network.logic))
    for output in network.outputs:
        elements += leaves(output.conditions)
    found = _element_problems(ctx, elements, key)
    for output in network.outputs:
        target = output.target
        allowed = (isinstance(target, Coil) and target.coil in _ALLOWED_COILS) or (
            isinstance(target, Box) and call_target(target.name) is not None
        )
        if not allowed:
            where = f"{key}/{target.id}" if target.id else key
            found.append(ctx.problem("GRA263", key, where, found=describe(target)))
    if not network.outputs:
        found.append(ctx.problem("GRA265", key, network=key))
    count = len(elements) + len(network.outputs)
    if count > MAX_ELEMENTS:
        found.append(ctx.problem("GRA262", key, count=count, limit=MAX_ELEMENTS))
    return found

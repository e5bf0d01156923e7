"""Operands an editor has not filled in yet: ``<??.?>`` (a bit) and ``<???>`` (anything else).

TIA Portal draws a new contact, coil or box with these placeholders and saves the network as
it is; the compiler then names each one. The lowering does the same (LAD212) before it emits
anything: every element holding a placeholder is reported and left out of the network it
lowers, so the generated STL never holds one (the STL compiler would read ``<??.?>`` as a
syntax error on a line that means nothing to the user).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from nasaq.lang.lad.boxes import box_spec
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Midline,
    Network,
    OpenDb,
    Output,
    Parallel,
    Series,
)

_PLACEHOLDER = re.compile(r"<[?.]+>")
_TIMER_COILS = frozenset({"SP", "SE", "SD", "SS", "SF"})
_COUNTER_COILS = frozenset({"CU", "CD", "SC"})

# report(code, element id, **params), as ``to_stl.LabelMaker.report`` takes it.
Report = Callable[..., None]


def is_placeholder(operand: str | None) -> bool:
    """``<`` then only ``?`` and ``.`` then ``>``: an operand nobody has written yet."""
    return operand is not None and _PLACEHOLDER.fullmatch(operand.strip()) is not None


def without_unfilled(network: Network, report: Report) -> Network:
    """``network`` without the elements that hold a placeholder, each reported once (LAD212)
    in reading order; ``network`` itself when it has none."""
    pruner = _Pruner(report)
    logic = pruner.series(network.logic)
    outputs: list[Output] = []
    for output in network.outputs:
        conditions = pruner.series(output.conditions)
        target = pruner.final(output.target)
        if target is not None:
            outputs.append(Output(conditions=conditions, target=target))
    if not pruner.found:
        return network
    return network.model_copy(update={"logic": logic, "outputs": outputs})


class _Pruner:
    def __init__(self, report: Report) -> None:
        self.report = report
        self.found = False

    def check(self, element_id: str, operand: str | None, what: str, **params: object) -> bool:
        """Whether ``operand`` is filled in; reports it when it is not."""
        if not is_placeholder(operand):
            return True
        self.found = True
        self.report("LAD212", element_id, what=what, **params)
        return False

    def series(self, series: Series) -> Series:
        kept: list[Element] = []
        for element in series.elements:
            if isinstance(element, Parallel):
                kept += self.parallel(element)
            elif isinstance(element, Box):
                box = self.box(element)
                if box is not None:
                    kept.append(box)
            elif self.element(element):
                kept.append(element)
        return series if _same(kept, series.elements) else Series(elements=kept)

    def element(self, element: Element) -> bool:
        if isinstance(element, Contact | Midline):
            return self.check(element.id, element.operand, "bit")
        if isinstance(element, EdgeContact):
            return self.check(element.id, element.memory, "bit")
        return True  # status contacts and NOT have no operand

    def parallel(self, parallel: Parallel) -> list[Element]:
        """The parallel with its branches pruned: a branch emptied by pruning goes (an empty
        branch as drawn stays, for LAD206); one branch left stands in series; none, nothing."""
        branches: list[Series] = []
        for branch in parallel.branches:
            pruned = self.series(branch)
            if pruned.elements or not branch.elements:
                branches.append(pruned)
        if _same(branches, parallel.branches):
            return [parallel]
        if len(branches) >= 2:
            return [parallel.model_copy(update={"branches": branches})]
        return list(branches[0].elements) if branches else []

    def box(self, box: Box) -> Box | None:
        spec = box_spec(box.name)
        filled = self.check(
            box.id, box.instance, spec.address if spec and spec.address else "operand"
        )
        inputs: dict[str, str | Series] = {}
        for pin, value in box.inputs.items():
            if isinstance(value, Series):
                pruned = self.series(value)
                if pruned.elements or not value.elements:
                    inputs[pin] = pruned
            elif self.check(box.id, value, "operand", pin=pin):
                inputs[pin] = value
            else:
                filled = False
        for pin, operand in box.outputs.items():
            filled = self.check(box.id, operand, "operand", pin=pin) and filled
        if not filled:
            return None
        if _same(list(inputs.values()), list(box.inputs.values())):
            return box
        return box.model_copy(update={"inputs": inputs})

    def final(self, final: Final) -> Final | None:
        if isinstance(final, Box):
            return self.box(final)
        if isinstance(final, OpenDb):
            return final if self.check(final.id, final.block, "operand") else None
        if not isinstance(final, Coil):
            return final  # jumps and RET name a label, never an operand
        what = (
            "timer"
            if final.coil in _TIMER_COILS
            else "counter"
            if final.coil in _COUNTER_COILS
            else "bit"
        )
        filled = self.check(final.id, final.operand, what)
        filled = self.check(final.id, final.value, "value") and filled
        return final if filled else None


def _same(kept: Sequence[object], given: Sequence[object]) -> bool:
    """Whether pruning left ``given`` as it was (the very same objects)."""
    return len(kept) == len(given) and all(a is b for a, b in zip(kept, given, strict=True))

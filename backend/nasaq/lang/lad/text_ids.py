"""Element ids in reading order: the n-th element of a network is ``en`` unless it has an id.

Reading order is the order of the text format: the rung's logic left to right (a PARALLEL
before its branches, a box before the logic wired into its pins), then each output's
conditions and its final element. The reader numbers what the text leaves unnamed and the
printer leaves out every id that equals its number, so both walk the network the same way.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.lang.lad.model import Box, Element, Final, Network, Output, Parallel, Series


def default_id(position: int) -> str:
    return f"e{position}"


@dataclass
class _Numbering:
    count: int = 0
    seen: set[str] = field(default_factory=set)
    duplicates: list[str] = field(default_factory=list)

    def name(self, given: str) -> str:
        self.count += 1
        chosen = given or default_id(self.count)
        if chosen in self.seen:
            self.duplicates.append(chosen)
        self.seen.add(chosen)
        return chosen

    def series(self, series: Series) -> Series:
        return Series(elements=[self.element(element) for element in series.elements])

    def element(self, element: Element) -> Element:
        named = self.name(element.id)
        if isinstance(element, Parallel):
            branches = [self.series(branch) for branch in element.branches]
            return element.model_copy(update={"id": named, "branches": branches})
        if isinstance(element, Box):
            return self.box(element, named)
        return element.model_copy(update={"id": named})

    def box(self, box: Box, named: str) -> Box:
        inputs = {
            pin: self.series(value) if isinstance(value, Series) else value
            for pin, value in box.inputs.items()
        }
        return box.model_copy(update={"id": named, "inputs": inputs})

    def final(self, final: Final) -> Final:
        named = self.name(final.id)
        if isinstance(final, Box):
            return self.box(final, named)
        return final.model_copy(update={"id": named})


def number_elements(network: Network) -> tuple[Network, list[str]]:
    """The network with every element named (given ids kept), and the ids that name more than
    one element (a given id may also clash with the number of a later element)."""
    numbering = _Numbering()
    logic = numbering.series(network.logic)
    outputs = [
        Output(
            conditions=numbering.series(output.conditions), target=numbering.final(output.target)
        )
        for output in network.outputs
    ]
    named = network.model_copy(update={"logic": logic, "outputs": outputs})
    return named, numbering.duplicates


def number_series(series: Series) -> tuple[Series, list[str]]:
    """``series`` numbered on its own from ``e1`` (a condition of a Graph step or transition),
    and the ids that name more than one element."""
    numbering = _Numbering()
    return numbering.series(series), numbering.duplicates

"""Transition, interlock and supervision conditions and the permanent networks, lowered by
LAD's own lowering (``nasaq.lang.lad.to_stl``) once the step and transition variables in their
operands are rewritten to the instance DB's members.

A condition becomes a chain that leaves its value in the RLO (with the first-check bit set, so
the caller may AND more onto it); an empty or absent condition is TRUE and emits nothing.
"""

from __future__ import annotations

from nasaq.diagnostics import Span
from nasaq.lang.graph.lower_chart import Chart
from nasaq.lang.graph.lower_emit import Emitter
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Midline,
    Network,
    Output,
    Parallel,
    Series,
)
from nasaq.lang.lad.to_stl import NetworkLowering, network_to_stl
from nasaq.lang.lad.to_stl_unfilled import without_unfilled


class Resolver:
    """Rewrites the operands of LAD logic: step/transition variables → ``#Step.X`` …"""

    def __init__(self, chart: Chart) -> None:
        self.chart = chart

    def series(self, series: Series) -> Series:
        return Series(elements=[self.element(item) for item in series.elements])

    def element(self, element: Element) -> Element:
        operand = self.chart.operand
        if isinstance(element, Contact):
            return element.model_copy(update={"operand": operand(element.operand)})
        if isinstance(element, EdgeContact):
            return element.model_copy(update={"memory": operand(element.memory)})
        if isinstance(element, Midline):
            return element.model_copy(update={"operand": operand(element.operand)})
        if isinstance(element, Parallel):
            branches = [self.series(branch) for branch in element.branches]
            return element.model_copy(update={"branches": branches})
        if isinstance(element, Box):
            return self.box(element)
        return element

    def box(self, box: Box) -> Box:
        inputs: dict[str, str | Series] = {
            pin: self.series(value) if isinstance(value, Series) else self.chart.operand(value)
            for pin, value in box.inputs.items()
        }
        outputs = {pin: self.chart.operand(value) for pin, value in box.outputs.items()}
        return box.model_copy(update={"inputs": inputs, "outputs": outputs})

    def network(self, network: Network) -> Network:
        if network.stl is not None:
            return network
        outputs = []
        for output in network.outputs:
            target = output.target
            if isinstance(target, Coil):
                target = target.model_copy(update={"operand": self.chart.operand(target.operand)})
            elif isinstance(target, Box):
                target = self.box(target)
            conditions = self.series(output.conditions)
            outputs.append(Output(conditions=conditions, target=target))
        return network.model_copy(update={"logic": self.series(network.logic), "outputs": outputs})


class Conditions:
    """Emits conditions and permanent networks into the FB's code."""

    def __init__(self, chart: Chart, out: Emitter) -> None:
        self.chart = chart
        self.out = out
        self.resolver = Resolver(chart)

    def chain(self, series: Series | None, origin: str) -> bool:
        """The condition's chain; False (nothing emitted) when it is absent or empty (TRUE).
        Its lines go to ``<origin>/<element id>`` (``T3/e2``, ``S2/C/e1``, ``S2/V/e1``), so
        monitoring draws each element's power flow; a bracket of no element to ``origin``."""
        if series is None or not series.elements:
            return False
        lowering = NetworkLowering(self.out.labels)
        # An operand not filled in yet (``<???>``, as the editor draws a new element) is
        # reported (LAD212, an error) and its element left out, as LAD does, rather than
        # reaching the STL compiler as a syntax error on a line the user never wrote.
        filled = without_unfilled(Network(logic=series), lowering.report).logic
        elements = self.resolver.series(filled).elements
        if not elements:
            self._take([], [], origin)
            return False
        wrap = len(elements) == 1 and isinstance(elements[0], Parallel)
        if wrap:  # "O a; O b" would not take a following "A": bracket it
            lowering.emit("A(")
        lowering.chain(elements, False)
        if wrap:
            lowering.owner = None
            lowering.emit(")")
        self._take(lowering.lines, lowering.elements, origin)
        return True

    def network(self, network: Network, origin: str) -> None:
        """A permanent network, its lines owned by ``<origin>/<element id>``."""
        lines, elements = network_to_stl(self.resolver.network(network), self.out.labels)
        self._take(lines, elements, origin)

    def _take(self, lines: list[str], elements: list[str | None], origin: str) -> None:
        owners = [f"{origin}/{element}" if element else origin for element in elements]
        self.out.extend(lines, owners)
        labels = self.out.labels
        for problem in labels.diagnostics:  # LAD's problems, placed on the Graph element
            span = problem.span or Span()
            element = span.element
            where = f"{origin}/{element}" if element else origin
            self.out.diagnostics.append(problem.model_copy(update={"span": Span(element=where)}))
        labels.diagnostics.clear()

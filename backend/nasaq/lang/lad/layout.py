"""Where each element of a LAD rung sits on the grid, so the front end only draws.

Files hold structure, never coordinates; the layout is computed, the same way every time, from
the series/parallel tree. The grid is in cells: a contact or coil is one cell, a box two cells wide
and as tall as its pins need. The rules:

* a series runs left to right on its top row; the elements' tops are aligned;
* a parallel stacks its branches downwards, each as wide as it needs; a shorter branch is
  finished by a horizontal :class:`LadWire`, and the branches are joined at the parallel's left
  and right edges by vertical :class:`LadLink` s (a link at ``column`` is drawn on that
  column's left edge);
* a box's flow pins (EN/ENO, a timer's S/Q; none for a comparator's left side) are on its top
  row, where the rung's wire passes, then one row per input/output pin; a Boolean pin fed by
  logic gets that logic drawn left of the box, from the pin's row down;
* the outputs are stacked at the right rail: each output's conditions start where the common
  logic ends, its final element (coil, jump, box ...) touches the rail. A rung being drawn may
  have no outputs yet: the rail then stands right after its logic (an empty rung is a rung of
  no width and one row).

Every wire and link names the power flow it carries (``flow``), so that the editor colours it
from the monitored flows without walking the tree again: ``"rail"`` is the flow of the left
rail, ``"<id>"`` the flow out of element ``id`` and ``"<id>:in"`` the flow into it.

Nothing overlaps, by construction: every tree node owns a rectangle and places its children
inside it. FBD's layout is in ``layout_fbd``.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict

from nasaq.lang.lad.boxes import box_spec
from nasaq.lang.lad.fbd import flow_pins
from nasaq.lang.lad.layout_fbd import FbdLayout, fbd_layout
from nasaq.lang.lad.model import Box, Element, Final, Network, Parallel, Series

__all__ = ["FbdLayout", "LadLayout", "fbd_layout", "lad_layout"]


class _Frozen(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class LadPin(_Frozen):
    """Where a box pin meets its wire, with the operand written at it (if any); ``open``: a pin
    of a catalogued box that nothing is connected to (drawn so it can be connected, as TIA
    Portal draws every pin of a box)."""

    name: str
    side: Literal["left", "right"]
    row: int
    operand: str | None = None
    open: bool = False


class LadCell(_Frozen):
    """One element (or output target) on the grid; ``kind`` is the model's ``kind``."""

    id: str
    kind: str
    column: int
    row: int
    width: int
    height: int
    pins: list[LadPin] = []


class LadRegion(_Frozen):
    """The rectangle a parallel (OR) occupies; its branches are cells inside it."""

    id: str
    column: int
    row: int
    width: int
    height: int


class LadLink(_Frozen):
    """A vertical wire on the left edge of ``column``, from ``from_row`` down to ``to_row``.

    ``flow`` is the power flow it carries: ``"<id>:in"`` (the flow into element ``id``) on the
    left edge of parallel ``id``, ``"<id>"`` (the flow out of it) on its right edge; the link
    joining several outputs carries the flow out of the common logic, ``"<id>"`` of its last
    element or ``"rail"`` (the left rail) when it is empty."""

    column: int
    from_row: int
    to_row: int
    flow: str


class LadWire(_Frozen):
    """A horizontal wire on ``row`` filling the cells ``from_column`` .. ``to_column`` - 1.

    ``flow`` is the power flow it carries, written ``"rail"`` (the left rail), ``"<id>"`` (the
    flow out of element ``id``) or ``"<id>:in"`` (the flow into element ``id``):

    * the wire finishing a shorter branch of a parallel carries the flow out of the branch's
      last element; an empty branch, the flow into the parallel (``"<parallel id>:in"``);
    * the wire a box's power flow takes over the logic drawn into its pins, ``"<box id>:in"``;
      the wire finishing the logic of a pin, the flow out of its last element (``"rail"`` when
      empty: logic wired into a pin starts from the rail);
    * the wire from an output's conditions to its final element, the flow out of the last
      condition, or without conditions, of the common logic (its last element, or ``"rail"``)."""

    row: int
    from_column: int
    to_column: int
    flow: str


class LadLayout(_Frozen):
    """The whole rung: ``columns`` is where the right rail stands, ``rows`` the rung's height."""

    columns: int
    rows: int
    cells: list[LadCell]
    parallels: list[LadRegion]
    links: list[LadLink]
    wires: list[LadWire]


# --- measuring -------------------------------------------------------------------------------


def _series_size(series: Series) -> tuple[int, int]:
    width, height = 0, 1
    for element in series.elements:
        w, h = _element_size(element)
        width, height = width + w, max(height, h)
    return width, height


def _element_size(element: Element | Final) -> tuple[int, int]:
    if isinstance(element, Parallel):
        sizes = [_series_size(branch) for branch in element.branches]
        return max(1, *(w for w, _ in sizes)), sum(h for _, h in sizes)
    if isinstance(element, Box):
        pins_width, rows = _box_rows(element)
        return pins_width + 2, rows
    return 1, 1


def _box_rows(box: Box) -> tuple[int, int]:
    """The width of the logic drawn into the box's pins, and the rows the box needs."""
    pins_width, row = 0, 1
    for _, value in _pin_inputs(box):
        if isinstance(value, Series):
            w, h = _series_size(value)
            pins_width, row = max(pins_width, w), row + h
        else:
            row += 1
    return pins_width, max(row, 1 + len(_pin_outputs(box)))


def _flow_after(series: Series, into: str) -> str:
    """The flow out of ``series`` fed by the flow ``into``: out of its last element."""
    return series.elements[-1].id if series.elements else into


def _pin_inputs(box: Box) -> list[tuple[str, str | Series | None]]:
    """The input pins below the top row. A catalogued box has all its pins in the catalogue's
    order (None: not connected; its flow pin only when written out), then any pin it does not
    know; a call, the pins written, in their order (its interface is the called block's)."""
    spec = box_spec(box.name)
    if spec is None:
        return list(box.inputs.items())
    flow_in = flow_pins(box.name)[0]
    names = [pin.name for pin in spec.inputs if pin.name != flow_in or pin.name in box.inputs]
    names += [name for name in box.inputs if name not in names]
    return [(name, box.inputs.get(name)) for name in names]


def _pin_outputs(box: Box) -> list[tuple[str, str | None]]:
    """The output pins below the top row: all but the one the power flow leaves by (a
    catalogued box: all of them in the catalogue's order, None where not connected)."""
    flow_out = flow_pins(box.name)[1]
    spec = box_spec(box.name)
    names = [] if spec is None else [pin.name for pin in spec.outputs if pin.name != flow_out]
    names += [name for name in box.outputs if name != flow_out and name not in names]
    return [(name, box.outputs.get(name)) for name in names]


# --- placing ---------------------------------------------------------------------------------


class _Grid:
    def __init__(self) -> None:
        self.cells: list[LadCell] = []
        self.parallels: list[LadRegion] = []
        self.links: list[LadLink] = []
        self.wires: list[LadWire] = []

    def series(self, series: Series, column: int, row: int) -> int:
        """Places the series from (column, row); returns the column after it."""
        for element in series.elements:
            column = self.element(element, column, row)
        return column

    def element(self, element: Element | Final, column: int, row: int) -> int:
        if isinstance(element, Parallel):
            return self.parallel(element, column, row)
        if isinstance(element, Box):
            return self.box(element, column, row)
        self.cells.append(
            LadCell(id=element.id, kind=element.kind, column=column, row=row, width=1, height=1)
        )
        return column + 1

    def parallel(self, parallel: Parallel, column: int, row: int) -> int:
        width, height = _element_size(parallel)
        into = f"{parallel.id}:in"
        top = row
        for branch in parallel.branches:
            end = self.series(branch, column, top)
            if end < column + width:
                flow = _flow_after(branch, into)
                self.wires.append(
                    LadWire(row=top, from_column=end, to_column=column + width, flow=flow)
                )
            last, top = top, top + _series_size(branch)[1]
        self.links.append(LadLink(column=column, from_row=row, to_row=last, flow=into))
        self.links.append(
            LadLink(column=column + width, from_row=row, to_row=last, flow=parallel.id)
        )
        self.parallels.append(
            LadRegion(id=parallel.id, column=column, row=row, width=width, height=height)
        )
        return column + width

    def box(self, box: Box, column: int, row: int) -> int:
        pins_width, rows = _box_rows(box)
        at = column + pins_width
        if pins_width:  # the power flow passes over the logic drawn into the pins
            self.wires.append(
                LadWire(row=row, from_column=column, to_column=at, flow=f"{box.id}:in")
            )
        flow_in, flow_out = flow_pins(box.name)
        pins = [] if flow_in is None else [LadPin(name=flow_in, side="left", row=row)]
        next_row = row + 1
        for name, value in _pin_inputs(box):
            if isinstance(value, Series):
                end = self.series(value, column, next_row)
                if end < at:
                    flow = _flow_after(value, "rail")
                    self.wires.append(
                        LadWire(row=next_row, from_column=end, to_column=at, flow=flow)
                    )
                pins.append(LadPin(name=name, side="left", row=next_row))
                next_row += _series_size(value)[1]
            else:
                pins.append(
                    LadPin(name=name, side="left", row=next_row, operand=value, open=value is None)
                )
                next_row += 1
        if flow_out is not None:
            operand = box.outputs.get(flow_out)
            pins.append(LadPin(name=flow_out, side="right", row=row, operand=operand))
        pins.extend(
            LadPin(name=name, side="right", row=row + 1 + index, operand=operand, open=not operand)
            for index, (name, operand) in enumerate(_pin_outputs(box))
        )
        self.cells.append(
            LadCell(id=box.id, kind=box.kind, column=at, row=row, width=2, height=rows, pins=pins)
        )
        return at + 2


def lad_layout(network: Network) -> LadLayout:
    """The grid layout of one rung: deterministic, nothing overlapping, every element placed.
    A network kept as STL has no rung: an empty grid (the editor shows its STL lines). A rung
    without outputs ends at its logic: the right rail stands right after it."""
    if network.stl is not None:
        return LadLayout(columns=0, rows=0, cells=[], parallels=[], links=[], wires=[])
    grid = _Grid()
    logic_end = grid.series(network.logic, 0, 0)
    logic_height = _series_size(network.logic)[1]
    common = _flow_after(network.logic, "rail")
    sizes = [(_series_size(out.conditions), _element_size(out.target)) for out in network.outputs]
    rail = logic_end + max((cond[0] + target[0] for cond, target in sizes), default=0)
    row = 0
    tops = []
    for output, (cond, target) in zip(network.outputs, sizes, strict=True):
        end = grid.series(output.conditions, logic_end, row)
        start = rail - target[0]
        if end < start:
            flow = _flow_after(output.conditions, common)
            grid.wires.append(LadWire(row=row, from_column=end, to_column=start, flow=flow))
        grid.element(output.target, start, row)
        tops.append(row)
        row += max(cond[1], target[1])
    if len(tops) > 1:
        grid.links.append(LadLink(column=logic_end, from_row=tops[0], to_row=tops[-1], flow=common))
    return LadLayout(
        columns=rail,
        rows=max(logic_height, row),
        cells=grid.cells,
        parallels=grid.parallels,
        links=grid.links,
        wires=grid.wires,
    )

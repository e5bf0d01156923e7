/**
 * Where each element of a LAD rung sits on the grid. A port of backend/nasaq/lang/lad/layout.py
 * (`lad_layout`), held equal to it by tests/frontend/ladParity.test.ts, so the editor redraws a
 * rung at once after an edit, exactly as the server would lay it out.
 *
 * The grid is in cells: a contact or coil is one cell, a box two cells wide and as tall as its pins
 * need. A series runs left to right on its top row; a parallel stacks its branches downwards, a
 * shorter branch finished by a wire, joined at its edges by links; a box's flow pins are on its top
 * row, then one row per pin, logic wired into a pin drawn left of the box from the pin's row down;
 * the outputs are stacked at the right rail (a rung being drawn without outputs ends at its logic:
 * an empty rung has no width and one row). Every tree node owns a rectangle and places its
 * children inside it, so nothing overlaps.
 *
 * Each wire and link names the power flow it carries, so the editor colours it from a flow map
 * without walking the tree: `rail` (the left rail), `<id>` (out of element id), `<id>:in` (into it).
 */
import { boxSpec, flowPins } from './boxes';
import type { Box, Element, Final, LadCell, LadLayout, LadLink, LadPin, LadRegion, LadWire, Network, Parallel, Series } from './model';

type Size = readonly [width: number, height: number];

// --- measuring -------------------------------------------------------------------------------

function seriesSize(series: Series): Size {
  let width = 0;
  let height = 1;
  for (const element of series.elements) {
    const [w, h] = elementSize(element);
    width += w;
    height = Math.max(height, h);
  }
  return [width, height];
}

function elementSize(element: Element | Final): Size {
  if (element.kind === 'parallel') {
    const sizes = element.branches.map(seriesSize);
    return [Math.max(1, ...sizes.map(([w]) => w)), sizes.reduce((sum, [, h]) => sum + h, 0)];
  }
  if (element.kind === 'box') {
    const [pinsWidth, rows] = boxRows(element);
    return [pinsWidth + 2, rows];
  }
  return [1, 1];
}

/** The width of the logic drawn into the box's pins, and the rows the box needs. */
function boxRows(box: Box): Size {
  let pinsWidth = 0;
  let row = 1;
  for (const [, value] of pinInputs(box)) {
    if (value === null || typeof value === 'string') {
      row += 1;
    } else {
      const [w, h] = seriesSize(value);
      pinsWidth = Math.max(pinsWidth, w);
      row += h;
    }
  }
  return [pinsWidth, Math.max(row, 1 + pinOutputs(box).length)];
}

/** The flow out of `series` when `into` flows into it: out of its last element. */
function flowAfter(series: Series, into: string): string {
  return series.elements[series.elements.length - 1]?.id ?? into;
}

/**
 * The input pins below the top row. A catalogued box has all its pins in the catalogue's order
 * (null: not connected; its flow pin only when written out), then any pin it does not know; a
 * call, the pins written, in their order (its interface is the called block's).
 */
function pinInputs(box: Box): [string, string | Series | null][] {
  const spec = boxSpec(box.name);
  if (spec === null) return Object.entries(box.inputs);
  const flowIn = flowPins(box.name)[0];
  const names = spec.inputs.filter((pin) => pin.name !== flowIn || pin.name in box.inputs).map((pin) => pin.name);
  for (const name of Object.keys(box.inputs)) if (!names.includes(name)) names.push(name);
  return names.map((name) => [name, box.inputs[name] ?? null]);
}

/**
 * The output pins below the top row: all but the one the power flow leaves by (a catalogued
 * box: all of them in the catalogue's order, null where not connected).
 */
function pinOutputs(box: Box): [string, string | null][] {
  const flowOut = flowPins(box.name)[1];
  const spec = boxSpec(box.name);
  const names = spec === null ? [] : spec.outputs.filter((pin) => pin.name !== flowOut).map((pin) => pin.name);
  for (const name of Object.keys(box.outputs)) if (name !== flowOut && !names.includes(name)) names.push(name);
  return names.map((name) => [name, box.outputs[name] ?? null]);
}

// --- placing ---------------------------------------------------------------------------------

function wire(row: number, fromColumn: number, toColumn: number, flow: string): LadWire {
  return { row, from_column: fromColumn, to_column: toColumn, flow };
}

function link(column: number, fromRow: number, toRow: number, flow: string): LadLink {
  return { column, from_row: fromRow, to_row: toRow, flow };
}

function pin(name: string, side: LadPin['side'], row: number, operand: string | null = null, open = false): LadPin {
  return { name, side, row, operand, open };
}

/** The cells, regions, links and wires placed so far. */
class Grid {
  readonly cells: LadCell[] = [];
  readonly parallels: LadRegion[] = [];
  readonly links: LadLink[] = [];
  readonly wires: LadWire[] = [];

  /** Places the series from (column, row); returns the column after it. */
  series(series: Series, column: number, row: number): number {
    let at = column;
    for (const element of series.elements) at = this.element(element, at, row);
    return at;
  }

  element(element: Element | Final, column: number, row: number): number {
    if (element.kind === 'parallel') return this.parallel(element, column, row);
    if (element.kind === 'box') return this.box(element, column, row);
    this.cells.push({ id: element.id, kind: element.kind, column, row, width: 1, height: 1, pins: [] });
    return column + 1;
  }

  parallel(parallel: Parallel, column: number, row: number): number {
    const [width, height] = elementSize(parallel);
    // Every branch starts from the flow into the parallel; its right edge carries the OR.
    const into = `${parallel.id}:in`;
    let top = row;
    let last = row;
    for (const branch of parallel.branches) {
      const end = this.series(branch, column, top);
      if (end < column + width) this.wires.push(wire(top, end, column + width, flowAfter(branch, into)));
      last = top;
      top += seriesSize(branch)[1];
    }
    this.links.push(link(column, row, last, into));
    this.links.push(link(column + width, row, last, parallel.id));
    this.parallels.push({ id: parallel.id, column, row, width, height });
    return column + width;
  }

  box(box: Box, column: number, row: number): number {
    const [pinsWidth, rows] = boxRows(box);
    const at = column + pinsWidth;
    // The power flow into the box passes over the logic drawn into its pins.
    if (pinsWidth) this.wires.push(wire(row, column, at, `${box.id}:in`));
    const [flowIn, flowOut] = flowPins(box.name);
    const pins: LadPin[] = flowIn === null ? [] : [pin(flowIn, 'left', row)];
    let nextRow = row + 1;
    for (const [name, value] of pinInputs(box)) {
      if (value === null || typeof value === 'string') {
        pins.push(pin(name, 'left', nextRow, value, value === null));
        nextRow += 1;
        continue;
      }
      const end = this.series(value, column, nextRow);
      // Logic wired into a pin starts from the rail, on its own rows.
      if (end < at) this.wires.push(wire(nextRow, end, at, flowAfter(value, 'rail')));
      pins.push(pin(name, 'left', nextRow));
      nextRow += seriesSize(value)[1];
    }
    if (flowOut !== null) pins.push(pin(flowOut, 'right', row, box.outputs[flowOut] ?? null));
    pinOutputs(box).forEach(([name, operand], index) => pins.push(pin(name, 'right', row + 1 + index, operand, !operand)));
    this.cells.push({ id: box.id, kind: box.kind, column: at, row, width: 2, height: rows, pins });
    return at + 2;
  }
}

/**
 * The grid layout of one rung: deterministic, nothing overlapping, every element placed. A network
 * kept as STL has no rung: an empty grid (the editor shows its STL lines). A rung without outputs
 * ends at its logic: the right rail stands right after it.
 */
export function ladLayout(network: Network): LadLayout {
  if (network.stl !== null) return { columns: 0, rows: 0, cells: [], parallels: [], links: [], wires: [] };
  const grid = new Grid();
  const logicEnd = grid.series(network.logic, 0, 0);
  const logicHeight = seriesSize(network.logic)[1];
  const common = flowAfter(network.logic, 'rail');
  const outputs = network.outputs.map((output) => ({ output, cond: seriesSize(output.conditions), target: elementSize(output.target) }));
  const rail = logicEnd + Math.max(0, ...outputs.map(({ cond, target }) => cond[0] + target[0]));
  let row = 0;
  let lastTop = 0; // the outputs' tops run from row 0 down to the last output's
  for (const { output, cond, target } of outputs) {
    const end = grid.series(output.conditions, logicEnd, row);
    const start = rail - target[0];
    if (end < start) grid.wires.push(wire(row, end, start, flowAfter(output.conditions, common)));
    grid.element(output.target, start, row);
    lastTop = row;
    row += Math.max(cond[1], target[1]);
  }
  if (outputs.length > 1) grid.links.push(link(logicEnd, 0, lastTop, common));
  return {
    columns: rail,
    rows: Math.max(logicHeight, row),
    cells: grid.cells,
    parallels: grid.parallels,
    links: grid.links,
    wires: grid.wires,
  };
}

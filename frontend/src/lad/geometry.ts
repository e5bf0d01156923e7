/**
 * Pixels of a LAD rung: the grid of `ladLayout` (cells, rows) turned into the boxes the
 * renderer draws, hit tests and navigates by, and the wire positions where an element can be
 * inserted. One grid cell is one contact or coil; a box takes two cells and a row per pin.
 */
import type { LadCell, LadLayout, Network } from './model';
import { LOGIC, walk, type InsertPoint, type Place, type SeriesRef } from './tree';

/** Width of one grid cell: a contact with its operand written above it. */
export const CELL_W = 100;
/** Height of one grid row: the operand (and its address) above, the symbol on the wire. */
export const ROW_H = 70;
/** Where the wire runs inside a row. */
export const WIRE_Y = 44;
/** The left power rail's x; column 0 starts right of it. */
export const RAIL_X = 10;
export const ORIGIN_X = 18;

export function columnX(column: number): number {
  return ORIGIN_X + column * CELL_W;
}

export function rowY(row: number): number {
  return row * ROW_H;
}

export function wireY(row: number): number {
  return row * ROW_H + WIRE_Y;
}

/** The drawing's size for a layout (at least one row, and room for the end marker). */
export function rungSize(layout: LadLayout): { width: number; height: number } {
  return { width: columnX(Math.max(layout.columns, 1)) + CELL_W / 2, height: Math.max(1, layout.rows) * ROW_H };
}

export interface Rect {
  x: number;
  y: number;
  width: number;
  height: number;
}

export function cellRect(cell: Pick<LadCell, 'column' | 'row' | 'width' | 'height'>): Rect {
  return { x: columnX(cell.column), y: rowY(cell.row), width: cell.width * CELL_W, height: cell.height * ROW_H };
}

/**
 * Every element's extent on the grid: its cell; a parallel's region; a box with the logic drawn
 * into its pins (which stands left of the box) included, so "before the box" is left of that logic.
 */
export function elementExtents(network: Network, layout: LadLayout): Map<string, { column: number; row: number; width: number; height: number }> {
  const extents = new Map<string, { column: number; row: number; width: number; height: number }>();
  for (const cell of layout.cells) extents.set(cell.id, { column: cell.column, row: cell.row, width: cell.width, height: cell.height });
  for (const region of layout.parallels) extents.set(region.id, { column: region.column, row: region.row, width: region.width, height: region.height });
  // Boxes: widen to the left over their pin logic (children are placed before the box's cell).
  walk(network, (element) => {
    if (element.kind !== 'box') return;
    const own = extents.get(element.id);
    if (!own) return;
    let left = own.column;
    for (const value of Object.values(element.inputs)) {
      if (typeof value !== 'object' || value === null) continue;
      for (const inner of value.elements) {
        const extent = extents.get(inner.id);
        if (extent) left = Math.min(left, extent.column);
      }
    }
    extents.set(element.id, { ...own, column: left, width: own.column + own.width - left });
  });
  return extents;
}

/** A wire position drawn on the rung: where the insertion marker and drop targets go. */
export interface InsertSpot {
  point: InsertPoint;
  x: number;
  row: number;
}

/**
 * The wire positions of every series of the rung: before each element and after the last
 * (an empty rung: at its start). Positions of series that no element of the grid locates are
 * left out.
 */
export function insertSpots(network: Network, layout: LadLayout): InsertSpot[] {
  const extents = elementExtents(network, layout);
  const spots: InsertSpot[] = [];
  const series = new Map<string, { ref: SeriesRef; ids: string[] }>();
  walk(network, (element, place) => {
    if (place.kind !== 'series') return;
    const key = JSON.stringify(place.series);
    const entry = series.get(key) ?? { ref: place.series, ids: [] };
    entry.ids[place.index] = element.id;
    series.set(key, entry);
  });
  for (const { ref, ids } of series.values()) {
    ids.forEach((id, index) => {
      const extent = extents.get(id);
      if (extent) spots.push({ point: { series: ref, index }, x: columnX(extent.column), row: extent.row });
    });
    const last = extents.get(ids[ids.length - 1] ?? '');
    if (last) spots.push({ point: { series: ref, index: ids.length }, x: columnX(last.column + last.width), row: last.row });
  }
  if (network.logic.elements.length === 0) {
    spots.push({ point: { series: LOGIC, index: 0 }, x: columnX(0), row: 0 });
  }
  // An output without conditions: the position right before its final element.
  network.outputs.forEach((output, k) => {
    if (output.conditions.elements.length > 0 || network.outputs.length === 1) return;
    const target = extents.get(output.target.id);
    if (target) spots.push({ point: { series: { root: k, steps: [] }, index: 0 }, x: columnX(target.column), row: target.row });
  });
  return spots;
}

/** The place (series position or output) of each element id drawn. */
export function placeOfId(network: Network, id: string): Place | null {
  let found: Place | null = null;
  walk(network, (element, place) => {
    if (found === null && element.id === id) found = place;
  });
  return found;
}

/** Where a box pin's operand is written (the operand field opens there). */
export function pinPoint(cell: LadCell, pin: string): { x: number; y: number } {
  const found = cell.pins.find((p) => p.name === pin);
  const rect = cellRect(cell);
  if (!found) return { x: rect.x, y: rect.y };
  return { x: found.side === 'left' ? rect.x - 40 : rect.x + rect.width - 56, y: rowY(found.row) + WIRE_Y - 30 };
}

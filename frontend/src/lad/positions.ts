/**
 * Where the elements of a network are drawn, in LAD (the grid) or in FBD (elkjs' positions): the
 * arrow keys move between these boxes, and the operand field opens on them. The selection is an
 * element of the model in both views, so only the drawing differs.
 */
import type { NavItem } from '../diagram/navigation';
import { fbdGeometryOf } from './fbdGeometry';
import { CELL_W, ROW_H, columnX, elementExtents, pinPoint, rowY } from './geometry';
import { layoutOf } from './layoutCache';
import type { Network } from './model';

export type DiagramMode = 'LAD' | 'FBD';

/** The selectable boxes of a network, and `header` above them (the network's title line). */
export function navItemsOf(network: Network, mode: DiagramMode): NavItem<string>[] {
  const items: NavItem<string>[] = [{ key: 'header', x: 0, y: -ROW_H, width: CELL_W, height: ROW_H / 2 }];
  if (network.stl !== null) return items;
  if (mode === 'FBD') {
    const geometry = fbdGeometryOf(network);
    for (const placed of geometry?.nodes ?? []) {
      const id = placed.node.id;
      if (!id.startsWith('&') && !/^n\d+$/.test(id)) items.push({ key: id, x: placed.x, y: placed.y, width: placed.width, height: placed.height });
      for (const port of placed.node.ports) {
        const at = placed.ports.get(port.id);
        if (port.element && at && port.element !== id) items.push({ key: port.element, x: at.x - 90, y: at.y - 10, width: 80, height: 20 });
      }
    }
    return items;
  }
  const layout = layoutOf(network);
  const cells = new Map(layout.cells.map((cell) => [cell.id, cell]));
  for (const [id] of elementExtents(network, layout)) {
    const cell = cells.get(id);
    if (cell) items.push({ key: id, x: columnX(cell.column), y: rowY(cell.row), width: cell.width * CELL_W, height: ROW_H });
  }
  return items;
}

/** Where the operand field of an element (or of one of its pins) opens, in the body's pixels. */
export function fieldPosition(network: Network, mode: DiagramMode, id: string, field: string): { x: number; y: number } {
  if (mode === 'FBD') {
    const item = navItemsOf(network, 'FBD').find((candidate) => candidate.key === id);
    return item ? { x: item.x, y: Math.max(0, item.y - 4) } : { x: 0, y: 0 };
  }
  const layout = layoutOf(network);
  const cell = layout.cells.find((candidate) => candidate.id === id);
  if (field.startsWith('pin:') && cell) return pinPoint(cell, field.slice(4));
  const extent = elementExtents(network, layout).get(id);
  return extent ? { x: columnX(extent.column), y: rowY(extent.row) } : { x: 0, y: 0 };
}

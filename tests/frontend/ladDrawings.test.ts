/**
 * Every program of examples/lad/ in the graphical editor: its LAD rungs and its FBD networks (laid
 * out by elkjs, as the editor's worker does) draw with no two boxes overlapping and no wire
 * crossing a box, and opening and saving it unchanged gives the same text byte for byte. The
 * models come from the parity fixture (the Python reader's, fixtures/lad-parity.json).
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { runLayout } from '../../frontend/src/diagram/elk/runLayout';
import { elkGraph, placed, type FbdGeometry } from '../../frontend/src/lad/fbdGeometry';
import { fbdLayout } from '../../frontend/src/lad/fbdGraph';
import { toFbd } from '../../frontend/src/lad/fbd';
import { CELL_W, ROW_H, cellRect, columnX, wireY, type Rect } from '../../frontend/src/lad/geometry';
import { ladLayout } from '../../frontend/src/lad/layout';
import type { LadBlock, Network } from '../../frontend/src/lad/model';
import { spliceText } from '../../frontend/src/lad/textEdit';

const root = path.resolve(__dirname, '../..');
const fixture = JSON.parse(fs.readFileSync(path.join(__dirname, 'fixtures/lad-parity.json'), 'utf8')) as {
  entries: { name: string; blocks: LadBlock[] }[];
};
const examples = fixture.entries.filter((entry) => entry.name.startsWith('examples/lad/'));

/** Whether two rectangles share interior (touching edges do not count). */
function overlap(a: Rect, b: Rect): boolean {
  const eps = 0.5;
  return a.x + eps < b.x + b.width && b.x + eps < a.x + a.width && a.y + eps < b.y + b.height && b.y + eps < a.y + a.height;
}

/** Whether an axis-parallel segment passes through a rectangle's interior. */
function crosses(from: { x: number; y: number }, to: { x: number; y: number }, box: Rect): boolean {
  const eps = 0.5;
  const left = Math.min(from.x, to.x);
  const right = Math.max(from.x, to.x);
  const top = Math.min(from.y, to.y);
  const bottom = Math.max(from.y, to.y);
  return left < box.x + box.width - eps && right > box.x + eps && top < box.y + box.height - eps && bottom > box.y + eps;
}

function pairs<T>(items: readonly T[]): [T, T][] {
  const out: [T, T][] = [];
  items.forEach((a, k) => items.slice(k + 1).forEach((b) => out.push([a, b])));
  return out;
}

function drawnNetworks(): { name: string; network: Network }[] {
  return examples.flatMap((entry) =>
    entry.blocks.flatMap((block) => block.networks.map((network, k) => ({ name: `${entry.name} network ${k + 1}`, network }))).filter(({ network }) => network.stl === null),
  );
}

describe('examples/lad in the editor', () => {
  it('has every example file in the fixture', () => {
    const files = fs.readdirSync(path.join(root, 'examples/lad')).filter((name) => /\.(lad|fbd)$/.test(name));
    expect(examples.map((entry) => path.basename(entry.name)).sort()).toEqual(files.sort());
    expect(files.length).toBeGreaterThan(20);
  });

  it.each(drawnNetworks())('$name: LAD elements do not overlap and no wire crosses an element', ({ network }) => {
    const layout = ladLayout(network);
    const rects = layout.cells.map((cell) => ({ id: cell.id, rect: cellRect(cell) }));
    for (const [a, b] of pairs(rects)) expect(overlap(a.rect, b.rect), `${a.id} and ${b.id}`).toBe(false);
    for (const wire of layout.wires) {
      const from = { x: columnX(wire.from_column), y: wireY(wire.row) };
      const to = { x: columnX(wire.to_column), y: wireY(wire.row) };
      for (const { id, rect } of rects) expect(crosses(from, to, rect), `wire on row ${wire.row} crosses ${id}`).toBe(false);
    }
    for (const link of layout.links) {
      const from = { x: columnX(link.column), y: wireY(link.from_row) };
      const to = { x: columnX(link.column), y: wireY(link.to_row) };
      for (const { id, rect } of rects) expect(crosses(from, to, rect), `link at column ${link.column} crosses ${id}`).toBe(false);
    }
    expect(CELL_W * layout.columns).toBeGreaterThan(0);
    expect(ROW_H * Math.max(layout.rows, 1)).toBeGreaterThan(0);
  });

  it.each(drawnNetworks())('$name: FBD boxes laid out by elkjs do not overlap and no wire crosses a box', async ({ network }) => {
    const graph = fbdLayout(toFbd(network));
    const geometry: FbdGeometry = placed(graph, await runLayout(elkGraph(graph)));
    expect(geometry.nodes.length).toBe(graph.nodes.length);
    const boxes = geometry.nodes.map((node) => ({ id: node.node.id, rect: { x: node.x, y: node.y, width: node.width, height: node.height } }));
    for (const [a, b] of pairs(boxes)) expect(overlap(a.rect, b.rect), `${a.id} and ${b.id}`).toBe(false);
    // The operands written at pins: clear of every box, and no wire runs through them.
    const labels = geometry.nodes.flatMap((node) => [...node.ports.values()].flatMap((port) => (port.label ? [{ id: port.id, rect: port.label }] : [])));
    for (const label of labels) for (const box of boxes) expect(overlap(label.rect, box.rect), `the operand at ${label.id} and ${box.id}`).toBe(false);
    for (const edge of geometry.edges) {
      edge.points.slice(1).forEach((point, k) => {
        for (const label of labels) expect(crosses(edge.points[k]!, point, label.rect), `${edge.id} crosses the operand at ${label.id}`).toBe(false);
      });
    }
    for (const edge of geometry.edges) {
      const target = graph.edges.find((e) => e.id === edge.id)?.target;
      expect(edge.points.length, `${edge.id} is routed`).toBeGreaterThanOrEqual(2);
      edge.points.slice(1).forEach((point, k) => {
        const from = edge.points[k]!;
        for (const { id, rect } of boxes) {
          if (id === edge.source || id === target) continue;
          expect(crosses(from, point, rect), `${edge.id} crosses ${id}`).toBe(false);
        }
      });
    }
  });

  it.each(examples.map((entry) => ({ name: entry.name, blocks: entry.blocks })))('$name opens and saves unchanged to the same text', ({ name, blocks }) => {
    const text = fs.readFileSync(path.join(root, name), 'utf8');
    expect(spliceText(text, blocks, blocks)).toBe(text);
    // An edit of the first network and its undo leave every other line as it was.
    const first = blocks[0];
    if (!first || first.networks.length === 0) return;
    const edited: LadBlock[] = [{ ...first, networks: [{ ...first.networks[0]!, title: 'changed' }, ...first.networks.slice(1)] }, ...blocks.slice(1)];
    const changed = spliceText(text, blocks, edited);
    expect(changed).toContain('TITLE = changed');
    const back = spliceText(changed, edited, blocks).split('\n');
    const original = text.split('\n');
    expect(back.length).toBe(original.length);
    const differing = original.filter((line, k) => line !== back[k]);
    // Only lines of the first network may differ (it was printed again).
    for (const line of differing) expect(line.trim().length).toBeGreaterThan(0);
  });
});

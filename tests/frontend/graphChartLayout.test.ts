/**
 * THE LAYOUT TEST of the S7-Graph chart (frontend/src/graph/chartGraph.ts): every sequencer of
 * every course source (tests/scenarios/graph/*.graph, read by the Python reader into
 * fixtures/graph-chart.json by fixtures/make_graph_chart.py) laid out by elkjs as the worker does
 * it: no two boxes overlap, no edge passes through a box it does not connect, every edge starts
 * and ends on its own boxes, every step and transition is drawn exactly once, and the branch
 * lines are where S7-Graph draws them.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { runLayout } from '../../frontend/src/diagram/elk/runLayout';
import { layoutSequencer, sequencerGraph, stepNode, transitionNode, type Box, type ChartLayout } from '../../frontend/src/graph/chartGraph';
import type { GraphBlock, Sequencer } from '../../frontend/src/graph/model';

const fixture = JSON.parse(fs.readFileSync(path.resolve(__dirname, 'fixtures/graph-chart.json'), 'utf8')) as {
  files: Record<string, GraphBlock[]>;
  generated: Record<string, GraphBlock[]>;
};
const chain = fixture.generated['chain200.graph']![0]!.sequencers[0]!;
const sequencers: [string, Sequencer][] = [];
for (const [file, blocks] of Object.entries(fixture.files)) {
  for (const block of blocks) for (const sequencer of block.sequencers) sequencers.push([`${file} ${block.name} ${sequencer.name}`, sequencer]);
}

const EPS = 0.5;

function overlap(a: Box, b: Box): boolean {
  return a.x < b.x + b.width - EPS && b.x < a.x + a.width - EPS && a.y < b.y + b.height - EPS && b.y < a.y + a.height - EPS;
}

function onBorder(point: { x: number; y: number }, box: Box): boolean {
  const inX = point.x >= box.x - EPS && point.x <= box.x + box.width + EPS;
  const inY = point.y >= box.y - EPS && point.y <= box.y + box.height + EPS;
  const atX = Math.abs(point.x - box.x) < EPS || Math.abs(point.x - box.x - box.width) < EPS;
  const atY = Math.abs(point.y - box.y) < EPS || Math.abs(point.y - box.y - box.height) < EPS;
  return inX && inY && (atX || atY);
}

/** Does the axis-parallel segment a-b pass through the inside of the box? */
function crosses(a: { x: number; y: number }, b: { x: number; y: number }, box: Box): boolean {
  const x1 = Math.min(a.x, b.x);
  const x2 = Math.max(a.x, b.x);
  const y1 = Math.min(a.y, b.y);
  const y2 = Math.max(a.y, b.y);
  return x1 < box.x + box.width - EPS && x2 > box.x + EPS && y1 < box.y + box.height - EPS && y2 > box.y + EPS;
}

function boxes(chart: ChartLayout): Map<string, Box> {
  const all = new Map<string, Box>();
  for (const placed of chart.steps) all.set(stepNode(placed.step.name), placed);
  for (const placed of chart.transitions) all.set(transitionNode(placed.transition.name), placed);
  return all;
}

describe('the sequencer chart layout', () => {
  it('has every course source to lay out', () => {
    expect(Object.keys(fixture.files).length).toBe(34);
    expect(sequencers.length).toBeGreaterThanOrEqual(34);
  });

  it.each([...sequencers, ['the 200-step bench sequencer', chain] as [string, Sequencer]])('%s: boxes apart, edges on their own boxes only, everything once', { timeout: 60_000 }, async (_name, sequencer) => {
    const chart = await layoutSequencer(sequencer, runLayout);
    // Every step and transition exactly once.
    expect(chart.steps.map((s) => s.step.name).sort()).toEqual(sequencer.steps.map((s) => s.name).sort());
    expect(chart.transitions.map((t) => t.transition.name).sort()).toEqual(sequencer.transitions.map((t) => t.name).sort());
    const all = boxes(chart);
    expect(all.size).toBe(sequencer.steps.length + sequencer.transitions.length);
    const list = [...all.entries()];
    // Findings are collected, not asserted one by one: a 200-step chart has a million checks.
    const wrong: string[] = [];
    for (const [id, box] of list) {
      if (!(box.width > 0) || box.x + box.width > chart.width + EPS || box.y + box.height > chart.height + EPS) wrong.push(`${id} outside the chart`);
    }
    for (let i = 0; i < list.length; i += 1) {
      for (let j = i + 1; j < list.length; j += 1) {
        if (overlap(list[i]![1], list[j]![1])) wrong.push(`${list[i]![0]} overlaps ${list[j]![0]}`);
      }
    }
    // One edge per source of a transition and per target of a transition that is not a jump or an end.
    const expected = sequencer.transitions.reduce((n, t) => n + t.source.length + (t.jump ? 0 : t.target.length), 0);
    expect(chart.edges.length).toBe(expected);
    for (const edge of chart.edges) {
      const from = all.get(edge.from)!;
      const to = all.get(edge.to)!;
      if (edge.points.length < 2) {
        wrong.push(`${edge.id} has no route`);
        continue;
      }
      if (!onBorder(edge.points[0]!, from)) wrong.push(`${edge.id} does not start on ${edge.from}`);
      if (!onBorder(edge.points[edge.points.length - 1]!, to)) wrong.push(`${edge.id} does not end on ${edge.to}`);
      for (let k = 1; k < edge.points.length; k += 1) {
        const a = edge.points[k - 1]!;
        const b = edge.points[k]!;
        if (!(Math.abs(a.x - b.x) < EPS || Math.abs(a.y - b.y) < EPS)) wrong.push(`${edge.id} is not orthogonal`);
        for (const [id, box] of list) {
          if (id !== edge.from && id !== edge.to && crosses(a, b, box)) wrong.push(`${edge.id} crosses ${id}`);
        }
      }
    }
    expect(wrong).toEqual([]);
  });

  it('draws each branch with its own line: single for alternatives, double for simultaneous', async () => {
    const alternative = sequencers.find(([name]) => name.startsWith('g02b'))![1];
    const simultaneous = sequencers.find(([name]) => name.startsWith('g02c'))![1];
    const alt = await layoutSequencer(alternative, runLayout);
    const sim = await layoutSequencer(simultaneous, runLayout);
    expect(alt.branches.some((b) => b.kind === 'alternative')).toBe(true);
    expect(alt.branches.some((b) => b.kind === 'simultaneous')).toBe(false);
    // g02c: Trans1 opens Step2 and Step6 together, Trans2 joins Step2 and Step7.
    const kinds = sim.branches.filter((b) => b.kind === 'simultaneous');
    expect(kinds.length).toBe(2);
    const trans1 = sim.transitions.find((t) => t.transition.name === 'Trans1')!;
    const trans2 = sim.transitions.find((t) => t.transition.name === 'Trans2')!;
    // The divergence line is under Trans1, the convergence line over Trans2.
    expect(kinds.some((b) => b.y > trans1.y + trans1.height - EPS && b.y < trans2.y)).toBe(true);
    expect(kinds.some((b) => b.y < trans2.y + EPS && b.y > trans1.y + trans1.height)).toBe(true);
    for (const line of kinds) expect(line.x2 - line.x1).toBeGreaterThan(40);
  });

  it('is deterministic: the same sequencer gives the same graph and the same drawing', async () => {
    const [, sequencer] = sequencers.find(([name]) => name.startsWith('g17'))!;
    expect(JSON.stringify(sequencerGraph(sequencer))).toBe(JSON.stringify(sequencerGraph(structuredClone(sequencer))));
    const a = await layoutSequencer(sequencer, runLayout);
    const b = await layoutSequencer(structuredClone(sequencer), runLayout);
    expect(b).toEqual(a);
  });

  it('draws a jump as an arrow in its transition, not as an edge back up the chart', async () => {
    const [, sequencer] = sequencers.find(([name]) => name.startsWith('g02a'))!;
    const jumps = sequencer.transitions.filter((t) => t.jump);
    expect(jumps.length).toBeGreaterThan(0);
    const chart = await layoutSequencer(sequencer, runLayout);
    for (const jump of jumps) {
      expect(chart.edges.some((e) => e.from === transitionNode(jump.name))).toBe(false);
      const placed = chart.transitions.find((t) => t.transition.name === jump.name)!;
      expect(placed.jumpTo?.name).toBe(jump.target[0]);
    }
  });
});

/**
 * One sequencer as the chart draws it, S7-Graph's way: top to bottom, a step box, below it a
 * short transition bar with its condition written small beside it, then the next step.
 *
 * The sequencer becomes an elkjs graph (layered, downwards, the diagram layer's one set of
 * options) whose nodes are the steps and the transitions, so the layout never puts a box on a
 * box. Branches come from the ports: every edge leaving a step leaves from its one bottom port
 * and every edge entering a transition's top port arrives at one point, and elkjs routes the
 * edges of a port together along one horizontal segment. That segment is the branch line:
 * single where a step opens (alternative) or a step is entered from several transitions
 * (alternative closing), double where a transition has several targets (simultaneous
 * divergence) or sources (simultaneous convergence). A jump is no edge at all but an arrow
 * inside its transition's node, labelled with the target, and a sequence end a short stop
 * line there: long back edges across the chart would hide the sequence they return to.
 *
 * Speed (a 200-step sequencer opens in under a second): a straight run of the chart (step,
 * transition, step, ... with no branch in between) has one drawing only, so it is ONE elkjs node
 * and is unpacked into its boxes and straight edges afterwards (`chartRuns`, `placeChart`). elkjs
 * then lays out 43 nodes instead of 406 for the bench's chart: 0.1-0.25 s in the browser's worker
 * instead of 1.5-1.9 s, with the same guarantees (the layout test). Cheaper elkjs options (other
 * node placement, polyline routing, no model order) were measured too: 10-15 % at best, within
 * the noise next to that, so the diagram layer's options (and S7-Graph's branch order) stay.
 */
import type { ElkExtendedEdge, ElkNode, ElkPoint } from 'elkjs/lib/elk-api';
import { LAYERED_OPTIONS } from '../diagram/elk/options';
import type { Element } from '../lad/model';
import type { Sequencer, Series, Step, Transition } from './model';

/** The step box, the row under it for its active time, and where its edges meet it. */
export const STEP_W = 128;
/** Where a step's name starts in its box, and how many of its characters are written (the tooltip has it all). */
export const STEP_NAME_X = 44;
const STEP_NAME_CHARS = 24;
export const STEP_BOX_H = 36;
const STEP_TIME_H = 16;
export const STEP_H = STEP_BOX_H + STEP_TIME_H;
/** The transition: its bar's centre line, the bar's half width, the condition's start. */
export const TRANS_X = 20;
export const TRANS_BAR = 14;
export const TRANS_TEXT_X = 44;
export const TRANS_H = 26;
/** The extra height below a jump's bar (arrow and target) and a sequence end's stop line. */
const JUMP_H = 34;
const END_H = 18;
/** Characters of a condition written beside its bar before it is cut (the tooltip has it all). */
export const CONDITION_CHARS = 36;
/** Width of one character of the chart's small monospace text. */
export const CHAR_W = 6.7;

/** The gap between a box and the next one down (elkjs's gap between layers). */
const LAYER_GAP = 22;

const CHART_OPTIONS = {
  ...LAYERED_OPTIONS,
  'elk.direction': 'DOWN',
  // The chart's order is S7-Graph's: branches left to right by priority, as the model lists them.
  // No crossing minimisation keeps it (and saves a third of the layout time of a long chart).
  'elk.layered.crossingMinimization.strategy': 'NONE',
  'elk.spacing.nodeNode': '36',
  'elk.layered.spacing.nodeNodeBetweenLayers': String(LAYER_GAP),
  'elk.layered.spacing.edgeNodeBetweenLayers': '12',
  'elk.padding': '[top=16,left=16,bottom=16,right=16]',
};
const PORTS = { 'elk.portConstraints': 'FIXED_POS' };

export function stepNode(name: string): string {
  return `s:${name}`;
}
export function transitionNode(name: string): string {
  return `t:${name}`;
}

/** A condition in a line of text: contacts in series `&`, parallel branches `( | )`, NC contacts `/`. */
export function conditionText(series: Series | null): string {
  if (!series || series.elements.length === 0) return '';
  return seriesText(series);
}

function seriesText(series: Series): string {
  return series.elements.map((element) => elementText(element) ?? '?').join(' & ');
}

function elementText(element: Element): string | undefined {
  switch (element.kind) {
    case 'contact':
      return `${element.negated ? '/' : ''}${element.operand}`;
    case 'status':
      return `${element.negated ? '/' : ''}${element.bit}`;
    case 'not':
      return 'NOT';
    case 'edge':
      return `${element.edge}(${element.memory})`;
    case 'midline':
      return `#(${element.operand})`;
    case 'box':
      return boxText(element.name, element.inputs);
    case 'parallel':
      return `(${element.branches.map(seriesText).join(' | ')})`;
  }
}

function boxText(name: string, inputs: Record<string, string | Series>): string {
  const args = Object.entries(inputs)
    .filter(([pin]) => pin !== 'EN')
    .map(([, value]) => (typeof value === 'string' ? value : seriesText(value)));
  return `${name}(${args.join(', ')})`;
}

/** A step's name as written in its box. */
export function stepName(name: string): string {
  return name.length > STEP_NAME_CHARS ? `${name.slice(0, STEP_NAME_CHARS - 1)}…` : name;
}

/** A step box wide enough for its name. */
export function stepWidth(step: Step): number {
  return Math.max(STEP_W, Math.ceil(STEP_NAME_X + stepName(step.name).length * CHAR_W + 14));
}

/** The condition as drawn beside the bar: cut after CONDITION_CHARS characters. */
export function shortCondition(text: string): string {
  return text.length > CONDITION_CHARS ? `${text.slice(0, CONDITION_CHARS - 1)}…` : text;
}

export function transitionLabel(transition: Transition): string {
  const condition = conditionText(transition.condition);
  return `T${transition.number}${condition ? `  ${shortCondition(condition)}` : ''}`;
}

/** What a jump's arrow says: the target's number and name. */
export function jumpLabel(target: string, number: number | null): string {
  return number === null ? `→ ${target}` : `→ S${number} ${target}`;
}

function transitionSize(transition: Transition, numbers: ReadonlyMap<string, number>): { width: number; height: number } {
  const label = transitionLabel(transition);
  const target = transition.target[0] ?? '';
  const jump = transition.jump ? jumpLabel(target, numbers.get(target) ?? null).length - TRANS_TEXT_X / CHAR_W + 4 : 0;
  const width = TRANS_TEXT_X + Math.max(label.length, jump) * CHAR_W + 6;
  const height = TRANS_H + (transition.jump ? JUMP_H : transition.target.length === 0 ? END_H : 0);
  return { width: Math.ceil(width), height };
}

/** Steps and transitions in chart order: each step followed by the transitions that leave it. */
export function chartOrder(sequencer: Sequencer): (Step | Transition)[] {
  const order: (Step | Transition)[] = [];
  const placed = new Set<string>();
  const leaving = new Map<string, Transition[]>();
  for (const transition of sequencer.transitions) {
    const last = transition.source[transition.source.length - 1];
    if (last === undefined) continue;
    const list = leaving.get(last) ?? [];
    list.push(transition);
    leaving.set(last, list);
  }
  for (const step of sequencer.steps) {
    order.push(step);
    for (const transition of leaving.get(step.name) ?? []) {
      order.push(transition);
      placed.add(transition.name);
    }
  }
  for (const transition of sequencer.transitions) if (!placed.has(transition.name)) order.push(transition);
  return order;
}

function isStep(item: Step | Transition): item is Step {
  return 'actions' in item;
}

/** A step or transition as elkjs sees it: its box, and the x of the line its edges meet it on. */
interface ChartItem {
  id: string;
  width: number;
  height: number;
  /** x of the top and bottom ports in the box: a step's middle, a transition's bar. */
  axis: number;
  /** Whether edges leave it downwards (not a jump, not a sequence end). */
  south: boolean;
}

/**
 * A straight run of the chart: step, its only transition, that transition's only target step,
 * and so on, for as long as nothing joins or leaves in between. A run has one drawing only (its
 * boxes one under the other on one axis, a layer gap apart), so it goes to elkjs as ONE node and
 * elkjs lays out just the branches between runs: a 200-step chain of a few branches is some 40
 * nodes instead of 400, which takes elkjs a tenth of the time (the layered algorithm grows faster
 * than the number of layers) and is what lets such a chart open in well under a second.
 */
interface Run {
  id: string;
  items: ChartItem[];
  /** Each item's offset in the run's node. */
  offsets: { x: number; y: number }[];
  width: number;
  height: number;
  axis: number;
}

function chartItems(sequencer: Sequencer): { items: ChartItem[]; edges: ElkExtendedEdge[] } {
  const numbers = new Map(sequencer.steps.map((step) => [step.name, step.number]));
  const steps = new Set(numbers.keys());
  const items: ChartItem[] = [];
  const edges: ElkExtendedEdge[] = [];
  for (const item of chartOrder(sequencer)) {
    if (isStep(item)) {
      const width = stepWidth(item);
      items.push({ id: stepNode(item.name), width, height: STEP_H, axis: width / 2, south: true });
      continue;
    }
    const id = transitionNode(item.name);
    const { width, height } = transitionSize(item, numbers);
    const south = !item.jump && item.target.length > 0;
    items.push({ id, width, height, axis: TRANS_X, south });
    for (const source of item.source) {
      if (!steps.has(source)) continue;
      edges.push({ id: `e:${source}>${item.name}`, sources: [`${stepNode(source)}.S`], targets: [`${id}.N`] });
    }
    if (south) {
      for (const target of item.target) {
        if (!steps.has(target)) continue;
        edges.push({ id: `e:${item.name}>${target}`, sources: [`${id}.S`], targets: [`${stepNode(target)}.N`] });
      }
    }
  }
  return { items, edges };
}

function nodeOf(port: string): string {
  return port.replace(/\.[NS]$/, '');
}

/** The sequencer's runs in chart order, and the edges inside them (drawn straight, not by elkjs). */
function chartRuns(sequencer: Sequencer): { runs: Run[]; edges: ElkExtendedEdge[]; inside: Set<string> } {
  const { items, edges } = chartItems(sequencer);
  const leaving = new Map<string, ElkExtendedEdge[]>();
  const entering = new Map<string, number>();
  for (const edge of edges) {
    const from = nodeOf(edge.sources[0]!);
    leaving.set(from, [...(leaving.get(from) ?? []), edge]);
    const to = nodeOf(edge.targets[0]!);
    entering.set(to, (entering.get(to) ?? 0) + 1);
  }
  // The one edge on to the next item of a run: the only edge leaving, into an item entered only by it.
  const next = new Map<string, ElkExtendedEdge>();
  const hasPrevious = new Set<string>();
  for (const [from, out] of leaving) {
    const only = out.length === 1 ? out[0]! : null;
    if (only && entering.get(nodeOf(only.targets[0]!)) === 1 && nodeOf(only.targets[0]!) !== from) {
      next.set(from, only);
      hasPrevious.add(nodeOf(only.targets[0]!));
    }
  }
  const byId = new Map(items.map((item) => [item.id, item]));
  const taken = new Set<string>();
  const inside = new Set<string>();
  const runs: Run[] = [];
  const follow = (first: ChartItem): Run => {
    const members: ChartItem[] = [first];
    taken.add(first.id);
    for (let edge = next.get(first.id); edge; ) {
      const item = byId.get(nodeOf(edge.targets[0]!));
      if (!item || taken.has(item.id)) break; // a closed loop: its last edge is an ordinary one
      inside.add(edge.id!);
      members.push(item);
      taken.add(item.id);
      edge = next.get(item.id);
    }
    const axis = Math.max(...members.map((item) => item.axis));
    const offsets: { x: number; y: number }[] = [];
    let y = 0;
    let width = 0;
    for (const item of members) {
      offsets.push({ x: axis - item.axis, y });
      width = Math.max(width, axis - item.axis + item.width);
      y += item.height + LAYER_GAP;
    }
    const id = members.length === 1 ? first.id : `run:${first.id}`;
    return { id, items: members, offsets, width, height: y - LAYER_GAP, axis };
  };
  // Runs start where nothing leads straight in; a loop with no such start is cut at its first item.
  const started = new Map<string, Run>();
  for (const item of items) if (!hasPrevious.has(item.id)) started.set(item.id, follow(item));
  for (const item of items) if (!taken.has(item.id)) started.set(item.id, follow(item));
  for (const item of items) {
    const run = started.get(item.id);
    if (run) runs.push(run);
  }
  return { runs, edges, inside };
}

/** The elkjs graph of a sequencer (the same sequencer always gives the same graph, hence the same drawing). */
export function sequencerGraph(sequencer: Sequencer): ElkNode {
  const { runs, edges, inside } = chartRuns(sequencer);
  const children: ElkNode[] = runs.map((run) => {
    const first = run.items[0]!;
    const last = run.items[run.items.length - 1]!;
    const ports = [{ id: `${first.id}.N`, x: run.axis, y: 0, width: 0, height: 0, layoutOptions: { 'elk.port.side': 'NORTH' } }];
    if (last.south) ports.push({ id: `${last.id}.S`, x: run.axis, y: run.height, width: 0, height: 0, layoutOptions: { 'elk.port.side': 'SOUTH' } });
    return { id: run.id, width: run.width, height: run.height, layoutOptions: PORTS, ports };
  });
  return { id: `seq:${sequencer.name}`, layoutOptions: CHART_OPTIONS, children, edges: edges.filter((edge) => !inside.has(edge.id!)) };
}

// -- the laid-out chart --------------------------------------------------------------------------

export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

export interface PlacedStep extends Box {
  step: Step;
}

export interface PlacedTransition extends Box {
  transition: Transition;
  /** The jump's target step (its number), when the transition is a jump. */
  jumpTo: Step | null;
}

export interface PlacedEdge {
  id: string;
  from: string;
  to: string;
  points: ElkPoint[];
}

/** A branch line: single (alternative) or double (simultaneous), horizontal at y. */
export interface BranchLine {
  kind: 'alternative' | 'simultaneous';
  y: number;
  x1: number;
  x2: number;
}

export interface ChartLayout {
  width: number;
  height: number;
  steps: PlacedStep[];
  transitions: PlacedTransition[];
  edges: PlacedEdge[];
  branches: BranchLine[];
}

function pointsOf(edge: ElkExtendedEdge): ElkPoint[] {
  const section = edge.sections?.[0];
  if (!section) return [];
  return [section.startPoint, ...(section.bendPoints ?? []), section.endPoint];
}

/**
 * The branch line of edges meeting at one port: the horizontal run they share, widened to take
 * in every edge of the group (a straight edge included).
 */
function branchLine(group: readonly ElkPoint[][], outgoing: boolean, kind: BranchLine['kind']): BranchLine | null {
  let y: number | null = null;
  for (const points of group) {
    if (points.length < 3) continue;
    // The first bend of an edge leaving the port, the last of an edge arriving at it.
    const bend = outgoing ? points[1] : points[points.length - 2];
    if (bend) {
      y = bend.y;
      break;
    }
  }
  if (y === null) return null;
  let x1 = Infinity;
  let x2 = -Infinity;
  for (const points of group) {
    for (let k = 1; k < points.length; k += 1) {
      const a = points[k - 1]!;
      const b = points[k]!;
      const low = Math.min(a.y, b.y);
      const high = Math.max(a.y, b.y);
      if (low - 0.5 <= y && y <= high + 0.5) {
        if (Math.abs(a.y - b.y) < 0.5) {
          x1 = Math.min(x1, a.x, b.x);
          x2 = Math.max(x2, a.x, b.x);
        } else {
          x1 = Math.min(x1, a.x);
          x2 = Math.max(x2, a.x);
        }
      }
    }
  }
  if (!(x2 - x1 > 0.5)) return null;
  return { kind, y, x1, x2 };
}

/** Where elkjs put everything, in the terms the chart draws: each run's boxes and straight edges unpacked. */
export function placeChart(sequencer: Sequencer, laid: ElkNode): ChartLayout {
  const { runs, edges: all, inside } = chartRuns(sequencer);
  const nodes = new Map((laid.children ?? []).map((node) => [node.id, node]));
  const boxes = new Map<string, Box>();
  for (const run of runs) {
    const node = nodes.get(run.id);
    run.items.forEach((item, k) => {
      const offset = run.offsets[k]!;
      boxes.set(item.id, { x: (node?.x ?? 0) + offset.x, y: (node?.y ?? 0) + offset.y, width: item.width, height: item.height });
    });
  }
  const stepsByName = new Map(sequencer.steps.map((step) => [step.name, step]));
  const boxOf = (id: string): Box => boxes.get(id) ?? { x: 0, y: 0, width: 0, height: 0 };
  const steps = sequencer.steps.map((step) => ({ step, ...boxOf(stepNode(step.name)) }));
  const transitions = sequencer.transitions.map((transition) => ({
    transition,
    jumpTo: transition.jump ? stepsByName.get(transition.target[0] ?? '') ?? null : null,
    ...boxOf(transitionNode(transition.name)),
  }));
  const routed = new Map((laid.edges ?? []).map((edge) => [edge.id, edge]));
  const edges: PlacedEdge[] = [];
  const leaving = new Map<string, ElkPoint[][]>();
  const arriving = new Map<string, ElkPoint[][]>();
  for (const edge of all) {
    const from = edge.sources[0] ?? '';
    const to = edge.targets[0] ?? '';
    let points: ElkPoint[];
    if (inside.has(edge.id!)) {
      // Inside a run: straight down from the middle of one box's bottom to the next box's top.
      const a = boxOf(nodeOf(from));
      const b = boxOf(nodeOf(to));
      const x = b.x + (to.startsWith('t:') ? TRANS_X : b.width / 2);
      points = [{ x, y: a.y + a.height }, { x, y: b.y }];
    } else {
      const laidEdge = routed.get(edge.id!);
      points = laidEdge ? pointsOf(laidEdge) : [];
    }
    edges.push({ id: edge.id!, from: nodeOf(from), to: nodeOf(to), points });
    leaving.set(from, [...(leaving.get(from) ?? []), points]);
    arriving.set(to, [...(arriving.get(to) ?? []), points]);
  }
  const branches: BranchLine[] = [];
  for (const [port, group] of leaving) {
    if (group.length < 2) continue;
    const line = branchLine(group, true, port.startsWith('t:') ? 'simultaneous' : 'alternative');
    if (line) branches.push(line);
  }
  for (const [port, group] of arriving) {
    if (group.length < 2) continue;
    const line = branchLine(group, false, port.startsWith('t:') ? 'simultaneous' : 'alternative');
    if (line) branches.push(line);
  }
  return { width: laid.width ?? 0, height: laid.height ?? 0, steps, transitions, edges, branches };
}

/** The laid-out chart of a sequencer, with the layout function the caller runs (the worker in the page). */
export async function layoutSequencer(sequencer: Sequencer, layout: (graph: ElkNode) => Promise<ElkNode>): Promise<ChartLayout> {
  return placeChart(sequencer, await layout(sequencerGraph(sequencer)));
}

/**
 * A chart of `steps` steps in a chain with alternative branches every few steps, a simultaneous
 * branch and a jump back, laid out a few times in the worker while a page with `.graph` files is
 * idle: elkjs runs several times slower until V8 has compiled its code, and the user's first chart
 * should not wait for that. Its branches matter: straight runs become one node each
 * (`chartRuns`), so only a chart with many branches gives elkjs a graph of a real chart's size.
 */
export function warmUpSequencer(steps = 40): Sequencer {
  const step = (k: number): Step => ({ number: k, name: `Step${k}`, initial: k === 1, comment: '', interlock: null, supervision: null, actions: [] });
  const condition: Series = { elements: [{ id: 'e1', kind: 'contact', operand: 'M 0.0', negated: false }] };
  let number = 0;
  const transitions: Transition[] = [];
  const transition = (source: string[], target: string[], jump = false): void => {
    number += 1;
    transitions.push({ number, name: `Trans${number}`, comment: '', source, target, jump, condition });
  };
  for (let k = 1; k < steps; k += 1) {
    if (k === 5) transition([`Step${k}`], [`Step${k + 1}`, `Step${k + 2}`]);
    else if (k === 6) continue;
    else if (k === 7) transition([`Step${k - 1}`, `Step${k}`], [`Step${k + 1}`]);
    else transition([`Step${k}`], [`Step${k + 1}`]);
    // An alternative branch skipping a step, every third step after the simultaneous one.
    if (k >= 8 && k % 3 === 2 && k + 2 <= steps) transition([`Step${k}`], [`Step${k + 2}`]);
  }
  transition(['Step2'], ['Step4']);
  transition([`Step${steps}`], ['Step1'], true);
  return { name: 'warm-up', comment: '', steps: Array.from({ length: steps }, (_, k) => step(k + 1)), transitions };
}

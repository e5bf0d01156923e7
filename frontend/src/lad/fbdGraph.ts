/**
 * A layered description of an FBD network, ready for elkjs (`elk.layered`) or direct drawing. A
 * port of backend/nasaq/lang/lad/layout_fbd.py (`fbd_layout`), held equal to it by
 * tests/frontend/ladParity.test.ts.
 *
 * Operands are not boxes: an operand (or status bit) is the label of the pin it feeds. Boxes are
 * nodes with ports (WEST inputs, EAST outputs, numbered from the top), wires are edges from an
 * output port to an input port; the common logic feeds every output through its own edge, and the
 * `flow` of an OR box feeds the first pin of each of its branches. Layers come from the longest
 * path to an output (final boxes in the last layer); within a layer nodes are ordered by first
 * visit, walking the outputs and each box's inputs top-down, so a network always gives the same
 * layout. A network being drawn without outputs ends at its common logic, the last layer (a lone
 * operand is a node without a box, its text and negation on its output port); an empty one has no
 * nodes. The walk tells nodes apart by object identity, as the Python walk does by `id()`.
 */
import { boxSpec, flowPins } from './boxes';
import type { FbdFinal, FbdLayout, FbdLayoutEdge, FbdLayoutNode, FbdLogic, FbdNetwork, FbdNode, FbdPort } from './model';

type Node = FbdNode | FbdFinal;
type Pin = readonly [name: string, value: string | FbdNode | null];

const TITLES = { AND: '&', OR: '>=1', XOR: 'XOR' } as const;
const OTHER_TITLES: Readonly<Record<string, string>> = { not: 'NOT', ret: 'RET', opn: 'OPN' };

/**
 * The node's input pins in drawing order, each with its operand text or feeding node (null: a pin
 * of a catalogued box nothing is connected to; such a box shows all its pins in catalogue order).
 */
function inputsOf(node: Node): Pin[] {
  switch (node.kind) {
    case 'logic':
      return node.inputs.map((item, index) => [`IN${index + 1}`, item] as const);
    case 'box': {
      const flowIn = flowPins(node.name)[0] ?? 'EN';
      const spec = boxSpec(node.name);
      const names = spec ? spec.inputs.filter((pin) => pin.name !== flowIn).map((pin) => pin.name) : [];
      for (const name of Object.keys(node.inputs)) if (!names.includes(name)) names.push(name);
      const pins: Pin[] = names.map((name) => [name, node.inputs[name] ?? null] as const);
      return node.en === null ? pins : [[flowIn, node.en], ...pins];
    }
    case 'operand':
    case 'status':
    case 'branch':
      return [];
    default:
      return [['IN', node.input]];
  }
}

/** The node's output pins, each with the operand written at it. */
function outputsOf(node: Node): [string, string | null][] {
  switch (node.kind) {
    // An operand is a node only as the lone logic of a network without outputs.
    case 'operand':
      return [['OUT', node.operand]];
    case 'status':
      return [['OUT', node.bit]];
    case 'box': {
      const flowOut = flowPins(node.name)[1] ?? 'OUT';
      const spec = boxSpec(node.name);
      const names = spec ? spec.outputs.filter((pin) => pin.name !== flowOut).map((pin) => pin.name) : [];
      for (const name of Object.keys(node.outputs)) if (name !== flowOut && !names.includes(name)) names.push(name);
      return [[flowOut, node.outputs[flowOut] ?? null], ...names.map((name) => [name, node.outputs[name] ?? null] as [string, string | null])];
    }
    case 'assign':
    case 'jump':
    case 'ret':
    case 'opn':
      return [];
    default:
      return [['OUT', null]];
  }
}

/** What is written in the box. */
function titleOf(node: Node): string {
  switch (node.kind) {
    case 'operand':
    case 'status':
      return ''; // no box: the operand is written at its output
    case 'logic':
      return TITLES[node.op];
    case 'box':
      return node.instance === null ? node.name : `${node.instance} ${node.name}`;
    case 'assign':
      return node.coil;
    case 'jump':
      return node.negated ? 'JMPN' : 'JMP';
    case 'midline':
      return '#';
    case 'edge':
      return node.edge;
    default:
      return OTHER_TITLES[node.kind] ?? node.kind;
  }
}

/** The operand written above the box (the coil's bit, the midline's, the edge memory ...). */
function operandOf(node: Node): string | null {
  switch (node.kind) {
    case 'assign':
    case 'midline':
      return node.operand;
    case 'edge':
      return node.memory;
    case 'jump':
      return node.label;
    case 'opn':
      return node.block;
    default:
      return null;
  }
}

/** A node no box is drawn for: text, an operand or a status bit on a pin, an open T-branch. */
function isPinLabel(fed: string | FbdNode): boolean {
  return typeof fed === 'string' || fed.kind === 'operand' || fed.kind === 'status' || fed.kind === 'branch';
}

/** The walk from the outputs: each node's longest path to an output, its name, its first visit. */
class Layering {
  readonly logic: FbdNode;
  readonly depth = new Map<Node, number>();
  readonly first: Node[] = [];
  readonly ids = new Map<Node, string>();
  readonly inLogic = new Set<Node>();
  readonly ands = new Map<string, FbdLogic>();
  readonly path = new Set<Node>();
  /** For a node, the inputs (as written in it) that tap a wire of the node itself. */
  readonly loops = new Map<Node, Set<string | FbdNode>>();

  constructor(fbd: FbdNetwork) {
    this.logic = fbd.logic;
    this.mark(fbd.logic, this.inLogic);
    for (const final of fbd.outputs) this.mark(final, new Set());
  }

  /** Records the AND boxes a T-branch may tap, and (in `seen`) the nodes under `node`. */
  private mark(node: Node, seen: Set<Node>): void {
    seen.add(node);
    if (node.kind === 'logic') {
      if (node.op === 'AND' && node.id && !this.ands.has(node.id)) this.ands.set(node.id, node);
      if (node.flow !== null) this.mark(node.flow, seen);
    }
    for (const [, value] of inputsOf(node)) if (value !== null && typeof value !== 'string') this.mark(value, seen);
  }

  /**
   * The node behind a wire: the common logic behind a T-branch, the AND box behind a tap of its
   * wire (a T-branch inside the common logic itself, or a tap of a box that is not there, which
   * LAD refuses, stays an open pin).
   */
  resolve(node: string | FbdNode, owner: Node): string | FbdNode {
    if (typeof node !== 'string' && node.kind === 'branch') {
      if (node.source) return this.ands.get(node.source) ?? node;
      if (!this.inLogic.has(owner)) return this.logic;
    }
    return node;
  }

  visit(node: Node, depth: number): void {
    const known = this.depth.get(node);
    if (known === undefined) {
      this.first.push(node);
      this.ids.set(node, this.name(node));
    } else if (known >= depth) {
      return;
    }
    this.depth.set(node, depth);
    this.path.add(node);
    for (const [, value] of inputsOf(node)) {
      if (value === null) continue;
      const fed = this.resolve(value, node);
      if (typeof fed === 'string' || isPinLabel(fed)) continue;
      if (this.path.has(fed)) {
        // A box tapping its own wire (no LAD has one): the pin stays open.
        this.loopsOf(node).add(value);
        continue;
      }
      this.visit(fed, depth + 1);
    }
    this.path.delete(node);
  }

  isLoop(node: Node, value: string | FbdNode): boolean {
    return this.loops.get(node)?.has(value) ?? false;
  }

  private loopsOf(node: Node): Set<string | FbdNode> {
    let found = this.loops.get(node);
    if (found === undefined) {
      found = new Set();
      this.loops.set(node, found);
    }
    return found;
  }

  /** The node's own id unless taken (or empty), else the first free `n<count>`. */
  private name(node: Node): string {
    const taken = new Set(this.ids.values());
    if (node.id && !taken.has(node.id)) return node.id;
    let count = taken.size;
    while (taken.has(`n${count}`)) count += 1;
    return `n${count}`;
  }
}

/** The ports of one node and the edges into its input ports. */
function portsAndEdges(walk: Layering, node: Node, name: string): { ports: FbdPort[]; edges: FbdLayoutEdge[]; outputs: number } {
  const ports: FbdPort[] = [];
  const edges: FbdLayoutEdge[] = [];
  inputsOf(node).forEach(([pin, value], index) => {
    const port = `${name}.W.${index}`;
    const west = (label: string | null = null, negated = false, element: string | null = null, open = false): FbdPort => ({ id: port, name: pin, side: 'WEST', index, label, negated, element, open });
    if (value === null) {
      ports.push(west(null, false, null, true));
      return;
    }
    const fed = walk.resolve(value, node);
    if (typeof fed === 'string') {
      ports.push(west(fed));
    } else if (fed.kind === 'operand') {
      // The contact is the LAD element behind the operand: the editor selects it there.
      ports.push(west(fed.operand, fed.negated, fed.id || null));
    } else if (fed.kind === 'status') {
      ports.push(west(fed.bit, fed.negated, fed.id || null));
    } else {
      ports.push(west());
      if (fed.kind === 'branch' || walk.isLoop(node, value)) return;
      const source = walk.ids.get(fed) ?? '';
      edges.push({ id: `${source}->${port}`, source, source_port: `${source}.E.0`, target: name, target_port: port });
    }
  });
  const outputs = outputsOf(node);
  // A lone operand (a network without outputs) has its negation and its element at its output.
  const lone = node.kind === 'operand' || node.kind === 'status';
  const negated = lone && node.negated;
  const element = lone ? node.id || null : null;
  const isBox = node.kind === 'box';
  outputs.forEach(([pin, label], index) =>
    ports.push({ id: `${name}.E.${index}`, name: pin, side: 'EAST', index, label, negated, element, open: isBox && index > 0 && label === null }),
  );
  return { ports, edges, outputs: outputs.length };
}

/** Whether `node` is the empty series: an AND without inputs, always true (the rail). */
function isRail(node: FbdNode): boolean {
  return node.kind === 'logic' && node.op === 'AND' && node.inputs.length === 0 && node.flow === null;
}

/**
 * The layered graph of one FBD network (see above for the rules); none for a network kept as STL
 * or an empty one.
 */
export function fbdLayout(fbd: FbdNetwork): FbdLayout {
  if (fbd.stl !== null) return { layers: 0, nodes: [], edges: [] };
  const walk = new Layering(fbd);
  for (const final of fbd.outputs) walk.visit(final, 0);
  if (fbd.outputs.length === 0 && !isRail(fbd.logic)) walk.visit(fbd.logic, 0);
  if (walk.depth.size === 0) return { layers: 0, nodes: [], edges: [] };
  const deepest = Math.max(...walk.depth.values());
  const orders = new Map<number, number>();
  const nodes: FbdLayoutNode[] = [];
  const edges: FbdLayoutEdge[] = [];
  for (const node of walk.first) {
    const name = walk.ids.get(node) ?? '';
    const layer = deepest - (walk.depth.get(node) ?? 0);
    const order = orders.get(layer) ?? 0;
    orders.set(layer, order + 1);
    const drawn = portsAndEdges(walk, node, name);
    edges.push(...drawn.edges);
    const height = Math.max(1, drawn.ports.length - drawn.outputs, drawn.outputs);
    nodes.push({ id: name, kind: node.kind, title: titleOf(node), operand: operandOf(node), layer, order, width: 2, height, ports: drawn.ports });
  }
  return { layers: deepest + 1, nodes, edges };
}

/**
 * An FBD network's drawing: the layered graph of `fbdLayout` (boxes with their pins, wires)
 * handed to elkjs in the diagram layer's worker, and the positions that come back. Box sizes
 * follow from their pins, so the layout is the same every time for the same network; the
 * positions of each network are remembered while the network object lives.
 */
import type { ElkExtendedEdge, ElkNode } from 'elkjs/lib/elk-api';
import { layoutGraph } from '../diagram/elk/elkClient';
import { LAYERED_OPTIONS, NODE_OPTIONS } from '../diagram/elk/options';
import { fbdLayout } from './fbdGraph';
import { toFbd } from './fbd';
import type { FbdLayout, FbdLayoutNode, Network } from './model';

/** The title row of a box, and the height of each pin row below it. */
export const TITLE_H = 24;
export const PIN_H = 30;
const LOGIC_W = 52;
const BOX_W = 92;

export interface PlacedPort {
  id: string;
  x: number;
  y: number;
  /** Where elkjs put the operand written at the pin (room kept free of boxes and wires). */
  label: { x: number; y: number; width: number; height: number } | null;
}

export interface PlacedNode {
  node: FbdLayoutNode;
  x: number;
  y: number;
  width: number;
  height: number;
  ports: Map<string, PlacedPort>;
}

export interface PlacedEdge {
  id: string;
  source: string;
  points: readonly { x: number; y: number }[];
}

export interface FbdGeometry {
  graph: FbdLayout;
  nodes: PlacedNode[];
  edges: PlacedEdge[];
  width: number;
  height: number;
}

function nodeWidth(node: FbdLayoutNode): number {
  return node.kind === 'logic' || node.kind === 'not' ? LOGIC_W : BOX_W;
}

function nodeHeight(node: FbdLayoutNode): number {
  const west = node.ports.filter((port) => port.side === 'WEST').length;
  const east = node.ports.filter((port) => port.side === 'EAST').length;
  return TITLE_H + Math.max(1, west, east) * PIN_H;
}

function portY(index: number): number {
  return TITLE_H + index * PIN_H + PIN_H / 2;
}

/** About how wide a pin's operand is written (monospace, 11.5 px): elkjs keeps wires off it. */
export function labelWidth(text: string): number {
  return Math.min(text.length, LABEL_CHARS) * 7 + 8;
}

/** Operands longer than this are cut (with an ellipsis) where they are written at a pin. */
export const LABEL_CHARS = 14;

/** What a pin shows beside it: its operand, or `...` when nothing is connected. */
export function portText(port: FbdLayoutNode['ports'][number]): string | null {
  if (port.label !== null && port.label !== undefined) return port.label;
  return port.open ? '...' : null;
}

/** The elkjs graph of an FBD layout: fixed port positions, the model's order kept. */
export function elkGraph(graph: FbdLayout): ElkNode {
  const nodes = [...graph.nodes].sort((a, b) => a.layer - b.layer || a.order - b.order);
  const children: ElkNode[] = nodes.map((node) => {
    const width = nodeWidth(node);
    return {
      id: node.id,
      width,
      height: nodeHeight(node),
      layoutOptions: { ...NODE_OPTIONS, 'elk.margins': `[top=${node.operand ? 18 : 4},left=0,bottom=4,right=0]` },
      ports: node.ports.map((port) => {
        const text = portText(port);
        return {
          id: port.id,
          width: 0,
          height: 0,
          x: port.side === 'WEST' ? 0 : width,
          y: portY(port.index),
          layoutOptions: { 'elk.port.side': port.side },
          ...(text ? { labels: [{ id: `${port.id}.label`, text, width: labelWidth(text), height: 14 }] } : {}),
        };
      }),
    };
  });
  const edges: ElkExtendedEdge[] = graph.edges.map((edge) => ({ id: edge.id, sources: [edge.source_port], targets: [edge.target_port] }));
  return { id: 'fbd', layoutOptions: LAYERED_OPTIONS, children, edges };
}

/** The positions elkjs gave, in the terms of the FBD layout. */
export function placed(graph: FbdLayout, laid: ElkNode): FbdGeometry {
  const byId = new Map(graph.nodes.map((node) => [node.id, node]));
  const nodes: PlacedNode[] = [];
  for (const child of laid.children ?? []) {
    const node = byId.get(child.id);
    if (!node) continue;
    const x = child.x ?? 0;
    const y = child.y ?? 0;
    const ports = new Map<string, PlacedPort>();
    for (const port of child.ports ?? []) {
      const px = x + (port.x ?? 0);
      const py = y + (port.y ?? 0);
      const text = port.labels?.[0];
      const label = text ? { x: px + (text.x ?? 0), y: py + (text.y ?? 0), width: text.width ?? 0, height: text.height ?? 0 } : null;
      ports.set(port.id, { id: port.id, x: px, y: py, label });
    }
    nodes.push({ node, x, y, width: child.width ?? nodeWidth(node), height: child.height ?? nodeHeight(node), ports });
  }
  const edges: PlacedEdge[] = (laid.edges ?? []).map((edge) => {
    const section = (edge as ElkExtendedEdge).sections?.[0];
    const points = section ? [section.startPoint, ...(section.bendPoints ?? []), section.endPoint] : [];
    const source = graph.edges.find((e) => e.id === edge.id)?.source ?? '';
    return { id: edge.id, source, points };
  });
  return { graph, nodes, edges, width: laid.width ?? 0, height: laid.height ?? 0 };
}

// -- per network, remembered -------------------------------------------------------------------

const graphs = new WeakMap<Network, FbdLayout>();
const geometries = new WeakMap<Network, FbdGeometry>();
const running = new WeakSet<Network>();
const listeners = new Set<() => void>();
let version = 0;

export function fbdGraphOf(network: Network): FbdLayout {
  let graph = graphs.get(network);
  if (!graph) {
    graph = fbdLayout(toFbd(network));
    graphs.set(network, graph);
  }
  return graph;
}

/** The network's positions if laid out already; else the layout starts (listeners hear when it is done). */
export function fbdGeometryOf(network: Network): FbdGeometry | null {
  const known = geometries.get(network);
  if (known) return known;
  if (!running.has(network)) {
    running.add(network);
    const graph = fbdGraphOf(network);
    layoutGraph(elkGraph(graph)).then(
      (laid) => {
        geometries.set(network, placed(graph, laid));
        version += 1;
        listeners.forEach((listener) => listener());
      },
      () => running.delete(network),
    );
  }
  return null;
}

/** An estimate before the layout is known: the layers side by side, each layer's boxes stacked. */
export function estimatedHeight(network: Network): number {
  const graph = fbdGraphOf(network);
  const perLayer = new Map<number, number>();
  for (const node of graph.nodes) perLayer.set(node.layer, (perLayer.get(node.layer) ?? 0) + nodeHeight(node) + 26);
  return Math.max(60, ...perLayer.values()) + 28;
}

/**
 * The height of a network's FBD body: laid out, or estimated until then. It starts no layout: a
 * network is laid out when it is drawn, so a long block does not queue every network at once.
 */
export function fbdBodyHeight(network: Network): number {
  const geometry = geometries.get(network);
  return (geometry ? geometry.height : estimatedHeight(network)) + 12;
}

export function subscribeFbdLayouts(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

export function fbdLayoutVersion(): number {
  return version;
}

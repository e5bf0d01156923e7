/**
 * The diagram layer's one layout worker: graphs in, positioned graphs out, so a large FBD network
 * or sequencer never blocks the editor. Layouts run one after another, each answer carrying how
 * long its own layout took. elkjs runs several times slower until V8 has compiled its code, so
 * the worker warms it up: a few small networks at start, and whatever shapes the editors send as
 * warm-up (`warmUpLayout`, e.g. the chart's sequencer when a page may soon show one). Warm-up runs
 * one small layout at a time and only while no real request waits, so a user's layout never
 * queues behind more than one warm-up piece.
 */
import type { ElkNode } from 'elkjs/lib/elk-api';
import { LAYERED_OPTIONS, NODE_OPTIONS } from './options';
import { newElk } from './runLayout';

interface Request {
  id: number;
  graph: ElkNode;
  /** A warm-up: lay the graph out this many times when idle, answer nothing. */
  warm?: number;
}

// Made before the handler is set: making it installs elkjs's own handler (see `newElk`).
const elk = newElk();
/**
 * A small graph of the shape the editors send (boxes in layers, fixed ports, port labels,
 * orthogonal wires), laid out a few times so that elkjs's code for it is compiled before the
 * first real network arrives.
 */
function warmUp(): ElkNode {
  const children: ElkNode[] = [];
  const edges: ElkNode['edges'] = [];
  for (let k = 0; k < 12; k += 1) {
    children.push({
      id: `n${k}`,
      width: 60,
      height: 84,
      layoutOptions: NODE_OPTIONS,
      ports: [0, 1].map((index) => ({
        id: `n${k}.W.${index}`,
        x: 0,
        y: 39 + index * 30,
        width: 0,
        height: 0,
        layoutOptions: { 'elk.port.side': 'WEST' },
        labels: [{ id: `n${k}.W.${index}.label`, text: 'I 0.0', width: 43, height: 14 }],
      })).concat([{ id: `n${k}.E.0`, x: 60, y: 39, width: 0, height: 0, layoutOptions: { 'elk.port.side': 'EAST' }, labels: [] }]),
    });
    if (k >= 3) edges.push({ id: `e${k}`, sources: [`n${k - 3}.E.0`], targets: [`n${k}.W.${k % 2}`] });
  }
  return { id: 'warm-up', layoutOptions: LAYERED_OPTIONS, children, edges };
}

const requests: Request[] = [];
const warming: ElkNode[] = [warmUp(), warmUp(), warmUp()];
let pumping = false;

async function answer({ id, graph }: Request): Promise<void> {
  const started = performance.now();
  try {
    const laid = await elk.layout(graph);
    self.postMessage({ id, graph: laid, ms: performance.now() - started });
  } catch (error) {
    self.postMessage({ id, error: error instanceof Error ? error.message : String(error) });
  }
}

/** Real requests first, in order; a warm-up piece only when none waits; messages get in between. */
async function pump(): Promise<void> {
  if (pumping) return;
  pumping = true;
  for (;;) {
    const request = requests.shift();
    if (request) await answer(request);
    else {
      const graph = warming.shift();
      if (!graph) break;
      await elk.layout(graph).catch(() => undefined);
    }
    await new Promise((resolve) => setTimeout(resolve, 0));
  }
  pumping = false;
}

self.onmessage = (event: MessageEvent<Request>) => {
  const { graph, warm } = event.data;
  if (warm === undefined) requests.push(event.data);
  else for (let k = 0; k < Math.min(warm, 20); k += 1) warming.push(structuredClone(graph));
  void pump();
};
void pump();

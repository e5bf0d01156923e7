/**
 * The diagram layer's one layout worker: graphs in, positioned graphs out, so a large FBD network
 * or sequencer never blocks the editor. Layouts run one after another, each answer carrying how
 * long its own layout took; a first small layout at start warms elkjs up (its first run compiles
 * and initialises much of its code), so a user's first network does not pay for that.
 */
import type { ElkNode } from 'elkjs/lib/elk-api';
import { LAYERED_OPTIONS, NODE_OPTIONS } from './options';
import { newElk } from './runLayout';

interface Request {
  id: number;
  graph: ElkNode;
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

let queue: Promise<unknown> = (async () => {
  for (let k = 0; k < 3; k += 1) await elk.layout(warmUp()).catch(() => undefined);
})();

async function answer({ id, graph }: Request): Promise<void> {
  const started = performance.now();
  try {
    const laid = await elk.layout(graph);
    self.postMessage({ id, graph: laid, ms: performance.now() - started });
  } catch (error) {
    self.postMessage({ id, error: error instanceof Error ? error.message : String(error) });
  }
}

self.onmessage = (event: MessageEvent<Request>) => {
  queue = queue.then(() => answer(event.data));
};

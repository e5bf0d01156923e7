/**
 * The diagram layer's one layout worker: graphs in, positioned graphs out, so a large FBD network
 * or sequencer never blocks the editor. Layouts run one after another, each answer carrying how
 * long its own layout took; a first small layout at start warms elkjs up (its first run compiles
 * and initialises much of its code), so a user's first network does not pay for that.
 */
import type { ElkNode } from 'elkjs/lib/elk-api';
import { newElk } from './runLayout';

interface Request {
  id: number;
  graph: ElkNode;
}

// Made before the handler is set: making it installs elkjs's own handler (see `newElk`).
const elk = newElk();
const WARM_UP: ElkNode = {
  id: 'warm-up',
  layoutOptions: { 'elk.algorithm': 'layered' },
  children: [
    { id: 'a', width: 10, height: 10 },
    { id: 'b', width: 10, height: 10 },
  ],
  edges: [{ id: 'a-b', sources: ['a'], targets: ['b'] }],
};
let queue: Promise<unknown> = elk.layout(WARM_UP).catch(() => undefined);

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

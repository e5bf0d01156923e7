/**
 * Layouts from the diagram layer's worker, remembered by the graph they were asked for: the same
 * network asks once however often it is drawn. Where no worker can be made (tests in jsdom), the
 * layout runs in the page instead.
 */
import type { ElkNode } from 'elkjs/lib/elk-api';

interface Answer {
  id: number;
  graph?: ElkNode;
  ms?: number;
  error?: string;
}

const CACHE_LIMIT = 2000;
const cache = new Map<string, Promise<ElkNode>>();
const waiting = new Map<number, { resolve: (graph: ElkNode) => void; reject: (error: Error) => void }>();
let worker: Worker | null | undefined;
let nextId = 1;
/** The performance mark every layout leaves, with how long the worker took (`detail.ms`): `make bench` reads it. */
export const LAYOUT_MARK = 'nasaq:elk-layout';

function theWorker(): Worker | null {
  if (worker !== undefined) return worker;
  try {
    worker = typeof Worker === 'undefined' ? null : new Worker(new URL('./elk.worker.ts', import.meta.url), { type: 'module' });
  } catch {
    worker = null;
  }
  worker?.addEventListener('message', (event: MessageEvent<Answer>) => {
    const { id, graph, ms, error } = event.data;
    const entry = waiting.get(id);
    if (!entry) return;
    waiting.delete(id);
    if (typeof ms === 'number' && typeof performance.mark === 'function') {
      performance.mark(LAYOUT_MARK, { detail: { ms, nodes: graph?.children?.length ?? 0 } });
    }
    if (graph) entry.resolve(graph);
    else entry.reject(new Error(error ?? 'layout failed'));
  });
  return worker;
}

/**
 * Has the worker lay `graph` out `times` times while it is idle, so that elkjs's code for graphs
 * of that shape is compiled before a user waits for one (a cold elkjs is several times slower).
 * Starts the worker; nothing where there is none.
 */
export function warmUpLayout(graph: ElkNode, times: number): void {
  theWorker()?.postMessage({ id: 0, graph, warm: times });
}

/** The laid-out graph (positions, edge routes); one request per distinct graph. */
export function layoutGraph(graph: ElkNode): Promise<ElkNode> {
  const key = JSON.stringify(graph);
  const known = cache.get(key);
  if (known) return known;
  const running = theWorker();
  const answer = running
    ? new Promise<ElkNode>((resolve, reject) => {
        const id = nextId++;
        waiting.set(id, { resolve, reject });
        running.postMessage({ id, graph });
      })
    : import('./runLayout').then(({ runLayout }) => runLayout(graph));
  if (cache.size >= CACHE_LIMIT) {
    const oldest = cache.keys().next().value;
    if (oldest !== undefined) cache.delete(oldest);
  }
  cache.set(key, answer);
  answer.catch(() => cache.delete(key));
  return answer;
}

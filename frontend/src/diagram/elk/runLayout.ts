/**
 * Runs elkjs on a graph. The worker (`elk.worker.ts`) calls this off the main thread; tests call
 * it directly. elkjs's bundled build carries its layout code, so nothing is loaded from anywhere.
 */
import ELK from 'elkjs/lib/elk.bundled.js';
import type { ElkNode } from 'elkjs/lib/elk-api';

export type Elk = InstanceType<typeof ELK>;

/**
 * A new elkjs instance. In a worker its bundled code takes the worker's `onmessage` for itself
 * when the instance is made, so the worker makes its instance first and then sets its own handler.
 */
export function newElk(): Elk {
  return new ELK();
}

let shared: Elk | null = null;

export async function runLayout(graph: ElkNode): Promise<ElkNode> {
  shared ??= newElk();
  return shared.layout(graph);
}

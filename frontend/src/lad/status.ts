/**
 * Program status of one network: the power flow on every wire, worked out from what the CPU
 * reported for each element (`ElementStatus` of the monitoring protocol) and the rung's tree.
 *
 * The server reports what only the CPU knows: each contact's operand as it was read, each box's
 * ENO or Q, a NOT's or an edge's result. The wires between are the tree's logic: series AND,
 * a parallel passes the OR of its branches, every branch starting from the flow into the
 * parallel (the model's reading, the same as the STL the rung lowers to). An element the CPU did
 * not process in the sampled scan (a network jumped over, a box whose EN was 0) is grey.
 */
import { andFlow, type Flow } from '../diagram/powerFlow';
import { boxSpec } from './boxes';
import type { Network, Series } from './model';
import type { Element, Final } from './tree';

/** What the CPU reported for one element (the protocol's `ElementStatus` without its address). */
export interface ElementState {
  value: boolean | number | string | null;
  out: boolean | null;
  pins: Readonly<Record<string, boolean | number | string | null>>;
}

/** The flow at each point of a rung: `rail`, `<id>` (out of an element), `<id>:in` (into it). */
export type FlowMap = ReadonlyMap<string, Flow>;

function orFlows(flows: readonly Flow[]): Flow {
  if (flows.some((flow) => flow === undefined)) return undefined;
  if (flows.some((flow) => flow === 1)) return 1;
  if (flows.some((flow) => flow === 0)) return 0;
  return null;
}

function truth(value: unknown): boolean {
  return value === true || (typeof value === 'number' && value !== 0);
}

/** Elements that check a condition (their result ANDs onto the flow), as opposed to acting on it. */
function isCheck(element: Element | Final): boolean {
  if (element.kind === 'contact' || element.kind === 'status') return true;
  if (element.kind !== 'box') return false;
  const family = boxSpec(element.name)?.family;
  return family === 'compare' || family === 'edge';
}

/**
 * The flows of a network from its elements' states. `states` is empty when the network was not
 * processed in the sampled scan: every point is then grey (null).
 */
export function networkFlows(network: Network, states: ReadonlyMap<string, ElementState>): FlowMap {
  const flows = new Map<string, Flow>();
  const processed = states.size > 0;
  const rail: Flow = processed ? 1 : null;
  flows.set('rail', rail);

  const element = (item: Element | Final, into: Flow): Flow => {
    flows.set(`${item.id}:in`, into);
    const state = states.get(item.id);
    let out: Flow;
    if (item.kind === 'parallel') {
      out = orFlows(item.branches.map((branch) => series(branch, into)));
    } else if (isCheck(item)) {
      if (!state) out = null;
      else {
        const holds = item.kind === 'box' ? truth(state.out) : truth(state.value) !== ('negated' in item && item.negated);
        out = andFlow(into, holds ? 1 : 0);
      }
    } else {
      if (item.kind === 'box') {
        // Logic wired into a pin starts at the rail, on its own row.
        for (const value of Object.values(item.inputs)) {
          if (typeof value === 'object' && value !== null) series(value, rail);
        }
      }
      out = state ? (state.out === null ? into : state.out ? 1 : 0) : null;
    }
    flows.set(item.id, out);
    return out;
  };

  const series = (items: Series, into: Flow): Flow => {
    let flow = into;
    for (const item of items.elements) flow = element(item, flow);
    return flow;
  };

  const common = series(network.logic, rail);
  for (const output of network.outputs) element(output.target, series(output.conditions, common));
  return flows;
}

/**
 * Power flow as TIA Portal draws program status: a wire or element is green and solid where the
 * flow is 1, blue and dashed where it is 0, grey where the CPU did not process it in the sampled
 * scan. Offline there is no status at all and the diagram keeps its normal colours. Every
 * graphical editor styles its wires through these classes (`powerFlow.css`).
 */
import './powerFlow.css';

/** 1 or 0: the flow; null: not processed; undefined: offline (no status shown). */
export type Flow = 0 | 1 | null | undefined;

export function flowClass(flow: Flow): string {
  if (flow === undefined) return '';
  if (flow === null) return 'pf-none';
  return flow ? 'pf-on' : 'pf-off';
}

/** The state a test or a screen reader reads off an element: `on`, `off`, `none` or `offline`. */
export function flowState(flow: Flow): 'on' | 'off' | 'none' | 'offline' {
  if (flow === undefined) return 'offline';
  if (flow === null) return 'none';
  return flow ? 'on' : 'off';
}

export function flowOf(value: boolean | null | undefined): Flow {
  if (value === undefined) return undefined;
  if (value === null) return null;
  return value ? 1 : 0;
}

/** AND of two flows: not processed wins over everything, as the CPU either ran both or neither. */
export function andFlow(a: Flow, b: Flow): Flow {
  if (a === undefined || b === undefined) return undefined;
  if (a === null || b === null) return null;
  return a && b ? 1 : 0;
}

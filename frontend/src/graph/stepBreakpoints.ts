/**
 * Breakpoints on the activation of an S7-Graph step (the Control Sequencer's "break at step"):
 * the CPU holds when step `step` of the FB is about to become active, however it becomes so.
 * Like the editor's breakpoints they belong to the browser (localStorage), not to a session, so
 * they survive reloads and downloads; `useBreakpointSync` hands them to the monitoring client
 * with the others, which keeps them set on the server (`Location.step`).
 */
import type { BreakpointRequest } from '../api/monitorClient';

export interface StepBreakpoint {
  projectId: number;
  /** The FB as the session names it (`FB1`, or its symbol): see `sessionBlockName`. */
  block: string;
  step: number;
}

export const STEP_BREAKPOINTS_STORAGE_KEY = 'nasaq.debug.graphSteps';

/** The key of a step breakpoint, shared with the client's reports (`state.breakpoints`). */
export function stepBreakpointKey(bp: StepBreakpoint): string {
  return `${bp.projectId}:${bp.block}@step${bp.step}`;
}

function isStepBreakpoint(value: unknown): value is StepBreakpoint {
  const bp = value as StepBreakpoint;
  return (
    typeof bp === 'object' &&
    bp !== null &&
    Number.isInteger(bp.projectId) &&
    typeof bp.block === 'string' &&
    Number.isInteger(bp.step) &&
    bp.step > 0
  );
}

/** What the server needs for the step breakpoints of one project. */
export function stepRequestsFor(list: readonly StepBreakpoint[], projectId: number): BreakpointRequest[] {
  return list
    .filter((bp) => bp.projectId === projectId)
    .map((bp) => ({ key: stepBreakpointKey(bp), location: { block: bp.block, step: bp.step }, condition: null }));
}

type Listener = () => void;

export interface StepBreakpointStore {
  list: () => readonly StepBreakpoint[];
  has: (bp: StepBreakpoint) => boolean;
  /** Adds the breakpoint, or removes it when it is there. */
  toggle: (bp: StepBreakpoint) => void;
  add: (bp: StepBreakpoint) => void;
  subscribe: (listener: Listener) => () => void;
}

function safeStorage(): Storage | null {
  try {
    return typeof localStorage === 'undefined' ? null : localStorage;
  } catch {
    return null;
  }
}

export function createStepBreakpointStore(storage: Pick<Storage, 'getItem' | 'setItem'> | null = safeStorage()): StepBreakpointStore {
  const read = (): StepBreakpoint[] => {
    try {
      const parsed: unknown = JSON.parse(storage?.getItem(STEP_BREAKPOINTS_STORAGE_KEY) ?? '[]');
      return Array.isArray(parsed) ? parsed.filter(isStepBreakpoint) : [];
    } catch {
      return [];
    }
  };
  let items: readonly StepBreakpoint[] = read();
  const listeners = new Set<Listener>();
  const commit = (next: readonly StepBreakpoint[]) => {
    items = next;
    try {
      storage?.setItem(STEP_BREAKPOINTS_STORAGE_KEY, JSON.stringify(items));
    } catch {
      // A full or blocked storage: the breakpoints still work until the page reloads.
    }
    listeners.forEach((listener) => listener());
  };
  const same = (a: StepBreakpoint) => (b: StepBreakpoint) => stepBreakpointKey(a) === stepBreakpointKey(b);
  const store: StepBreakpointStore = {
    list: () => items,
    has: (bp) => items.some(same(bp)),
    toggle(bp) {
      commit(store.has(bp) ? items.filter((other) => !same(bp)(other)) : [...items, { ...bp }]);
    },
    add(bp) {
      if (!store.has(bp)) commit([...items, { ...bp }]);
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
  return store;
}

/** The app's step breakpoints. */
export const stepBreakpoints = createStepBreakpointStore();

import { useSyncExternalStore } from 'react';
import type { Diagnostic } from '../api/types';

type Listener = () => void;

/**
 * The diagnostics of the open project. The compiler service fills it in a later
 * release; today nothing reports problems, so it starts (and stays) empty.
 */
export interface DiagnosticsStore {
  get: () => readonly Diagnostic[];
  set: (diagnostics: readonly Diagnostic[]) => void;
  clear: () => void;
  subscribe: (listener: Listener) => () => void;
}

export function createDiagnosticsStore(initial: readonly Diagnostic[] = []): DiagnosticsStore {
  let items: readonly Diagnostic[] = initial;
  const listeners = new Set<Listener>();
  const notify = () => listeners.forEach((listener) => listener());
  return {
    get: () => items,
    set: (next) => {
      items = [...next];
      notify();
    },
    clear: () => {
      if (items.length === 0) return;
      items = [];
      notify();
    },
    subscribe: (listener) => {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

/** The application's one diagnostics store. */
export const diagnosticsStore = createDiagnosticsStore();

export function useDiagnostics(store: DiagnosticsStore = diagnosticsStore): readonly Diagnostic[] {
  return useSyncExternalStore(store.subscribe, store.get, store.get);
}

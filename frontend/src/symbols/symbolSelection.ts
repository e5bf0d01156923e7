import { useSyncExternalStore } from 'react';

/** A symbol whose row a symbol table tab should select: F12 on `"Motor"` in an editor. */
export interface SymbolRowRequest {
  projectId: number;
  file: string;
  /** The symbol's name (letter case does not count). */
  name: string;
  /** Grows with every request, so the same symbol can be asked for twice. */
  seq: number;
}

let current: SymbolRowRequest | null = null;
let seq = 0;
const listeners = new Set<() => void>();

/** Asks the tab of `file` to show the table with the row of `name` selected. */
export function requestSymbolRow(projectId: number, file: string, name: string): void {
  seq += 1;
  current = { projectId, file, name, seq };
  listeners.forEach((listener) => listener());
}

function subscribe(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/** The newest request for this file of the project (null: none). */
export function useSymbolRowRequest(projectId: number, file: string): SymbolRowRequest | null {
  const request = useSyncExternalStore(subscribe, () => current, () => null);
  return request && request.projectId === projectId && request.file === file ? request : null;
}

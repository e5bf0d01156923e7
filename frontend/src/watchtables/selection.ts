import { useSyncExternalStore } from 'react';
import { panelTab } from '../panels/panelTab';
import { readStored, writeStored } from '../ui/usePersistentState';

/**
 * Which watch table of a project the bottom panel shows (by file name), remembered per project;
 * the project tree opens a table by choosing it here and bringing the Watch tab forward.
 */
const listeners = new Set<() => void>();
const chosen = new Map<number, string | null>();

const storageKey = (projectId: number) => `nasaq.watch.table.${projectId}`;

export function selectedWatchTable(projectId: number): string | null {
  if (!chosen.has(projectId)) chosen.set(projectId, readStored(storageKey(projectId)));
  return chosen.get(projectId) ?? null;
}

export function selectWatchTable(projectId: number, name: string | null): void {
  if (selectedWatchTable(projectId) === name) return;
  chosen.set(projectId, name);
  writeStored(storageKey(projectId), name ?? '');
  listeners.forEach((listener) => listener());
}

/** Shows `name` in the watch table panel (tree: Enter or double-click on a table). */
export function openWatchTable(projectId: number, name: string): void {
  selectWatchTable(projectId, name);
  panelTab.show('watch');
}

function subscribe(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

export function useSelectedWatchTable(projectId: number | null): string | null {
  return useSyncExternalStore(
    subscribe,
    () => (projectId === null ? null : selectedWatchTable(projectId) || null),
    () => null,
  );
}

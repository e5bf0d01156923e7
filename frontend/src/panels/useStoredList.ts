import { useCallback, useState } from 'react';
import { readStored, writeStored } from '../ui/usePersistentState';

/** The list remembered under `key`, its items that pass `isItem` (none when it is unreadable). */
export function readStoredList<T>(key: string, isItem: (item: unknown) => item is T): T[] {
  return load(key, isItem);
}

/** Forgets the list under `key` (it moved elsewhere, e.g. into a watch table file). */
export function forgetStoredList(key: string): void {
  try {
    window.localStorage.removeItem(key);
  } catch {
    // Storage unavailable: there was nothing to forget.
  }
}

function load<T>(key: string, isItem: (item: unknown) => item is T): T[] {
  try {
    const parsed: unknown = JSON.parse(readStored(key) ?? '[]');
    return Array.isArray(parsed) ? parsed.filter(isItem) : [];
  } catch {
    return [];
  }
}

/**
 * A list remembered in localStorage under `key` (e.g. the trend's entries per project); switching
 * to another key shows that key's list.
 */
export function useStoredList<T>(
  key: string,
  isItem: (item: unknown) => item is T,
): [readonly T[], (change: (items: readonly T[]) => readonly T[]) => void] {
  const [state, setState] = useState(() => ({ key, items: load(key, isItem) as readonly T[] }));
  let current = state;
  if (state.key !== key) {
    current = { key, items: load(key, isItem) };
    setState(current);
  }
  const update = useCallback(
    (change: (items: readonly T[]) => readonly T[]) =>
      setState((previous) => {
        const items = change(previous.items);
        writeStored(previous.key, JSON.stringify(items));
        return { key: previous.key, items };
      }),
    [],
  );
  return [current.items, update];
}

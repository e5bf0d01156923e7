import { useSyncExternalStore } from 'react';
import { panelTab } from '../panels/panelTab';

/**
 * What the editor asks of the cross-reference tools (Shift+F12: show the references of the
 * operand under the caret; F2: rename it), from outside the panels that answer. Each request is
 * a new object, so asking twice for the same operand shows it again.
 */
export interface XrefRequest {
  projectId: number;
  target: string;
}

type Listener = () => void;

function createRequests() {
  let current: XrefRequest | null = null;
  const listeners = new Set<Listener>();
  return {
    get: () => current,
    set(request: XrefRequest | null) {
      current = request;
      listeners.forEach((listener) => listener());
    },
    subscribe(listener: Listener) {
      listeners.add(listener);
      return () => {
        listeners.delete(listener);
      };
    },
  };
}

/** The operand whose cross-references the panel shows. */
export const referenceRequests = createRequests();
/** The operand being renamed (the rename dialog is open while it is set). */
export const renameRequests = createRequests();

/** The bottom panel's id of the Cross-references tab. */
export const XREF_TAB = 'xref';
export const ASSIGNMENT_TAB = 'assignments';

/** Shows the references of `target` in the Cross-references panel and brings it forward. */
export function showReferences(projectId: number, target: string): void {
  referenceRequests.set({ projectId, target });
  panelTab.show(XREF_TAB);
}

export function openRename(projectId: number, target: string): void {
  renameRequests.set({ projectId, target });
}

export function useRequest(requests: ReturnType<typeof createRequests>): XrefRequest | null {
  return useSyncExternalStore(requests.subscribe, requests.get, requests.get);
}

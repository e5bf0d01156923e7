import type { EditorTab } from './EditorTabsContext';

/**
 * Whether a tab holds text the server does not have: a change the autosave has not sent yet or
 * is sending, a save refused by a conflict or failed. A reload or a closed browser tab would drop
 * it, so the page asks first (the pending save is sent at the same time and usually lands).
 */
export function holdsUnsavedText(tab: EditorTab): boolean {
  if (tab.kind !== 'source') return false;
  if (!tab.file) return tab.dirty;
  return tab.save.status !== 'saved';
}

/** Whether closing this editor tab would lose text for good: the autosave could not save it
 * (conflict, error); a change merely pending is saved as the tab closes. */
export function closingLosesText(tab: EditorTab): boolean {
  if (tab.kind !== 'source') return false;
  if (!tab.file) return tab.dirty;
  return tab.save.status === 'conflict' || tab.save.status === 'failed';
}

/** Edits a view holds before they reach its tab's text (the STL view of a LAD/FBD block waits
 * for a pause in the typing), by key: a reload asks while any is pending. */
const pendingEdits = new Set<string>();

export function setPendingEdit(key: string, pending: boolean): void {
  if (pending) pendingEdits.add(key);
  else pendingEdits.delete(key);
}

export function hasPendingEdits(): boolean {
  return pendingEdits.size > 0;
}

import { useCallback, useState, type FocusEvent, type KeyboardEvent } from 'react';

export interface TreeKeyboardActions {
  /** Expands the item if it can be expanded and is closed; returns true if it did. */
  expand: (key: string) => boolean;
  /** Collapses the item if it is open; returns true if it did. */
  collapse: (key: string) => boolean;
  /** Enter or Space on an item. */
  activate: (key: string) => void;
}

const ITEM = '[role="treeitem"]';

function itemsOf(tree: HTMLElement): HTMLElement[] {
  return Array.from(tree.querySelectorAll<HTMLElement>(ITEM));
}

function levelOf(element: Element | undefined): number {
  return Number(element?.getAttribute('aria-level') ?? '1');
}

/** The nearest item before `index` with a lower aria-level (the tree is flat). */
function parentOf(items: HTMLElement[], index: number): HTMLElement | null {
  const level = levelOf(items[index]);
  for (let i = index - 1; i >= 0; i -= 1) {
    if (levelOf(items[i]) < level) return items[i] ?? null;
  }
  return null;
}

function keyOf(element: Element | null): string | null {
  return element instanceof HTMLElement ? (element.dataset.treeKey ?? null) : null;
}

/**
 * Keyboard support of the WAI-ARIA tree pattern with a roving tab stop:
 * Up/Down move, Home/End jump, the inline-end arrow opens or enters an item and the
 * inline-start arrow closes it or goes to its parent (arrows mirror in RTL pages).
 */
export function useTreeKeyboard(visibleKeys: readonly string[], actions: TreeKeyboardActions) {
  const [active, setActive] = useState<string | null>(null);
  const tabStop = active !== null && visibleKeys.includes(active) ? active : (visibleKeys[0] ?? null);

  const focusKey = useCallback((tree: HTMLElement, key: string | null) => {
    if (key === null) return;
    const target = itemsOf(tree).find((item) => item.dataset.treeKey === key);
    target?.focus();
  }, []);

  const onFocus = useCallback((event: FocusEvent<HTMLElement>) => {
    const item = (event.target as HTMLElement).closest<HTMLElement>(ITEM);
    const key = keyOf(item);
    if (key !== null) setActive(key);
  }, []);

  const onKeyDown = useCallback(
    (event: KeyboardEvent<HTMLElement>) => {
      const tree = event.currentTarget;
      const current = (event.target as HTMLElement).closest<HTMLElement>(ITEM);
      const key = keyOf(current);
      if (!current || key === null) return;
      const items = itemsOf(tree);
      const index = items.indexOf(current);
      const rtl = tree.closest<HTMLElement>('[dir]')?.dir === 'rtl';
      const inward = rtl ? 'ArrowLeft' : 'ArrowRight';
      const outward = rtl ? 'ArrowRight' : 'ArrowLeft';

      switch (event.key) {
        case 'ArrowDown':
          focusKey(tree, keyOf(items[index + 1] ?? null));
          break;
        case 'ArrowUp':
          focusKey(tree, keyOf(items[index - 1] ?? null));
          break;
        case 'Home':
          focusKey(tree, keyOf(items[0] ?? null));
          break;
        case 'End':
          focusKey(tree, keyOf(items[items.length - 1] ?? null));
          break;
        case inward:
          if (!actions.expand(key) && current.getAttribute('aria-expanded') === 'true') {
            focusKey(tree, keyOf(items[index + 1] ?? null));
          }
          break;
        case outward:
          if (!actions.collapse(key)) focusKey(tree, keyOf(parentOf(items, index)));
          break;
        case 'Enter':
        case ' ':
          actions.activate(key);
          break;
        default:
          return;
      }
      event.preventDefault();
      event.stopPropagation();
    },
    [actions, focusKey],
  );

  return { tabStop, onFocus, onKeyDown };
}

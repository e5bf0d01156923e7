import { useEffect, useLayoutEffect, useRef, useState, type KeyboardEvent } from 'react';
import { createPortal } from 'react-dom';

export interface MenuAction {
  id: string;
  label: string;
  onSelect: () => void;
  /** Destroys something (delete): drawn in the danger colour, after a separator. */
  danger?: boolean;
}

interface RowMenuProps {
  /** The element the menu opens beside (a tree row), and gives the focus back to. */
  anchor: Element;
  label: string;
  actions: readonly MenuAction[];
  onClose: (restoreFocus: boolean) => void;
  testId?: string;
}

const GAP = 2;

/**
 * A context menu (WAI-ARIA menu pattern): opens with the focus on its first item; Up/Down,
 * Home/End move; Enter or Space chooses; Escape closes and gives the focus back to the row;
 * Tab or a click elsewhere closes it. Drawn in a layer of its own, beside the row, on screen.
 */
export function RowMenu({ anchor, label, actions, onClose, testId }: RowMenuProps) {
  const menu = useRef<HTMLUListElement>(null);
  const [position, setPosition] = useState<{ top: number; left: number } | null>(null);
  const closeRef = useRef(onClose);
  closeRef.current = onClose;

  useLayoutEffect(() => {
    const element = menu.current;
    if (!element) return;
    const row = anchor.getBoundingClientRect();
    const own = element.getBoundingClientRect();
    const rtl = getComputedStyle(anchor).direction === 'rtl';
    const width = own.width || 200;
    const height = own.height || 0;
    let left = rtl ? row.left : row.right - width;
    left = Math.max(GAP, Math.min(left, window.innerWidth - width - GAP));
    let top = row.bottom + GAP;
    if (top + height > window.innerHeight - GAP) top = Math.max(GAP, row.top - height - GAP);
    setPosition({ top, left });
  }, [anchor]);

  // The first item takes the focus once the menu is placed (a hidden element cannot).
  const placed = position !== null;
  useEffect(() => {
    if (placed) menu.current?.querySelector<HTMLElement>('[role="menuitem"]')?.focus();
  }, [placed]);

  useEffect(() => {
    const onPointer = (event: PointerEvent) => {
      if (menu.current && !menu.current.contains(event.target as Node)) closeRef.current(false);
    };
    document.addEventListener('pointerdown', onPointer, true);
    return () => document.removeEventListener('pointerdown', onPointer, true);
  }, []);

  function onKeyDown(event: KeyboardEvent<HTMLUListElement>) {
    const items = Array.from(menu.current?.querySelectorAll<HTMLElement>('[role="menuitem"]') ?? []);
    const index = items.indexOf(document.activeElement as HTMLElement);
    const focus = (next: number) => items[(next + items.length) % items.length]?.focus();
    switch (event.key) {
      case 'ArrowDown':
        focus(index + 1);
        break;
      case 'ArrowUp':
        focus(index - 1);
        break;
      case 'Home':
        focus(0);
        break;
      case 'End':
        focus(items.length - 1);
        break;
      case 'Escape':
        closeRef.current(true);
        break;
      case 'Tab':
        closeRef.current(true);
        break;
      default:
        return;
    }
    event.preventDefault();
    event.stopPropagation();
  }

  const choose = (action: MenuAction) => {
    closeRef.current(true);
    action.onSelect();
  };

  return createPortal(
    <ul
      ref={menu}
      role="menu"
      aria-label={label}
      className="row-menu"
      data-testid={testId}
      style={position ? { top: position.top, left: position.left } : { visibility: 'hidden', top: 0, left: 0 }}
      onKeyDown={onKeyDown}
    >
      {actions.map((action, index) => (
        <li
          key={action.id}
          role="none"
          className={action.danger && index > 0 && !actions[index - 1]?.danger ? 'row-menu__group' : undefined}
        >
          <button
            type="button"
            role="menuitem"
            tabIndex={-1}
            className={action.danger ? 'row-menu__item row-menu__item--danger' : 'row-menu__item'}
            data-action={action.id}
            onClick={() => choose(action)}
          >
            {action.label}
          </button>
        </li>
      ))}
    </ul>,
    document.body,
  );
}

/**
 * The application's keyboard shortcuts, listed in Help → About. A feature that adds one adds
 * its row here: the keys as printed on the keyboard, and the catalogue key of what it does.
 */
export interface Shortcut {
  keys: string;
  /** `aria-keyshortcuts` form, e.g. `Control+B`. */
  aria: string;
  labelKey: string;
}

export const SHORTCUTS: readonly Shortcut[] = [{ keys: 'Ctrl+B', aria: 'Control+B', labelKey: 'cpu.download.label' }];

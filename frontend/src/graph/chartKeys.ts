/**
 * The chart's keyboard, S7-Graph's shortcuts where it has them: Insert adds a step and a
 * transition, Alt+A / Alt+S / Alt+J / Alt+E an alternative branch, a simultaneous branch, a jump
 * and a sequence end, Delete removes, F2 renames or renumbers, Enter opens the step view,
 * Ctrl+Z / Ctrl+Y (and Ctrl+Shift+Z) undo and redo, Alt+Left / Alt+Right move a branch. Arrows
 * (without a modifier) move the selection; the chart handles them itself.
 */

export type ChartCommand =
  | 'insertStep'
  | 'alternative'
  | 'simultaneous'
  | 'jump'
  | 'end'
  | 'delete'
  | 'renumber'
  | 'rename'
  | 'open'
  | 'undo'
  | 'redo'
  | 'moveLeft'
  | 'moveRight';

export interface KeyLike {
  key: string;
  code?: string;
  altKey: boolean;
  ctrlKey: boolean;
  metaKey: boolean;
  shiftKey: boolean;
}

/** Alt+letter by the key's place on the keyboard (`code`), so it works in any layout (Persian, Arabic). */
const ALT_LETTERS: Record<string, ChartCommand> = { KeyA: 'alternative', KeyS: 'simultaneous', KeyJ: 'jump', KeyE: 'end' };
const ALT_KEYS: Record<string, ChartCommand> = { a: 'alternative', s: 'simultaneous', j: 'jump', e: 'end', ArrowLeft: 'moveLeft', ArrowRight: 'moveRight' };

/** The command a key stands for in the focused chart, or null. */
export function chartCommand(event: KeyLike): ChartCommand | null {
  const ctrl = event.ctrlKey || event.metaKey;
  if (ctrl && !event.altKey) {
    const key = event.key.toLowerCase();
    if (key === 'z' || event.code === 'KeyZ') return event.shiftKey ? 'redo' : 'undo';
    if (key === 'y' || event.code === 'KeyY') return 'redo';
    return null;
  }
  if (event.altKey && !ctrl) {
    if (event.key === 'ArrowLeft' || event.key === 'ArrowRight') return ALT_KEYS[event.key] ?? null;
    return (event.code ? ALT_LETTERS[event.code] : undefined) ?? ALT_KEYS[event.key.toLowerCase()] ?? null;
  }
  if (event.altKey || ctrl || event.shiftKey) return null;
  switch (event.key) {
    case 'Insert':
      return 'insertStep';
    case 'Delete':
      return 'delete';
    case 'F2':
      return 'rename';
    case 'Enter':
      return 'open';
    default:
      return null;
  }
}

/**
 * Every keyboard shortcut of the IDE, as data: the help dialog lists them, buttons take their
 * `aria-keyshortcuts` from here, and a test checks that each has a translated label. The keys
 * follow STEP 7 / TIA Portal where those have one (Ctrl+B download, Ctrl+F7-like compile) and
 * Monaco's own bindings inside the code editor, which Nasaq leaves as they are.
 */

export type Platform = 'mac' | 'linux' | 'windows';

/** Where a shortcut works: anywhere, in the code editor, or on a row of the project tree. */
export type ShortcutScope = 'global' | 'editor' | 'tree';

export const SCOPES: readonly ShortcutScope[] = ['global', 'editor', 'tree'];

export interface Shortcut {
  id: string;
  /**
   * The keys as printed on the keyboard, each entry one alternative, each alternative the keys
   * pressed together (`['Ctrl', 'B']`). `mac`/`linux` replace `keys` where the platform differs.
   */
  keys: readonly (readonly string[])[];
  mac?: readonly (readonly string[])[];
  linux?: readonly (readonly string[])[];
  /** Catalogue key of what the shortcut does (namespace `shortcuts`). */
  labelKey: string;
  scope: ShortcutScope;
}

export const SHORTCUTS: readonly Shortcut[] = [
  { id: 'download', keys: [['Ctrl', 'B']], mac: [['⌘', 'B']], labelKey: 'shortcuts.action.download', scope: 'global' },
  { id: 'compile', keys: [['Ctrl', 'F7']], mac: [['⌘', 'F7']], labelKey: 'shortcuts.action.compile', scope: 'global' },
  { id: 'help', keys: [['F1'], ['?']], labelKey: 'shortcuts.action.help', scope: 'global' },
  { id: 'closeDialog', keys: [['Esc']], labelKey: 'shortcuts.action.closeDialog', scope: 'global' },
  {
    id: 'definition',
    keys: [['F12'], ['Ctrl', 'click']],
    mac: [['F12'], ['⌘', 'click']],
    labelKey: 'shortcuts.action.definition',
    scope: 'editor',
  },
  {
    id: 'format',
    keys: [['Shift', 'Alt', 'F']],
    mac: [['⇧', '⌥', 'F']],
    linux: [['Ctrl', 'Shift', 'I']],
    labelKey: 'shortcuts.action.format',
    scope: 'editor',
  },
  { id: 'completion', keys: [['Ctrl', 'Space']], mac: [['⌃', 'Space']], labelKey: 'shortcuts.action.completion', scope: 'editor' },
  { id: 'breakpoint', keys: [['F9']], labelKey: 'shortcuts.action.breakpoint', scope: 'editor' },
  { id: 'find', keys: [['Ctrl', 'F']], mac: [['⌘', 'F']], labelKey: 'shortcuts.action.find', scope: 'editor' },
  { id: 'replace', keys: [['Ctrl', 'H']], mac: [['⌥', '⌘', 'F']], labelKey: 'shortcuts.action.replace', scope: 'editor' },
  { id: 'commands', keys: [['F1']], labelKey: 'shortcuts.action.commands', scope: 'editor' },
  { id: 'references', keys: [['Shift', 'F12']], mac: [['⇧', 'F12']], labelKey: 'xref.shortcut.references', scope: 'editor' },
  { id: 'renameSymbol', keys: [['F2']], labelKey: 'xref.shortcut.rename', scope: 'editor' },
  { id: 'open', keys: [['Enter']], labelKey: 'shortcuts.action.open', scope: 'tree' },
  { id: 'rename', keys: [['F2']], labelKey: 'shortcuts.action.rename', scope: 'tree' },
  { id: 'delete', keys: [['Delete']], labelKey: 'shortcuts.action.delete', scope: 'tree' },
  { id: 'menu', keys: [['Shift', 'F10']], labelKey: 'shortcuts.action.menu', scope: 'tree' },
];

/** The platform of this browser, from its user agent (the keys printed differ on a Mac). */
export function currentPlatform(userAgent: string = typeof navigator === 'undefined' ? '' : navigator.userAgent): Platform {
  if (/Mac|iPhone|iPad/.test(userAgent)) return 'mac';
  if (/Linux|X11|CrOS/.test(userAgent) && !/Android/.test(userAgent)) return 'linux';
  return 'windows';
}

/** The key combinations of a shortcut on a platform. */
export function keysOf(shortcut: Shortcut, platform: Platform): readonly (readonly string[])[] {
  return (platform === 'mac' ? shortcut.mac : platform === 'linux' ? shortcut.linux : undefined) ?? shortcut.keys;
}

const ARIA_NAMES: Record<string, string> = { Ctrl: 'Control', '⌘': 'Meta', '⌥': 'Alt', '⇧': 'Shift', '⌃': 'Control', Esc: 'Escape' };

/** The `aria-keyshortcuts` value of a shortcut (keyboard alternatives only; a click is not a key). */
export function ariaKeys(id: string, platform: Platform = currentPlatform()): string {
  const shortcut = SHORTCUTS.find((item) => item.id === id);
  if (!shortcut) throw new Error(`unknown shortcut ${id}`);
  return keysOf(shortcut, platform)
    .filter((combo) => !combo.includes('click'))
    .map((combo) => combo.map((key) => ARIA_NAMES[key] ?? key).join('+'))
    .join(' ');
}

/** `Ctrl+F7` for a title attribute: the first alternative, keys joined with `+`. */
export function keyText(id: string, platform: Platform = currentPlatform()): string {
  const shortcut = SHORTCUTS.find((item) => item.id === id);
  if (!shortcut) throw new Error(`unknown shortcut ${id}`);
  return (keysOf(shortcut, platform)[0] ?? []).join('+');
}

/** Ctrl (Cmd on a Mac) with `key` and no other modifier. */
export function isCommandKey(event: KeyboardEvent, key: string): boolean {
  return (event.ctrlKey || event.metaKey) && !event.altKey && !event.shiftKey && event.key.toLowerCase() === key.toLowerCase();
}

/** Whether the keystroke's target takes text (a field, or Monaco's hidden textarea). */
export function typingInto(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable) return true;
  if (target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement) return true;
  if (target instanceof HTMLInputElement) return !['button', 'checkbox', 'radio', 'submit', 'reset'].includes(target.type);
  return false;
}

/** Inside the Monaco editor, where F1 opens Monaco's command palette. */
export function inCodeEditor(target: EventTarget | null): boolean {
  return target instanceof Element && target.closest('.monaco-editor') !== null;
}

/**
 * The keystroke that opens the shortcuts dialog: F1 outside the code editor (Monaco keeps F1
 * for its command palette), or `?` where no text is typed (`؟` on Arabic and Persian layouts).
 * Ctrl+/ is left alone: Monaco toggles a line comment with it.
 */
export function opensShortcutHelp(event: KeyboardEvent): boolean {
  if (event.ctrlKey || event.metaKey || event.altKey) return false;
  if (event.key === 'F1') return !event.shiftKey && !inCodeEditor(event.target);
  return (event.key === '?' || event.key === '؟') && !typingInto(event.target);
}

/**
 * Monaco's own texts (context menu, find widget, command palette, hovers) in Arabic, Persian and
 * Vietnamese, which Monaco itself does not ship.
 *
 * How Monaco 0.57's ESM build localizes: every text is a call `localize(<n>, "English")`, and
 * `nls.js` looks `<n>` up in the array `globalThis._VSCODE_NLS_MESSAGES`, falling back to the
 * English it was given. So Nasaq fills that array before Monaco's modules run (`load.ts` calls
 * `applyMonacoLanguage` before importing `setup.ts`). The tables here are keyed by the English
 * text, which a translator can read; `messageIds.json` (written by
 * `frontend/scripts/monaco-nls-ids.mjs`, checked by a test) gives the numbers of this Monaco
 * version for each English text.
 *
 * A language switch: texts Monaco looks up when it shows them (find widget counts, "No results",
 * hovers, the command palette's groups) follow at once, as `followDocumentLanguage` swaps the
 * table when `<html lang>` changes. The labels of actions (context menu, command names) are read
 * once, when Monaco loads: they follow at the next page load — as in VS Code, where a display
 * language change restarts the window. The app's own context-menu items (go to definition,
 * breakpoints) are i18next texts and follow at once.
 */
import ar from './ar.json';
import fa from './fa.json';
import messageIds from './messageIds.json';
import vi from './vi.json';

type Table = Record<string, string>;

/** The languages whose Monaco texts Nasaq supplies (English is Monaco's own). */
export const MONACO_TABLES: Readonly<Record<string, Table>> = { ar, fa, vi };

const IDS: Readonly<Record<string, readonly number[]>> = messageIds;

declare global {
  var _VSCODE_NLS_MESSAGES: string[] | undefined;
  var _VSCODE_NLS_LANGUAGE: string | undefined;
}

/** Monaco's message array for `language`, or undefined for English (and unknown languages). */
export function monacoMessages(language: string): string[] | undefined {
  const table = MONACO_TABLES[language];
  if (!table) return undefined;
  const messages: string[] = [];
  for (const [english, translated] of Object.entries(table)) {
    for (const id of IDS[english] ?? []) messages[id] = translated;
  }
  return messages;
}

/** Makes Monaco speak `language` (from now on: see the module comment for what follows when). */
export function applyMonacoLanguage(language: string): void {
  globalThis._VSCODE_NLS_MESSAGES = monacoMessages(language);
  globalThis._VSCODE_NLS_LANGUAGE = MONACO_TABLES[language] ? language : undefined;
}

let observer: MutationObserver | null = null;

/** Applies the page's language (`<html lang>`) now and whenever the interface language changes. */
export function followDocumentLanguage(): void {
  if (typeof document === 'undefined') return;
  const root = document.documentElement;
  applyMonacoLanguage(root.lang);
  if (observer || typeof MutationObserver === 'undefined') return;
  observer = new MutationObserver(() => applyMonacoLanguage(root.lang));
  observer.observe(root, { attributes: true, attributeFilter: ['lang'] });
}

import { describe, expect, it } from 'vitest';
// @ts-expect-error -- Monaco ships no types for its message lookup (esm/vs/nls.js)
import { localize } from 'monaco-editor/nls';
import ar from '../../frontend/src/editor/monaco/locales/ar.json';
import fa from '../../frontend/src/editor/monaco/locales/fa.json';
import messageIds from '../../frontend/src/editor/monaco/locales/messageIds.json';
import vi from '../../frontend/src/editor/monaco/locales/vi.json';
import { applyMonacoLanguage, monacoMessages } from '../../frontend/src/editor/monaco/locales';
// @ts-expect-error -- a plain Node script of the front end's tooling, without types
import { messageIdsOf, scanMonacoMessages } from '../../frontend/scripts/monacoNls.mjs';

const TABLES: Record<string, Record<string, string>> = { ar, fa, vi };
const placeholders = (text: string) => [...text.matchAll(/\{\d+\}/g)].map((m) => m[0]).sort();
// Key names and technical words that stay Latin in any language, as on the keyboard.
const LATIN_ALLOWED = new Set(['Enter', 'Esc', 'Tab', 'JSON']);

describe("Monaco's own texts in Arabic, Persian and Vietnamese", () => {
  it('knows the message numbers of the installed Monaco (run frontend/scripts/monaco-nls-ids.mjs)', () => {
    const scanned = messageIdsOf(scanMonacoMessages(), Object.keys(fa)) as Record<string, number[]>;
    expect(scanned).toEqual(messageIds);
    for (const [english, ids] of Object.entries(scanned)) expect(ids.length, english).toBeGreaterThan(0);
  }, 60_000); // it reads all of Monaco's modules

  it.each(['ar', 'fa', 'vi'])('%s translates every text, keeping its {n} placeholders', (language) => {
    const table = TABLES[language]!;
    expect(Object.keys(table).sort()).toEqual(Object.keys(fa).sort());
    for (const [english, text] of Object.entries(table)) {
      expect(text.trim(), english).not.toBe('');
      expect(placeholders(text), `${language}: ${english}`).toEqual(placeholders(english));
      if (language !== 'vi') {
        const latin = (text.match(/[A-Za-z]+/g) ?? []).filter((word) => !LATIN_ALLOWED.has(word));
        expect(latin, `${language}: ${text}`).toEqual([]);
      } else {
        expect(text, english).not.toBe(english);
      }
    }
  });

  it("makes Monaco's lookup answer in the chosen language, and in English again", () => {
    const [noResults] = (messageIds as Record<string, number[]>)['No results']!;
    const [ofCount] = (messageIds as Record<string, number[]>)['{0} of {1}']!;
    applyMonacoLanguage('fa');
    expect(localize(noResults!, 'No results')).toBe('نتیجه‌ای نیست');
    expect(localize(ofCount!, '{0} of {1}', 3, 7)).toBe('3 از 7');
    applyMonacoLanguage('vi');
    expect(localize(ofCount!, '{0} of {1}', 3, 7)).toBe('3 trên 7');
    applyMonacoLanguage('en');
    expect(localize(noResults!, 'No results')).toBe('No results');
    expect(monacoMessages('en')).toBeUndefined();
  });
});

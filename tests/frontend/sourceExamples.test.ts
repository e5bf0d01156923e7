import { describe, expect, it } from 'vitest';
import { SCL_EXAMPLE, STL_EXAMPLE, sourceExample } from '../../frontend/src/editor/examples';

/** The code of a program: without its comments and block titles. */
const code = (text: string) =>
  text
    .replace(/\/\/.*$/gm, '')
    .replace(/\(\*.*?\*\)/g, '')
    .replace(/^TITLE = .*$/gm, '');

describe("a new source's example program in the interface language", () => {
  it.each(['ar', 'fa', 'vi'])('%s: translated comments, the same code', (language) => {
    for (const [kind, english] of [['stl', STL_EXAMPLE], ['scl', SCL_EXAMPLE]] as const) {
      const text = sourceExample(kind, language);
      expect(code(text)).toBe(code(english));
      expect(text).not.toBe(english);
      const comments = text.match(/\/\/.*$|\(\*.*?\*\)|^TITLE = .*$/gm) ?? [];
      const englishLeft = comments.filter((comment) => /\b(?:the|button|motor|start|level|pump|cycle)\b/i.test(comment));
      expect(englishLeft).toEqual([]);
    }
  });

  it("follows the page's language, English when it has none", () => {
    document.documentElement.lang = 'fa';
    expect(sourceExample('stl')).toContain('// شستی راه‌اندازی');
    document.documentElement.lang = '';
    expect(sourceExample('stl')).toBe(STL_EXAMPLE);
  });
});

import { describe, expect, it } from 'vitest';
import {
  CATALOGUES,
  LANGUAGES,
  detectInitialLanguage,
  directionOf,
  matchLanguage,
  nativeNameOf,
} from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';

type Tree = { [key: string]: string | Tree };

function flatten(tree: Tree, prefix = ''): Map<string, string> {
  const out = new Map<string, string>();
  for (const [key, value] of Object.entries(tree)) {
    const path = prefix ? `${prefix}.${key}` : key;
    if (typeof value === 'string') out.set(path, value);
    else for (const [inner, text] of flatten(value, path)) out.set(inner, text);
  }
  return out;
}

function placeholders(text: string): string[] {
  return [...text.matchAll(/\{\{\s*([\w.]+)\s*\}\}/g)].map((match) => match[1] ?? '').sort();
}

const flat = Object.fromEntries(LANGUAGES.map((lang) => [lang, flatten(CATALOGUES[lang] as Tree)])) as Record<
  (typeof LANGUAGES)[number],
  Map<string, string>
>;
const english = flat.en;

describe('translation catalogues', () => {
  it('has the four interface languages, English first', () => {
    expect(LANGUAGES).toEqual(['en', 'ar', 'fa', 'vi']);
    expect(english.size).toBeGreaterThan(100);
  });

  it.each(['ar', 'fa', 'vi'] as const)('%s has exactly the English key set', (lang) => {
    const keys = [...flat[lang].keys()].sort();
    expect(keys).toEqual([...english.keys()].sort());
  });

  it.each(LANGUAGES)('%s has no empty strings and only string leaves', (lang) => {
    for (const [key, text] of flat[lang]) {
      expect(typeof text, key).toBe('string');
      expect(text.trim().length, `${lang}:${key} is empty`).toBeGreaterThan(0);
    }
  });

  it.each(['ar', 'fa', 'vi'] as const)('%s uses the same {{placeholders}} as English for every key', (lang) => {
    for (const [key, text] of english) {
      expect(placeholders(flat[lang].get(key) ?? ''), `${lang}:${key}`).toEqual(placeholders(text));
    }
  });

  it.each(['ar', 'fa', 'vi'] as const)('%s is really translated, not copied from English', (lang) => {
    const same = [...english]
      .filter(([key, text]) => !key.startsWith('language.') && flat[lang].get(key) === text)
      .map(([key]) => key);
    // Only mnemonics and pure placeholders may stay identical (RUN, STOP, HOLD, "{{field}}: {{reason}}").
    expect(same.sort()).toEqual(
      [
        'cpu.mode.hold',
        'cpu.mode.run',
        'cpu.mode.stop',
        'problems.invalid_request',
        'problems.mon_bad_value',
        'problems.mon_unknown_target',
        'phrases.field_reason',
        'phrases.not_constant',
        'problemWords.NOT',
        // The names of the three views of a block are the languages' standard abbreviations.
        'lad.views.LAD',
        'lad.views.FBD',
        'lad.views.STL',
        // The trend's REAL axis is named by the S7 data type, as the watch table's formats are.
        'trend.unit.real',
      ].sort(),
    );
  });

  it('marks Arabic and Persian right-to-left, English and Vietnamese left-to-right', () => {
    expect(CATALOGUES.ar.language.dir).toBe('rtl');
    expect(CATALOGUES.fa.language.dir).toBe('rtl');
    expect(CATALOGUES.en.language.dir).toBe('ltr');
    expect(CATALOGUES.vi.language.dir).toBe('ltr');
    expect(LANGUAGES.map(directionOf)).toEqual(['ltr', 'rtl', 'rtl', 'ltr']);
  });

  it('names every language in that language', () => {
    expect(LANGUAGES.map(nativeNameOf)).toEqual(['English', 'العربية', 'فارسی', 'Tiếng Việt']);
  });

  it('keeps CPU mnemonics in Latin letters in every language', () => {
    for (const lang of LANGUAGES) {
      expect(flat[lang].get('cpu.run.label')).toMatch(/^RUN\b/);
      expect(flat[lang].get('cpu.stop.label')).toMatch(/^STOP\b/);
      expect(flat[lang].get('cpu.step.label')).toMatch(/^STEP\b/);
    }
  });

  it('writes Persian with Persian letters and Arabic with Arabic letters', () => {
    const persian = [...flat.fa.values()].join(' ');
    const arabic = [...flat.ar.values()].join(' ');
    // Arabic yeh/kaf (ي ك) do not belong in Persian text; Persian yeh/kaf/gaf/peh (ی ک گ پ) not in Arabic.
    expect(persian).not.toMatch(/[\u064A\u0643]/);
    expect(arabic).not.toMatch(/[\u06CC\u06A9\u06AF\u067E]/);
    expect(persian).toMatch(/[\u0600-\u06FF]/);
    expect(flat.vi.get('lessons.units.blocks.text')).toContain('Khối tổ chức');
  });
});

describe('initial language', () => {
  it('prefers the remembered choice', () => {
    expect(detectInitialLanguage('fa', ['vi-VN'])).toBe('fa');
  });

  it('else takes the first supported browser language', () => {
    expect(detectInitialLanguage(null, ['de-DE', 'ar-EG', 'en'])).toBe('ar');
    expect(detectInitialLanguage('xx', ['vi'])).toBe('vi');
  });

  it('else falls back to English', () => {
    expect(detectInitialLanguage(null, ['de-DE', 'fr'])).toBe('en');
    expect(detectInitialLanguage(null, [])).toBe('en');
  });

  it('matches language tags by their primary subtag', () => {
    expect(matchLanguage('FA-ir')).toBe('fa');
    expect(matchLanguage('vi_VN')).toBe('vi');
    expect(matchLanguage('arn')).toBeNull();
    expect(matchLanguage('')).toBeNull();
  });

  it.each(['ar', 'fa', 'vi'] as const)('%s nests the translated word a LAD problem names', (lang) => {
    const i18n = createI18n(lang);
    const params = { network: 2, element: 'b1', coil: 'SD', what: 'value' };
    const text = i18n.t('problems.lad_coil_incomplete', params);
    expect(text).toContain(flat[lang].get('problemWords.value'));
    expect(text).not.toMatch(/value|\$t\(/);
    expect(i18n.t('problems.lad_needs_flow', { ...params, what: 'midline' })).toContain(
      flat[lang].get('problemWords.midline'),
    );
  });
});

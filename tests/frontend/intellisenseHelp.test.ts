/**
 * The hover help catalogue: every instruction the STL tokenizer knows (both mnemonic sets) and
 * every SCL standard function has a text in all four languages, with its placeholders filled,
 * really translated; the SIMATIC spellings share the international entries.
 */
import { describe, expect, it } from 'vitest';
import { SCL_STANDARD_FUNCTIONS } from '../../frontend/src/editor/languages/scl';
import { GERMAN_MNEMONICS, INTERNATIONAL_MNEMONICS, STL_MNEMONICS } from '../../frontend/src/editor/languages/stl';
import { HELP, functionHelp, instructionHelp } from '../../frontend/src/editor/intellisense/help';
import { STL_HELP } from '../../frontend/src/editor/intellisense/help/instructions';

const LANGUAGES = ['en', 'ar', 'fa', 'vi'] as const;
const ARABIC_SCRIPT = /[\u0600-\u06FF]/;
const VIETNAMESE_LETTERS = /[ăâđêôơưạảấầẩẫậắằẳẵặẹẻẽếềểễệỉịọỏốồổỗộớờởỡợụủứừửữựỳỵỷỹ]/i;

function keys(object: object): string[] {
  return Object.keys(object).sort();
}

describe('the help catalogue', () => {
  it('has the same keys in every language', () => {
    for (const language of LANGUAGES) {
      for (const part of ['labels', 'words', 'stl', 'scl'] as const) {
        expect(keys(HELP[language][part]), `${language}.${part}`).toEqual(keys(HELP.en[part]));
      }
    }
  });

  it('is written in each language, not copied from English', () => {
    for (const part of ['labels', 'stl', 'scl'] as const) {
      for (const [key, english] of Object.entries(HELP.en[part])) {
        const ar = (HELP.ar[part] as Record<string, string>)[key]!;
        const fa = (HELP.fa[part] as Record<string, string>)[key]!;
        const vi = (HELP.vi[part] as Record<string, string>)[key]!;
        expect(ar, `ar ${part}.${key}`).toMatch(ARABIC_SCRIPT);
        expect(fa, `fa ${part}.${key}`).toMatch(ARABIC_SCRIPT);
        expect(fa, `fa ${part}.${key} is not the Arabic text`).not.toBe(ar);
        expect(vi, `vi ${part}.${key}`).not.toBe(english);
      }
    }
    const vietnamese = Object.values(HELP.vi.stl).filter((text) => VIETNAMESE_LETTERS.test(text));
    expect(vietnamese.length).toBe(Object.keys(HELP.vi.stl).length);
  });

  it('keeps the placeholders of each template', () => {
    for (const part of ['stl', 'scl'] as const) {
      for (const [key, english] of Object.entries(HELP.en[part])) {
        const wanted = (english.match(/\{\w+\}/g) ?? []).sort();
        for (const language of LANGUAGES) {
          const text = (HELP[language][part] as Record<string, string>)[key]!;
          expect((text.match(/\{\w+\}/g) ?? []).sort(), `${language} ${part}.${key}`).toEqual(wanted);
        }
      }
    }
  });

  it('has a family text for every instruction entry', () => {
    expect(keys(STL_HELP)).toEqual([...INTERNATIONAL_MNEMONICS].sort());
    for (const [mnemonic, entry] of Object.entries(STL_HELP)) {
      expect(HELP.en.stl, mnemonic).toHaveProperty(entry.family);
    }
  });
});

describe('instruction help', () => {
  it.each(LANGUAGES)('explains every instruction the STL tokenizer knows, in %s', (language) => {
    for (const mnemonic of STL_MNEMONICS) {
      const sets = [INTERNATIONAL_MNEMONICS.includes(mnemonic) ? 'en' : null, GERMAN_MNEMONICS.includes(mnemonic) ? 'de' : null];
      for (const set of sets.filter((item): item is 'en' | 'de' => item !== null)) {
        const help = instructionHelp(mnemonic, set, language);
        expect(help, `${mnemonic} (${set})`).not.toBeNull();
        expect(help!.text.length, `${mnemonic} (${set})`).toBeGreaterThan(10);
        expect(help!.text, `${mnemonic} (${set})`).not.toMatch(/\{\w+\}/);
        expect(help!.syntax, mnemonic).not.toContain('{m}');
      }
    }
  });

  it('gives a German spelling the entry of its international instruction', () => {
    expect(instructionHelp('U', 'de', 'en')!.text).toBe(instructionHelp('A', 'en', 'en')!.text);
    expect(instructionHelp('SPB', 'de', 'fa')!.text).toBe(instructionHelp('JC', 'en', 'fa')!.text);
    expect(instructionHelp('U', 'de', 'en')!.otherSpelling).toBe('A');
    expect(instructionHelp('JC', 'en', 'en')!.otherSpelling).toBe('SPB');
    // SE is the on-delay timer in German and the extended pulse internationally
    expect(instructionHelp('SE', 'de', 'en')!.text).toContain('on-delay');
    expect(instructionHelp('SE', 'en', 'en')!.text).toContain('extended pulse');
    expect(instructionHelp('SV', 'de', 'en')!.text).toContain('extended pulse');
    expect(instructionHelp('U', 'en', 'en')).toBeNull();
  });

  it('names the status bits an instruction writes', () => {
    expect(instructionHelp('A', 'en', 'en')!.status).toEqual(['RLO', '/FC', 'STA', 'OR']);
    expect(instructionHelp('+I', 'en', 'en')!.status).toEqual(['CC0', 'CC1', 'OV', 'OS']);
    expect(instructionHelp('L', 'en', 'en')!.status).toEqual([]);
    expect(instructionHelp('+I', 'en', 'vi')!.text).toContain('số nguyên (16 bit)');
  });
});

describe('standard function help', () => {
  it.each(LANGUAGES)('explains every SCL standard function, in %s', (language) => {
    for (const name of SCL_STANDARD_FUNCTIONS) {
      const help = functionHelp(name, language);
      expect(help, name).not.toBeNull();
      expect(help!.text, name).not.toMatch(/\{\w+\}/);
      expect(help!.text.length, name).toBeGreaterThan(8);
    }
  });

  it('shows the parameters in the syntax', () => {
    expect(functionHelp('LIMIT', 'en')!.syntax).toBe('LIMIT(MN := ..., IN := ..., MX := ...) : ANY');
    expect(functionHelp('INT_TO_REAL', 'en')!.text).toBe('Converts a value of type INT to REAL.');
    expect(functionHelp('WORD_BCD_TO_INT', 'en')!.syntax).toBe('WORD_BCD_TO_INT(...) : INT');
    expect(functionHelp('Scale', 'en')).toBeNull();
  });
});

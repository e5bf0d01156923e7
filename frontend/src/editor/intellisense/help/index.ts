/**
 * The hover help catalogue: the texts of one language filled in for an STL instruction (in the
 * mnemonic set of its file) or an SCL standard function. Unknown languages fall back to English.
 */
import { ar } from './ar';
import { en, type HelpCatalogue } from './en';
import { fa } from './fa';
import { STL_HELP, sclFunctionHelp, type StatusBit } from './instructions';
import { vi } from './vi';
import { spellingOf, toInternational, type MnemonicSet } from '../mnemonicSet';

export const HELP: Readonly<Record<'en' | 'ar' | 'fa' | 'vi', HelpCatalogue>> = { en, ar, fa, vi };
export type HelpLanguage = keyof typeof HELP;

export function catalogueOf(language: string): HelpCatalogue {
  return HELP[(language in HELP ? language : 'en') as HelpLanguage];
}

/** `{name}` placeholders filled: a word of the catalogue, or `=literal` as written. */
export function fill(template: string, params: Readonly<Record<string, string>> | undefined, catalogue: HelpCatalogue): string {
  return template.replace(/\{(\w+)\}/g, (whole, key: string) => {
    const value = params?.[key];
    if (value === undefined) return whole;
    if (value.startsWith('=')) return value.slice(1);
    return (catalogue.words as Record<string, string>)[value] ?? value;
  });
}

export interface InstructionHelp {
  /** As the file spells it. */
  mnemonic: string;
  /** The other set's spelling, when it differs. */
  otherSpelling: string | null;
  syntax: string;
  text: string;
  status: readonly StatusBit[];
}

/** The help of an STL instruction written `mnemonic` in a file of the given set; null if none. */
export function instructionHelp(mnemonic: string, set: MnemonicSet, language: string): InstructionHelp | null {
  const upper = mnemonic.toUpperCase();
  const international = toInternational(upper, set);
  const entry = international ? STL_HELP[international] : undefined;
  if (!international || !entry) return null;
  const catalogue = catalogueOf(language);
  const other = spellingOf(international, set === 'de' ? 'en' : 'de');
  return {
    mnemonic: upper,
    otherSpelling: other !== upper ? other : null,
    syntax: entry.syntax.replaceAll('{m}', upper),
    text: fill((catalogue.stl as Record<string, string>)[entry.family] ?? '', entry.params, catalogue),
    status: entry.status,
  };
}

export interface FunctionHelp {
  name: string;
  syntax: string;
  text: string;
  result: string;
  inputs: readonly string[];
}

/** The help of an SCL standard function; null for other names. */
export function functionHelp(name: string, language: string): FunctionHelp | null {
  const upper = name.toUpperCase();
  const entry = sclFunctionHelp(upper);
  if (!entry) return null;
  const catalogue = catalogueOf(language);
  const args = entry.inputs.length ? entry.inputs.map((input) => `${input} := ...`).join(', ') : '...';
  return {
    name: upper,
    syntax: `${upper}(${args}) : ${entry.result}`,
    text: fill((catalogue.scl as Record<string, string>)[entry.family] ?? '', entry.params, catalogue),
    result: entry.result,
    inputs: entry.inputs,
  };
}

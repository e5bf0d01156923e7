/**
 * Which mnemonic set an STL file is written in, as the compiler decides it
 * (`nasaq.lang.stl.mnemonics.detect`): the instructions only one set has (`U`, `SPB`, `AUF` are
 * SIMATIC/German; `A`, `JC`, `OPN` international) and the address areas of the operands (`E`,
 * `A`, `EW`, `AB` German; `I`, `Q`, `IW`, `QB` international) each count one vote; German wins
 * only with more votes, so a new or empty file gets the international set. Completion offers
 * the file's set, hover help names the other set's spelling.
 */
import { GERMAN_MNEMONICS, GERMAN_TO_INTERNATIONAL, INTERNATIONAL_MNEMONICS } from '../languages/stl';

export type MnemonicSet = 'en' | 'de';

const INTERNATIONAL = new Set(INTERNATIONAL_MNEMONICS);
const GERMAN = new Set(GERMAN_MNEMONICS);
const GERMAN_ONLY = new Set(GERMAN_MNEMONICS.filter((m) => !INTERNATIONAL.has(m)));
const INTERNATIONAL_ONLY = new Set(INTERNATIONAL_MNEMONICS.filter((m) => !GERMAN.has(m)));
const TO_GERMAN: Readonly<Record<string, string>> = Object.fromEntries(
  Object.entries(GERMAN_TO_INTERNATIONAL).map(([german, international]) => [international, german]),
);

const GERMAN_AREA = /^(?:E|A|EB|EW|ED|AB|AW|AD|PEB|PEW|PED|PAB|PAW|PAD)\s*\d/i;
const INTERNATIONAL_AREA = /^(?:I|Q|IB|IW|ID|QB|QW|QD|PIB|PIW|PID|PQB|PQW|PQD)\s*\d/i;
/** A statement: an optional label, the instruction, its operand. */
const STATEMENT = /^\s*(?:[A-Za-z_]\w{0,3}\s*:(?!=)\s*)?([^\s;/]+)\s*([^;/]*)/;

export function detectMnemonicSet(text: string): MnemonicSet {
  let german = 0;
  let international = 0;
  let code = false;
  for (const line of text.split('\n')) {
    if (/^\s*BEGIN\b/i.test(line)) code = true;
    else if (/^\s*END_/i.test(line)) code = false;
    if (!code) continue;
    const match = STATEMENT.exec(line);
    if (!match) continue;
    const mnemonic = (match[1] ?? '').toUpperCase();
    if (GERMAN_ONLY.has(mnemonic)) german += 1;
    else if (INTERNATIONAL_ONLY.has(mnemonic)) international += 1;
    const operand = (match[2] ?? '').trim();
    if (GERMAN_AREA.test(operand)) german += 1;
    else if (INTERNATIONAL_AREA.test(operand)) international += 1;
  }
  return german > international ? 'de' : 'en';
}

/** The international mnemonic of an instruction written in a file of `set`; null if unknown. */
export function toInternational(mnemonic: string, set: MnemonicSet): string | null {
  const upper = mnemonic.toUpperCase();
  if (set === 'de') {
    if (upper in GERMAN_TO_INTERNATIONAL) return GERMAN_TO_INTERNATIONAL[upper] ?? null;
    return GERMAN.has(upper) ? upper : null;
  }
  return INTERNATIONAL.has(upper) ? upper : null;
}

/** How `set` spells an international mnemonic. */
export function spellingOf(international: string, set: MnemonicSet): string {
  return set === 'de' ? (TO_GERMAN[international] ?? international) : international;
}

/** The instructions a file of `set` may use, as it spells them. */
export function mnemonicsOf(set: MnemonicSet): readonly string[] {
  return set === 'de' ? GERMAN_MNEMONICS : INTERNATIONAL_MNEMONICS;
}

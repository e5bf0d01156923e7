/**
 * S7 analog values as the S7-300 module data manual represents them ("Representation of analog
 * values"): a channel's nominal range is 0..27648 (unipolar: 0-10 V, 0/4-20 mA) or
 * -27648..27648 (bipolar: ±10 V, ±20 mA); the overrange goes up to 32511 (and down to -32512
 * bipolar), the underrange of unipolar inputs down to -4864 (4-20 mA: 1.185 mA); 32767 is an
 * overflow (or a wire break) and -32768 an underflow. The program scales a raw value to
 * engineering units, usually with FC105 SCALE (FC106 UNSCALE for outputs):
 * `OUT = (IN - K1) / (K2 - K1) * (HI_LIM - LO_LIM) + LO_LIM`, K1 = 0 (bipolar -27648), K2 = 27648.
 */
import type { SourceText } from '../api/sessions';

export const NOMINAL = 27648;
export const OVERRANGE = 32511;
export const UNIPOLAR_UNDERRANGE = -4864;
export const BIPOLAR_UNDERRANGE = -32512;
export const OVERFLOW = 32767;
export const UNDERFLOW = -32768;

export type Region = 'overflow' | 'overrange' | 'nominal' | 'underrange' | 'underflow';

/** Where a raw value lies in the module's range. */
export function regionOf(raw: number, bipolar: boolean): Region {
  const low = bipolar ? -NOMINAL : 0;
  const underrange = bipolar ? BIPOLAR_UNDERRANGE : UNIPOLAR_UNDERRANGE;
  if (raw > OVERRANGE) return 'overflow';
  if (raw > NOMINAL) return 'overrange';
  if (raw >= low) return 'nominal';
  if (raw >= underrange) return 'underrange';
  return 'underflow';
}

/** The slider's ends: the whole measuring range including over- and underrange. */
export function sliderRange(bipolar: boolean): { min: number; max: number } {
  return { min: bipolar ? BIPOLAR_UNDERRANGE : UNIPOLAR_UNDERRANGE, max: OVERRANGE };
}

/** The raw value as percent of the nominal range (27648 = 100 %). */
export function percentOf(raw: number): number {
  return (raw / NOMINAL) * 100;
}

export interface Scale {
  /** The block that scales (`FC105`, `"Scale"`, `SCALE`). */
  block: string;
  low: number;
  high: number;
  bipolar: boolean;
  /** Where the program puts the scaled value (`"Level"`, `MD10`), when it says. */
  target: string | null;
}

/** FC105 SCALE's formula (FC106 UNSCALE is its inverse: the same pair of values). */
export function scaled(raw: number, scale: Scale): number {
  const k1 = scale.bipolar ? -NOMINAL : 0;
  return ((raw - k1) / (NOMINAL - k1)) * (scale.high - scale.low) + scale.low;
}

/** A number for the hint: at most 2 decimals, no trailing zeros. */
export function shortNumber(value: number): string {
  return String(Number(value.toFixed(2)));
}

const LOW_NAMES = new Set(['LO_LIM', 'LOW', 'LO', 'MIN', 'LOW_LIM', 'LOWER']);
const HIGH_NAMES = new Set(['HI_LIM', 'HIGH', 'HI', 'MAX', 'HIGH_LIM', 'UPPER']);
const RESULT_NAMES = ['OUT', 'RET_VAL'];
// A call's block and its parameter list: `CALL "Scale" (…)`, `CALL FC 105 (…)`, `x := SCALE(…)`.
const CALL = /(?:CALL\s+)?("[^"]+"|FC\s*\d+|[A-Za-z_]\w*)\s*(?:,\s*(?:"[^"]+"|DB\s*\d+)\s*)?\(([^()]*:=[^()]*)\)/gi;
const LITERAL = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?$/i;

function parameters(list: string): Map<string, string> {
  const found = new Map<string, string>();
  for (const part of list.split(/[,;](?=\s*[A-Za-z_]\w*\s*:?=)/)) {
    const match = /^\s*([A-Za-z_]\w*)\s*:?=>?\s*(.*?)\s*[,;]?\s*$/s.exec(part);
    if (match) found.set(match[1]!.toUpperCase(), match[2]!.replace(/\s+/g, ' ').trim());
  }
  return found;
}

/** `IW 64`, `%IW64`, `PEW 256` → `IW64`, `PIW256`; a quoted symbol stays as it is. */
function operand(text: string): string {
  const compact = text.replace(/\s+/g, '').replace(/^%/, '').toUpperCase();
  const match = /^(P?)([EAIQ])W(\d+)$/.exec(compact);
  if (!match) return text.trim();
  return `${match[1]}${match[2] === 'E' ? 'I' : match[2] === 'A' ? 'Q' : match[2]}W${match[3]}`;
}

function numberOf(text: string | undefined): number | null {
  if (text === undefined) return null;
  const clean = text.replace(/^REAL#/i, '');
  return LITERAL.test(clean) ? Number(clean) : null;
}

/**
 * How the program scales the analog word at byte `byte` (named `names`: its addresses and its
 * symbol in quotes): the first call that passes it and has a low and a high limit given as
 * numbers (FC105's `LO_LIM`/`HI_LIM`, or `Low`/`High` of a scaling function of the project).
 * Limits held in variables are not known before the program runs: no scale then.
 */
export function findScale(sources: readonly SourceText[], names: readonly string[]): Scale | null {
  const wanted = new Set(names.map((name) => operand(name).toUpperCase()));
  for (const source of sources) {
    if (!/\.(?:awl|stl|scl)$/i.test(source.name)) continue;
    for (const match of source.text.matchAll(CALL)) {
      const params = parameters(match[2]!);
      const passed = [...params].find(([, value]) => wanted.has(operand(value).toUpperCase()))?.[0];
      if (passed === undefined) continue;
      let low: number | null = null;
      let high: number | null = null;
      for (const [name, value] of params) {
        if (LOW_NAMES.has(name)) low = numberOf(value);
        if (HIGH_NAMES.has(name)) high = numberOf(value);
      }
      if (low === null || high === null) continue;
      // The engineering value: FC105's OUT (a function's RET_VAL), or FC106's IN when the word is its OUT.
      const result = RESULT_NAMES.includes(passed) ? params.get('IN') : RESULT_NAMES.map((name) => params.get(name)).find(Boolean);
      return {
        block: match[1]!.replace(/\s+/g, ''),
        low,
        high,
        bipolar: /^TRUE$/i.test(params.get('BIPOLAR') ?? ''),
        target: result ?? null,
      };
    }
  }
  return null;
}

/** What a user typed in a word's field: decimal, `16#…`/`W#16#…` or `2#…`; null if not a word. */
export function parseWord(text: string): number | null {
  const clean = text.trim().replace(/_/g, '').toUpperCase();
  let value: number;
  if (/^[+-]?\d+$/.test(clean)) {
    value = Number(clean);
    return value >= UNDERFLOW && value <= OVERFLOW ? value : null;
  }
  if (/^(?:W#)?16#[0-9A-F]{1,4}$/.test(clean)) value = parseInt(clean.slice(clean.lastIndexOf('#') + 1), 16);
  else if (/^2#[01]{1,16}$/.test(clean)) value = parseInt(clean.slice(2), 2);
  else return null;
  // A hex or binary pattern above 16#7FFF is a negative INT, as the module sends it.
  return value > OVERFLOW ? value - 0x10000 : value;
}

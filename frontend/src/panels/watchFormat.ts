/**
 * Display formats of the watch table, as STEP 7's "Monitor/Modify Variables" offers them: the
 * value a frame carries (typed by the entry's type: INT signed, REAL a number, BOOL true/false,
 * CHAR a character, TIME and S5TIME milliseconds) shown as binary, hex, decimal, REAL, characters
 * or a time.
 *
 * The S7-1200/1500 types show as TIA Portal's watch table shows them: SINT/LINT/LTIME signed,
 * USINT ... ULINT unsigned, LREAL a double (15 significant digits), LTIME in nanoseconds as
 * `LT#1D_2H_3M_4S_5MS_6US_7NS`, a WCHAR as its character, a STRING/WSTRING quoted. The 64-bit
 * integers come as numbers, or as their digits in a string above 2**53 (what a JSON number
 * keeps exact), and are formatted with BigInt so BIN and HEX show every bit.
 *
 * S5TIME and COUNTER are STEP 7's SIMATIC_TIME and COUNTER formats. A timer (`T1`) shows its
 * time value as `S5T#1S850MS` and a counter (`C5`) its count as `C#5`. A WORD in these formats
 * is read as the CPU stores them: a timer word holds the time base in bits 12-13 (00 = 10 ms,
 * 01 = 100 ms, 10 = 1 s, 11 = 10 s) and three BCD digits (0-999) in bits 0-11; a counter word
 * three BCD digits. A word that is no valid BCD shows as hex, as it could not be loaded as a
 * time or count. Modify values typed in these formats are stored back in the same encoding
 * (the smallest time base that holds the time; finer parts dropped, as `L S5T#` does).
 */
import type { WatchValue } from '../api/monitor';

export type DisplayFormat = 'bool' | 'bin' | 'hex' | 'dec' | 'real' | 'char' | 'time' | 's5time' | 'counter';

/** The formats' names, as STEP 7 writes them; they stay Latin in every language, like mnemonics. */
export const FORMAT_NAMES: Record<DisplayFormat, string> = {
  bool: 'BOOL',
  bin: 'BIN',
  hex: 'HEX',
  dec: 'DEC',
  real: 'REAL',
  char: 'CHAR',
  time: 'TIME',
  s5time: 'S5TIME',
  counter: 'COUNTER',
};

/** Bits of each elementary type a watch entry can have. */
const TYPE_BITS: Record<string, number> = {
  BOOL: 1,
  BYTE: 8,
  CHAR: 8,
  WORD: 16,
  INT: 16,
  S5TIME: 16,
  DATE: 16,
  DWORD: 32,
  DINT: 32,
  REAL: 32,
  TIME: 32,
  TIME_OF_DAY: 32,
  TOD: 32,
  SINT: 8,
  USINT: 8,
  UINT: 16,
  WCHAR: 16,
  UDINT: 32,
  LINT: 64,
  ULINT: 64,
  LWORD: 64,
  LREAL: 64,
  LTIME: 64,
};
const SIGNED = new Set(['INT', 'DINT', 'TIME', 'SINT']);
const SIGNED_64 = new Set(['LINT', 'LTIME']);

export function bitsOf(type: string | undefined): number | null {
  return type ? (TYPE_BITS[type.toUpperCase()] ?? null) : null;
}

/** The formats that make sense for a type (none for a type the table cannot show as a number). */
export function formatsFor(type: string | undefined): DisplayFormat[] {
  const kind = type?.toUpperCase();
  if (kind === 'TIMER') return ['s5time', 'dec'];
  if (kind === 'COUNTER') return ['counter', 'dec'];
  const bits = bitsOf(type);
  if (bits === null) return [];
  if (bits === 1) return ['bool', 'bin'];
  if (kind === 'LTIME') return ['time', 'dec', 'hex', 'bin'];
  if (kind === 'LREAL') return ['real', 'hex', 'bin'];
  if (bits === 64) return ['bin', 'hex', 'dec', 'real', 'char'];
  if (kind === 'WCHAR') return ['char', 'hex', 'dec', 'bin'];
  if (bits === 32) return ['bin', 'hex', 'dec', 'real', 'char', 'time'];
  if (kind === 'S5TIME') return ['s5time', 'dec'];
  if (kind === 'WORD') return ['bin', 'hex', 'dec', 'char', 's5time', 'counter'];
  return ['bin', 'hex', 'dec', 'char'];
}

/** The format a new row of this type starts with. */
export function defaultFormat(type: string | undefined): DisplayFormat {
  switch (type?.toUpperCase()) {
    case 'BOOL':
      return 'bool';
    case 'INT':
    case 'DINT':
    case 'DATE':
    case 'SINT':
    case 'USINT':
    case 'UINT':
    case 'UDINT':
    case 'LINT':
    case 'ULINT':
      return 'dec';
    case 'REAL':
    case 'LREAL':
      return 'real';
    case 'CHAR':
    case 'WCHAR':
      return 'char';
    case 'S5TIME':
    case 'TIMER':
      return 's5time';
    case 'COUNTER':
      return 'counter';
    case 'TIME':
    case 'TIME_OF_DAY':
    case 'TOD':
    case 'LTIME':
      return 'time';
    default:
      return 'hex';
  }
}

const floatView = new DataView(new ArrayBuffer(4));

function floatBits(value: number): number {
  floatView.setFloat32(0, value);
  return floatView.getUint32(0);
}

function bitsFloat(pattern: number): number {
  floatView.setUint32(0, pattern >>> 0);
  return floatView.getFloat32(0);
}

/** The unsigned bit pattern of a value of `type` (REAL as IEEE 754 single). */
function patternOf(value: number | string | boolean, type: string, bits: number): number | null {
  if (typeof value === 'boolean') return value ? 1 : 0;
  if (typeof value === 'string') {
    if (type === 'CHAR') return value.charCodeAt(0) & 0xff;
    if (type === 'WCHAR') return value.charCodeAt(0) & 0xffff;
    if (type === 'REAL') {
      const special: Record<string, number> = { NaN: Number.NaN, '+Inf': Infinity, '-Inf': -Infinity };
      return value in special ? floatBits(special[value]!) : null;
    }
    return null;
  }
  if (type === 'REAL') return floatBits(value);
  if (type === 'S5TIME') return null; // the value is the time in ms; its BCD pattern is not sent
  if (bits === 32) return value >>> 0;
  return ((value % 2 ** bits) + 2 ** bits) % 2 ** bits;
}

function signedOf(pattern: number, bits: number): number {
  return pattern >= 2 ** (bits - 1) ? pattern - 2 ** bits : pattern;
}

function formatReal(value: number): string {
  if (Number.isNaN(value)) return 'NaN';
  if (!Number.isFinite(value)) return value > 0 ? '+Inf' : '-Inf';
  if (value !== 0 && (Math.abs(value) >= 1e7 || Math.abs(value) < 1e-4)) return value.toExponential(6);
  return String(Number(value.toPrecision(7)));
}

/** `T#1D_2H_3M_4S_5MS`, `T#-500MS`, `T#0MS`. */
export function formatTime(ms: number, prefix = 'T#'): string {
  const sign = ms < 0 ? '-' : '';
  let rest = Math.abs(Math.trunc(ms));
  const parts: string[] = [];
  for (const [unit, size] of [
    ['D', 86_400_000],
    ['H', 3_600_000],
    ['M', 60_000],
    ['S', 1_000],
  ] as const) {
    if (rest >= size) {
      parts.push(`${Math.floor(rest / size)}${unit}`);
      rest %= size;
    }
  }
  if (rest > 0 || parts.length === 0) parts.push(`${rest}MS`);
  return `${prefix}${sign}${parts.join('_')}`;
}

function formatTimeOfDay(ms: number): string {
  const h = Math.floor(ms / 3_600_000);
  const m = Math.floor((ms % 3_600_000) / 60_000);
  const s = Math.floor((ms % 60_000) / 1000);
  const rest = ms % 1000;
  return `TOD#${h}:${String(m).padStart(2, '0')}:${String(s).padStart(2, '0')}.${String(rest).padStart(3, '0')}`;
}

function formatChars(pattern: number, bits: number): string {
  let text = '';
  for (let shift = bits - 8; shift >= 0; shift -= 8) {
    const code = Math.floor(pattern / 2 ** shift) & 0xff;
    text += code >= 32 && code < 127 ? String.fromCharCode(code) : '.';
  }
  return `'${text}'`;
}

const HEX_PREFIX: Record<number, string> = { 8: 'B#16#', 16: 'W#16#', 32: 'DW#16#', 64: 'LW#16#' };
const SPECIAL_FLOATS: Record<string, number> = { NaN: Number.NaN, '+Inf': Infinity, '-Inf': -Infinity };

const doubleView = new DataView(new ArrayBuffer(8));

/** The unsigned 64-bit pattern of a value of a 64-bit type (LREAL as IEEE 754 double). */
function longPatternOf(value: number | string | boolean, type: string): bigint | null {
  if (type === 'LREAL') {
    const number = typeof value === 'string' ? SPECIAL_FLOATS[value] : typeof value === 'number' ? value : undefined;
    if (number === undefined) return null;
    doubleView.setFloat64(0, number);
    return doubleView.getBigUint64(0);
  }
  if (typeof value === 'boolean') return value ? 1n : 0n;
  if (typeof value === 'number') return Number.isInteger(value) ? BigInt.asUintN(64, BigInt(value)) : null;
  return /^-?\d+$/.test(value) ? BigInt.asUintN(64, BigInt(value)) : null;
}

/** `LT#1D_2H_3M_4S_5MS_6US_7NS`, `LT#-500MS`, `LT#0NS`: an LTIME (nanoseconds) as TIA writes it. */
export function formatLongTime(ns: bigint): string {
  const sign = ns < 0n ? '-' : '';
  let rest = ns < 0n ? -ns : ns;
  const parts: string[] = [];
  for (const [unit, size] of [
    ['D', 86_400_000_000_000n],
    ['H', 3_600_000_000_000n],
    ['M', 60_000_000_000n],
    ['S', 1_000_000_000n],
    ['MS', 1_000_000n],
    ['US', 1_000n],
  ] as const) {
    if (rest >= size) {
      parts.push(`${rest / size}${unit}`);
      rest %= size;
    }
  }
  if (rest > 0n || parts.length === 0) parts.push(`${rest}NS`);
  return `LT#${sign}${parts.join('_')}`;
}

/** An LREAL as TIA shows it: up to 15 significant digits, exponent outside 1e-4 .. 1e15. */
function formatLongReal(value: number): string {
  if (Number.isNaN(value)) return 'NaN';
  if (!Number.isFinite(value)) return value > 0 ? '+Inf' : '-Inf';
  if (value !== 0 && (Math.abs(value) >= 1e15 || Math.abs(value) < 1e-4)) {
    return Number(value.toPrecision(15)).toExponential();
  }
  return String(Number(value.toPrecision(15)));
}

function formatLong(value: number | string | boolean, kind: string, format: DisplayFormat): string {
  if (kind === 'LREAL' && typeof value === 'string' && value in SPECIAL_FLOATS && format === 'real') return value;
  const pattern = longPatternOf(value, kind);
  if (pattern === null) return String(value);
  switch (format) {
    case 'bin':
      return `2#${pattern.toString(2).padStart(64, '0').replace(/(\d{4})(?=\d)/g, '$1_')}`;
    case 'hex':
      return `LW#16#${pattern.toString(16).toUpperCase().padStart(16, '0').replace(/([0-9A-F]{4})(?=[0-9A-F])/g, '$1_')}`;
    case 'dec':
      return String(SIGNED_64.has(kind) ? BigInt.asIntN(64, pattern) : pattern);
    case 'real':
      doubleView.setBigUint64(0, pattern);
      return formatLongReal(doubleView.getFloat64(0));
    case 'time':
      return formatLongTime(BigInt.asIntN(64, pattern));
    case 'char': {
      let text = '';
      for (let shift = 56n; shift >= 0n; shift -= 8n) {
        const code = Number((pattern >> shift) & 0xffn);
        text += code >= 32 && code < 127 ? String.fromCharCode(code) : '.';
      }
      return `'${text}'`;
    }
    default:
      return String(value);
  }
}

/** A watch value as text in `format`; '' when there is no value yet. */
export function formatValue(value: WatchValue['value'], type: string | undefined, format: DisplayFormat): string {
  if (value === null || value === undefined) return '';
  const kind = (type ?? '').toUpperCase();
  if (/^W?STRING\[/.test(kind) && typeof value === 'string') return `'${value.replace(/'/g, "''")}'`;
  if ((kind === 'TIMER' || kind === 'COUNTER') && typeof value === 'number') {
    if (format === 'dec') return String(value);
    return kind === 'TIMER' ? formatS5Time(value) : `C#${value}`;
  }
  const bits = bitsOf(kind);
  if (bits === null) return typeof value === 'string' ? value : String(value);
  if (bits === 1) {
    const on = value === true || value === 1;
    return format === 'bin' ? (on ? '2#1' : '2#0') : on ? 'TRUE' : 'FALSE';
  }
  if (bits === 64) return formatLong(value, kind, format);
  if (kind === 'WCHAR' && typeof value === 'string' && format === 'char') return `WCHAR#'${value}'`;
  if (kind === 'S5TIME' && typeof value === 'number') return format === 'dec' ? String(value) : formatS5Time(value);
  if (kind === 'REAL' && (format === 'real' || typeof value === 'string') && format !== 'bin' && format !== 'hex') {
    return typeof value === 'string' ? value : formatReal(Number(value));
  }
  const pattern = patternOf(value, kind, bits);
  if (pattern === null) return String(value);
  switch (format) {
    case 'bin': {
      const digits = pattern.toString(2).padStart(bits, '0');
      return `2#${digits.replace(/(\d{4})(?=\d)/g, '$1_')}`;
    }
    case 'hex':
      return `${HEX_PREFIX[bits] ?? '16#'}${pattern.toString(16).toUpperCase().padStart(bits / 4, '0')}`;
    case 'dec':
      return String(SIGNED.has(kind) ? signedOf(pattern, bits) : kind === 'REAL' ? signedOf(pattern, 32) : pattern);
    case 'real':
      return bits === 32 ? formatReal(bitsFloat(pattern)) : String(pattern);
    case 'char':
      return formatChars(pattern, bits);
    case 's5time': {
      const ms = bits === 16 ? s5TimeOfWord(pattern) : null;
      return ms === null ? `W#16#${pattern.toString(16).toUpperCase().padStart(4, '0')}` : formatS5Time(ms);
    }
    case 'counter': {
      const count = bits === 16 ? countOfWord(pattern) : null;
      return count === null ? `W#16#${pattern.toString(16).toUpperCase().padStart(4, '0')}` : `C#${count}`;
    }
    case 'time':
      if (kind === 'TIME_OF_DAY' || kind === 'TOD') return formatTimeOfDay(pattern);
      return formatTime(signedOf(pattern, 32));
    default:
      return value ? 'TRUE' : 'FALSE';
  }
}

/** The time bases of S5TIME, by the code in bits 12-13 of a timer word. */
const S5_BASES_MS = [10, 100, 1000, 10_000] as const;
/** The longest S5TIME: 999 × 10 s. */
export const S5TIME_MAX_MS = 9_990_000;

/** Three BCD digits (bits 0-11) as a number; null when a nibble is above 9. */
function bcd3(pattern: number): number | null {
  let value = 0;
  for (let shift = 8; shift >= 0; shift -= 4) {
    const digit = (pattern >> shift) & 0xf;
    if (digit > 9) return null;
    value = value * 10 + digit;
  }
  return value;
}

function toBcd3(value: number): number {
  return (Math.floor(value / 100) << 8) | (Math.floor(value / 10) % 10 << 4) | value % 10;
}

/** The time of a timer word in ms; null when its value is no BCD. */
export function s5TimeOfWord(word: number): number | null {
  const value = bcd3(word & 0xfff);
  return value === null ? null : value * S5_BASES_MS[(word >> 12) & 3]!;
}

/** The count of a counter word; null when it is no BCD. */
export function countOfWord(word: number): number | null {
  return word & 0xf000 ? null : bcd3(word);
}

/** A time in ms as a timer word: the smallest base that holds it, finer parts dropped. */
export function wordOfS5Time(ms: number): number {
  const code = S5_BASES_MS.findIndex((base) => Math.floor(ms / base) <= 999);
  return (code << 12) | toBcd3(Math.floor(ms / S5_BASES_MS[code]!));
}

/** A count (0-999) as a counter word. */
export function wordOfCount(count: number): number {
  return toBcd3(count);
}

/** `S5T#1S850MS`, `S5T#2H46M30S`, `S5T#0MS`: STEP 7's spelling of a timer value (no days). */
export function formatS5Time(ms: number): string {
  let rest = Math.max(0, Math.trunc(ms));
  let text = '';
  for (const [unit, size] of [
    ['H', 3_600_000],
    ['M', 60_000],
    ['S', 1_000],
  ] as const) {
    if (rest >= size) {
      text += `${Math.floor(rest / size)}${unit}`;
      rest %= size;
    }
  }
  if (rest > 0 || text === '') text += `${rest}MS`;
  return `S5T#${text}`;
}

const S5_UNITS_MS: Record<string, number> = { D: 86_400_000, H: 3_600_000, M: 60_000, S: 1000, MS: 1 };

/** `S5T#1S850MS`, `S5TIME#2s_500ms`, `s5t#1.5s` in ms; null when it is no S5TIME constant. */
export function parseS5Time(text: string): number | null {
  const match = /^S5T(?:IME)?#(.+)$/i.exec(text.trim());
  if (!match) return null;
  const body = match[1]!.replace(/_/g, '').toUpperCase();
  const parts = /^(?:(\d+(?:\.\d+)?)(MS|D|H|M|S))+$/.test(body) ? [...body.matchAll(/(\d+(?:\.\d+)?)(MS|D|H|M|S)/g)] : null;
  if (!parts) return null;
  const ms = parts.reduce((sum, part) => sum + Number(part[1]) * S5_UNITS_MS[part[2]!]!, 0);
  return Number.isFinite(ms) && ms <= S5TIME_MAX_MS ? Math.floor(ms) : null;
}

/** `C#5` (0-999) as the count; null when it is no counter constant. */
export function parseCount(text: string): number | null {
  const match = /^C#(\d{1,3})$/i.exec(text.trim());
  return match ? Number(match[1]) : null;
}

/**
 * What the user typed in a row shown in `format`, as the value to send for an entry of `type`:
 * in a WORD shown as S5TIME or COUNTER, `S5T#…` and `C#…` become the timer or counter word;
 * null when the text is such a constant but not a valid one (out of range, bad unit).
 */
export function modifyValueFor(
  text: string,
  type: string | undefined,
  format: DisplayFormat,
): boolean | number | string | null {
  const trimmed = text.trim();
  const kind = (type ?? '').toUpperCase();
  if (/^S5T(IME)?#/i.test(trimmed)) {
    const ms = parseS5Time(trimmed);
    if (ms === null) return null;
    return kind === 'WORD' && format === 's5time' ? wordOfS5Time(ms) : trimmed;
  }
  if (/^C#/i.test(trimmed)) {
    const count = parseCount(trimmed);
    if (count === null) return null;
    return kind === 'WORD' || kind === 'INT' ? wordOfCount(count) : count;
  }
  return parseModifyValue(trimmed);
}

/** A value in `format` to show as the example of what a row takes. */
export function exampleOf(format: DisplayFormat): string {
  return format === 'counter' ? 'C#5' : format === 's5time' ? 'S5T#1S850MS' : format === 'bool' ? 'TRUE' : '16#FF';
}

/**
 * What the user typed as the value to send: `true`/`false` and plain numbers as JSON values,
 * everything else (`16#FF`, `T#2S`, `'A'`) as text the server parses for the target's type.
 */
export function parseModifyValue(text: string): boolean | number | string {
  const trimmed = text.trim();
  if (/^(true|false)$/i.test(trimmed)) return trimmed.toLowerCase() === 'true';
  if (/^[+-]?\d+$/.test(trimmed) && Number.isSafeInteger(Number(trimmed))) return Number(trimmed);
  if (/^[+-]?(\d+\.\d*|\.\d+)(e[+-]?\d+)?$/i.test(trimmed)) return Number(trimmed);
  return trimmed;
}

/** A watch value as a number for the trend (BOOL 0/1); null when it has none. */
export function numericValue(value: boolean | number | string | null | undefined): number | null {
  if (typeof value === 'boolean') return value ? 1 : 0;
  if (typeof value === 'number') return Number.isFinite(value) ? value : null;
  if (typeof value === 'string' && value.length === 1) return value.charCodeAt(0);
  if (typeof value === 'string' && /^-?\d+$/.test(value)) return Number(value); // a 64-bit integer
  return null;
}

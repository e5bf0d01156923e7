/**
 * Display formats of the watch table, as STEP 7's "Monitor/Modify Variables" offers them: the
 * value a frame carries (typed by the entry's type: INT signed, REAL a number, BOOL true/false,
 * CHAR a character, TIME and S5TIME milliseconds) shown as binary, hex, decimal, REAL, characters
 * or a time.
 */
import type { WatchValue } from '../api/monitor';

export type DisplayFormat = 'bool' | 'bin' | 'hex' | 'dec' | 'real' | 'char' | 'time';

/** The formats' names, as STEP 7 writes them; they stay Latin in every language, like mnemonics. */
export const FORMAT_NAMES: Record<DisplayFormat, string> = {
  bool: 'BOOL',
  bin: 'BIN',
  hex: 'HEX',
  dec: 'DEC',
  real: 'REAL',
  char: 'CHAR',
  time: 'TIME',
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
};
const SIGNED = new Set(['INT', 'DINT', 'TIME']);

export function bitsOf(type: string | undefined): number | null {
  return type ? (TYPE_BITS[type.toUpperCase()] ?? null) : null;
}

/** The formats that make sense for a type (none for a type the table cannot show as a number). */
export function formatsFor(type: string | undefined): DisplayFormat[] {
  const bits = bitsOf(type);
  if (bits === null) return [];
  if (bits === 1) return ['bool', 'bin'];
  if (bits === 32) return ['bin', 'hex', 'dec', 'real', 'char', 'time'];
  if (type?.toUpperCase() === 'S5TIME') return ['bin', 'hex', 'dec', 'time'];
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
      return 'dec';
    case 'REAL':
      return 'real';
    case 'CHAR':
      return 'char';
    case 'TIME':
    case 'S5TIME':
    case 'TIME_OF_DAY':
    case 'TOD':
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

const HEX_PREFIX: Record<number, string> = { 8: 'B#16#', 16: 'W#16#', 32: 'DW#16#' };

/** A watch value as text in `format`; '' when there is no value yet. */
export function formatValue(value: WatchValue['value'], type: string | undefined, format: DisplayFormat): string {
  if (value === null || value === undefined) return '';
  const kind = (type ?? '').toUpperCase();
  const bits = bitsOf(kind);
  if (bits === null) return typeof value === 'string' ? value : String(value);
  if (bits === 1) {
    const on = value === true || value === 1;
    return format === 'bin' ? (on ? '2#1' : '2#0') : on ? 'TRUE' : 'FALSE';
  }
  if (kind === 'S5TIME' && typeof value === 'number') return format === 'dec' ? String(value) : formatTime(value, 'S5T#');
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
    case 'time':
      if (kind === 'TIME_OF_DAY' || kind === 'TOD') return formatTimeOfDay(pattern);
      return formatTime(signedOf(pattern, 32));
    default:
      return value ? 'TRUE' : 'FALSE';
  }
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
  return null;
}

/**
 * The catalogue of LAD/FBD boxes: their pins (direction, S7 type), whether they have EN/ENO, and
 * what they lower to. A port of backend/nasaq/lang/lad/boxes.py (and `flow_pins` of fbd.py); the
 * Python module is the reference and tests/frontend/ladParity.test.ts holds the two equal.
 *
 * A box sits in series in a rung: the power flow into it feeds its flow pin (EN, or the first
 * Boolean input of a timer, counter or flip-flop) and the flow out of it is its flow out (ENO or
 * Q). Timers, counters, flip-flops and POS/NEG have an operand written above the box (the timer,
 * the counter, the bit), held in `Box.instance`. Calls of FC/FB/SFC/SFB are not catalogued: their
 * pins are the called block's parameters (see {@link callTarget}).
 */

export type Family = 'compare' | 'move' | 'math' | 'convert' | 'word' | 'shift' | 'timer' | 'counter' | 'flipflop' | 'edge';
export type Direction = 'in' | 'out';
export type Address = 'timer' | 'counter' | 'bit';

export interface Pin {
  readonly name: string;
  readonly direction: Direction;
  /** The S7 type: BOOL, INT, DINT, REAL, WORD, DWORD, S5TIME, ANY. */
  readonly type: string;
}

/**
 * One box: `op` is its STL operation (`+I`, `SD`, `==I` ...; empty for MOVE); `canFail` boxes
 * clear ENO on overflow; `address` names the operand kind written above the box, or is null.
 */
export class BoxSpec {
  constructor(
    readonly name: string,
    readonly family: Family,
    readonly pins: readonly Pin[],
    readonly enEno: boolean,
    readonly op: string,
    readonly canFail: boolean = false,
    readonly flowPin: string | null = null,
    readonly flowOut: string | null = null,
    readonly address: Address | null = null,
  ) {}

  pin(name: string): Pin | null {
    return this.pins.find((pin) => pin.name === name) ?? null;
  }

  get inputs(): readonly Pin[] {
    return this.pins.filter((pin) => pin.direction === 'in');
  }

  get outputs(): readonly Pin[] {
    return this.pins.filter((pin) => pin.direction === 'out');
  }
}

function p(name: string, type: string, direction: Direction = 'in'): Pin {
  return { name, direction, type };
}

const EN = p('EN', 'BOOL');
const ENO = p('ENO', 'BOOL', 'out');
const TYPES: readonly (readonly [string, string])[] = [
  ['I', 'INT'],
  ['DI', 'DINT'],
  ['R', 'REAL'],
];
const COMPARES = ['==', '<>', '>', '<', '>=', '<='] as const;

/** A box with EN/ENO around its own pins. */
function enBox(name: string, family: Family, op: string, pins: readonly Pin[], canFail = false): BoxSpec {
  return new BoxSpec(name, family, [EN, ...pins, ENO], true, op, canFail, 'EN', 'ENO');
}

/** IN1, IN2 → OUT of one type. */
function two(name: string, family: Family, op: string, type: string, canFail: boolean): BoxSpec {
  return enBox(name, family, op, [p('IN1', type), p('IN2', type), p('OUT', type, 'out')], canFail);
}

/** IN → OUT. */
function one(name: string, family: Family, op: string, typeIn: string, typeOut: string, canFail: boolean): BoxSpec {
  return enBox(name, family, op, [p('IN', typeIn), p('OUT', typeOut, 'out')], canFail);
}

function compareBoxes(): BoxSpec[] {
  const boxes: BoxSpec[] = [];
  for (const [suffix, type] of [['I', 'INT'], ['D', 'DINT'], ['R', 'REAL']] as const) {
    for (const relation of COMPARES) {
      boxes.push(new BoxSpec(`CMP${relation}${suffix}`, 'compare', [p('IN1', type), p('IN2', type)], false, relation + suffix));
    }
  }
  return boxes;
}

function mathBoxes(): BoxSpec[] {
  const boxes: BoxSpec[] = [];
  for (const [suffix, type] of TYPES) {
    const letter = suffix === 'DI' ? 'D' : suffix;
    for (const [name, sign] of [['ADD', '+'], ['SUB', '-'], ['MUL', '*'], ['DIV', '/']] as const) {
      boxes.push(two(`${name}_${suffix}`, 'math', sign + letter, type, true));
    }
  }
  boxes.push(two('MOD_DI', 'math', 'MOD', 'DINT', true));
  boxes.push(one('ABS', 'math', 'ABS', 'REAL', 'REAL', false));
  for (const name of ['SQR', 'SQRT', 'EXP', 'LN', 'SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN']) {
    boxes.push(one(name, 'math', name, 'REAL', 'REAL', true));
  }
  return boxes;
}

const CONVERSIONS: readonly (readonly [string, string, string, string, boolean])[] = [
  ['BCD_I', 'BTI', 'WORD', 'INT', false],
  ['I_BCD', 'ITB', 'INT', 'WORD', true],
  ['I_DI', 'ITD', 'INT', 'DINT', false],
  ['DI_R', 'DTR', 'DINT', 'REAL', false],
  ['BCD_DI', 'BTD', 'DWORD', 'DINT', false],
  ['DI_BCD', 'DTB', 'DINT', 'DWORD', true],
  ['ROUND', 'RND', 'REAL', 'DINT', true],
  ['TRUNC', 'TRUNC', 'REAL', 'DINT', true],
  ['CEIL', 'RND+', 'REAL', 'DINT', true],
  ['FLOOR', 'RND-', 'REAL', 'DINT', true],
  ['INV_I', 'INVI', 'INT', 'INT', false],
  ['INV_DI', 'INVD', 'DINT', 'DINT', false],
  ['NEG_I', 'NEGI', 'INT', 'INT', true],
  ['NEG_DI', 'NEGD', 'DINT', 'DINT', true],
  ['NEG_R', 'NEGR', 'REAL', 'REAL', false],
];

const SHIFTS: readonly (readonly [string, string, string])[] = [
  ['SHL_W', 'SLW', 'WORD'],
  ['SHR_W', 'SRW', 'WORD'],
  ['SHL_DW', 'SLD', 'DWORD'],
  ['SHR_DW', 'SRD', 'DWORD'],
  ['SHR_I', 'SSI', 'INT'],
  ['SHR_DI', 'SSD', 'DINT'],
  ['ROL_DW', 'RLD', 'DWORD'],
  ['ROR_DW', 'RRD', 'DWORD'],
];

function wordAndShiftBoxes(): BoxSpec[] {
  const boxes: BoxSpec[] = [];
  for (const [name, op] of [['WAND', 'A'], ['WOR', 'O'], ['WXOR', 'XO']] as const) {
    boxes.push(two(`${name}_W`, 'word', `${op}W`, 'WORD', false));
    boxes.push(two(`${name}_DW`, 'word', `${op}D`, 'DWORD', false));
  }
  for (const [name, op, type] of SHIFTS) {
    boxes.push(enBox(name, 'shift', op, [p('IN', type), p('N', 'WORD'), p('OUT', type, 'out')]));
  }
  return boxes;
}

function timerBoxes(): BoxSpec[] {
  const pins = [p('S', 'BOOL'), p('TV', 'S5TIME'), p('R', 'BOOL'), p('BI', 'WORD', 'out'), p('BCD', 'WORD', 'out'), p('Q', 'BOOL', 'out')];
  const timers = [['S_PULSE', 'SP'], ['S_PEXT', 'SE'], ['S_ODT', 'SD'], ['S_ODTS', 'SS'], ['S_OFFDT', 'SF']] as const;
  return timers.map(([name, op]) => new BoxSpec(name, 'timer', pins, false, op, false, 'S', 'Q', 'timer'));
}

function counterBoxes(): BoxSpec[] {
  const tail = [p('S', 'BOOL'), p('PV', 'WORD'), p('R', 'BOOL'), p('CV', 'WORD', 'out'), p('CV_BCD', 'WORD', 'out'), p('Q', 'BOOL', 'out')];
  const cu = p('CU', 'BOOL');
  const cd = p('CD', 'BOOL');
  return [
    new BoxSpec('S_CU', 'counter', [cu, ...tail], false, 'CU', false, 'CU', 'Q', 'counter'),
    new BoxSpec('S_CD', 'counter', [cd, ...tail], false, 'CD', false, 'CD', 'Q', 'counter'),
    new BoxSpec('S_CUD', 'counter', [cu, cd, ...tail], false, 'CU', false, 'CU', 'Q', 'counter'),
  ];
}

function bitBoxes(): BoxSpec[] {
  const q = p('Q', 'BOOL', 'out');
  return [
    new BoxSpec('SR', 'flipflop', [p('S', 'BOOL'), p('R1', 'BOOL'), q], false, 'S', false, 'S', 'Q', 'bit'),
    new BoxSpec('RS', 'flipflop', [p('R', 'BOOL'), p('S1', 'BOOL'), q], false, 'R', false, 'R', 'Q', 'bit'),
    new BoxSpec('POS', 'edge', [p('M_BIT', 'BOOL'), q], false, 'FP', false, null, 'Q', 'bit'),
    new BoxSpec('NEG', 'edge', [p('M_BIT', 'BOOL'), q], false, 'FN', false, null, 'Q', 'bit'),
  ];
}

function catalogue(): Readonly<Record<string, BoxSpec>> {
  const boxes = [
    ...compareBoxes(),
    enBox('MOVE', 'move', '', [p('IN', 'ANY'), p('OUT', 'ANY', 'out')]),
    ...mathBoxes(),
    ...CONVERSIONS.map(([name, op, typeIn, typeOut, canFail]) => one(name, 'convert', op, typeIn, typeOut, canFail)),
    ...wordAndShiftBoxes(),
    ...timerBoxes(),
    ...counterBoxes(),
    ...bitBoxes(),
  ];
  // No box name is an integer-like key, so the object keeps the catalogue's order, as the dict does.
  return Object.freeze(Object.fromEntries(boxes.map((box) => [box.name, box])));
}

/** Every catalogued box by name, in the catalogue's order. */
export const CATALOGUE: Readonly<Record<string, BoxSpec>> = catalogue();

/**
 * Python's `\s` on text (what `str.isspace` calls whitespace). JavaScript's `\s` differs in a few
 * characters (it lacks U+001C..U+001F and U+0085 and has U+FEFF), and names must match the same way
 * in the editor and on the server.
 */
export const PYTHON_SPACE = '\\t\\n\\v\\f\\r\\x1c-\\x20\\x85\\xa0\\u1680\\u2000-\\u200a\\u2028\\u2029\\u202f\\u205f\\u3000';
const SPACES = new RegExp(`[${PYTHON_SPACE}]+`, 'gu');
const CALL = new RegExp(`^[${PYTHON_SPACE}]*(?:(FC|FB|SFC|SFB)[${PYTHON_SPACE}]*(\\p{Nd}+)|("[^"]+"))[${PYTHON_SPACE}]*$`, 'iu');

/** The catalogued box `name` (spaces and case ignored: `cmp >=i` is `CMP>=I`). */
export function boxSpec(name: string): BoxSpec | null {
  const key = name.replace(SPACES, '').toUpperCase();
  return Object.hasOwn(CATALOGUE, key) ? (CATALOGUE[key] ?? null) : null;
}

/**
 * For a call box (`FC 10`, `FB 5`, `SFB 4`, `"Motor"`): its name as STL writes it and whether it
 * needs an instance DB (FB/SFB; a symbol may be either, so it does not).
 */
export function callTarget(name: string): [string, boolean] | null {
  const found = CALL.exec(name);
  if (found === null) return null;
  if (found[3]) return [found[3], false];
  const kind = (found[1] ?? '').toUpperCase();
  return [`${kind} ${decimal(found[2] ?? '')}`, kind === 'FB' || kind === 'SFB'];
}

/**
 * The number a run of decimal digits writes, as Python's `int` reads it: any script's digits
 * (Arabic-Indic ٣ is 3), leading zeros dropped, no limit on its size.
 */
function decimal(digits: string): string {
  let ascii = '';
  for (const char of digits) ascii += String(digitValue(char.codePointAt(0) ?? 0));
  return BigInt(ascii).toString();
}

const DIGIT = /\p{Nd}/u;

/**
 * The value of a decimal digit (Unicode category Nd). Unicode keeps every script's digits as runs
 * of ten code points from 0 to 9, some runs back to back (the mathematical digits): the value is
 * the distance from the start of the unbroken stretch of digits, modulo ten.
 */
function digitValue(code: number): number {
  let start = code;
  while (start > 0 && DIGIT.test(String.fromCodePoint(start - 1))) start -= 1;
  return (code - start) % 10;
}

/**
 * The pins the power flow enters and leaves box `name` by: EN/ENO for boxes with EN/ENO and calls,
 * S/Q for a timer ..., [null, null] for a comparator (fbd.py's `flow_pins`).
 */
export function flowPins(name: string): [string | null, string | null] {
  const spec = boxSpec(name);
  if (spec === null) return ['EN', 'ENO'];
  return [spec.flowPin, spec.flowOut];
}

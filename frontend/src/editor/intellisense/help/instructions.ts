/**
 * What the hover help says about each STL instruction and SCL standard function, apart from the
 * words: the kind of text (`family`, a template of each language's catalogue), what fills its
 * placeholders (`params`: a word of the catalogue, or `=literal` kept as written), the syntax and
 * the status bits the instruction writes. Instructions are keyed by their international
 * mnemonic; the SIMATIC (German) spellings map to the same entries (`languages/stl.ts`).
 *
 * The status bits are STEP 7's (the same abbreviations in every language): RLO, /FC, STA, OR,
 * OS, OV, CC0, CC1, BR. Semantics as in the course digests and `nasaq.cpu`.
 */

export type StatusBit = 'RLO' | '/FC' | 'STA' | 'OR' | 'OS' | 'OV' | 'CC0' | 'CC1' | 'BR';

export interface HelpEntry {
  family: string;
  params?: Readonly<Record<string, string>>;
  /** `{m}` stands for the mnemonic as the file spells it. */
  syntax: string;
  status: readonly StatusBit[];
}

const LOGIC: StatusBit[] = ['RLO', '/FC', 'STA', 'OR'];
// =, S and R: OR 0, STA takes the bit's new value, /FC 0 (STEP 7's status-word tables).
const FC: StatusBit[] = ['OR', 'STA', '/FC'];
const MATH: StatusBit[] = ['CC0', 'CC1', 'OV', 'OS'];
const SHIFTS: StatusBit[] = ['CC0', 'CC1', 'OV'];
const NONE: StatusBit[] = [];

const entry = (family: string, syntax: string, status: readonly StatusBit[], params?: Record<string, string>): HelpEntry =>
  params ? { family, syntax, status, params } : { family, syntax, status };

function build(): Record<string, HelpEntry> {
  const table: Record<string, HelpEntry> = {};
  const ops = { A: 'and', O: 'or', X: 'xor' } as const;
  for (const [m, op] of Object.entries(ops)) {
    table[m] = entry('logic', '{m} <bit>', LOGIC, { op });
    table[`${m}N`] = entry('logicNot', '{m} <bit>', LOGIC, { op });
    table[`${m}(`] = entry('nest', '{m}', ['/FC', 'OR'], { op });
    table[`${m}N(`] = entry('nestNot', '{m}', ['/FC', 'OR'], { op });
  }
  table[')'] = entry('nestClose', ')', LOGIC);
  table['='] = entry('assign', '= <bit>', FC);
  table.S = entry('set', '{m} <bit | timer | counter>', FC);
  table.R = entry('reset', '{m} <bit | timer | counter>', FC);
  table.SET = entry('setRlo', '{m}', ['RLO', '/FC', 'STA', 'OR']);
  table.CLR = entry('clearRlo', '{m}', ['RLO', '/FC', 'STA', 'OR']);
  table.NOT = entry('notRlo', '{m}', ['STA', 'RLO']);
  table.SAVE = entry('save', '{m}', ['BR']);
  table.FP = entry('edge', '{m} <edge memory bit>', LOGIC, { edge: 'rising' });
  table.FN = entry('edge', '{m} <edge memory bit>', LOGIC, { edge: 'falling' });
  const timers = { SP: 'pulse', SE: 'extendedPulse', SD: 'onDelay', SS: 'retentiveOnDelay', SF: 'offDelay' };
  for (const [m, kind] of Object.entries(timers)) table[m] = entry('timer', '{m} <timer>', FC, { kind });
  table.FR = entry('enable', '{m} <timer | counter>', FC);
  table.CU = entry('count', '{m} <counter>', FC, { dir: 'up' });
  table.CD = entry('count', '{m} <counter>', FC, { dir: 'down' });
  table.L = entry('load', '{m} <operand | constant>', NONE);
  table.LC = entry('loadBcd', '{m} <timer | counter>', NONE);
  table.T = entry('transfer', '{m} <operand>', NONE);
  for (const m of ['TAK', 'PUSH', 'POP', 'ENT', 'LEAVE']) table[m] = entry(m.toLowerCase(), '{m}', NONE);
  table.INC = entry('incDec', '{m} <0..255>', NONE, { dir: 'up' });
  table.DEC = entry('incDec', '{m} <0..255>', NONE, { dir: 'down' });
  table['+'] = entry('addConstant', '+ <constant>', NONE);
  table.CAW = entry('swapBytes', '{m}', NONE, { width: 'word' });
  table.CAD = entry('swapBytes', '{m}', NONE, { width: 'dword' });
  const types = { I: 'int', D: 'dint', R: 'real' } as const;
  const arithmetic = { '+': 'add', '-': 'subtract', '*': 'multiply', '/': 'divide' } as const;
  const relations = { '==': 'eq', '<>': 'ne', '>': 'gt', '<': 'lt', '>=': 'ge', '<=': 'le' } as const;
  for (const [suffix, type] of Object.entries(types)) {
    for (const [sign, op] of Object.entries(arithmetic)) table[`${sign}${suffix}`] = entry('arithmetic', `${sign}${suffix}`, MATH, { op, type });
    for (const [sign, rel] of Object.entries(relations)) {
      const bits: StatusBit[] = suffix === 'R' ? ['RLO', '/FC', 'STA', 'OR', 'CC0', 'CC1', 'OV', 'OS'] : ['RLO', '/FC', 'STA', 'OR', 'CC0', 'CC1', 'OV'];
      table[`${sign}${suffix}`] = entry('compare', `${sign}${suffix}`, bits, { rel, type });
    }
  }
  table.MOD = entry('modulo', '{m}', MATH);
  table.ABS = entry('absolute', '{m}', NONE);
  const functions = { SQR: 'square', SQRT: 'squareRoot', EXP: 'exponential', LN: 'logarithm', SIN: 'sine', COS: 'cosine', TAN: 'tangent', ASIN: 'arcSine', ACOS: 'arcCosine', ATAN: 'arcTangent' };
  for (const [m, fn] of Object.entries(functions)) table[m] = entry('realFunction', '{m}', MATH, { fn });
  const conversions: Array<[string, string, string, StatusBit[]]> = [
    ['BTI', 'bcd3', 'int', NONE],
    ['ITB', 'int', 'bcd3', ['OV', 'OS']],
    ['BTD', 'bcd7', 'dint', NONE],
    ['DTB', 'dint', 'bcd7', ['OV', 'OS']],
    ['ITD', 'int', 'dint', NONE],
    ['DTR', 'dint', 'real', NONE],
  ];
  for (const [m, from, to, bits] of conversions) table[m] = entry('convert', '{m}', bits, { from, to });
  table.INVI = entry('invert', '{m}', NONE, { width: 'word' });
  table.INVD = entry('invert', '{m}', NONE, { width: 'dword' });
  table.NEGI = entry('negate', '{m}', MATH, { type: 'int' });
  table.NEGD = entry('negate', '{m}', MATH, { type: 'dint' });
  table.NEGR = entry('negate', '{m}', NONE, { type: 'real' });
  table.RND = entry('round', '{m}', ['OV', 'OS'], { mode: 'nearest' });
  table['RND+'] = entry('round', '{m}', ['OV', 'OS'], { mode: 'upward' });
  table['RND-'] = entry('round', '{m}', ['OV', 'OS'], { mode: 'downward' });
  table.TRUNC = entry('round', '{m}', ['OV', 'OS'], { mode: 'towardZero' });
  const wordOps = { A: 'and', O: 'or', XO: 'xor' } as const;
  for (const [m, op] of Object.entries(wordOps)) {
    table[`${m}W`] = entry('wordLogic', '{m} [<constant>]', SHIFTS, { op, width: 'word' });
    table[`${m}D`] = entry('wordLogic', '{m} [<constant>]', SHIFTS, { op, width: 'dword' });
  }
  table.SSI = entry('shiftSigned', '{m} [<0..15>]', SHIFTS, { width: 'word' });
  table.SSD = entry('shiftSigned', '{m} [<0..32>]', SHIFTS, { width: 'dword' });
  table.SLW = entry('shift', '{m} [<0..15>]', SHIFTS, { dir: 'left', width: 'word' });
  table.SRW = entry('shift', '{m} [<0..15>]', SHIFTS, { dir: 'right', width: 'word' });
  table.SLD = entry('shift', '{m} [<0..32>]', SHIFTS, { dir: 'left', width: 'dword' });
  table.SRD = entry('shift', '{m} [<0..32>]', SHIFTS, { dir: 'right', width: 'dword' });
  table.RLD = entry('rotate', '{m} [<0..32>]', SHIFTS, { dir: 'left' });
  table.RRD = entry('rotate', '{m} [<0..32>]', SHIFTS, { dir: 'right' });
  table.RLDA = entry('rotateCc1', '{m}', SHIFTS, { dir: 'left' });
  table.RRDA = entry('rotateCc1', '{m}', SHIFTS, { dir: 'right' });
  table.JU = entry('jumpAlways', '{m} <label>', NONE);
  table.JC = entry('jumpRlo', '{m} <label>', ['RLO', '/FC', 'STA', 'OR'], { state: '=1' });
  table.JCN = entry('jumpRlo', '{m} <label>', ['RLO', '/FC', 'STA', 'OR'], { state: '=0' });
  table.JCB = entry('jumpRloSave', '{m} <label>', ['BR', 'RLO', '/FC', 'STA', 'OR'], { state: '=1' });
  table.JNB = entry('jumpRloSave', '{m} <label>', ['BR', 'RLO', '/FC', 'STA', 'OR'], { state: '=0' });
  table.JBI = entry('jumpBr', '{m} <label>', ['/FC', 'OR'], { state: '=1' });
  table.JNBI = entry('jumpBr', '{m} <label>', ['/FC', 'OR'], { state: '=0' });
  table.JO = entry('jumpOverflow', '{m} <label>', NONE);
  table.JOS = entry('jumpStoredOverflow', '{m} <label>', ['OS']);
  const results = { JZ: 'zero', JN: 'notZero', JP: 'positive', JM: 'negative', JPZ: 'positiveOrZero', JMZ: 'negativeOrZero', JUO: 'unordered' };
  for (const [m, result] of Object.entries(results)) table[m] = entry('jumpResult', '{m} <label>', NONE, { result });
  table.JL = entry('jumpList', '{m} <label>', NONE);
  table.LOOP = entry('loop', '{m} <label>', NONE);
  table['MCR('] = entry('mcrOpen', 'MCR(', ['/FC', 'OR']);
  table[')MCR'] = entry('mcrClose', ')MCR', ['/FC', 'OR']);
  table.MCRA = entry('mcrActivate', '{m}', NONE);
  table.MCRD = entry('mcrDeactivate', '{m}', NONE);
  table.CALL = entry('call', '{m} <FC | FB, instance DB> (<parameters>)', NONE);
  table.UC = entry('callUnconditional', '{m} <FC | FB>', NONE);
  table.CC = entry('callConditional', '{m} <FC | FB>', ['/FC', 'OR', 'STA']);
  table.BE = entry('blockEnd', '{m}', NONE);
  table.BEU = entry('blockEnd', '{m}', NONE);
  table.BEC = entry('blockEndConditional', '{m}', ['RLO', '/FC', 'STA', 'OR']);
  table.OPN = entry('openDb', '{m} <DB | DI>', NONE);
  table.CDB = entry('swapDb', '{m}', NONE);
  for (const n of ['1', '2']) {
    table[`LAR${n}`] = entry('loadAr', '{m} [<pointer>]', NONE, { reg: `=AR${n}` });
    table[`TAR${n}`] = entry('transferAr', '{m} [<operand>]', NONE, { reg: `=AR${n}` });
    table[`+AR${n}`] = entry('addAr', '{m} [<P#byte.bit>]', NONE, { reg: `=AR${n}` });
  }
  table.CAR = entry('swapAr', '{m}', NONE);
  table.NOP = entry('nop', '{m} 0 | {m} 1', NONE);
  table.BLD = entry('bld', '{m} <number>', NONE);
  return table;
}

/** Every international mnemonic's entry. */
export const STL_HELP: Readonly<Record<string, HelpEntry>> = build();

/** An SCL standard function: its text, its parameters (the snippet's names) and result. */
export interface SclFunctionHelp {
  family: string;
  params?: Readonly<Record<string, string>>;
  /** Named parameters (`IN1`, `L`); empty: one value in parentheses (`INT_TO_REAL(x)`). */
  inputs: readonly string[];
  result: string;
}

const CONVERSION = /^([A-Z_]+?)_TO_([A-Z_]+)$/;
const SCL_EXPLICIT: Record<string, SclFunctionHelp> = {
  ABS: { family: 'sclAbs', inputs: [], result: 'ANY_NUM' },
  EXPD: { family: 'sclMath', params: { fn: 'exponential10' }, inputs: [], result: 'REAL' },
  LOG: { family: 'sclMath', params: { fn: 'logarithm10' }, inputs: [], result: 'REAL' },
  ROUND: { family: 'sclRound', params: { mode: 'nearest' }, inputs: [], result: 'DINT' },
  TRUNC: { family: 'sclRound', params: { mode: 'towardZero' }, inputs: [], result: 'DINT' },
  CEIL: { family: 'sclRound', params: { mode: 'upward' }, inputs: [], result: 'DINT' },
  FLOOR: { family: 'sclRound', params: { mode: 'downward' }, inputs: [], result: 'DINT' },
  // TIA Portal's BCD names: BCD16 is a WORD of 3 digits and a sign, BCD32 a DWORD of 7
  BCD_TO_INT: { family: 'convertBcd', params: { from: '=WORD', to: '=INT' }, inputs: [], result: 'INT' },
  BCD16_TO_INT: { family: 'convertBcd', params: { from: '=WORD', to: '=INT' }, inputs: [], result: 'INT' },
  INT_TO_BCD: { family: 'convertBcd', params: { from: '=INT', to: '=WORD' }, inputs: [], result: 'WORD' },
  INT_TO_BCD16: { family: 'convertBcd', params: { from: '=INT', to: '=WORD' }, inputs: [], result: 'WORD' },
  BCD32_TO_DINT: { family: 'convertBcd', params: { from: '=DWORD', to: '=DINT' }, inputs: [], result: 'DINT' },
  DINT_TO_BCD32: { family: 'convertBcd', params: { from: '=DINT', to: '=DWORD' }, inputs: [], result: 'DWORD' },
  ROL: { family: 'sclRotate', params: { dir: 'left' }, inputs: ['IN', 'N'], result: 'ANY_BIT' },
  ROR: { family: 'sclRotate', params: { dir: 'right' }, inputs: ['IN', 'N'], result: 'ANY_BIT' },
  SHL: { family: 'sclShift', params: { dir: 'left' }, inputs: ['IN', 'N'], result: 'ANY_BIT' },
  SHR: { family: 'sclShift', params: { dir: 'right' }, inputs: ['IN', 'N'], result: 'ANY_BIT' },
  LIMIT: { family: 'limit', inputs: ['MN', 'IN', 'MX'], result: 'ANY' },
  MAX: { family: 'max', inputs: ['IN1', 'IN2'], result: 'ANY' },
  MIN: { family: 'min', inputs: ['IN1', 'IN2'], result: 'ANY' },
  MUX: { family: 'mux', inputs: ['K', 'IN0', 'IN1'], result: 'ANY' },
  SEL: { family: 'sel', inputs: ['G', 'IN0', 'IN1'], result: 'ANY' },
  CONCAT: { family: 'concat', inputs: ['IN1', 'IN2'], result: 'STRING' },
  DELETE: { family: 'delete', inputs: ['IN', 'L', 'P'], result: 'STRING' },
  FIND: { family: 'find', inputs: ['IN1', 'IN2'], result: 'INT' },
  INSERT: { family: 'insert', inputs: ['IN1', 'IN2', 'P'], result: 'STRING' },
  LEFT: { family: 'left', inputs: ['IN', 'L'], result: 'STRING' },
  RIGHT: { family: 'right', inputs: ['IN', 'L'], result: 'STRING' },
  MID: { family: 'mid', inputs: ['IN', 'L', 'P'], result: 'STRING' },
  LEN: { family: 'len', inputs: ['S'], result: 'INT' },
  REPLACE: { family: 'replace', inputs: ['IN1', 'IN2', 'L', 'P'], result: 'STRING' },
  I_STRNG: { family: 'toString', params: { type: '=INT' }, inputs: ['I'], result: 'STRING' },
  DI_STRNG: { family: 'toString', params: { type: '=DINT' }, inputs: ['I'], result: 'STRING' },
  R_STRNG: { family: 'toString', params: { type: '=REAL' }, inputs: ['IN'], result: 'STRING' },
  STRNG_I: { family: 'fromString', params: { type: '=INT' }, inputs: ['S'], result: 'INT' },
  STRNG_DI: { family: 'fromString', params: { type: '=DINT' }, inputs: ['S'], result: 'DINT' },
  STRNG_R: { family: 'fromString', params: { type: '=REAL' }, inputs: ['S'], result: 'REAL' },
  AD_DT_TM: { family: 'addTime', inputs: ['T', 'D'], result: 'DATE_AND_TIME' },
  SB_DT_TM: { family: 'subtractTime', inputs: ['T', 'D'], result: 'DATE_AND_TIME' },
  SB_DT_DT: { family: 'timeBetween', inputs: ['T1', 'T2'], result: 'TIME' },
  D_TOD_DT: { family: 'combineDateTime', inputs: ['IN1', 'IN2'], result: 'DATE_AND_TIME' },
  DT_DATE: { family: 'dtDate', inputs: ['IN'], result: 'DATE' },
  DT_DAY: { family: 'dtDay', inputs: ['IN'], result: 'INT' },
  DT_TOD: { family: 'dtTod', inputs: ['IN'], result: 'TIME_OF_DAY' },
  S_CU: { family: 'sclCounter', params: { kind: 'upCounter' }, inputs: ['C_NO', 'CU', 'S', 'PV', 'R', 'Q', 'CV'], result: 'WORD' },
  S_CD: { family: 'sclCounter', params: { kind: 'downCounter' }, inputs: ['C_NO', 'CD', 'S', 'PV', 'R', 'Q', 'CV'], result: 'WORD' },
  S_CUD: { family: 'sclCounter', params: { kind: 'upDownCounter' }, inputs: ['C_NO', 'CU', 'CD', 'S', 'PV', 'R', 'Q', 'CV'], result: 'WORD' },
  // TIA Portal, S7-1200/1500: VARIANT and ARRAY[*] parameters
  LOWER_BOUND: { family: 'lowerBound', inputs: ['ARR', 'DIM'], result: 'DINT' },
  UPPER_BOUND: { family: 'upperBound', inputs: ['ARR', 'DIM'], result: 'DINT' },
  COUNTOFELEMENTS: { family: 'countOfElements', inputs: [], result: 'UDINT' },
  IS_ARRAY: { family: 'isArray', inputs: [], result: 'BOOL' },
  TYPEOF: { family: 'typeOf', inputs: [], result: 'VARIANT type' },
  TYPEOFELEMENTS: { family: 'typeOfElements', inputs: [], result: 'VARIANT type' },
  SERIALIZE: { family: 'serialize', inputs: ['SRC_VARIABLE', 'DEST_ARRAY', 'POS'], result: 'INT' },
  DESERIALIZE: { family: 'deserialize', inputs: ['SRC_ARRAY', 'DEST_VARIABLE', 'POS'], result: 'INT' },
  VARIANTGET: { family: 'variantGet', inputs: ['SRC', 'DST'], result: 'VOID' },
  VARIANTPUT: { family: 'variantPut', inputs: ['SRC', 'DST'], result: 'VOID' },
  MOVE_BLK_VARIANT: { family: 'moveBlkVariant', inputs: ['SRC', 'COUNT', 'SRC_INDEX', 'DEST_INDEX', 'DEST'], result: 'INT' },
  // TIA Portal, S7-1200/1500: DB_ANY and direct memory access
  DB_ANY_TO_UINT: { family: 'dbAnyToUint', inputs: ['IN'], result: 'UINT' },
  UINT_TO_DB_ANY: { family: 'uintToDbAny', inputs: ['IN'], result: 'DB_ANY' },
  PEEK: { family: 'peek', params: { width: '=BYTE' }, inputs: ['AREA', 'DBNUMBER', 'BYTEOFFSET'], result: 'BYTE' },
  PEEK_WORD: { family: 'peek', params: { width: '=WORD' }, inputs: ['AREA', 'DBNUMBER', 'BYTEOFFSET'], result: 'WORD' },
  PEEK_DWORD: { family: 'peek', params: { width: '=DWORD' }, inputs: ['AREA', 'DBNUMBER', 'BYTEOFFSET'], result: 'DWORD' },
  PEEK_BOOL: { family: 'peekBool', inputs: ['AREA', 'DBNUMBER', 'BYTEOFFSET', 'BITOFFSET'], result: 'BOOL' },
  POKE: { family: 'poke', inputs: ['AREA', 'DBNUMBER', 'BYTEOFFSET', 'VALUE'], result: 'VOID' },
  POKE_BOOL: { family: 'pokeBool', inputs: ['AREA', 'DBNUMBER', 'BYTEOFFSET', 'BITOFFSET', 'VALUE'], result: 'VOID' },
  // TIA Portal, S7-1200/1500: numbers into text and back
  VAL_STRG: { family: 'valStrg', inputs: ['IN', 'SIZE', 'PREC', 'FORMAT', 'P', 'OUT'], result: 'VOID' },
  STRG_VAL: { family: 'strgVal', inputs: ['IN', 'FORMAT', 'P', 'OUT'], result: 'VOID' },
};
const S5_TIMERS = { S_PULSE: 'pulse', S_PEXT: 'extendedPulse', S_ODT: 'onDelay', S_ODTS: 'retentiveOnDelay', S_OFFDT: 'offDelay' };
const SCL_MATH = { SQR: 'square', SQRT: 'squareRoot', EXP: 'exponential', LN: 'logarithm', SIN: 'sine', COS: 'cosine', TAN: 'tangent', ASIN: 'arcSine', ACOS: 'arcCosine', ATAN: 'arcTangent' };
const COMPARISONS = { EQ: 'eq', NE: 'ne', GT: 'gt', LT: 'lt', GE: 'ge', LE: 'le' };

/** The help of an SCL standard function (upper-case name), or null for other names. */
export function sclFunctionHelp(name: string): SclFunctionHelp | null {
  const explicit = SCL_EXPLICIT[name];
  if (explicit) return explicit;
  const timer = (S5_TIMERS as Record<string, string>)[name];
  if (timer) return { family: 'sclTimer', params: { kind: timer }, inputs: ['T_NO', 'S', 'TV', 'R', 'Q', 'BI'], result: 'S5TIME' };
  const math = (SCL_MATH as Record<string, string>)[name];
  if (math) return { family: 'sclMath', params: { fn: math }, inputs: [], result: 'REAL' };
  const compare = /^(EQ|NE|GT|LT|GE|LE)_(STRNG|DT)$/.exec(name);
  if (compare) {
    const strings = compare[2] === 'STRNG';
    return {
      family: strings ? 'compareStrings' : 'compareDates',
      params: { rel: (COMPARISONS as Record<string, string>)[compare[1]!]! },
      inputs: strings ? ['S1', 'S2'] : ['DT1', 'DT2'],
      result: 'BOOL',
    };
  }
  const conversion = CONVERSION.exec(name);
  if (conversion) {
    const [, from = '', to = ''] = conversion;
    const bcd = from.endsWith('_BCD') || to.startsWith('BCD_');
    return {
      family: bcd ? 'convertBcd' : 'sclConvert',
      params: { from: `=${from.replace(/_BCD$/, '')}`, to: `=${to.replace(/^BCD_/, '')}` },
      inputs: [],
      result: to.replace(/^BCD_/, ''),
    };
  }
  return null;
}

/**
 * STEP 7 STL (AWL) for the Monaco editor: a Monarch tokenizer and the language configuration.
 *
 * The word lists are the compiler's own: the mnemonics are `backend/nasaq/lang/stl/mnemonics.py`
 * (both sets, international and SIMATIC/German), the keywords, addresses and constants are the
 * terminals of `grammars/stl.lark`, the data types `backend/nasaq/ir/types.py`. A vitest test
 * (`tests/frontend/editorLanguages.test.ts`) reads those files and fails when they drift apart.
 *
 * Only types are imported from Monaco, so this module costs nothing in the app shell.
 */
import type { languages } from 'monaco-editor/editor/editor.api';

export const STL_LANGUAGE_ID = 'stl';

/** `mnemonics.INTERNATIONAL`: the international (English) mnemonic set. */
export const INTERNATIONAL_MNEMONICS: readonly string[] = [
  'A', 'AN', 'O', 'ON', 'X', 'XN', 'A(', 'AN(', 'O(', 'ON(', 'X(', 'XN(', ')', '=', 'S', 'R',
  'SET', 'CLR', 'NOT', 'SAVE', 'FP', 'FN', 'SP', 'SE', 'SD', 'SS', 'SF', 'FR', 'CU', 'CD', 'L',
  'LC', 'T', 'TAK', 'PUSH', 'POP', 'ENT', 'LEAVE', 'INC', 'DEC', '+', 'CAW', 'CAD', '+I', '-I',
  '*I', '/I', '+D', '-D', '*D', '/D', 'MOD', '+R', '-R', '*R', '/R', 'ABS', 'SQR', 'SQRT', 'EXP',
  'LN', 'SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN', '==I', '<>I', '>I', '<I', '>=I', '<=I', '==D',
  '<>D', '>D', '<D', '>=D', '<=D', '==R', '<>R', '>R', '<R', '>=R', '<=R', 'BTI', 'ITB', 'BTD',
  'DTB', 'ITD', 'DTR', 'INVI', 'INVD', 'NEGI', 'NEGD', 'NEGR', 'RND', 'RND+', 'RND-', 'TRUNC', 'AW',
  'OW', 'XOW', 'AD', 'OD', 'XOD', 'SSI', 'SSD', 'SLW', 'SRW', 'SLD', 'SRD', 'RLD', 'RRD', 'RLDA',
  'RRDA', 'JU', 'JC', 'JCN', 'JCB', 'JNB', 'JBI', 'JNBI', 'JO', 'JOS', 'JZ', 'JN', 'JP', 'JM', 'JPZ',
  'JMZ', 'JUO', 'JL', 'LOOP', 'MCR(', ')MCR', 'MCRA', 'MCRD', 'CALL', 'UC', 'CC', 'BE', 'BEC',
  'BEU', 'OPN', 'CDB', 'LAR1', 'LAR2', 'TAR1', 'TAR2', 'CAR', '+AR1', '+AR2', 'NOP', 'BLD',
];

/** `mnemonics.GERMAN_TO_INTERNATIONAL`: the SIMATIC (German) spellings that differ. */
export const GERMAN_TO_INTERNATIONAL: Readonly<Record<string, string>> = {
  U: 'A', UN: 'AN', 'U(': 'A(', 'UN(': 'AN(', SI: 'SP', SV: 'SE', SE: 'SD', SA: 'SF', ZV: 'CU',
  ZR: 'CD', TAW: 'CAW', TAD: 'CAD', UW: 'AW', UD: 'AD', SPA: 'JU', SPB: 'JC', SPBN: 'JCN',
  SPBB: 'JCB', SPBNB: 'JNB', SPBI: 'JBI', SPBIN: 'JNBI', SPO: 'JO', SPS: 'JOS', SPZ: 'JZ',
  SPN: 'JN', SPP: 'JP', SPM: 'JM', SPPZ: 'JPZ', SPMZ: 'JMZ', SPU: 'JUO', SPL: 'JL', AUF: 'OPN',
  TDB: 'CDB', BEB: 'BEC', BEA: 'BEU', TAR: 'CAR',
};

/** `mnemonics.GERMAN`: the international set less its renamed instructions, plus the German
 * names (SE stays: in German it is the on-delay timer, international SD). */
export const GERMAN_MNEMONICS: readonly string[] = (() => {
  const renamed = new Set(Object.values(GERMAN_TO_INTERNATIONAL));
  const kept = INTERNATIONAL_MNEMONICS.filter((m) => !renamed.has(m));
  return [...new Set([...kept, ...Object.keys(GERMAN_TO_INTERNATIONAL), 'SE'])];
})();

/** Every mnemonic of either set: the editor does not know which set a file uses until the
 * compiler has seen all of it, so both are highlighted everywhere. */
export const STL_MNEMONICS: readonly string[] = [...new Set([...INTERNATIONAL_MNEMONICS, ...GERMAN_MNEMONICS])];

/** The jumps of both sets (JU ... JL, LOOP; SPA ... SPL): their operand is a label. */
export const JUMP_MNEMONICS: readonly string[] = (() => {
  const international = INTERNATIONAL_MNEMONICS.filter((m) => /^J[A-Z]*$/.test(m) || m === 'LOOP');
  const german = Object.keys(GERMAN_TO_INTERNATIONAL).filter((m) => international.includes(GERMAN_TO_INTERNATIONAL[m]!));
  return [...international, ...german];
})();

/** Mnemonics spelled with letters (A, SPBN, RND+, U( ...): the tokenizer reads them as words. */
const WORD_MNEMONICS = STL_MNEMONICS.filter((m) => /^[A-Z]/.test(m) && !JUMP_MNEMONICS.includes(m));

/** The block structure keywords of `grammars/stl.lark`. */
export const STL_BLOCK_KEYWORDS: readonly string[] = [
  'ORGANIZATION_BLOCK', 'FUNCTION_BLOCK', 'FUNCTION', 'DATA_BLOCK', 'TYPE', 'BEGIN',
  'END_ORGANIZATION_BLOCK', 'END_FUNCTION_BLOCK', 'END_FUNCTION', 'END_DATA_BLOCK', 'END_TYPE',
  'STRUCT', 'END_STRUCT', 'ARRAY', 'OF', 'NETWORK', 'TITLE', 'END_VAR',
];

/** `VAR_KW` of the grammar: the declaration sections. */
export const STL_VAR_KEYWORDS: readonly string[] = ['VAR', 'VAR_INPUT', 'VAR_OUTPUT', 'VAR_IN_OUT', 'VAR_TEMP'];

/** `HEADER_KEY` and `FLAG_KW` of the grammar: block properties. */
export const STL_HEADER_KEYS: readonly string[] = ['AUTHOR', 'FAMILY', 'NAME', 'VERSION'];
export const STL_FLAGS: readonly string[] = [
  'KNOW_HOW_PROTECT', 'READ_ONLY', 'NON_RETAIN', 'UNLINKED', 'STANDARD', 'CODE_VERSION1',
];

/** `ELEMENTARY_BITS` and `TYPE_ALIASES` of `nasaq.ir.types`, plus STRING and VOID (a return type). */
export const PLC_TYPES: readonly string[] = [
  'BOOL', 'BYTE', 'CHAR', 'WORD', 'INT', 'S5TIME', 'DATE', 'DWORD', 'DINT', 'REAL', 'TIME',
  'TIME_OF_DAY', 'DATE_AND_TIME', 'POINTER', 'ANY', 'TIMER', 'COUNTER', 'BLOCK_FB', 'BLOCK_FC',
  'BLOCK_DB', 'BLOCK_SDB', 'TOD', 'DT', 'STRING', 'VOID',
  // S7-1200/1500 only
  'SINT', 'USINT', 'UINT', 'UDINT', 'LINT', 'ULINT', 'LREAL', 'LWORD', 'LTIME', 'WCHAR',
];

// The address and constant terminals of grammars/stl.lark, as JavaScript regular expressions.
const ADDRESS =
  /(?:DB[ \t]*\d+[ \t]*\.[ \t]*DB[XBWD]|DBX|DBB|DBW|DBD|DIX|DIB|DIW|DID|PIB|PIW|PID|PEB|PEW|PED|PQB|PQW|PQD|PAB|PAW|PAD|SFC|SFB|UDT|DB|DI|FC|FB|OB|IX|IB|IW|ID|QX|QB|QW|QD|EX|EB|EW|ED|AX|AB|AW|AD|MX|MB|MW|MD|LX|LB|LW|LD|VX|VB|VW|VD|I|Q|E|A|M|L|V|T|C|Z)[ \t]*\d+(?:\.\d+)*(?!\w)|SF[BC][ \t]*-\d+(?!\w)/;
const AREA =
  /(?:DBX|DBB|DBW|DBD|DIX|DIB|DIW|DID|PIB|PIW|PID|PEB|PEW|PED|PQB|PQW|PQD|PAB|PAW|PAD|SFC|SFB|DB|DI|FC|FB|IX|IB|IW|ID|QX|QB|QW|QD|EX|EB|EW|ED|AX|AB|AW|AD|MX|MB|MW|MD|LX|LB|LW|LD|VX|VB|VW|VD|I|Q|E|A|M|L|V|T|C|Z|X|B|W|D)(?=[ \t]*\[)/;
const POINTER =
  /P#(?:#\w+|(?:DB[ \t]*\d+[ \t]*\.[ \t]*)?(?:[A-Za-z]+[ \t]*)?\d+\.\d+(?:[ \t]+[A-Za-z_]+[ \t]+\d+)?|(?:DB\d+|"[^"\r\n]*")\.[^\W\d]\w*(?:\.[^\W\d]\w*|\[[ \t]*\d+(?:[ \t]*,[ \t]*\d+)*[ \t]*\])*)/;
const BYTES = /B#\([ \t]*[+-]?\d+[ \t]*(?:,[ \t]*[+-]?\d+[ \t]*)*\)/;
const TYPED = /(?:DATE_AND_TIME|TIME_OF_DAY|S5TIME|S5T|DATE|TIME|TOD|DT|DW|L|B|W|C|T|D|\d+)#[+-]?[0-9A-Za-z_.:#+-]+/;
const REAL = /[+-]?\d+(?:\.\d+(?:[eE][+-]?\d+)?|[eE][+-]?\d+)/;
const STATUS_CMP = /(?:==|<>|>=|<=|>|<)0(?![\w.])/;
/** `WORD_OP` / `SYM_OP` of the grammar: how an instruction is spelled at a statement's start. */
const WORD_OP = /[A-Za-z_]\w*(?:\(|==R(?!\w)|==|<>|>=|<=|<|>|[+-](?!\w))?/;
const SYM_OP = /\)(?:MCR(?!\w))?|(?:==|<>|>=|<=|>|<)[IDR](?!\w)|[+\-*/][IDR](?!\w)|\+AR[12](?!\w)|\+|=/;

/**
 * The Monarch tokenizer. STL is line-oriented: the first word of a statement is the
 * instruction, the rest its operands, so `A` is "And" at the start and the German output area
 * in `U A 4.0`, `T` the transfer and the timer in `T T 1`. `includeLF` lets the operand state
 * end with its line (or at a `;`), as the compiler's newline filter does.
 */
export const stlLanguage: languages.IMonarchLanguage = {
  defaultToken: '',
  tokenPostfix: '.stl',
  ignoreCase: true,
  includeLF: true,

  mnemonics: WORD_MNEMONICS as string[],
  jumps: JUMP_MNEMONICS as string[],
  blockKeywords: STL_BLOCK_KEYWORDS as string[],
  varKeywords: STL_VAR_KEYWORDS as string[],
  headerKeys: STL_HEADER_KEYS as string[],
  flags: STL_FLAGS as string[],
  types: PLC_TYPES as string[],

  address: ADDRESS,
  area: AREA,
  pointer: POINTER,
  bytes: BYTES,
  typed: TYPED,
  real: REAL,
  statusCmp: STATUS_CMP,
  wordOp: WORD_OP,
  symOp: SYM_OP,

  brackets: [
    { open: '(', close: ')', token: 'delimiter.parenthesis' },
    { open: '[', close: ']', token: 'delimiter.square' },
  ],

  tokenizer: {
    // A statement's start (and everything outside code: headers, DB values).
    root: [
      // Block properties (VERSION : 0.1) and jump labels (M001:) start a line, before blanks.
      [/^([ \t]*)((?:AUTHOR|FAMILY|NAME|VERSION)(?!\w))([ \t]*)(:)(?!=)([^\n;/]*)/, ['', 'keyword', '', 'delimiter', 'string.header']],
      [/^([ \t]*)([A-Za-z_]\w*)([ \t]*:)(?!=)/, ['', 'label', 'delimiter']],
      [/[ \t\r\n]+/, ''],
      { include: '@comment' },
      [/(TITLE)([ \t]*)(=.*)/, ['keyword', '', 'comment.title']],
      // A CALL's parameter on a line of its own, or a DB value: name := operand
      [/[A-Za-z_]\w*(?=[ \t]*:=)/, { token: 'identifier', next: '@operands' }],
      [/VAR(?:_INPUT|_OUTPUT|_IN_OUT|_TEMP)?(?!\w)/, { token: 'keyword', next: '@declarations' }],
      [/STRUCT(?!\w)/, { token: 'keyword', next: '@declarations' }],
      [
        /@wordOp/,
        {
          cases: {
            '@mnemonics': { token: 'keyword.instruction', next: '@operands' },
            '@jumps': { token: 'keyword.instruction', next: '@jumpTarget' },
            '@blockKeywords': 'keyword',
            '@flags': 'keyword',
            '@types': 'type',
            '@default': { token: '@rematch', next: '@operands' },
          },
        },
      ],
      [/@symOp/, { token: 'keyword.instruction', next: '@operands' }],
      { include: '@attributes' },
      { include: '@operand' },
    ],

    // The operands of one instruction: up to the end of the line or a ";".
    operands: [
      [/\n/, '', '@pop'],
      [/;/, 'delimiter', '@pop'],
      [/[ \t\r]+/, ''],
      { include: '@comment' },
      { include: '@operand' },
    ],

    // A jump's label (JCN M001: M001 is the label, not the memory byte).
    jumpTarget: [
      [/[ \t\r]+/, ''],
      [/[A-Za-z_]\w*/, { token: 'label', switchTo: '@operands' }],
      [/./, { token: '@rematch', switchTo: '@operands' }],
      [/\n/, '', '@pop'],
    ],

    // VAR ... END_VAR and STRUCT ... END_STRUCT: names, types, initial values.
    declarations: [
      [/[ \t\r\n]+/, ''],
      { include: '@comment' },
      [/END_VAR(?!\w)|END_STRUCT(?!\w)/, 'keyword', '@pop'],
      [/STRUCT(?!\w)/, 'keyword', '@push'],
      [/(?:ARRAY|OF)(?!\w)/, 'keyword'],
      [/[A-Za-z_]\w*/, { cases: { '@types': 'type', '@default': 'identifier' } }],
      { include: '@attributes' },
      { include: '@operand' },
    ],

    comment: [[/\/\/.*/, 'comment']],

    // { S7_m_c := 'true' } system attributes of blocks and declarations.
    attributes: [[/\{/, { token: 'annotation', next: '@attributeList' }]],
    attributeList: [
      [/\}/, 'annotation', '@pop'],
      [/'(?:[^'\n$]|\$.)*'/, 'string'],
      [/:=/, 'annotation'],
      [/[^}'\n:]+|:/, 'annotation'],
      [/\n/, ''],
    ],

    // Operands, constants, symbols: the same in code, declarations and DB values.
    operand: [
      [/@pointer/, 'number.pointer'],
      [/@bytes/, 'number'],
      [/@typed/, 'number'],
      [/@address/, 'address'],
      [/@area/, 'address'],
      [/"[^"\n]*"/, 'variable.symbol'],
      [/"[^"\n]*$/, 'variable.symbol.invalid'],
      [/##?\w+/, 'variable.local'],
      [/'(?:[^'\n$]|\$.)*'/, 'string'],
      [/'[^\n]*$/, 'string.invalid'],
      [/@statusCmp/, 'operator'],
      [/@real/, 'number.float'],
      [/[+-]?\d+/, 'number'],
      [/:=/, 'operator'],
      [/[A-Za-z_]\w*/, { cases: { '@types': 'type', '@default': 'identifier' } }],
      [/[()[\]]/, '@brackets'],
      [/[,.:;]/, 'delimiter'],
      [/[=<>+\-*/]/, 'operator'],
    ],
  },
};

export const stlConfiguration: languages.LanguageConfiguration = {
  comments: { lineComment: '//' },
  brackets: [
    ['(', ')'],
    ['[', ']'],
  ],
  autoClosingPairs: [
    { open: '(', close: ')' },
    { open: '[', close: ']' },
    { open: '"', close: '"', notIn: ['string', 'comment'] },
    { open: "'", close: "'", notIn: ['string', 'comment'] },
  ],
  surroundingPairs: [
    { open: '(', close: ')' },
    { open: '[', close: ']' },
    { open: '"', close: '"' },
    { open: "'", close: "'" },
  ],
  // #local and plain names are words; so are addresses with their bit (M 10.1 stays two words).
  wordPattern: /#?[A-Za-z_]\w*|-?\d+(?:\.\d+)?/g,
};

/** The keywords that open and close a foldable region of an STL source. */
const STL_OPENERS: Readonly<Record<string, string>> = {
  ORGANIZATION_BLOCK: 'END_ORGANIZATION_BLOCK',
  FUNCTION_BLOCK: 'END_FUNCTION_BLOCK',
  FUNCTION: 'END_FUNCTION',
  DATA_BLOCK: 'END_DATA_BLOCK',
  TYPE: 'END_TYPE',
  VAR: 'END_VAR',
  VAR_INPUT: 'END_VAR',
  VAR_OUTPUT: 'END_VAR',
  VAR_IN_OUT: 'END_VAR',
  VAR_TEMP: 'END_VAR',
  STRUCT: 'END_STRUCT',
};

export interface LineRange {
  /** 1-based, as Monaco counts lines. */
  start: number;
  end: number;
}

/**
 * Foldable regions of an STL source: blocks, declaration sections, structures, and each
 * NETWORK up to the line before the next NETWORK or the block's end.
 */
export function stlFoldingRanges(text: string): LineRange[] {
  const lines = text.split(/\r?\n/);
  const ranges: LineRange[] = [];
  const open: Array<{ end: string; line: number }> = [];
  let network: number | null = null;
  const closeNetwork = (last: number) => {
    if (network !== null && last > network) ranges.push({ start: network, end: last });
    network = null;
  };
  lines.forEach((raw, index) => {
    const line = index + 1;
    const code = raw.replace(/\/\/.*$/, '').replace(/'(?:[^'$]|\$.)*'|"[^"]*"/g, ' ');
    const first = /^\s*([A-Za-z_]\w*)/.exec(code)?.[1]?.toUpperCase();
    if (!first) return;
    if (first === 'NETWORK') {
      closeNetwork(line - 1);
      network = line;
      return;
    }
    const closer = STL_OPENERS[first];
    if (closer) {
      open.push({ end: closer, line });
      return;
    }
    if (first.startsWith('END_')) {
      if (first !== 'END_VAR' && first !== 'END_STRUCT') closeNetwork(line - 1);
      const at = open.map((entry) => entry.end).lastIndexOf(first);
      if (at >= 0) {
        const [entry] = open.splice(at);
        if (entry && line > entry.line) ranges.push({ start: entry.line, end: line });
      }
    }
  });
  closeNetwork(lines.length);
  return ranges.sort((a, b) => a.start - b.start);
}

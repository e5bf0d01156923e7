/**
 * S7-SCL for the Monaco editor: a Monarch tokenizer and the language configuration.
 *
 * The word lists are the compiler's own: keywords, operators, addresses and literals are the
 * terminals of `grammars/scl.lark`; the standard functions are those the type checker knows
 * (`nasaq.lang.scl.typecheck.rules.calls.STANDARD`: conversions, numeric, bit string, string,
 * S5 timer/counter and IEC library functions); the data types `nasaq.ir.types`. A vitest test
 * (`tests/frontend/editorLanguages.test.ts`) reads those files and fails when they drift apart.
 *
 * Only types are imported from Monaco, so this module costs nothing in the app shell.
 */
import type { languages } from 'monaco-editor/editor/editor.api';
import { PLC_TYPES, type LineRange } from './stl';

export const SCL_LANGUAGE_ID = 'scl';

/** Reserved words of `grammars/scl.lark` (the VAR sections, header keys and flags apart). */
export const SCL_KEYWORDS: readonly string[] = [
  'ORGANIZATION_BLOCK', 'FUNCTION_BLOCK', 'FUNCTION', 'PROGRAM', 'DATA_BLOCK', 'TYPE', 'BEGIN',
  'END_ORGANIZATION_BLOCK', 'END_FUNCTION_BLOCK', 'END_FUNCTION', 'END_PROGRAM', 'END_DATA_BLOCK',
  'END_TYPE', 'END_VAR', 'CONST', 'END_CONST', 'LABEL', 'END_LABEL', 'STRUCT', 'END_STRUCT', 'ARRAY',
  'OF', 'AT', 'IF', 'THEN', 'ELSIF', 'ELSE', 'END_IF', 'CASE', 'END_CASE', 'FOR', 'TO', 'BY', 'DO',
  'END_FOR', 'WHILE', 'END_WHILE', 'REPEAT', 'UNTIL', 'END_REPEAT', 'EXIT', 'CONTINUE', 'GOTO',
  'RETURN', 'END_REGION', 'TITLE',
];

/** `VAR_KW` of the grammar, with the qualifiers that may follow a section's keyword. */
export const SCL_VAR_KEYWORDS: readonly string[] = [
  'VAR', 'VAR_INPUT', 'VAR_OUTPUT', 'VAR_IN_OUT', 'VAR_TEMP', 'VAR_STAT',
  'CONSTANT', 'RETAIN', 'NON_RETAIN', 'DB_SPECIFIC',
];
export const SCL_HEADER_KEYS: readonly string[] = ['AUTHOR', 'FAMILY', 'NAME', 'VERSION'];
export const SCL_FLAGS: readonly string[] = ['KNOW_HOW_PROTECT', 'NON_RETAIN', 'READ_ONLY', 'UNLINKED', 'STANDARD'];

/** The word operators of the grammar; TRUE and FALSE are literals. */
export const SCL_WORD_OPERATORS: readonly string[] = ['NOT', 'AND', 'XOR', 'OR', 'MOD', 'DIV'];
export const SCL_CONSTANTS: readonly string[] = ['TRUE', 'FALSE'];

/** Names the binder gives a meaning: the enable input/output and the OK flag. */
export const SCL_PREDEFINED_VARIABLES: readonly string[] = ['EN', 'ENO', 'OK'];

/** `nasaq.lang.scl.typecheck.rules.calls.STANDARD`: the functions S7-SCL calls by name. */
export const SCL_STANDARD_FUNCTIONS: readonly string[] = [
  'ABS', 'ACOS', 'AD_DT_TM', 'ASIN', 'ATAN', 'BLOCK_DB_TO_WORD', 'BOOL_TO_BYTE', 'BOOL_TO_DWORD',
  'BOOL_TO_WORD', 'BYTE_BCD_TO_INT', 'BYTE_TO_BOOL', 'BYTE_TO_CHAR', 'BYTE_TO_DWORD', 'BYTE_TO_WORD',
  'CHAR_TO_BYTE', 'CHAR_TO_INT', 'CHAR_TO_STRING', 'CONCAT', 'COS', 'DATE_TO_DINT', 'DELETE',
  'DINT_TO_BCD_DWORD', 'DINT_TO_DATE', 'DINT_TO_DWORD', 'DINT_TO_INT', 'DINT_TO_REAL', 'DINT_TO_TIME',
  'DINT_TO_TOD', 'DI_STRNG', 'DT_DATE', 'DT_DAY', 'DT_TOD', 'DWORD_BCD_TO_DINT', 'DWORD_TO_BOOL',
  'DWORD_TO_BYTE', 'DWORD_TO_DINT', 'DWORD_TO_REAL', 'DWORD_TO_WORD', 'D_TOD_DT', 'EQ_DT', 'EQ_STRNG',
  'EXP', 'EXPD', 'FIND', 'GE_DT', 'GE_STRNG', 'GT_DT', 'GT_STRNG', 'INSERT', 'INT_TO_BCD_BYTE',
  'INT_TO_BCD_WORD', 'INT_TO_CHAR', 'INT_TO_DINT', 'INT_TO_REAL', 'INT_TO_WORD', 'I_STRNG', 'LEFT',
  'LEN', 'LE_DT', 'LE_STRNG', 'LIMIT', 'LN', 'LOG', 'LT_DT', 'LT_STRNG', 'MAX', 'MID', 'MIN', 'MUX',
  'NE_DT', 'NE_STRNG', 'REAL_TO_DINT', 'REAL_TO_DWORD', 'REAL_TO_INT', 'REPLACE', 'RIGHT', 'ROL',
  'ROR', 'ROUND', 'R_STRNG', 'SB_DT_DT', 'SB_DT_TM', 'SEL', 'SHL', 'SHR', 'SIN', 'SQR', 'SQRT',
  'STRING_TO_CHAR', 'STRNG_DI', 'STRNG_I', 'STRNG_R', 'S_CD', 'S_CU', 'S_CUD', 'S_ODT', 'S_ODTS',
  'S_OFFDT', 'S_PEXT', 'S_PULSE', 'TAN', 'TIME_TO_DINT', 'TOD_TO_DINT', 'TRUNC', 'WORD_BCD_TO_INT',
  'WORD_TO_BLOCK_DB', 'WORD_TO_BOOL', 'WORD_TO_BYTE', 'WORD_TO_DWORD', 'WORD_TO_INT',
  // TIA Portal's names (BCD, rounding, Unicode text)
  'BCD16_TO_INT', 'BCD32_TO_DINT', 'BCD_TO_INT', 'CEIL', 'DINT_TO_BCD32', 'FLOOR', 'INT_TO_BCD',
  'INT_TO_BCD16', 'STRING_TO_WSTRING', 'WSTRING_TO_STRING',
  // TIA Portal's text instructions and conversions (S7-1200/1500)
  'CHAR_TO_WSTRING', 'DTL_TO_DATE', 'DTL_TO_TOD', 'STRG_VAL', 'STRING_TO_WCHAR', 'VAL_STRG',
  'WCHAR_TO_STRING', 'WCHAR_TO_WSTRING', 'WSTRING_TO_CHAR', 'WSTRING_TO_WCHAR',
  // TIA Portal's VARIANT and ARRAY[*] instructions (S7-1200/1500)
  'COUNTOFELEMENTS', 'DESERIALIZE', 'IS_ARRAY', 'LOWER_BOUND', 'MOVE_BLK_VARIANT', 'SERIALIZE',
  'TYPEOF', 'TYPEOFELEMENTS', 'UPPER_BOUND', 'VARIANTGET', 'VARIANTPUT',
  // TIA Portal's DB_ANY and direct memory instructions (S7-1200/1500)
  'DB_ANY_TO_UINT', 'PEEK', 'PEEK_BOOL', 'PEEK_DWORD', 'PEEK_WORD', 'POKE', 'POKE_BOOL',
  'UINT_TO_DB_ANY',
];

// The address and literal terminals of grammars/scl.lark, as JavaScript regular expressions.
const ADDRESS =
  /%?(?:PIB|PIW|PID|PQB|PQW|PQD|SFC|SFB|UDT|IB|IW|ID|IX|QB|QW|QD|QX|MB|MW|MD|MX|DB|DI|FC|FB|OB|I|Q|M|T|C)[ \t]*\d+(?:\.\d+)?(?!\w)/;
const AREA = /%?(?:PIB|PIW|PID|PQB|PQW|PQD|IB|IW|ID|IX|QB|QW|QD|QX|MB|MW|MD|MX|I|Q|M)(?=[ \t]*\[)/;
const DB_ADDRESS = /%?(?:DBX|DBB|DBW|DBD|DX|DB|DW|DD)[ \t]*\d+(?:\.\d+)?(?!\w)|%?D[ \t]*\d+\.\d+(?!\w)/;
const DB_AREA = /%?(?:DBX|DBB|DBW|DBD|DX|DB|DW|DD)(?=[ \t]*\[)/;
const BASED = /(?:[A-Za-z_]\w*#)?[+-]?(?:2#[01_]+|8#[0-7_]+|16#[0-9A-Fa-f_]+)(?!\w)/;
const TYPED =
  /[A-Za-z_]\w*#(?:\d+-\d+-\d+-\d+:\d+:\d+(?:\.\d+)?|\d+-\d+-\d+|\d+:\d+:\d+(?:\.\d+)?|[+-]?(?:\d[\d_]*(?:\.\d+)?(?:ms|d|h|m|s)_?)+|[+-]?\d[\d_]*(?:\.\d[\d_]*)?(?:[eE][+-]?\d+)?|'(?:[^'\r\n$]|\$.)*'|TRUE|FALSE|\([^)\r\n]*\))(?!\w)/;
const REAL = /\d[\d_]*(?:\.\d[\d_]*(?:[eE][+-]?\d+)?|[eE][+-]?\d+)/;

export const sclLanguage: languages.IMonarchLanguage = {
  defaultToken: '',
  tokenPostfix: '.scl',
  ignoreCase: true,

  keywords: SCL_KEYWORDS as string[],
  varKeywords: SCL_VAR_KEYWORDS as string[],
  headerKeys: SCL_HEADER_KEYS as string[],
  flags: SCL_FLAGS as string[],
  wordOperators: SCL_WORD_OPERATORS as string[],
  constants: SCL_CONSTANTS as string[],
  predefinedVariables: SCL_PREDEFINED_VARIABLES as string[],
  functions: SCL_STANDARD_FUNCTIONS as string[],
  types: PLC_TYPES as string[],

  address: ADDRESS,
  area: AREA,
  dbAddress: DB_ADDRESS,
  dbArea: DB_AREA,
  based: BASED,
  typed: TYPED,
  real: REAL,

  brackets: [
    { open: '(', close: ')', token: 'delimiter.parenthesis' },
    { open: '[', close: ']', token: 'delimiter.square' },
  ],

  tokenizer: {
    root: [
      [/[ \t\r\n]+/, ''],
      { include: '@comments' },
      [/\{/, { token: 'annotation', next: '@attributeList' }],
      [/(TITLE)([ \t]*)(=.*)$/, ['keyword', '', 'comment.title']],
      // TIA's REGION takes the rest of its line as its title.
      [/(REGION)(?![ \t]*:=)(?!\w)(.*)$/, ['keyword', 'comment.title']],
      // ... and may write it again after END_REGION (up to a ";" or a comment).
      [/(END_REGION)(?!\w)((?:[ \t]+(?![ \t]|\/\/|\(\*|\/\*)(?:[^\r\n;/(]|\/(?![/*])|\((?!\*))*)?)/, ['keyword', 'comment.title']],
      [/((?:AUTHOR|FAMILY|NAME|VERSION)(?!\w))([ \t]*)(:)(?!=)/, ['keyword', '', 'delimiter']],
      // A member after a ".": DB10.DW2, "Data".DX1.1, DB11.DW[i]
      [/(\.)(@dbAddress)/, ['delimiter', 'address']],
      [/(\.)(@dbArea)/, ['delimiter', 'address']],
      [/@based/, 'number.hex'],
      [/@typed/, 'number'],
      [/@address/, 'address'],
      [/@area/, 'address'],
      [
        /[A-Za-z_]\w*/,
        {
          cases: {
            '@keywords': 'keyword',
            '@varKeywords': 'keyword',
            '@flags': 'keyword',
            '@wordOperators': 'keyword.operator',
            '@constants': 'constant',
            '@types': 'type',
            '@functions': 'predefined',
            '@predefinedVariables': 'variable.predefined',
            '@default': 'identifier',
          },
        },
      ],
      [/"[^"\n]*"/, 'variable.symbol'],
      [/"[^"\n]*$/, 'variable.symbol.invalid'],
      [/#[A-Za-z_]\w*/, 'variable.local'],
      [/'(?:[^'\n$]|\$.)*'/, 'string'],
      [/'[^\n]*$/, 'string.invalid'],
      [/@real/, 'number.float'],
      [/\d[\d_]*/, 'number'],
      [/:=|=>|\*\*|<>|<=|>=|[=<>+\-*/&]/, 'operator'],
      [/[()[\]]/, '@brackets'],
      [/\.\.|[;,.:]/, 'delimiter'],
    ],

    comments: [
      [/\/\/.*$/, 'comment'],
      [/\(\*/, 'comment', '@blockComment'],
      [/\/\*/, 'comment', '@cComment'],
    ],
    // (* ... *) nests, as TIA Portal reads it (nasaq.lang.scl README, "Comments").
    blockComment: [
      [/\*\)/, 'comment', '@pop'],
      [/\(\*/, 'comment', '@push'],
      [/[^*(]+|\*|\(/, 'comment'],
    ],
    cComment: [
      [/\*\//, 'comment', '@pop'],
      [/[^*]+|\*/, 'comment'],
    ],

    // { S7_Optimized_Access := 'FALSE' } attributes and { SCL_CreateDebugInfo := 'y' } pragmas.
    attributeList: [
      [/\}/, 'annotation', '@pop'],
      [/'(?:[^'\n$]|\$.)*'/, 'string'],
      [/[^}']+/, 'annotation'],
    ],
  },
};

export const sclConfiguration: languages.LanguageConfiguration = {
  comments: { lineComment: '//', blockComment: ['(*', '*)'] },
  brackets: [
    ['(', ')'],
    ['[', ']'],
  ],
  autoClosingPairs: [
    { open: '(', close: ')' },
    { open: '[', close: ']' },
    { open: '"', close: '"', notIn: ['string', 'comment'] },
    { open: "'", close: "'", notIn: ['string', 'comment'] },
    { open: '(*', close: ' *)', notIn: ['string'] },
  ],
  surroundingPairs: [
    { open: '(', close: ')' },
    { open: '[', close: ']' },
    { open: '"', close: '"' },
    { open: "'", close: "'" },
  ],
  wordPattern: /#?[A-Za-z_]\w*|-?\d+(?:\.\d+)?/g,
  // Indent after a line that opens a body, outdent the line that closes it.
  indentationRules: {
    increaseIndentPattern:
      /^\s*(?:.*\b(?:THEN|DO|OF|ELSE)\b\s*(?:\/\/.*)?$|REPEAT\b|VAR(?:_\w+)?\b(?!.*END_VAR)|STRUCT\b|BEGIN\b|REGION\b|CONST\b)/i,
    decreaseIndentPattern: /^\s*(?:END_\w+|ELSE\b|ELSIF\b|UNTIL\b|BEGIN\b)/i,
  },
};

/** The keywords that open a foldable region of an SCL source, and what closes it. */
const SCL_OPENERS: Readonly<Record<string, string>> = {
  ORGANIZATION_BLOCK: 'END_ORGANIZATION_BLOCK',
  FUNCTION_BLOCK: 'END_FUNCTION_BLOCK',
  FUNCTION: 'END_FUNCTION',
  PROGRAM: 'END_PROGRAM',
  DATA_BLOCK: 'END_DATA_BLOCK',
  TYPE: 'END_TYPE',
  VAR: 'END_VAR',
  VAR_INPUT: 'END_VAR',
  VAR_OUTPUT: 'END_VAR',
  VAR_IN_OUT: 'END_VAR',
  VAR_TEMP: 'END_VAR',
  VAR_STAT: 'END_VAR',
  CONST: 'END_CONST',
  LABEL: 'END_LABEL',
  STRUCT: 'END_STRUCT',
  IF: 'END_IF',
  CASE: 'END_CASE',
  FOR: 'END_FOR',
  WHILE: 'END_WHILE',
  REPEAT: 'END_REPEAT',
  REGION: 'END_REGION',
};

/** Foldable regions of an SCL source: blocks, sections and statements with an END_ keyword. */
export function sclFoldingRanges(text: string): LineRange[] {
  const ranges: LineRange[] = [];
  const open: Array<{ end: string; line: number }> = [];
  let inComment: '*)' | '*/' | null = null;
  text.split(/\r?\n/).forEach((raw, index) => {
    const line = index + 1;
    // Blank out comments (which may span lines), strings and symbols, then read the words.
    let code = '';
    let rest = raw;
    while (rest.length > 0) {
      if (inComment) {
        const end = rest.indexOf(inComment);
        if (end < 0) rest = '';
        else {
          rest = rest.slice(end + 2);
          inComment = null;
        }
        continue;
      }
      const next = /\/\/|\(\*|\/\*|'(?:[^'$]|\$.)*'?|"[^"]*"?|\{[^}]*\}?/.exec(rest);
      if (!next) {
        code += rest;
        break;
      }
      code += rest.slice(0, next.index) + ' ';
      rest = rest.slice(next.index + next[0].length);
      if (next[0] === '//') rest = '';
      else if (next[0] === '(*') inComment = '*)';
      else if (next[0] === '/*') inComment = '*/';
    }
    for (const match of code.matchAll(/[A-Za-z_]\w*/g)) {
      const word = match[0].toUpperCase();
      const closer = SCL_OPENERS[word];
      if (closer) {
        open.push({ end: closer, line });
      } else if (word.startsWith('END_')) {
        const at = open.map((entry) => entry.end).lastIndexOf(word);
        if (at >= 0) {
          const [entry] = open.splice(at);
          if (entry && line > entry.line) ranges.push({ start: entry.line, end: line });
        }
      }
    }
  });
  return ranges.sort((a, b) => a.start - b.start);
}

/**
 * The LAD/FBD text format (`.lad`, `.fbd`) for the Monaco editor: a Monarch tokenizer, the
 * language configuration and the foldable regions. Until the graphical editors draw them, LAD
 * and FBD blocks are edited as this text; the compiler places its problems on its lines.
 *
 * The words are the terminals of `grammars/lad.lark` (a vitest test reads the grammar and fails
 * when they drift apart). A network kept as STL (`STL [REASON LAD3xx] ... END_STL`) is
 * tokenized by the STL language, embedded.
 *
 * Only types are imported from Monaco, so this module costs nothing in the app shell.
 */
import type { languages } from 'monaco-editor/editor/editor.api';
import { PLC_TYPES, STL_LANGUAGE_ID, type LineRange } from './stl';

export const LAD_LANGUAGE_ID = 'lad';

/** The structure keywords of `grammars/lad.lark` (blocks, networks, rungs and branches). */
export const LAD_STRUCTURE_KEYWORDS: readonly string[] = [
  'ORGANIZATION_BLOCK', 'FUNCTION_BLOCK', 'FUNCTION', 'END_ORGANIZATION_BLOCK',
  'END_FUNCTION_BLOCK', 'END_FUNCTION', 'TITLE', 'LANGUAGE', 'BEGIN', 'NETWORK', 'COMMENT',
  'LABEL', 'RUNG', 'END_RUNG', 'OUTPUTS', 'END_OUTPUTS', 'PARALLEL', 'END_PARALLEL', 'BRANCH',
  'END_BRANCH', 'INSTANCE',
];

/** The element names of `grammars/lad.lark`: contacts, coils, boxes, jumps (any letter case). */
export const LAD_ELEMENTS: readonly string[] = [
  'CONTACT', 'CONTACTNC', 'STATUS', 'STATUSNC', 'NOT', 'EDGE', 'MIDLINE', 'BOX', 'COIL',
  'SETCOIL', 'RESETCOIL', 'SP', 'SE', 'SD', 'SS', 'SF', 'CU', 'CD', 'SC', 'SAVE', 'JUMP', 'JUMPN',
  'RETURN', 'OPEN',
];

/** `LANGUAGE_NAME` of the grammar: the view a block is in. */
export const LAD_VIEWS: readonly string[] = ['LAD', 'FBD'];

const VAR_SECTIONS = /(?:VAR(?:_INPUT|_OUTPUT|_IN_OUT|_TEMP)?|END_VAR|STRUCT|END_STRUCT|ARRAY|OF)(?!\w)/;
// An address as an operand is written: I 0.0, MW 10, DB5.DBX 2.1, T 1, C#10 ...
const ADDRESS =
  /(?:DB[ \t]*\d+[ \t]*\.[ \t]*DB[XBWD]|DBX|DBB|DBW|DBD|DIX|DIB|DIW|DID|PIB|PIW|PID|PQB|PQW|PQD|SFC|SFB|DB|DI|FC|FB|OB|IB|IW|ID|QB|QW|QD|MB|MW|MD|LB|LW|LD|I|Q|M|L|T|C)[ \t]*\d+(?:\.\d+)?(?!\w)/;
const TYPED = /(?:S5TIME|S5T|TIME|T|C|W|DW|L|B|D|\d+)#[+-]?[0-9A-Za-z_.:#+-]+/;

export const ladLanguage: languages.IMonarchLanguage = {
  defaultToken: '',
  tokenPostfix: '.lad',
  ignoreCase: true,

  structure: LAD_STRUCTURE_KEYWORDS as string[],
  elements: LAD_ELEMENTS as string[],
  views: LAD_VIEWS as string[],
  types: PLC_TYPES as string[],
  address: ADDRESS,
  typed: TYPED,
  varSections: VAR_SECTIONS,

  brackets: [{ open: '(', close: ')', token: 'delimiter.parenthesis' }],

  tokenizer: {
    root: [
      [/[ \t\r\n]+/, ''],
      { include: '@comments' },
      [/(TITLE|COMMENT)([ \t]*)(=.*)/, ['keyword', '', 'comment.title']],
      // A network that stays STL: its lines are STL, up to END_STL.
      [/(STL)([ \t]+)(REASON)([ \t]+)(LAD\d+)/, ['keyword', '', 'keyword', '', { token: 'string.reason', next: '@stl', nextEmbedded: STL_LANGUAGE_ID }]],
      [/STL(?!\w)/, { token: 'keyword', next: '@stl', nextEmbedded: STL_LANGUAGE_ID }],
      [/END_STL(?!\w)/, 'keyword'],
      [/(LABEL)([ \t]+)([A-Za-z_]\w*)/, ['keyword', '', 'label']],
      [/(JUMPN?)([ \t]*)(\()([ \t]*)([A-Za-z_]\w*)/, ['keyword.instruction', '', '@brackets', '', 'label']],
      [/@varSections/, 'keyword'],
      { include: '@operand' },
      [
        /[A-Za-z_]\w*/,
        {
          cases: {
            '@structure': 'keyword',
            '@elements': 'keyword.instruction',
            '@views': 'keyword',
            '@types': 'type',
            '@default': 'identifier',
          },
        },
      ],
      [/@[A-Za-z_]\w*/, 'tag'],
    ],

    stl: [[/^[ \t]*END_STL(?!\w)/, { token: '@rematch', next: '@pop', nextEmbedded: '@pop' }]],

    comments: [
      [/\/\/.*/, 'comment'],
      [/\(\*/, 'comment', '@blockComment'],
    ],
    blockComment: [
      [/\*\)/, 'comment', '@pop'],
      [/[^*]+|\*/, 'comment'],
    ],

    operand: [
      // A pin inside a box: IN1 := MW 10, OUT => MW 12.
      [/:=|=>/, 'operator'],
      [/P#[^\s,)]+/, 'number.pointer'],
      [/@typed/, 'number'],
      [/@address/, 'address'],
      [/"[^"\n]*"/, 'variable.symbol'],
      [/"[^"\n]*$/, 'variable.symbol.invalid'],
      [/##?\w+/, 'variable.local'],
      [/'(?:[^'\n$]|\$.)*'/, 'string'],
      [/[+-]?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?/, 'number'],
      [/[()]/, '@brackets'],
      [/[,.:;[\]]/, 'delimiter'],
      [/[=<>+\-*/]/, 'operator'],
    ],
  },
};

export const ladConfiguration: languages.LanguageConfiguration = {
  comments: { lineComment: '//', blockComment: ['(*', '*)'] },
  brackets: [['(', ')']],
  autoClosingPairs: [
    { open: '(', close: ')' },
    { open: '"', close: '"', notIn: ['string', 'comment'] },
  ],
  surroundingPairs: [
    { open: '(', close: ')' },
    { open: '"', close: '"' },
  ],
  wordPattern: /#?[A-Za-z_]\w*|-?\d+(?:\.\d+)?/g,
};

/** The keywords that open a foldable region of a LAD/FBD source, with the one that closes it. */
const LAD_OPENERS: Readonly<Record<string, string>> = {
  ORGANIZATION_BLOCK: 'END_ORGANIZATION_BLOCK',
  FUNCTION_BLOCK: 'END_FUNCTION_BLOCK',
  FUNCTION: 'END_FUNCTION',
  VAR: 'END_VAR',
  VAR_INPUT: 'END_VAR',
  VAR_OUTPUT: 'END_VAR',
  VAR_IN_OUT: 'END_VAR',
  VAR_TEMP: 'END_VAR',
  RUNG: 'END_RUNG',
  OUTPUTS: 'END_OUTPUTS',
  PARALLEL: 'END_PARALLEL',
  BRANCH: 'END_BRANCH',
  STL: 'END_STL',
};

/**
 * Foldable regions: blocks, declaration sections, each NETWORK up to the line before the next
 * one or the block's end, and rungs, parallels, branches and STL networks that span lines.
 */
export function ladFoldingRanges(text: string): LineRange[] {
  const ranges: LineRange[] = [];
  const open: Array<{ end: string; line: number }> = [];
  let network: number | null = null;
  let inStl = false;
  const closeNetwork = (last: number) => {
    if (network !== null && last > network) ranges.push({ start: network, end: last });
    network = null;
  };
  text.split(/\r?\n/).forEach((raw, index) => {
    const line = index + 1;
    const code = raw
      .replace(/\/\/.*$/, '')
      .replace(/"[^"]*"|'[^']*'/g, ' ')
      .replace(/\b(TITLE|COMMENT)[ \t]*=.*$/i, '$1'); // a title's words are text
    const words = [...code.matchAll(/[A-Za-z_]\w*/g)].map((match) => match[0].toUpperCase());
    if (inStl) {
      if (words[0] !== 'END_STL') return; // STL lines: their words are not this language's
      inStl = false;
    }
    for (const word of words) {
      if (word === 'NETWORK') {
        closeNetwork(line - 1);
        network = line;
        continue;
      }
      const closer = LAD_OPENERS[word];
      if (closer) {
        open.push({ end: closer, line });
        if (word === 'STL') {
          inStl = true;
          break;
        }
        continue;
      }
      const at = open.map((item) => item.end).lastIndexOf(word);
      if (at < 0) continue;
      const [opened] = open.splice(at);
      if (word.startsWith('END_') && /BLOCK$|FUNCTION$/.test(word)) closeNetwork(line - 1);
      if (opened && line > opened.line) ranges.push({ start: opened.line, end: line });
    }
  });
  return ranges.sort((a, b) => a.start - b.start || b.end - a.end);
}

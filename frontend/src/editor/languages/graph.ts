/**
 * The S7-Graph text format (`.graph`) for the Monaco editor: a Monarch tokenizer, the language
 * configuration and the foldable regions. Until the graphical editor draws the chart, a Graph FB
 * is edited as this text; the compiler places its problems on its lines.
 *
 * The words are the terminals of `grammars/graph.lark` (a vitest test reads the grammar and fails
 * when they drift apart). Conditions, interlocks, supervisions and the permanent instructions are
 * LAD text, so their element names and operands are LAD's (`lad.ts`).
 *
 * Only types are imported from Monaco, so this module costs nothing in the app shell.
 */
import type { languages } from 'monaco-editor/editor/editor.api';
import { LAD_ELEMENTS, LAD_STRUCTURE_KEYWORDS, ladConfiguration, ladLanguage } from './lad';
import { PLC_TYPES, type LineRange } from './stl';

export const GRAPH_LANGUAGE_ID = 'graph';

/** The structure keywords of `grammars/graph.lark`: blocks, sequencers, steps, transitions. */
export const GRAPH_STRUCTURE_KEYWORDS: readonly string[] = [
  'FUNCTION_BLOCK', 'END_FUNCTION_BLOCK', 'TITLE', 'COMMENT', 'SETTINGS', 'END_SETTINGS',
  'PARAMETERS', 'BEGIN', 'PERMANENT_PRE', 'END_PERMANENT_PRE', 'PERMANENT_POST',
  'END_PERMANENT_POST', 'SEQUENCER', 'END_SEQUENCER', 'STEP', 'INITIAL_STEP', 'END_STEP',
  'INTERLOCK', 'END_INTERLOCK', 'SUPERVISION', 'END_SUPERVISION', 'ACTIONS', 'END_ACTIONS',
  'TRANSITION', 'END_TRANSITION', 'FROM', 'TO', 'JUMP', 'STOP', 'CONDITION', 'END_CONDITION',
];

/** The values of the block settings: the FB parameter sets, the flags and their Booleans. */
export const GRAPH_SETTINGS: readonly string[] = [
  'MINIMUM', 'STANDARD', 'MAXIMUM', 'USER_DEFINED', 'SKIP_STEPS', 'ACKNOWLEDGE',
  'INTERLOCK_BLOCKS', 'TRUE', 'FALSE',
];

/** The events of an action row. */
export const GRAPH_EVENTS: readonly string[] = ['S1', 'S0', 'V1', 'V0', 'L1', 'L0', 'A1', 'R1'];

/** The qualifiers of an action row; each also with the C suffix (`NC`, `SC` ...). */
export const GRAPH_QUALIFIERS: readonly string[] = [
  'CALL', 'OFF', 'ON', 'CS', 'CU', 'CD', 'CR', 'TL', 'TD', 'TR', 'N', 'S', 'R', 'D', 'L',
];

const QUALIFIER_WORDS = [...GRAPH_QUALIFIERS, ...GRAPH_QUALIFIERS.map((word) => `${word}C`)];
const ladTokenizer = ladLanguage.tokenizer;

export const graphLanguage: languages.IMonarchLanguage = {
  defaultToken: '',
  tokenPostfix: '.graph',
  ignoreCase: true,

  structure: [...GRAPH_STRUCTURE_KEYWORDS, ...LAD_STRUCTURE_KEYWORDS],
  settings: GRAPH_SETTINGS as string[],
  events: GRAPH_EVENTS as string[],
  qualifiers: QUALIFIER_WORDS,
  elements: LAD_ELEMENTS as string[],
  types: PLC_TYPES as string[],
  address: ladLanguage.address,
  typed: ladLanguage.typed,
  varSections: ladLanguage.varSections,

  brackets: [{ open: '(', close: ')', token: 'delimiter.parenthesis' }],

  tokenizer: {
    root: [
      [/[ \t\r\n]+/, ''],
      { include: '@comments' },
      [/(TITLE|COMMENT)([ \t]*)(=.*)/, ['keyword', '', 'comment.title']],
      // A step or transition: its name is a label, its number a number.
      [/((?:INITIAL_)?STEP|TRANSITION|SEQUENCER)([ \t]+)([A-Za-z_]\w*)/, ['keyword', '', 'label']],
      // S7-Graph's step and transition variables: Fill.T, S3.X, Trans2.TT.
      [/([A-Za-z_]\w*)(\.)(X|T|U|TT)(?!\w)/, ['identifier', 'delimiter', 'variable.step']],
      [/@[A-Za-z_]\w*/, 'tag'],
      [/@varSections/, 'keyword'],
      // An action table: its rows start with an event and a qualifier (N, S1 NC, D ...).
      [/ACTIONS(?!\w)/, { token: 'keyword', next: '@actions' }],
      { include: '@operand' },
      [
        /[A-Za-z_]\w*/,
        {
          cases: {
            '@structure': 'keyword',
            '@settings': 'keyword.setting',
            '@elements': 'keyword.instruction',
            '@types': 'type',
            '@default': 'identifier',
          },
        },
      ],
    ],
    actions: [
      [/[ \t\r\n]+/, ''],
      { include: '@comments' },
      [/END_ACTIONS(?!\w)/, { token: 'keyword', next: '@pop' }],
      [/([A-Za-z_]\w*)(\.)(X|T|U|TT)(?!\w)/, ['identifier', 'delimiter', 'variable.step']],
      [/@[A-Za-z_]\w*/, 'tag'],
      { include: '@operand' },
      [
        /[A-Za-z_]\w*/,
        {
          cases: {
            '@events': 'keyword.event',
            '@qualifiers': 'keyword.instruction',
            '@default': 'identifier',
          },
        },
      ],
    ],
    comments: ladTokenizer.comments!,
    blockComment: ladTokenizer.blockComment!,
    operand: ladTokenizer.operand!,
  },
};

/** Comments, brackets and words as in the LAD/FBD text, whose element syntax Graph conditions use. */
export const graphConfiguration: languages.LanguageConfiguration = ladConfiguration;

/** The keywords that open a foldable region of a Graph source, with the one that closes it. */
const GRAPH_OPENERS: Readonly<Record<string, string>> = {
  FUNCTION_BLOCK: 'END_FUNCTION_BLOCK',
  SETTINGS: 'END_SETTINGS',
  VAR: 'END_VAR',
  VAR_INPUT: 'END_VAR',
  VAR_OUTPUT: 'END_VAR',
  VAR_IN_OUT: 'END_VAR',
  VAR_TEMP: 'END_VAR',
  PERMANENT_PRE: 'END_PERMANENT_PRE',
  PERMANENT_POST: 'END_PERMANENT_POST',
  SEQUENCER: 'END_SEQUENCER',
  STEP: 'END_STEP',
  INITIAL_STEP: 'END_STEP',
  INTERLOCK: 'END_INTERLOCK',
  SUPERVISION: 'END_SUPERVISION',
  ACTIONS: 'END_ACTIONS',
  TRANSITION: 'END_TRANSITION',
  CONDITION: 'END_CONDITION',
  RUNG: 'END_RUNG',
  PARALLEL: 'END_PARALLEL',
  BRANCH: 'END_BRANCH',
  OUTPUTS: 'END_OUTPUTS',
};

/** Foldable regions: the block, its settings and declarations, each sequencer, step,
 * transition and their parts that span lines. */
export function graphFoldingRanges(text: string): LineRange[] {
  const ranges: LineRange[] = [];
  const open: Array<{ end: string; line: number }> = [];
  let comment = false;
  text.split(/\r?\n/).forEach((raw, index) => {
    const line = index + 1;
    let code = raw;
    if (comment) {
      const end = code.indexOf('*)');
      if (end < 0) return;
      code = code.slice(end + 2);
      comment = false;
    }
    code = code
      .replace(/\(\*.*?\*\)/g, ' ')
      .replace(/\/\/.*$/, '')
      .replace(/"[^"]*"|'[^']*'/g, ' ')
      .replace(/\b(TITLE|COMMENT)[ \t]*=.*$/i, '$1'); // a title's words are text
    const start = code.indexOf('(*');
    if (start >= 0) {
      code = code.slice(0, start);
      comment = true;
    }
    for (const match of code.matchAll(/[A-Za-z_]\w*/g)) {
      const word = match[0].toUpperCase();
      const closer = GRAPH_OPENERS[word];
      if (closer) {
        open.push({ end: closer, line });
        continue;
      }
      const at = open.map((item) => item.end).lastIndexOf(word);
      if (at < 0) continue;
      const [opened] = open.splice(at);
      if (opened && line > opened.line) ranges.push({ start: opened.line, end: line });
    }
  });
  return ranges.sort((a, b) => a.start - b.start || b.end - a.end);
}

/** A new Graph source: an FB with one sequencer, its initial step, a second step and the
 * transitions between them, which compiles (call it from OB 1 with an instance DB). */
export function newGraphText(number: number): string {
  return `FUNCTION_BLOCK FB ${number}
TITLE =
SETTINGS
  PARAMETERS := STANDARD;
END_SETTINGS
BEGIN
SEQUENCER Sequencer1
INITIAL_STEP Step1 (1)
COMMENT = the initial step: active after the first call
ACTIONS
  N M 0.0;
END_ACTIONS
END_STEP

TRANSITION Trans1 (1) FROM Step1 TO Step2
CONDITION Contact(I 0.0) END_CONDITION
END_TRANSITION

STEP Step2 (2)
ACTIONS
  N M 0.1;
END_ACTIONS
END_STEP

TRANSITION Trans2 (2) FROM Step2 JUMP Step1
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
`;
}

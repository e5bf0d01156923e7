/**
 * The STL and SCL languages of the editor: their word lists match what the compilers accept
 * (read from the backend's own files), and Monaco's real Monarch tokenizer, run here in jsdom,
 * gives instructions, addresses, constants and comments their own token types.
 */
import fs from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import {
  SCL_CONSTANTS,
  SCL_KEYWORDS,
  SCL_STANDARD_FUNCTIONS,
  SCL_WORD_OPERATORS,
  sclConfiguration,
  sclFoldingRanges,
  sclLanguage,
} from '../../frontend/src/editor/languages/scl';
import {
  GERMAN_MNEMONICS,
  GERMAN_TO_INTERNATIONAL,
  INTERNATIONAL_MNEMONICS,
  JUMP_MNEMONICS,
  PLC_TYPES,
  STL_BLOCK_KEYWORDS,
  stlConfiguration,
  stlFoldingRanges,
  stlLanguage,
} from '../../frontend/src/editor/languages/stl';
import { SCL_EXAMPLE, STL_EXAMPLE } from '../../frontend/src/editor/examples';
import {
  LAD_ELEMENTS,
  LAD_STRUCTURE_KEYWORDS,
  LAD_VIEWS,
  ladConfiguration,
  ladFoldingRanges,
  ladLanguage,
} from '../../frontend/src/editor/languages/lad';
import { newSourceText } from '../../frontend/src/projects/fileNames';

const root = path.resolve(__dirname, '../..');
const read = (file: string) => fs.readFileSync(path.join(root, file), 'utf8');
const sorted = (items: Iterable<string>) => [...new Set(items)].sort();

/** The quoted strings of `NAME = frozenset([...])` in a Python file. */
function pythonSet(source: string, name: string): string[] {
  const match = new RegExp(`^${name}\\s*=\\s*frozenset\\(\\s*\\[([\\s\\S]*?)\\]`, 'm').exec(source);
  if (!match) throw new Error(`${name} not found`);
  return [...match[1]!.matchAll(/"([^"]+)"/g)].map((m) => m[1]!);
}

/** The keys of `NAME = {...}` (or `NAME: type = {...}`) in a Python file, with their values. */
function pythonDict(source: string, name: string): Array<[string, string]> {
  const match =
    new RegExp(`^${name}(?::[^=]+)?\\s*=\\s*\\{(.*)\\}\\s*$`, 'm').exec(source) ??
    new RegExp(`^${name}(?::[^=]+)?\\s*=\\s*\\{([\\s\\S]*?)^\\}`, 'm').exec(source);
  if (!match) throw new Error(`${name} not found`);
  return [...match[1]!.matchAll(/"([^"]+)"\s*:\s*("([^"]*)"|[^,\n]*)/g)].map((m) => [m[1]!, m[3] ?? m[2]!]);
}

/** Keyword terminals of a Lark grammar: `IF: "IF"i`, and a keyword written as a regular expression
 * that starts with its own name (`END_REGION.4: /END_REGION(?![\w])...`, which takes a title). */
function larkKeywords(grammar: string): string[] {
  return [
    ...[...grammar.matchAll(/^([A-Z_]+):\s*"([A-Z_]+)"i\s*$/gm)].map((m) => m[2]!),
    ...[...grammar.matchAll(/^([A-Z_]+)(?:\.\d+)?:\s*\/\1\(\?!\[\\w\]\)/gm)].map((m) => m[1]!),
  ];
}

describe('the word lists are the compilers\' own', () => {
  const mnemonics = read('backend/nasaq/lang/stl/mnemonics.py');

  it('STL: both mnemonic sets of nasaq.lang.stl.mnemonics', () => {
    expect(sorted(INTERNATIONAL_MNEMONICS)).toEqual(sorted(pythonSet(mnemonics, 'INTERNATIONAL')));
    expect(Object.entries(GERMAN_TO_INTERNATIONAL).sort()).toEqual(pythonDict(mnemonics, 'GERMAN_TO_INTERNATIONAL').sort());
    expect(GERMAN_MNEMONICS).toContain('SE');
    expect(GERMAN_MNEMONICS).toContain('SPBN');
    expect(GERMAN_MNEMONICS).not.toContain('JU');
    expect(sorted(JUMP_MNEMONICS)).toEqual(
      sorted(['JU', 'JC', 'JCN', 'JCB', 'JNB', 'JBI', 'JNBI', 'JO', 'JOS', 'JZ', 'JN', 'JP', 'JM', 'JPZ', 'JMZ', 'JUO', 'JL', 'LOOP',
        'SPA', 'SPB', 'SPBN', 'SPBB', 'SPBNB', 'SPBI', 'SPBIN', 'SPO', 'SPS', 'SPZ', 'SPN', 'SPP', 'SPM', 'SPPZ', 'SPMZ', 'SPU', 'SPL']),
    );
  });

  it('STL: the keywords of grammars/stl.lark', () => {
    expect(sorted([...STL_BLOCK_KEYWORDS])).toEqual(sorted(larkKeywords(read('grammars/stl.lark'))));
  });

  it('SCL: the keywords, word operators and literals of grammars/scl.lark', () => {
    const fromGrammar = larkKeywords(read('grammars/scl.lark'));
    expect(sorted([...SCL_KEYWORDS, ...SCL_WORD_OPERATORS, ...SCL_CONSTANTS])).toEqual(sorted(fromGrammar));
  });

  it('SCL: the standard functions the type checker knows', () => {
    const calls = read('backend/nasaq/lang/scl/typecheck/rules/calls.py');
    const s5 = read('backend/nasaq/lang/scl/typecheck/signatures.py');
    const conversions = read('backend/nasaq/lang/scl/typecheck/types.py');
    const library = read('backend/nasaq/lang/iec_library.py');
    const texts = read('backend/nasaq/lang/text_instructions.py');
    const numberText = read('backend/nasaq/lang/number_text.py');
    const instructions = read('backend/nasaq/lang/scl/typecheck/instructions.py');
    const variant = read('backend/nasaq/lang/scl/typecheck/variant.py');
    const standard = [
      ...pythonSet(variant, 'NAMES'),
      ...pythonSet(calls, 'REAL_FUNCTIONS'),
      ...pythonDict(texts, 'OVERLOADS').map(([key]) => key), // VAL_STRG, STRG_VAL
      ...pythonDict(numberText, 'CHARACTER_CONVERSIONS').map(([key]) => key),
      ...pythonDict(instructions, 'DTL_CONVERSIONS').map(([key]) => key),
      ...pythonDict(calls, 'FIXED_RESULTS').map(([key]) => key),
      ...pythonSet(calls, 'STRING_RESULTS'),
      ...pythonSet(calls, 'SAME_AS_INPUT'),
      ...pythonSet(calls, 'UNTYPED'),
      ...pythonDict(s5, 'S5_FUNCTIONS').map(([key]) => key),
      ...pythonSet(conversions, 'CONVERSIONS'),
      // _fc(1, "AD_DT_TM", ...) and the comparison tables' (10, "EQ_STRNG", ...)
      ...[...library.matchAll(/\(\s*\d+,\s*"([A-Z_]+)"/g)].map((m) => m[1]!),
    ];
    expect(standard.length).toBeGreaterThan(100);
    expect(sorted(SCL_STANDARD_FUNCTIONS)).toEqual(sorted(standard));
  });

  it('LAD/FBD: the keywords and element names of grammars/lad.lark', () => {
    // KEYWORD.5: /WORD(?!\w)/i and /(?:ONE|TWO)(?!\w)/i
    const terminals = [...read('grammars/lad.lark').matchAll(/^[A-Z_]+\.5:\s*\/(?:\(\?:)?([A-Z_|]+)\)?\(\?!\\w\)\/i\s*$/gm)];
    const words = terminals.flatMap((m) => m[1]!.split('|'));
    expect(words.length).toBeGreaterThan(40);
    expect(sorted([...LAD_STRUCTURE_KEYWORDS, ...LAD_ELEMENTS, ...LAD_VIEWS])).toEqual(sorted(words));
  });

  it('the data types of nasaq.ir.types, with STRING and VOID', () => {
    const types = read('backend/nasaq/ir/types.py');
    const elementary = pythonDict(types, 'ELEMENTARY_BITS').map(([key]) => key);
    const aliases = pythonDict(types, 'TYPE_ALIASES').map(([key]) => key);
    expect(elementary.length).toBeGreaterThan(15);
    expect(sorted(PLC_TYPES)).toEqual(sorted([...elementary, ...aliases, 'STRING', 'VOID']));
  });
});

type Monaco = typeof import('monaco-editor/editor/editor.api');
let monaco: Monaco;

beforeAll(async () => {
  // jsdom lacks two browser functions Monaco's services call while starting.
  globalThis.CSS ??= { escape: (text: string) => text.replace(/[^\w-]/g, (c) => `\\${c}`) } as typeof CSS;
  window.matchMedia ??= ((query: string) => ({
    matches: false,
    media: query,
    onchange: null,
    addListener: () => undefined,
    removeListener: () => undefined,
    addEventListener: () => undefined,
    removeEventListener: () => undefined,
    dispatchEvent: () => false,
  })) as typeof window.matchMedia;
  monaco = await import('monaco-editor/editor/editor.api');
  for (const [id, language, configuration] of [
    ['stl', stlLanguage, stlConfiguration],
    ['scl', sclLanguage, sclConfiguration],
    ['lad', ladLanguage, ladConfiguration],
  ] as const) {
    monaco.languages.register({ id });
    monaco.languages.setMonarchTokensProvider(id, language);
    monaco.languages.setLanguageConfiguration(id, configuration);
  }
}, 120_000);

/** [text, token type] of every token that is not blank, line after line. */
function tokens(text: string, language: 'stl' | 'scl' | 'lad'): Array<[string, string]> {
  const lines = text.split('\n');
  return monaco.editor.tokenize(text, language).flatMap((lineTokens, index) => {
    const line = lines[index] ?? '';
    return lineTokens
      .map((token, i): [string, string] => [
        line.slice(token.offset, lineTokens[i + 1]?.offset ?? line.length),
        token.type.replace(new RegExp(`\\.${language}$`), ''),
      ])
      .filter(([part]) => part.trim() !== '');
  });
}

const stl = (text: string) => tokens(text, 'stl');
const scl = (text: string) => tokens(text, 'scl');
const lad = (text: string) => tokens(text, 'lad');

describe('STL tokenizer', () => {
  it('reads a statement as instruction, operand and comment', () => {
    expect(stl('      A     I      0.0;   // start button')).toEqual([
      ['A', 'keyword.instruction'],
      ['I      0.0', 'address'],
      [';', 'delimiter'],
      ['// start button', 'comment'],
    ]);
  });

  it('knows the German set: A is an instruction first and an output afterwards', () => {
    expect(stl('U E 1.0\nUN A 4.0\n= A 4.1\nSPBN M001\nM001: SE T 1')).toEqual([
      ['U', 'keyword.instruction'],
      ['E 1.0', 'address'],
      ['UN', 'keyword.instruction'],
      ['A 4.0', 'address'],
      ['=', 'keyword.instruction'],
      ['A 4.1', 'address'],
      ['SPBN', 'keyword.instruction'],
      ['M001', 'label'],
      ['M001', 'label'],
      [':', 'delimiter'],
      ['SE', 'keyword.instruction'],
      ['T 1', 'address'],
    ]);
  });

  it('knows the international set, in any letter case', () => {
    expect(stl('an q 4.0\nJCN end1\nloop next\nT MW 10\nL DB1.DBW 2\nOPN DI 5\nCALL FC 10')).toEqual([
      ['an', 'keyword.instruction'],
      ['q 4.0', 'address'],
      ['JCN', 'keyword.instruction'],
      ['end1', 'label'],
      ['loop', 'keyword.instruction'],
      ['next', 'label'],
      ['T', 'keyword.instruction'],
      ['MW 10', 'address'],
      ['L', 'keyword.instruction'],
      ['DB1.DBW 2', 'address'],
      ['OPN', 'keyword.instruction'],
      ['DI 5', 'address'],
      ['CALL', 'keyword.instruction'],
      ['FC 10', 'address'],
    ]);
  });

  it('reads symbolic instructions and nesting', () => {
    const found = stl('A(\nO I 0.0\n)\n==I\n+I\n>=R\n+AR1 P#2.0\nRND+\nMCR(\n)MCR');
    expect(found.filter(([, type]) => type === 'keyword.instruction').map(([text]) => text)).toEqual([
      'A(', 'O', ')', '==I', '+I', '>=R', '+AR1', 'RND+', 'MCR(', ')MCR',
    ]);
  });

  it('reads every kind of constant', () => {
    const constants = [
      '16#FF', '2#1010', 'B#16#1F', 'W#16#FFFF', 'DW#16#FFFF_FFFF', 'L#100000', 'T#1s', 'S5T#2S', 'C#25',
      'D#2024-01-31', 'TOD#12:30:00', 'B#(1, 2)',
    ];
    for (const constant of constants) expect(stl(`L ${constant}`), constant).toEqual([['L', 'keyword.instruction'], [constant, 'number']]);
    expect(stl('L 1.5e3')).toEqual([['L', 'keyword.instruction'], ['1.5e3', 'number.float']]);
    expect(stl('L -12')).toEqual([['L', 'keyword.instruction'], ['-12', 'number']]);
    expect(stl('L P#M 1.0')).toEqual([['L', 'keyword.instruction'], ['P#M 1.0', 'number.pointer']]);
    expect(stl("L 'AB'")).toEqual([['L', 'keyword.instruction'], ["'AB'", 'string']]);
  });

  it('reads symbols, locals and indirect addresses', () => {
    expect(stl('A "Start button"\nT #count\nL MW [#ptr]')).toEqual([
      ['A', 'keyword.instruction'],
      ['"Start button"', 'variable.symbol'],
      ['T', 'keyword.instruction'],
      ['#count', 'variable.local'],
      ['L', 'keyword.instruction'],
      ['MW', 'address'],
      ['[', 'delimiter.square'],
      ['#ptr', 'variable.local'],
      [']', 'delimiter.square'],
    ]);
  });

  it('reads block headers, properties, declarations and networks', () => {
    const source = [
      'FUNCTION FC 10 : VOID',
      'TITLE = Motor control',
      'VERSION : 0.1',
      'VAR_INPUT',
      '  start : BOOL := FALSE;   // the start button',
      '  values : ARRAY [1 .. 4] OF INT;',
      'END_VAR',
      'BEGIN',
      'NETWORK',
      'CALL "Drive" (',
      '     run := #start,',
      '     speed := MW 10);',
      'END_FUNCTION',
    ].join('\n');
    expect(stl(source)).toEqual([
      ['FUNCTION', 'keyword'], ['FC 10', 'address'], [':', 'delimiter'], ['VOID', 'type'],
      ['TITLE', 'keyword'], ['= Motor control', 'comment.title'],
      ['VERSION', 'keyword'], [':', 'delimiter'], [' 0.1', 'string.header'],
      ['VAR_INPUT', 'keyword'],
      ['start', 'identifier'], [':', 'delimiter'], ['BOOL', 'type'], [':=', 'operator'], ['FALSE', 'identifier'],
      [';', 'delimiter'], ['// the start button', 'comment'],
      ['values', 'identifier'], [':', 'delimiter'], ['ARRAY', 'keyword'], ['[', 'delimiter.square'], ['1', 'number'],
      ['..', 'delimiter'], ['4', 'number'], [']', 'delimiter.square'], ['OF', 'keyword'], ['INT', 'type'],
      [';', 'delimiter'],
      ['END_VAR', 'keyword'],
      ['BEGIN', 'keyword'],
      ['NETWORK', 'keyword'],
      ['CALL', 'keyword.instruction'], ['"Drive"', 'variable.symbol'], ['(', 'delimiter.parenthesis'],
      ['run', 'identifier'], [':=', 'operator'], ['#start', 'variable.local'], [',', 'delimiter'],
      ['speed', 'identifier'], [':=', 'operator'], ['MW 10', 'address'], [')', 'delimiter.parenthesis'], [';', 'delimiter'],
      ['END_FUNCTION', 'keyword'],
    ]);
  });

  it('tokenizes the example a new source opens with, without unknown text', () => {
    const found = stl(STL_EXAMPLE);
    expect(found.filter(([, type]) => type === '')).toEqual([]);
    expect(found).toContainEqual(['JCN', 'keyword.instruction']);
    expect(found).toContainEqual(['M001', 'label']);
  });

  it('folds blocks, declaration sections and networks', () => {
    expect(stlFoldingRanges(STL_EXAMPLE)).toEqual([
      { start: 1, end: 28 },
      { start: 5, end: 7 },
      { start: 10, end: 18 },
      { start: 19, end: 27 },
    ]);
  });
});

describe('SCL tokenizer', () => {
  it('reads keywords, word operators, locals, symbols and numbers', () => {
    expect(scl('IF #level > 5 AND NOT "Stop" THEN')).toEqual([
      ['IF', 'keyword'],
      ['#level', 'variable.local'],
      ['>', 'operator'],
      ['5', 'number'],
      ['AND', 'keyword.operator'],
      ['NOT', 'keyword.operator'],
      ['"Stop"', 'variable.symbol'],
      ['THEN', 'keyword'],
    ]);
  });

  it('reads the statements and operators of S7-SCL', () => {
    const source = [
      'CASE mode OF 1: x := x MOD 2; ELSE: EXIT; END_CASE;',
      'FOR i := 1 TO 10 BY 2 DO CONTINUE; END_FOR;',
      'WHILE run XOR stop DO RETURN; END_WHILE;',
      'REPEAT n := n DIV 2; UNTIL n = 0 END_REPEAT;',
      'ok := a OR b;',
    ].join('\n');
    const kinds = new Map(scl(source));
    for (const word of ['CASE', 'OF', 'ELSE', 'EXIT', 'END_CASE', 'FOR', 'TO', 'BY', 'DO', 'CONTINUE', 'END_FOR', 'WHILE',
      'RETURN', 'END_WHILE', 'REPEAT', 'UNTIL', 'END_REPEAT']) {
      expect(kinds.get(word), word).toBe('keyword');
    }
    for (const word of ['MOD', 'XOR', 'DIV', 'OR']) expect(kinds.get(word), word).toBe('keyword.operator');
    expect(kinds.get(':=')).toBe('operator');
    expect(kinds.get('ok')).toBe('variable.predefined');
  });

  it('reads addresses, DB members and constants', () => {
    expect(scl('MW20 := INT_TO_WORD(DB10.DW2) OR %IW4;')).toEqual([
      ['MW20', 'address'], [':=', 'operator'], ['INT_TO_WORD', 'predefined'], ['(', 'delimiter.parenthesis'],
      ['DB10', 'address'], ['.', 'delimiter'], ['DW2', 'address'], [')', 'delimiter.parenthesis'],
      ['OR', 'keyword.operator'], ['%IW4', 'address'], [';', 'delimiter'],
    ]);
    expect(scl('"Data".DX1.1 := TRUE;')).toEqual([
      ['"Data"', 'variable.symbol'], ['.', 'delimiter'], ['DX1.1', 'address'], [':=', 'operator'],
      ['TRUE', 'constant'], [';', 'delimiter'],
    ]);
    for (const constant of ['16#FF', 'W#16#FFFF', 'DW#16#FF_FF', '2#1010', '8#17']) {
      expect(scl(`x := ${constant};`)[2], constant).toEqual([constant, 'number.hex']);
    }
    for (const constant of ['INT#-5', 'T#2s', 'S5T#1H_2M', 'TIME#-1d2h', 'D#1990-01-01', 'TOD#23:59:59.999', 'DT#95-01-01-12:12:12.2', "CHAR#'a'"]) {
      expect(scl(`x := ${constant};`)[2], constant).toEqual([constant, 'number']);
    }
    expect(scl("s := 'it''s $R$L';")[2]).toEqual(["'it''s $R$L'", 'string']);
    expect(scl('r := 1.5E-3;')[2]).toEqual(['1.5E-3', 'number.float']);
  });

  it('reads the three comment forms, over several lines, and attributes', () => {
    // (Monaco joins neighbouring tokens of one type.)
    expect(scl("a := 1; // line\n(* block\n still *) b := 2;\n/* c\n */\n{ S7_Optimized_Access := 'FALSE' }")).toEqual([
      ['a', 'identifier'], [':=', 'operator'], ['1', 'number'], [';', 'delimiter'], ['// line', 'comment'],
      ['(* block', 'comment'], [' still *)', 'comment'],
      ['b', 'identifier'], [':=', 'operator'], ['2', 'number'], [';', 'delimiter'],
      ['/* c', 'comment'], [' */', 'comment'],
      ['{ S7_Optimized_Access := ', 'annotation'], ["'FALSE'", 'string'], [' }', 'annotation'],
    ]);
  });

  it('reads declarations, types, regions and titles', () => {
    const found = scl("FUNCTION_BLOCK FB 10\nTITLE = 'Tank'\nVAR_INPUT\n  v : ARRAY[1..8] OF REAL;\nEND_VAR\nREGION Pump control\nEND_REGION");
    expect(found).toEqual([
      ['FUNCTION_BLOCK', 'keyword'], ['FB 10', 'address'],
      ['TITLE', 'keyword'], ["= 'Tank'", 'comment.title'],
      ['VAR_INPUT', 'keyword'],
      ['v', 'identifier'], [':', 'delimiter'], ['ARRAY', 'keyword'], ['[', 'delimiter.square'], ['1', 'number'],
      ['..', 'delimiter'], ['8', 'number'], [']', 'delimiter.square'], ['OF', 'keyword'], ['REAL', 'type'], [';', 'delimiter'],
      ['END_VAR', 'keyword'],
      ['REGION', 'keyword'], [' Pump control', 'comment.title'],
      ['END_REGION', 'keyword'],
    ]);
  });

  it('reads TIA Portal exports: END_REGION with its title, nested block comments', () => {
    expect(scl('END_REGION Pump control // done\n(* a (* b *) still *) x')).toEqual([
      ['END_REGION', 'keyword'], [' Pump control ', 'comment.title'], ['// done', 'comment'],
      ['(* a (* b *) still *)', 'comment'],
      ['x', 'identifier'],
    ]);
  });

  it('tokenizes the example a new source opens with, without unknown text', () => {
    expect(scl(SCL_EXAMPLE).filter(([, type]) => type === '')).toEqual([]);
  });

  it('folds blocks, sections and statements, skipping comments and strings', () => {
    const source = [
      'FUNCTION FC 1 : VOID', // 1
      'VAR_TEMP', // 2
      '  i : INT;', // 3
      'END_VAR', // 4
      'BEGIN', // 5
      "  IF a THEN // END_IF in a comment", // 6
      "    s := 'END_IF';", // 7
      '    (* FOR', // 8
      '    *)', // 9
      '    FOR i := 1 TO 3 DO', // 10
      '      x := i;', // 11
      '    END_FOR;', // 12
      '  END_IF;', // 13
      'END_FUNCTION', // 14
    ].join('\n');
    expect(sclFoldingRanges(source)).toEqual([
      { start: 1, end: 14 },
      { start: 2, end: 4 },
      { start: 6, end: 13 },
      { start: 10, end: 12 },
    ]);
  });
});

describe('LAD/FBD text tokenizer', () => {
  it('reads structure keywords, elements, operands, pins and element ids', () => {
    expect(lad('RUNG Contact(I 0.0) ContactNC("Stop") Coil(#out) @q END_RUNG')).toEqual([
      ['RUNG', 'keyword'],
      ['Contact', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['I 0.0', 'address'],
      [')', 'delimiter.parenthesis'],
      ['ContactNC', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['"Stop"', 'variable.symbol'],
      [')', 'delimiter.parenthesis'],
      ['Coil', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['#out', 'variable.local'],
      [')', 'delimiter.parenthesis'],
      ['@q', 'tag'],
      ['END_RUNG', 'keyword'],
    ]);
    expect(lad('Box(ADD_I, IN1 := MW 10, OUT => MW 12) SD(T 1, S5T#5S) JumpN(M001)')).toEqual([
      ['Box', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['ADD_I', 'identifier'],
      [',', 'delimiter'],
      ['IN1', 'identifier'],
      [':=', 'operator'],
      ['MW 10', 'address'],
      [',', 'delimiter'],
      ['OUT', 'identifier'],
      ['=>', 'operator'],
      ['MW 12', 'address'],
      [')', 'delimiter.parenthesis'],
      ['SD', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['T 1', 'address'],
      [',', 'delimiter'],
      ['S5T#5S', 'number'],
      [')', 'delimiter.parenthesis'],
      ['JumpN', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['M001', 'label'],
      [')', 'delimiter.parenthesis'],
    ]);
  });

  it('reads headers, titles, labels and both comment forms', () => {
    const text = 'FUNCTION FC 10 : VOID\nLANGUAGE FBD\nTITLE = Gates (* old *)\nNETWORK\nLABEL M001 // jump here';
    expect(lad(text)).toEqual([
      ['FUNCTION', 'keyword'],
      ['FC 10', 'address'],
      [':', 'delimiter'],
      ['VOID', 'type'],
      ['LANGUAGE', 'keyword'],
      ['FBD', 'keyword'],
      ['TITLE', 'keyword'],
      ['= Gates (* old *)', 'comment.title'],
      ['NETWORK', 'keyword'],
      ['LABEL', 'keyword'],
      ['M001', 'label'],
      ['// jump here', 'comment'],
    ]);
    expect(lad('(* a\nblock comment *) BEGIN')).toEqual([
      ['(* a', 'comment'],
      ['block comment *)', 'comment'],
      ['BEGIN', 'keyword'],
    ]);
  });

  it('reads a network kept as STL with the STL tokenizer, up to END_STL', () => {
    const text = 'STL REASON LAD306\n      A     I 0.0;\n      =     Q 4.0;\nEND_STL\nNETWORK';
    expect(lad(text)).toEqual([
      ['STL', 'keyword'],
      ['REASON', 'keyword'],
      ['LAD306', 'string.reason'],
      ['A', 'keyword.instruction.stl'],
      ['I 0.0', 'address.stl'],
      [';', 'delimiter.stl'],
      ['=', 'keyword.instruction.stl'],
      ['Q 4.0', 'address.stl'],
      [';', 'delimiter.stl'],
      ['END_STL', 'keyword'],
      ['NETWORK', 'keyword'],
    ]);
  });

  it('tokenizes every example LAD/FBD file and the new-source text without unknown text', () => {
    const folder = path.join(root, 'examples/lad');
    const files = fs.readdirSync(folder).filter((name) => /\.(?:lad|fbd)$/.test(name));
    expect(files.length).toBeGreaterThan(20);
    for (const text of [...files.map((name) => read(`examples/lad/${name}`)), newSourceText('lad', []), newSourceText('fbd', [])]) {
      const unknown = lad(text).filter(([, type]) => type === '');
      expect(unknown).toEqual([]);
    }
  });

  it('folds blocks, networks, rungs, parallels, branches and STL networks', () => {
    const text = [
      'ORGANIZATION_BLOCK OB 1', // 1
      'TITLE = an STL title, not an STL network', // 2
      'BEGIN', // 3
      'NETWORK', // 4
      'RUNG', // 5
      '  PARALLEL', // 6
      '    BRANCH Contact(I 0.0) END_BRANCH', // 7
      '    BRANCH', // 8
      '      Contact(Q 4.0)', // 9
      '    END_BRANCH', // 10
      '  END_PARALLEL', // 11
      '  Coil(Q 4.0)', // 12
      'END_RUNG', // 13
      'NETWORK', // 14
      'STL REASON LAD306', // 15
      '      A     I 0.1;  // RUNG in a comment', // 16
      '      =     Q 4.1;', // 17
      'END_STL', // 18
      'END_ORGANIZATION_BLOCK', // 19
    ].join('\n');
    expect(ladFoldingRanges(text)).toEqual([
      { start: 1, end: 19 },
      { start: 4, end: 13 },
      { start: 5, end: 13 },
      { start: 6, end: 11 },
      { start: 8, end: 10 },
      { start: 14, end: 18 },
      { start: 15, end: 18 },
    ]);
  });
});

/**
 * The S7-Graph text language of the editor: its words are the terminals of grammars/graph.lark,
 * Monaco's real Monarch tokenizer (run here in jsdom) reads every Graph scenario source without
 * unknown text, a `.graph` file opens in it, and a new Graph source is an FB that does not
 * clash with the project's blocks.
 */
import fs from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import {
  GRAPH_EVENTS,
  GRAPH_QUALIFIERS,
  GRAPH_SETTINGS,
  GRAPH_STRUCTURE_KEYWORDS,
  graphConfiguration,
  graphFoldingRanges,
  graphLanguage,
} from '../../frontend/src/editor/languages/graph';
import { languageOfFile } from '../../frontend/src/editor/fileLanguage';
import { newSourceText } from '../../frontend/src/projects/fileNames';
import type { TreeBlock } from '../../frontend/src/api/types';

const root = path.resolve(__dirname, '../..');
const read = (file: string) => fs.readFileSync(path.join(root, file), 'utf8');
const sorted = (items: Iterable<string>) => [...new Set(items)].sort();

/** The words of the grammar's keyword terminals: `STEP.5: /STEP(?!\w)/i`, alternatives too. */
function terminal(grammar: string, name: string): string[] {
  const match = new RegExp(`^${name}\\.\\d+:\\s*/(?:\\(\\?:)?([A-Z0-9_|]+)\\)?(C\\?)?\\(\\?!\\\\w\\)/i\\s*$`, 'm').exec(grammar);
  if (!match) throw new Error(`${name} not found`);
  return match[1]!.split('|');
}

describe('the words of the Graph language', () => {
  const grammar = read('grammars/graph.lark');

  it('are the keyword terminals of grammars/graph.lark', () => {
    const single = [...grammar.matchAll(/^([A-Z_]+)\.5:\s*\/([A-Z_]+)\(\?!\\w\)\/i\s*$/gm)].map((m) => m[2]!);
    expect(single.length).toBeGreaterThan(25);
    expect(sorted(GRAPH_STRUCTURE_KEYWORDS)).toEqual(sorted(single));
    expect(sorted(GRAPH_EVENTS)).toEqual(sorted(terminal(grammar, 'EVENT')));
    expect(sorted(GRAPH_QUALIFIERS)).toEqual(sorted(terminal(grammar, 'QUALIFIER')));
    const settings = ['PARAMETER_SET', 'FLAG_SETTING', 'BOOLEAN'].flatMap((name) => terminal(grammar, name));
    expect(sorted(GRAPH_SETTINGS)).toEqual(sorted(settings));
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
  monaco.languages.register({ id: 'graph' });
  monaco.languages.setMonarchTokensProvider('graph', graphLanguage);
  monaco.languages.setLanguageConfiguration('graph', graphConfiguration);
}, 120_000);

/** [text, token type] of every token that is not blank, line after line. */
function graph(text: string): Array<[string, string]> {
  const lines = text.split('\n');
  return monaco.editor.tokenize(text, 'graph').flatMap((lineTokens, index) => {
    const line = lines[index] ?? '';
    return lineTokens
      .map((token, i): [string, string] => [
        line.slice(token.offset, lineTokens[i + 1]?.offset ?? line.length),
        token.type.replace(/\.graph$/, ''),
      ])
      .filter(([part]) => part.trim() !== '');
  });
}

describe('Graph tokenizer', () => {
  it('gives steps, events, qualifiers, addresses, times and comments their types', () => {
    expect(graph('INITIAL_STEP Fill (2)')).toEqual([
      ['INITIAL_STEP', 'keyword'],
      ['Fill', 'label'],
      ['(', 'delimiter.parenthesis'],
      ['2', 'number'],
      [')', 'delimiter.parenthesis'],
    ]);
    expect(graph('ACTIONS\n  S1 NC Q 0.0, T#5S;  // the row\'s comment\nEND_ACTIONS N')).toEqual([
      ['ACTIONS', 'keyword'],
      ['S1', 'keyword.event'],
      ['NC', 'keyword.instruction'],
      ['Q 0.0', 'address'],
      [',', 'delimiter'],
      ['T#5S', 'number'],
      [';', 'delimiter'],
      ["// the row's comment", 'comment'],
      ['END_ACTIONS', 'keyword'],
      ['N', 'identifier'], // a qualifier only in an action table
    ]);
    expect(graph('CONDITION Box(CMP>D, IN1 := Fill.T, IN2 := T#10S) END_CONDITION')).toEqual([
      ['CONDITION', 'keyword'],
      ['Box', 'keyword.instruction'],
      ['(', 'delimiter.parenthesis'],
      ['CMP', 'identifier'],
      ['>', 'operator'],
      ['D', 'identifier'],
      [',', 'delimiter'],
      ['IN1', 'identifier'],
      [':=', 'operator'],
      ['Fill', 'identifier'],
      ['.', 'delimiter'],
      ['T', 'variable.step'],
      [',', 'delimiter'],
      ['IN2', 'identifier'],
      [':=', 'operator'],
      ['T#10S', 'number'],
      [')', 'delimiter.parenthesis'],
      ['END_CONDITION', 'keyword'],
    ]);
    expect(graph('TRANSITION Go (1) FROM (A, B) JUMP Idle (* a\nblock comment *) STOP')).toContainEqual(['STOP', 'keyword']);
    expect(graph('PARAMETERS := USER_DEFINED; SKIP_STEPS := TRUE;').map(([, type]) => type)).toEqual([
      'keyword',
      'operator',
      'keyword.setting',
      'delimiter',
      'keyword.setting',
      'operator',
      'keyword.setting',
      'delimiter',
    ]);
  });

  it('reads every Graph scenario source and the new-source text without unknown text', () => {
    const folder = path.join(root, 'tests/scenarios/graph');
    const files = fs.readdirSync(folder).filter((name) => name.endsWith('.graph'));
    expect(files.length).toBeGreaterThan(10);
    for (const text of [...files.map((name) => read(`tests/scenarios/graph/${name}`)), newSourceText('graph', [])]) {
      const unknown = graph(text).filter(([, type]) => type === '');
      expect(unknown).toEqual([]);
    }
  });

  it('folds the block, sequencers, steps, transitions and their parts', () => {
    const text = [
      'FUNCTION_BLOCK FB 1', // 1
      'TITLE = a STEP in a title', // 2
      'BEGIN', // 3
      'SEQUENCER S', // 4
      'INITIAL_STEP A (1)', // 5
      'ACTIONS', // 6
      '  N Q 4.0; // END_STEP in a comment', // 7
      'END_ACTIONS', // 8
      'END_STEP', // 9
      'TRANSITION T1 (1) FROM A JUMP A', // 10
      'CONDITION', // 11
      '  Contact(I 0.0) (* END_CONDITION', // 12
      '  not yet *) Contact(I 0.1)', // 13
      'END_CONDITION', // 14
      'END_TRANSITION', // 15
      'END_SEQUENCER', // 16
      'END_FUNCTION_BLOCK', // 17
    ].join('\n');
    expect(graphFoldingRanges(text)).toEqual([
      { start: 1, end: 17 },
      { start: 4, end: 16 },
      { start: 5, end: 9 },
      { start: 6, end: 8 },
      { start: 10, end: 15 },
      { start: 11, end: 14 },
    ]);
  });
});

describe('Graph files in the IDE', () => {
  it('open as Graph sources', () => {
    expect(languageOfFile('Conveyor.graph')).toBe('graph');
    expect(languageOfFile('CONVEYOR.GRAPH')).toBe('graph');
  });

  it('start as an FB with the first free FB number, an initial step and transitions', () => {
    const fb = (number: number): TreeBlock => ({ kind: 'FB', number, name: '', title: '', language: 'stl', file: 'a.awl', line: 1, instance_of: null });
    const text = newSourceText('graph', [fb(1), fb(2), { ...fb(3), kind: 'FC' }]);
    expect(text.split('\n')[0]).toBe('FUNCTION_BLOCK FB 3');
    expect(text).toMatch(/^INITIAL_STEP Step1 \(1\)$/m);
    expect(text).toMatch(/^TRANSITION Trans1 \(1\) FROM Step1 TO Step2$/m);
  });
});

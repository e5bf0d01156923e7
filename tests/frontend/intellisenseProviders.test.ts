/**
 * Completion and hover for STL and SCL: what is offered and explained at a place of the text,
 * from a project outline like the tank example's, and the Monaco providers that serve it (with
 * the fake Monaco).
 */
import { describe, expect, it } from 'vitest';
import type { OutlineMember, ProjectOutline } from '../../frontend/src/api/outline';
import { complete, type CompletionRequest } from '../../frontend/src/editor/intellisense/completion';
import { hoverAt, type HoverRequest } from '../../frontend/src/editor/intellisense/hover';
import { detectMnemonicSet } from '../../frontend/src/editor/intellisense/mnemonicSet';
import { bindModel, sourceOf } from '../../frontend/src/editor/intellisense/modelRegistry';
import { createOutlineStore } from '../../frontend/src/editor/intellisense/outlineStore';
import { markdownOf, registerIntellisense } from '../../frontend/src/editor/intellisense/register';
import { createProjectContentsStore } from '../../frontend/src/projects/projectContents';
import { FakeModel, fake, loadMonaco } from './fakeMonaco';

function member(path: string, type: string, section: OutlineMember['section'], comment = '', line: number | null = null): OutlineMember {
  const parts = path.split('.');
  return {
    path,
    name: parts.at(-1)!,
    type,
    section,
    depth: parts.length - 1,
    offset: null,
    initial: null,
    actual: null,
    comment,
    elementary: type !== 'STRUCT',
    file: null,
    line,
  };
}

export const OUTLINE: ProjectOutline = {
  symbols: [
    { name: 'Auto', address: 'I 0.0', type: 'BOOL', comment: 'selector switch', file: 'symbols.sdf', line: 1 },
    { name: 'High level alarm', address: 'Q 4.1', type: 'BOOL', comment: 'alarm horn', file: 'symbols.sdf', line: 4 },
    { name: 'TankSettings', address: 'DB 1', type: 'DB 1', comment: 'limits', file: 'symbols.sdf', line: 7 },
    { name: 'LevelControl', address: 'FB 10', type: 'FB 10', comment: 'controller', file: 'symbols.sdf', line: 8 },
  ],
  blocks: [
    { kind: 'OB', number: 1, name: 'Main', language: 'stl', file: 'OB1.awl', line: 1, return_type: null, instance_of: null, members: [member('Cycle', 'INT', 'TEMP', 'scan counter', 4)] },
    {
      kind: 'FB',
      number: 10,
      name: 'LevelControl',
      language: 'scl',
      file: 'LevelControl.scl',
      line: 1,
      return_type: null,
      instance_of: null,
      members: [
        member('Level', 'REAL', 'IN', 'measured level, %', 3),
        member('Pump', 'BOOL', 'OUT', 'run the pump', 6),
        member('State', 'STRUCT', 'STAT', '', 9),
        member('State.Filling', 'BOOL', 'STAT', 'filling', 10),
        member('Timer1', 'TON', 'STAT'),
        member('Sub', '"Valve"', 'STAT', 'a multi-instance'),
      ],
    },
    { kind: 'FB', number: 20, name: 'Valve', language: 'scl', file: 'Valve.scl', line: 1, return_type: null, instance_of: null, members: [member('Open', 'BOOL', 'IN'), member('Scratch', 'INT', 'TEMP')] },
    { kind: 'FC', number: 10, name: 'Scale', language: 'scl', file: 'Scale.scl', line: 1, return_type: 'REAL', instance_of: null, members: [member('Raw', 'INT', 'IN')] },
    {
      kind: 'DB',
      number: 1,
      name: 'TankSettings',
      language: 'stl',
      file: 'TankSettings.awl',
      line: 1,
      return_type: null,
      instance_of: null,
      members: [member('LowLevel', 'REAL', 'DATA', 'the pump starts below this'), member('HighLevel', 'REAL', 'DATA')],
    },
    { kind: 'DB', number: 10, name: 'LevelData', language: 'stl', file: 'LevelData.awl', line: 1, return_type: null, instance_of: 'FB 10', members: [member('Level', 'REAL', 'IN'), member('Pump', 'BOOL', 'OUT')] },
  ],
};

const SCL = `FUNCTION_BLOCK "LevelControl"
VAR_INPUT
  Level : REAL;
END_VAR
BEGIN
  Pump := Level > 5.0;
  x := LIMIT(MN := 0, IN := Level, MX := 100);

END_FUNCTION_BLOCK
`;

const STL = `ORGANIZATION_BLOCK "Main"
TITLE = main
BEGIN
NETWORK
      A     I 0.0;
      =     Q 4.0;
      L     "TankSettings".LowLevel;

END_ORGANIZATION_BLOCK
`;

function sclAt(line: number, column: number, text = SCL): CompletionRequest {
  return { text, line, column, language: 'scl', outline: OUTLINE, file: 'LevelControl.scl', uiLanguage: 'en' };
}

function stlAt(line: number, column: number, text = STL): CompletionRequest {
  return { text, line, column, language: 'stl', outline: OUTLINE, file: 'OB1.awl', uiLanguage: 'en' };
}

/** The text with `typed` as line `line` and the caret at its end. */
function typing(text: string, line: number, typed: string): { text: string; column: number } {
  const lines = text.split('\n');
  lines[line - 1] = typed;
  return { text: lines.join('\n'), column: typed.length + 1 };
}

function labels(request: CompletionRequest): string[] {
  return complete(request)?.suggestions.map((item) => item.label) ?? [];
}

describe('completion', () => {
  it('offers the members of a DB after its name and a dot', () => {
    const { text, column } = typing(SCL, 8, '  x := "TankSettings".Lo');
    const found = complete(sclAt(8, column, text))!;
    expect(found.suggestions.map((item) => item.label)).toEqual(['LowLevel', 'HighLevel']);
    expect(found.from).toBe(column - 2);
    expect(found.suggestions[0]).toMatchObject({ detail: 'REAL · DATA', documentation: 'the pump starts below this' });
    const absolute = typing(STL, 8, '      L     DB10.');
    expect(labels(stlAt(8, absolute.column, absolute.text))).toEqual(['Level', 'Pump']);
  });

  it('follows STRUCT members and multi-instances', () => {
    expect(labels(sclAt(8, 10, typing(SCL, 8, '  State.').text))).toEqual(['Filling']);
    // a multi-instance of FB "Valve": its interface without TEMP
    const sub = typing(SCL, 8, '  #Sub.');
    expect(labels(sclAt(8, sub.column, sub.text))).toEqual(['Open']);
  });

  it('offers symbols in quotes, replacing an auto-closed quote', () => {
    const { text, column } = typing(SCL, 8, '  x := "Hi"');
    const found = complete(sclAt(8, column - 1, text))!;
    expect(found.suggestions.map((item) => item.label)).toContain('"High level alarm"');
    expect(found.from).toBe(8);
    expect(found.to).toBe(column);
    const alarm = found.suggestions.find((item) => item.label === '"High level alarm"')!;
    expect(alarm).toMatchObject({ insertText: '"High level alarm"', detail: 'Q 4.1 · BOOL', documentation: 'alarm horn', kind: 'symbol' });
    // blocks without a symbol of their own are offered by name too
    expect(found.suggestions.map((item) => item.label)).toContain('"Valve"');
  });

  it('offers SCL members, snippets, standard functions with parameters and keywords', () => {
    const { text, column } = typing(SCL, 8, '  ');
    const found = complete(sclAt(8, column, text))!;
    const byLabel = new Map(found.suggestions.map((item) => [item.label, item]));
    const snippet = (label: string) => found.suggestions.find((item) => item.label === label && item.kind === 'snippet');
    expect(byLabel.get('Level')).toMatchObject({ kind: 'member', insertText: 'Level', detail: 'REAL · IN' });
    expect(snippet('FOR')).toMatchObject({ snippet: true, insertText: 'FOR ${1:i} := ${2:1} TO ${3:10} DO\n\t$0\nEND_FOR;' });
    expect(snippet('CASE')!.insertText).toContain('END_CASE;');
    expect(snippet('REPEAT')!.insertText).toContain('UNTIL ${1:condition}');
    expect(byLabel.get('LIMIT')).toMatchObject({ kind: 'function', insertText: 'LIMIT(MN := ${1}, IN := ${2}, MX := ${3})' });
    expect(byLabel.get('INT_TO_REAL')!.insertText).toBe('INT_TO_REAL(${1})');
    expect(byLabel.get('END_IF')).toMatchObject({ kind: 'keyword' });
    expect(byLabel.get('"Auto"')).toMatchObject({ kind: 'symbol' });
  });

  it('offers STL instructions of the file mnemonic set at the start of a statement', () => {
    const international = typing(STL, 8, '      J');
    const names = labels(stlAt(8, international.column, international.text));
    expect(names).toContain('JC');
    expect(names).not.toContain('SPB');
    const germanText = STL.replace('A     I 0.0', 'U     E 0.0').replace('=     Q 4.0', '=     A 4.0');
    const german = typing(germanText, 8, '      SP');
    const germanNames = labels(stlAt(8, german.column, german.text));
    expect(germanNames).toContain('SPB');
    expect(germanNames).not.toContain('JC');
    const item = complete(stlAt(8, german.column, german.text))!.suggestions.find((s) => s.label === 'U')!;
    expect(item.documentation).toContain('AND');
  });

  it('offers the block members as #name, symbols in operands and FCs/FBs after CALL', () => {
    const operand = typing(STL, 8, '      L     ');
    const names = labels(stlAt(8, operand.column, operand.text));
    expect(names).toContain('#Cycle');
    expect(names).toContain('"Auto"');
    const hash = typing(STL, 8, '      L     #C');
    expect(complete(stlAt(8, hash.column, hash.text))).toMatchObject({ from: hash.column - 2, suggestions: [{ label: '#Cycle', insertText: '#Cycle' }] });
    const call = typing(STL, 8, '      CALL  ');
    expect(labels(stlAt(8, call.column, call.text))).toEqual(['"LevelControl"', '"Valve"', '"Scale"']);
  });

  it('offers nothing in a comment', () => {
    const { text, column } = typing(STL, 8, '      A  I 0.0 // "Tank');
    expect(complete(stlAt(8, column, text))).toBeNull();
  });
});

describe('mnemonic set of a file', () => {
  it('is German when German instructions and areas are in the majority', () => {
    expect(detectMnemonicSet(STL)).toBe('en');
    expect(detectMnemonicSet('BEGIN\n  U E 0.0;\n  = A 4.0;\nEND_FUNCTION')).toBe('de');
    expect(detectMnemonicSet('')).toBe('en');
  });
});

function hoverRequest(text: string, line: number, column: number, language: 'stl' | 'scl', uiLanguage = 'en'): HoverRequest {
  return { text, line, column, language, outline: OUTLINE, file: language === 'stl' ? 'OB1.awl' : 'LevelControl.scl', uiLanguage };
}

describe('hover', () => {
  it('explains an STL instruction in the interface language', () => {
    const found = hoverAt(hoverRequest(STL, 5, 7, 'stl', 'fa'))!;
    expect(found).toMatchObject({ from: 7, to: 8 });
    expect(found.parts[0]).toEqual({ kind: 'code', text: 'A <bit>' });
    expect(found.parts[1]!.text).toContain('وضعیت سیگنال بیت');
    expect(found.parts[2]!.text).toBe('بیت‌های وضعیتِ تغییرکننده: RLO, /FC, STA, OR');
    expect(found.parts[3]!.text).toContain('U');
    expect(hoverAt(hoverRequest(STL, 6, 7, 'stl'))!.parts[1]!.text).toContain('Writes the RLO');
  });

  it('explains symbols, DB members, interface members and standard functions', () => {
    const symbol = hoverAt(hoverRequest(STL, 7, 16, 'stl'))!;
    expect(symbol.parts[0]).toEqual({ kind: 'code', text: '"TankSettings"  DB 1  DB 1' });
    const dbMember = hoverAt(hoverRequest(STL, 7, 30, 'stl'))!;
    expect(dbMember.parts[0]).toEqual({ kind: 'code', text: 'LowLevel : REAL' });
    expect(dbMember.parts[2]).toEqual({ kind: 'text', text: 'the pump starts below this' });
    const interfaceMember = hoverAt(hoverRequest(SCL, 6, 13, 'scl'))!;
    expect(interfaceMember.parts[0]).toEqual({ kind: 'code', text: 'Level : REAL' });
    expect(interfaceMember.parts[1]!.text).toBe('Variable · Section: IN');
    const limit = hoverAt(hoverRequest(SCL, 7, 9, 'scl', 'vi'))!;
    expect(limit.parts[0]!.text).toBe('LIMIT(MN := ..., IN := ..., MX := ...) : ANY');
    expect(limit.parts[1]!.text).toBe('IN bị giới hạn trong khoảng MN đến MX.');
  });

  it('explains nothing in comments or declarations', () => {
    expect(hoverAt(hoverRequest('      A  I 0.0; // A', 1, 20, 'stl'))).toBeNull();
    expect(hoverAt(hoverRequest('VAR\n  A : BOOL;\nEND_VAR', 2, 3, 'stl'))).toBeNull();
  });

  it('renders Arabic and Persian text right to left and code left to right', () => {
    expect(markdownOf({ kind: 'text', text: 'a < b' }, 'fa', 'stl')).toEqual({ value: '<div align="right">a &lt; b</div>', supportHtml: true });
    expect(markdownOf({ kind: 'text', text: 'a_b (c)' }, 'en', 'stl')).toEqual({ value: 'a\\_b \\(c\\)' });
    expect(markdownOf({ kind: 'code', text: 'A <bit>' }, 'ar', 'stl')).toEqual({ value: '```stl\nA <bit>\n```' });
  });
});

describe('the Monaco providers', () => {
  it('are registered for both languages and answer from the model project outline', async () => {
    fake.reset();
    const monaco = await loadMonaco();
    const contents = createProjectContentsStore({ listFiles: () => Promise.resolve([]), getBlocks: () => Promise.resolve({ blocks: [], diagnostics: [] }) });
    const requested: number[] = [];
    const store = createOutlineStore({ getOutline: (id) => (requested.push(id), Promise.resolve(OUTLINE)) }, contents);
    const registration = registerIntellisense(monaco as never, store);
    const model = new FakeModel(typing(SCL, 8, '  x := "TankSettings".').text, 'scl');
    const binding = bindModel(model, () => ({ projectId: 7, path: 'LevelControl.scl' }));
    expect(sourceOf(model)).toEqual({ projectId: 7, path: 'LevelControl.scl' });

    const completion = fake.providerOf('completion', 'scl') as { provideCompletionItems: (m: unknown, p: unknown) => Promise<{ suggestions: Array<Record<string, unknown>> }>; triggerCharacters: string[] };
    expect(completion.triggerCharacters).toEqual(['.', '#', '"']);
    const result = await completion.provideCompletionItems(model, { lineNumber: 8, column: 24 });
    expect(requested).toEqual([7]);
    expect(result.suggestions.map((item) => item.label)).toEqual(['LowLevel', 'HighLevel']);
    expect(result.suggestions[0]).toMatchObject({ kind: 3, range: { startLineNumber: 8, startColumn: 24, endColumn: 24 } });

    document.documentElement.lang = 'ar';
    const hover = fake.providerOf('hover', 'stl') as { provideHover: (m: unknown, p: unknown) => Promise<{ contents: Array<{ value: string }> } | null> };
    const stlModel = new FakeModel(STL, 'stl');
    const help = await hover.provideHover(stlModel, { lineNumber: 5, column: 7 });
    expect(help!.contents[1]!.value).toMatch(/^<div align="right">تفحص حالة إشارة البت/);
    document.documentElement.lang = 'en';

    binding.dispose();
    expect(sourceOf(model)).toBeNull();
    registration.dispose();
    expect(fake.providerOf('completion', 'scl')).toBeUndefined();
  });
});

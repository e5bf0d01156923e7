/**
 * The pieces behind file tabs, without React: the autosave (debounce, one save at a time, 409),
 * the live check (debounce, cancelling), diagnostics → markers, go to definition, the STL
 * formatter, the project contents store and the names of new files.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { ApiError } from '../../frontend/src/api/client';
import type { Diagnostic, FileInfo, ProjectBuild } from '../../frontend/src/api/types';
import { AUTOSAVE_DELAY_MS, Autosaver } from '../../frontend/src/editor/autosave';
import { markersFor } from '../../frontend/src/editor/diagnosticMarkers';
import { findDefinition, referenceAt } from '../../frontend/src/editor/definitions';
import { formatStl } from '../../frontend/src/editor/languages/stlFormat';
import { CHECK_DELAY_MS, LiveCheck } from '../../frontend/src/editor/liveCheck';
import type { SaveState } from '../../frontend/src/editor/EditorTabsContext';
import { freeCopyName, freeSourceName, nameTaken, newSourceText } from '../../frontend/src/projects/fileNames';
import { createProjectContentsStore } from '../../frontend/src/projects/projectContents';
import { block } from './projectServer';

function info(version: number, name = 'OB1.awl'): FileInfo {
  return { name, language: 'stl', size: 0, version, created_at: '', updated_at: '' };
}

function stale(current: number): ApiError {
  return new ApiError(
    { code: 'API111', key: 'file_changed', message: 'changed', params: { name: 'OB1.awl', current_version: current } },
    409,
  );
}

function diagnostic(file: string, line: number, column: number | null = 7, extra: Partial<Diagnostic> = {}): Diagnostic {
  return {
    code: 'STL201',
    severity: 'error',
    key: 'stl_unknown_instruction',
    message: 'Unknown instruction XYZ.',
    params: { mnemonic: 'XYZ', hint: '' },
    span: { file, line, column },
    ...extra,
  };
}

describe('Autosaver', () => {
  let states: SaveState['status'][];
  let save: ReturnType<typeof vi.fn>;
  let saved: Array<[number, string]>;

  function saver(version: number | null = 3) {
    return new Autosaver({
      text: 'A',
      version,
      save: save as never,
      onState: (state) => states.push(state.status),
      onSaved: (file, text) => saved.push([file.version, text]),
    });
  }

  beforeEach(() => {
    vi.useFakeTimers();
    states = [];
    saved = [];
    let version = 3;
    save = vi.fn(async (_text: string, base: number | null) => {
      if (base !== null && base !== version) throw stale(version);
      version += 1;
      return info(version);
    });
  });
  afterEach(() => vi.useRealTimers());

  it('saves once, a second after the last of several changes, with the loaded version', async () => {
    const autosave = saver();
    autosave.change('AB');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS - 100);
    autosave.change('ABC');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS - 100);
    expect(save).not.toHaveBeenCalled();
    await vi.advanceTimersByTimeAsync(100);
    expect(save).toHaveBeenCalledOnce();
    expect(save).toHaveBeenCalledWith('ABC', 3, { keepalive: false });
    expect(saved).toEqual([[4, 'ABC']]);
    expect(states).toEqual(['dirty', 'saving', 'saved']);
    // The next save sends the version the first one made.
    autosave.change('ABCD');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS);
    expect(save).toHaveBeenLastCalledWith('ABCD', 4, { keepalive: false });
  });

  it('does not save a text changed back to what the server has', async () => {
    const autosave = saver();
    autosave.change('AB');
    autosave.change('A');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS * 2);
    expect(save).not.toHaveBeenCalled();
    expect(states).toEqual(['dirty', 'saved']);
  });

  it('flushes at once, and a change during a save is saved after it', async () => {
    let release: (file: FileInfo) => void = () => undefined;
    save.mockImplementation(async (_text: string, base: number | null) => info((base ?? 0) + 1));
    save.mockImplementationOnce(() => new Promise<FileInfo>((resolve) => (release = resolve)));
    const autosave = saver();
    autosave.change('AB');
    const first = autosave.flush();
    expect(save).toHaveBeenCalledWith('AB', 3, { keepalive: false });
    autosave.change('ABC');
    release(info(4));
    await first;
    expect(states.at(-1)).toBe('dirty');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS);
    expect(save).toHaveBeenCalledTimes(2);
    expect(save).toHaveBeenLastCalledWith('ABC', 4, { keepalive: false });
    expect(states.at(-1)).toBe('saved');
  });

  it('stops in "conflict" on a stale version until the user overwrites', async () => {
    const autosave = saver(2);
    autosave.change('mine');
    await autosave.flush();
    expect(states.at(-1)).toBe('conflict');
    autosave.change('mine, more');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS * 3);
    expect(save).toHaveBeenCalledOnce();
    await autosave.overwrite();
    expect(save).toHaveBeenLastCalledWith('mine, more', 3, { keepalive: false });
    expect(states.at(-1)).toBe('saved');
  });

  it('takes the server text after a conflict, then saves on top of its version', async () => {
    const autosave = saver(2);
    autosave.change('mine');
    await autosave.flush();
    autosave.reloaded('theirs', 3);
    expect(states.at(-1)).toBe('saved');
    autosave.change('theirs');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS);
    expect(save).toHaveBeenCalledOnce();
    autosave.change('theirs + 1');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS);
    expect(save).toHaveBeenLastCalledWith('theirs + 1', 3, { keepalive: false });
  });

  it('retries after the server was away; a refusal waits for the next change', async () => {
    const down = new ApiError({ code: 'NET000', key: 'server_unreachable', message: 'down' }, 0);
    save.mockRejectedValueOnce(down);
    const autosave = saver();
    autosave.change('AB');
    await autosave.flush();
    expect(states.at(-1)).toBe('failed');
    await vi.advanceTimersByTimeAsync(5000);
    expect(save).toHaveBeenCalledTimes(2);
    expect(states.at(-1)).toBe('saved');

    const tooLarge = new ApiError({ code: 'API110', key: 'file_too_large', message: 'big' }, 413);
    save.mockRejectedValueOnce(tooLarge);
    autosave.change('ABC');
    await autosave.flush();
    await vi.advanceTimersByTimeAsync(10_000);
    expect(save).toHaveBeenCalledTimes(3);
    expect(states.at(-1)).toBe('failed');
  });

  it('saves what is pending when disposed, with keepalive, and nothing after a discard', async () => {
    const autosave = saver();
    autosave.change('AB');
    await autosave.dispose();
    expect(save).toHaveBeenCalledWith('AB', 3, { keepalive: true });

    const gone = saver();
    gone.change('AB');
    gone.discard();
    await gone.dispose();
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS * 2);
    expect(save).toHaveBeenCalledOnce();
  });

  it('saves a text opened with changes soon, without a version check when it has no version', async () => {
    const autosave = new Autosaver({
      text: 'new',
      version: null,
      saved: false,
      save: save as never,
      onState: () => undefined,
      onSaved: () => undefined,
    });
    expect(autosave.status).toBe('dirty');
    await vi.advanceTimersByTimeAsync(AUTOSAVE_DELAY_MS);
    expect(save).toHaveBeenCalledWith('new', null, { keepalive: false });
  });
});

describe('LiveCheck', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  const build: ProjectBuild = { blocks: [], diagnostics: [] };

  it('checks the newest text after a pause and cancels an older check', async () => {
    const signals: AbortSignal[] = [];
    const check = vi.fn(async (_text: string, signal: AbortSignal) => {
      signals.push(signal);
      return build;
    });
    const results: string[] = [];
    const live = new LiveCheck({ check, onResult: (_build, text) => results.push(text) });
    live.change('A');
    live.change('AB');
    await vi.advanceTimersByTimeAsync(CHECK_DELAY_MS - 1);
    expect(check).not.toHaveBeenCalled();
    await vi.advanceTimersByTimeAsync(1);
    expect(check).toHaveBeenCalledOnce();
    expect(results).toEqual(['AB']);
    live.change('AB');
    await vi.advanceTimersByTimeAsync(CHECK_DELAY_MS);
    expect(check).toHaveBeenCalledOnce();

    let release: (value: ProjectBuild) => void = () => undefined;
    check.mockImplementationOnce((_text, signal) => {
      signals.push(signal);
      return new Promise((resolve) => (release = resolve));
    });
    live.change('ABC');
    await vi.advanceTimersByTimeAsync(CHECK_DELAY_MS);
    live.change('ABCD');
    expect(signals.at(-1)!.aborted).toBe(true);
    release(build);
    await vi.advanceTimersByTimeAsync(CHECK_DELAY_MS);
    expect(results).toEqual(['AB', 'ABCD']);
  });

  it('checks at once when asked, and stops on dispose', async () => {
    const check = vi.fn(async () => build);
    const live = new LiveCheck({ check, onResult: () => undefined });
    live.change('A', true);
    expect(check).toHaveBeenCalledOnce();
    live.change('AB');
    live.dispose();
    await vi.advanceTimersByTimeAsync(CHECK_DELAY_MS * 2);
    expect(check).toHaveBeenCalledOnce();
  });
});

describe('markersFor', () => {
  const text = 'ORGANIZATION_BLOCK OB 1\nBEGIN\n      XYZ   "Motor";\n';
  const english = (d: Diagnostic) => d.message;

  it('keeps the file’s diagnostics, with the code, the message and the word as the range', () => {
    const markers = markersFor(
      [diagnostic('OB1.awl', 3), diagnostic('FC1.awl', 3), diagnostic('OB1.awl', 3, 13, { severity: 'warning' })],
      'OB1.awl',
      text,
      english,
    );
    expect(markers).toEqual([
      { line: 3, column: 7, endLine: 3, endColumn: 10, severity: 'error', code: 'STL201', message: 'Unknown instruction XYZ.' },
      { line: 3, column: 13, endLine: 3, endColumn: 20, severity: 'warning', code: 'STL201', message: 'Unknown instruction XYZ.' },
    ]);
  });

  it('uses the end the compiler gives, marks the line without a column, the first line without a line', () => {
    const withEnd = diagnostic('OB1.awl', 3, 7, { span: { file: 'OB1.awl', line: 3, column: 7, end_line: 3, end_column: 22 } });
    const noColumn = diagnostic('OB1.awl', 3, null);
    const noLine = { ...diagnostic('OB1.awl', 1), span: { file: 'OB1.awl' } };
    const [a, b, c] = markersFor([withEnd, noColumn, noLine], 'OB1.awl', text, english);
    expect([a!.column, a!.endColumn]).toEqual([7, 22]);
    expect([b!.column, b!.endColumn]).toEqual([7, 21]);
    expect([c!.line, c!.column, c!.endColumn]).toEqual([1, 1, 24]);
  });

  it('takes the message from the translation function', () => {
    const [marker] = markersFor([diagnostic('OB1.awl', 3)], 'OB1.awl', text, (d) => `«${String(d.params.mnemonic)}»`);
    expect(marker!.message).toBe('«XYZ»');
  });
});

describe('go to definition', () => {
  const blocks = [
    block('OB', 1, 'Main', 'OB1.awl', 1),
    block('FC', 10, 'Scale', 'Scale.scl', 8),
    block('FB', 10, 'LevelControl', 'LevelControl.scl', 7),
    block('DB', 1, 'TankSettings', 'TankSettings.awl', 2),
  ];

  it.each([
    ['      CALL  FC 10;', 15, 'Scale.scl'],
    ['      CALL  FC10;', 14, 'Scale.scl'],
    ['      CALL "Scale" (', 14, 'Scale.scl'],
    ['      CALL "LevelControl" , "LevelData" (', 14, 'LevelControl.scl'],
    ['           LowLevel := "TankSettings".LowLevel,', 27, 'TankSettings.awl'],
    ['      L     DB1.DBW 2', 14, 'TankSettings.awl'],
    ['  pump := scale(x := 1);', 12, 'Scale.scl'],
  ])('%s (column %d) → %s', (line, column, file) => {
    expect(findDefinition(blocks, line, column)?.file).toBe(file);
  });

  it('finds nothing in comments, on addresses or on unknown names', () => {
    expect(findDefinition(blocks, '      A     I 0.0;   // CALL FC 10', 33)).toBeNull();
    expect(findDefinition(blocks, '      A     I 0.0;', 13)).toBeNull();
    expect(findDefinition(blocks, '      CALL  FC 99;', 15)).toBeNull();
    expect(referenceAt('      CALL  SFC 46;', 15)).toEqual({ name: 'SFC' });
  });
});

describe('formatStl', () => {
  it('lays statements out in STEP 7’s columns, leaving declarations and data blocks alone', () => {
    const source = [
      'FUNCTION_BLOCK FB 1',
      'VAR_INPUT',
      '  start : BOOL;   // kept',
      'END_VAR',
      'BEGIN',
      'NETWORK',
      'TITLE = Motor',
      'a( ;',
      'o i 0.0;  // start',
      'O "Motor";',
      ') ;',
      'AN I0.1;',
      '= Q 4.0;',
      'M001: L MW20;',
      '  JCN M001;',
      '  CALL "Scale" (',
      '  Raw := "Level sensor",',
      '  RET_VAL := #level);',
      "  L 'a;b';",
      'END_FUNCTION_BLOCK',
      'DATA_BLOCK DB 1',
      'BEGIN',
      '  x := 1;',
      'END_DATA_BLOCK',
    ].join('\n');
    expect(formatStl(source).split('\n')).toEqual([
      'FUNCTION_BLOCK FB 1',
      'VAR_INPUT',
      '  start : BOOL;   // kept',
      'END_VAR',
      'BEGIN',
      'NETWORK',
      'TITLE = Motor',
      '      a(    ;',
      `      o     i      0.0;${' '.repeat(13)}// start`,
      '      O     "Motor";',
      '      )     ;',
      '      AN    I      0.1;',
      '      =     Q      4.0;',
      'M001: L     MW    20;',
      '      JCN   M001;',
      '      CALL  "Scale" (',
      '           Raw                      := "Level sensor",',
      '           RET_VAL                  := #level);',
      "      L     'a;b';",
      'END_FUNCTION_BLOCK',
      'DATA_BLOCK DB 1',
      'BEGIN',
      '  x := 1;',
      'END_DATA_BLOCK',
    ]);
  });

  it('is stable and keeps Windows line ends', () => {
    const source = 'ORGANIZATION_BLOCK OB 1\r\nBEGIN\r\nNETWORK\r\n  A I 0.0;\r\nEND_ORGANIZATION_BLOCK\r\n';
    const once = formatStl(source);
    expect(once).toBe('ORGANIZATION_BLOCK OB 1\r\nBEGIN\r\nNETWORK\r\n      A     I      0.0;\r\nEND_ORGANIZATION_BLOCK\r\n');
    expect(formatStl(once)).toBe(once);
  });
});

describe('project contents store', () => {
  const files = [info(1, 'OB1.awl'), info(1, 'FC1.awl')];
  const saved: ProjectBuild = {
    blocks: [block('OB', 1, 'Main', 'OB1.awl'), block('FC', 1, '', 'FC1.awl')],
    diagnostics: [diagnostic('OB1.awl', 3), diagnostic('FC1.awl', 4)],
  };

  function store() {
    const api = { listFiles: vi.fn(async () => files), getBlocks: vi.fn(async () => saved) };
    return { api, contents: createProjectContentsStore(api) };
  }

  it('loads files and blocks once, sorted by name', async () => {
    const { api, contents } = store();
    contents.ensure(1);
    contents.ensure(1);
    expect(contents.get(1)?.status).toBe('loading');
    await vi.waitFor(() => expect(contents.get(1)?.status).toBe('ready'));
    expect(api.listFiles).toHaveBeenCalledOnce();
    expect(contents.get(1)?.files.map((f) => f.name)).toEqual(['FC1.awl', 'OB1.awl']);
    expect(contents.get(1)?.diagnostics).toHaveLength(2);
  });

  it('keeps an unsaved file’s own diagnostics when another file’s check compiled its saved text', async () => {
    const { contents } = store();
    contents.ensure(1);
    await vi.waitFor(() => expect(contents.get(1)?.status).toBe('ready'));
    contents.setFileDirty(1, 'OB1.awl', true);
    contents.applyBuild(1, { blocks: saved.blocks, diagnostics: [] }, 'OB1.awl');
    expect(contents.get(1)?.diagnostics).toEqual([]);
    // FC1's check compiled OB1's saved text (with its old error): OB1 keeps its own result.
    contents.applyBuild(1, { blocks: saved.blocks, diagnostics: [diagnostic('OB1.awl', 3)] }, 'FC1.awl');
    expect(contents.get(1)?.diagnostics).toEqual([]);
    // Once OB1 is saved, the next build is right for it.
    contents.setFileDirty(1, 'OB1.awl', false);
    contents.applyBuild(1, { blocks: saved.blocks, diagnostics: [diagnostic('OB1.awl', 9)] }, 'FC1.awl');
    expect(contents.get(1)?.diagnostics.map((d) => d.span?.line)).toEqual([9]);
  });

  it('updates files, blocks and diagnostics locally on save, rename and delete', async () => {
    const { contents } = store();
    contents.ensure(1);
    await vi.waitFor(() => expect(contents.get(1)?.status).toBe('ready'));
    contents.putFile(1, info(2, 'Main.awl'), 'OB1.awl');
    expect(contents.get(1)?.files.map((f) => f.name)).toEqual(['FC1.awl', 'Main.awl']);
    expect(contents.get(1)?.blocks.find((b) => b.kind === 'OB')?.file).toBe('Main.awl');
    expect(contents.get(1)?.diagnostics.map((d) => d.span?.file).sort()).toEqual(['FC1.awl', 'Main.awl']);
    contents.removeFile(1, 'FC1.awl');
    expect(contents.get(1)?.files.map((f) => f.name)).toEqual(['Main.awl']);
    expect(contents.get(1)?.blocks.map((b) => b.kind)).toEqual(['OB']);
    expect(contents.get(1)?.diagnostics.map((d) => d.span?.file)).toEqual(['Main.awl']);
  });

  it('shows a failed load as an error, and loads again on demand', async () => {
    const { api, contents } = store();
    api.getBlocks.mockRejectedValueOnce(new ApiError({ code: 'API104', key: 'project_not_found', message: 'gone' }, 404));
    contents.ensure(1);
    await vi.waitFor(() => expect(contents.get(1)?.status).toBe('error'));
    expect(contents.get(1)?.error?.code).toBe('API104');
    await contents.reload(1);
    expect(contents.get(1)?.status).toBe('ready');
  });
});

describe('names of new files', () => {
  const files = [info(1, 'Source1.awl'), info(1, 'OB1.awl'), info(1, 'OB1_copy.awl')];

  it('finds free names, letter case aside', () => {
    expect(freeSourceName(files, 'awl')).toBe('Source2.awl');
    expect(freeSourceName(files, 'scl')).toBe('Source1.scl');
    expect(freeCopyName(files, 'OB1.awl')).toBe('OB1_copy2.awl');
    expect(nameTaken(files, 'ob1.AWL')).toBe(true);
    expect(nameTaken(files, 'OB1.awl', 'OB1.awl')).toBe(false);
  });

  it('starts a source with an empty FC the project does not have yet', () => {
    expect(newSourceText('stl', [block('FC', 1, '', 'a.awl'), block('FC', 2, '', 'a.awl')])).toMatch(/^FUNCTION FC 3 : VOID\n/);
    expect(newSourceText('scl', [])).toMatch(/^FUNCTION FC 1 : VOID\n[\s\S]*END_FUNCTION\n$/);
  });
});

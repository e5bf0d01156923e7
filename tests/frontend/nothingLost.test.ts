/**
 * Nothing a user typed is lost, and the rough edges a new user found: which tabs hold unsaved
 * text (a reload asks), the Start page's new source as a project file, Tab in the symbol grid,
 * the diagnostic buffer's link to a block's line, F12 on a symbol naming its row.
 */
import { describe, expect, it, vi } from 'vitest';
import { ApiError } from '../../frontend/src/api/client';
import type { FileInfo } from '../../frontend/src/api/types';
import { findDefinition } from '../../frontend/src/editor/definitions';
import type { EditorTab, SaveStatus, SourceTab } from '../../frontend/src/editor/EditorTabsContext';
import { STL_EXAMPLE } from '../../frontend/src/editor/examples';
import { createStartSource } from '../../frontend/src/editor/newSource';
import { closingLosesText, hasPendingEdits, holdsUnsavedText, setPendingEdit } from '../../frontend/src/editor/unsaved';
import { cpuEntryTarget } from '../../frontend/src/panels/CpuDiagnostics';
import { freeSymbolTableName } from '../../frontend/src/projects/fileNames';
import { tabTarget } from '../../frontend/src/symbols/SymbolGrid';
import { block } from './projectServer';

function fileInfo(name: string, version = 1): FileInfo {
  return { name, language: 'stl', size: 0, version, created_at: '', updated_at: '' };
}

function sourceTab(status: SaveStatus, withFile = true, dirty = status !== 'saved'): SourceTab {
  return {
    id: 'source-1',
    kind: 'source',
    name: 'OB1.awl',
    language: 'stl',
    text: '',
    dirty,
    file: withFile ? { projectId: 1, path: 'OB1.awl' } : null,
    markers: [],
    version: 1,
    save: { status, error: null },
    reveal: null,
  };
}

describe('unsaved text', () => {
  it('a reload asks while a change is pending, being saved, refused or failed', () => {
    expect(holdsUnsavedText(sourceTab('saved'))).toBe(false);
    for (const status of ['dirty', 'saving', 'conflict', 'failed'] as const) expect(holdsUnsavedText(sourceTab(status))).toBe(true);
    // A text without a file would be lost on any reload.
    expect(holdsUnsavedText(sourceTab('dirty', false))).toBe(true);
    const start: EditorTab = { id: 'start', kind: 'start' };
    expect(holdsUnsavedText(start)).toBe(false);
  });

  it('a reload also asks while a view holds typed text not yet in its tab (the STL view of a LAD block)', () => {
    expect(hasPendingEdits()).toBe(false);
    setPendingEdit('source-3:stl', true);
    expect(hasPendingEdits()).toBe(true);
    setPendingEdit('source-3:stl', false);
    expect(hasPendingEdits()).toBe(false);
  });

  it('closing a tab asks only when its text could not be saved (a pending save goes as it closes)', () => {
    expect(closingLosesText(sourceTab('dirty'))).toBe(false);
    expect(closingLosesText(sourceTab('saving'))).toBe(false);
    expect(closingLosesText(sourceTab('conflict'))).toBe(true);
    expect(closingLosesText(sourceTab('failed'))).toBe(true);
    expect(closingLosesText(sourceTab('dirty', false))).toBe(true);
  });
});

describe("the Start page's new source", () => {
  const api = (files: FileInfo[], blocks = [block('FC', 1, '', 'a.awl')]) => ({
    listFiles: vi.fn(async () => files),
    getBlocks: vi.fn(async () => ({ blocks, diagnostics: [] })),
    saveFile: vi.fn(async (_project: number, name: string, body: { text: string }) => ({ ...fileInfo(name), size: body.text.length })),
  });

  it('is a file of the project; an empty project gets the example program', async () => {
    const fake = api([fileInfo('symbols.sdf')]);
    const made = await createStartSource(7, 'stl', fake);
    expect(fake.saveFile).toHaveBeenCalledWith(7, 'Source1.awl', { text: STL_EXAMPLE });
    expect(made.info.name).toBe('Source1.awl');
    expect(made.text).toBe(STL_EXAMPLE);
    expect(fake.getBlocks).not.toHaveBeenCalled();
  });

  it('in a project with sources it is an empty FC with a free number and a free name', async () => {
    const fake = api([fileInfo('OB1.awl'), fileInfo('source1.scl')]);
    const made = await createStartSource(7, 'scl', fake);
    expect(made.info.name).toBe('Source2.scl');
    expect(made.text).toMatch(/^FUNCTION FC 2 : VOID\n/);
  });

  it('takes the next name when another tab took this one meanwhile (API108)', async () => {
    const fake = api([]);
    const taken = new ApiError({ code: 'API108', key: 'file_name_taken', message: 'taken', params: { name: 'Source1.awl' } }, 409);
    fake.saveFile.mockRejectedValueOnce(taken);
    const made = await createStartSource(3, 'stl', fake);
    expect(made.info.name).toBe('Source2.awl');
    expect(fake.saveFile).toHaveBeenCalledTimes(2);
  });

  it('passes on any other refusal', async () => {
    const fake = api([]);
    fake.saveFile.mockRejectedValueOnce(new ApiError({ code: 'API104', key: 'project_not_found', message: 'gone', params: {} }, 404));
    await expect(createStartSource(3, 'stl', fake)).rejects.toMatchObject({ code: 'API104' });
  });
});

describe('a new symbol table', () => {
  it('gets the first free name', () => {
    expect(freeSymbolTableName([])).toBe('Symbols.sdf');
    expect(freeSymbolTableName([fileInfo('symbols.SDF'), fileInfo('Symbols2.sdf')])).toBe('Symbols3.sdf');
  });
});

describe('Tab in the symbol grid', () => {
  it('goes along the row, then to the first cell of the next row; Shift+Tab back', () => {
    expect(tabTarget({ row: 0, col: 0 }, false, 3)).toEqual({ row: 0, col: 1 });
    expect(tabTarget({ row: 0, col: 3 }, false, 3)).toEqual({ row: 1, col: 0 });
    expect(tabTarget({ row: 1, col: 0 }, true, 3)).toEqual({ row: 0, col: 3 });
    expect(tabTarget({ row: 1, col: 2 }, true, 3)).toEqual({ row: 1, col: 1 });
  });

  it('leaves the grid past its first and last cell', () => {
    expect(tabTarget({ row: 0, col: 0 }, true, 3)).toBeNull();
    expect(tabTarget({ row: 2, col: 3 }, false, 3)).toBeNull();
  });
});

describe("the diagnostic buffer's link", () => {
  const blocks = [block('OB', 1, 'Main', 'OB1.awl', 1), block('FC', 10, 'Scale', 'scale.scl', 40)];

  it("opens the faulting block's file at the entry's line, or at the block's header", () => {
    expect(cpuEntryTarget({ block: 'FC10', line: 47 }, blocks)).toEqual({ file: 'scale.scl', line: 47 });
    expect(cpuEntryTarget({ block: 'FC 10', line: null }, blocks)).toEqual({ file: 'scale.scl', line: 40 });
  });

  it('has none for a block without a source or an entry without a block', () => {
    expect(cpuEntryTarget({ block: 'SFC46', line: 3 }, blocks)).toBeNull();
    expect(cpuEntryTarget({ block: null, line: null }, blocks)).toBeNull();
  });
});

describe('F12 on a symbol', () => {
  it("names the symbol, so the table selects its row", () => {
    const symbols = [{ name: 'Motor', address: 'Q 4.0', type: 'BOOL', comment: '', file: 'symbols.sdf', line: 3 }];
    expect(findDefinition([], '      =     "Motor"', 16, symbols)).toEqual({ file: 'symbols.sdf', line: 3, symbol: 'Motor' });
  });
});

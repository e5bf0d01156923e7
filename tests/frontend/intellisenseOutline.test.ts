/**
 * The project outline on the front end: its API shapes against the OpenAPI document, the store
 * that loads it and follows the project's saved files, and go to definition of symbols.
 */
import { afterEach, describe, expect, it, vi } from 'vitest';
import openapi from '../../frontend/src/api/openapi.json';
import {
  getOutline,
  type OutlineBlock,
  type OutlineMember,
  type OutlineSequencer,
  type OutlineStep,
  type OutlineSymbol,
  type OutlineTransition,
  type ProjectOutline,
} from '../../frontend/src/api/outline';
import type { FileInfo } from '../../frontend/src/api/types';
import { findDefinition } from '../../frontend/src/editor/definitions';
import { OUTLINE_RELOAD_MS, createOutlineStore } from '../../frontend/src/editor/intellisense/outlineStore';
import { createProjectContentsStore } from '../../frontend/src/projects/projectContents';
import { block } from './projectServer';

type Fields<T> = Record<keyof Required<T>, true>;
const schemas = openapi.components.schemas as Record<string, { properties?: Record<string, unknown> }>;
const propertiesOf = (name: string): string[] => Object.keys(schemas[name]?.properties ?? {}).sort();

const symbolFields: Fields<OutlineSymbol> = { name: true, address: true, type: true, comment: true, file: true, line: true };
const memberFields: Fields<OutlineMember> = {
  path: true,
  name: true,
  type: true,
  section: true,
  depth: true,
  offset: true,
  initial: true,
  actual: true,
  comment: true,
  elementary: true,
  file: true,
  line: true,
};
const blockFields: Fields<OutlineBlock> = {
  kind: true,
  number: true,
  name: true,
  language: true,
  file: true,
  line: true,
  return_type: true,
  instance_of: true,
  members: true,
  sequencers: true,
};
const outlineFields: Fields<ProjectOutline> = { symbols: true, blocks: true };
const sequencerFields: Fields<OutlineSequencer> = { name: true, line: true, steps: true, transitions: true };
const stepFields: Fields<OutlineStep> = { number: true, name: true, initial: true, line: true };
const transitionFields: Fields<OutlineTransition> = { number: true, name: true, source: true, target: true, line: true };

const OUTLINE: ProjectOutline = {
  symbols: [
    { name: 'Pump', address: 'Q 4.0', type: 'BOOL', comment: 'filling pump', file: 'symbols.sdf', line: 3 },
    { name: 'Scale', address: 'FC 10', type: 'FC 10', comment: '', file: 'symbols.sdf', line: 10 },
  ],
  blocks: [],
};

function info(name: string, version: number): FileInfo {
  return { name, language: 'stl', size: 0, version, created_at: '', updated_at: '' };
}

afterEach(() => {
  vi.useRealTimers();
  vi.unstubAllGlobals();
});

describe('the outline API', () => {
  it.each([
    ['OutlineSymbol', symbolFields],
    ['Member', memberFields],
    ['OutlineBlock', blockFields],
    ['ProjectOutline', outlineFields],
    ['OutlineSequencer', sequencerFields],
    ['OutlineStep', stepFields],
    ['OutlineTransition', transitionFields],
  ])('%s matches the OpenAPI document', (schema, record) => {
    expect(propertiesOf(schema).length).toBeGreaterThan(0);
    expect(Object.keys(record).sort()).toEqual(propertiesOf(schema));
  });

  it('is documented at /api/projects/{project_id}/outline', () => {
    expect(Object.keys(openapi.paths)).toContain('/api/projects/{project_id}/outline');
  });

  it('turns an error answer into an ApiError with the catalogue code', async () => {
    const body = { error: { code: 'API104', key: 'project_not_found', message: 'No project 9.', params: { id: 9 } } };
    vi.stubGlobal('fetch', vi.fn(() => Promise.resolve(new Response(JSON.stringify(body), { status: 404 }))));
    await expect(getOutline(9)).rejects.toMatchObject({ code: 'API104', status: 404 });
    vi.stubGlobal('fetch', vi.fn(() => Promise.resolve(new Response(JSON.stringify(OUTLINE), { status: 200 }))));
    await expect(getOutline(9)).resolves.toEqual(OUTLINE);
    vi.stubGlobal('fetch', vi.fn(() => Promise.reject(new TypeError('offline'))));
    await expect(getOutline(9)).rejects.toMatchObject({ code: 'NET000', status: 0 });
  });
});

describe('the outline store', () => {
  it('loads on first use and again when the project files change', async () => {
    vi.useFakeTimers();
    let files = [info('OB1.awl', 1)];
    const contents = createProjectContentsStore({
      listFiles: () => Promise.resolve(files),
      getBlocks: () => Promise.resolve({ blocks: [], diagnostics: [] }),
    });
    await contents.reload(5);
    const getOutline = vi.fn((_projectId: number) => Promise.resolve(OUTLINE));
    const store = createOutlineStore({ getOutline }, contents);
    const seen: number[] = [];
    store.subscribe(() => seen.push(getOutline.mock.calls.length));

    expect(store.get(5)).toBeNull();
    expect(await store.ready(5)).toMatchObject({ symbols: OUTLINE.symbols });
    expect(getOutline).toHaveBeenCalledTimes(1);
    expect(store.get(5)).not.toBeNull();

    // a save: the file's version changes, the outline follows shortly after
    files = [info('OB1.awl', 2)];
    contents.putFile(5, info('OB1.awl', 2));
    contents.putFile(5, info('OB1.awl', 2));
    expect(getOutline).toHaveBeenCalledTimes(1);
    await vi.advanceTimersByTimeAsync(OUTLINE_RELOAD_MS + 10);
    expect(getOutline).toHaveBeenCalledTimes(2);
    expect(seen).toEqual([1, 2]);

    // a change that is not a save (the unsaved text's diagnostics): no new load
    contents.applyBuild(5, { blocks: [], diagnostics: [] }, 'OB1.awl');
    await vi.advanceTimersByTimeAsync(OUTLINE_RELOAD_MS + 10);
    expect(getOutline).toHaveBeenCalledTimes(2);
    store.clear();
  });

  it('answers null when the outline cannot be loaded', async () => {
    const contents = createProjectContentsStore({ listFiles: () => Promise.resolve([]), getBlocks: () => Promise.resolve({ blocks: [], diagnostics: [] }) });
    const store = createOutlineStore({ getOutline: () => Promise.reject(new Error('down')) }, contents);
    expect(await store.ready(3)).toBeNull();
  });
});

describe('go to definition of symbols', () => {
  it('opens the symbol table at the symbol line; a block name still goes to the block', () => {
    const scale = block('FC', 10, 'Scale', 'Scale.scl', 5);
    expect(findDefinition([scale], '      =     "Pump";', 15, OUTLINE.symbols)).toEqual({ file: 'symbols.sdf', line: 3, symbol: 'Pump' });
    expect(findDefinition([scale], '      CALL  "Scale" (', 15, OUTLINE.symbols)).toBe(scale);
    expect(findDefinition([scale], '      =     "Unknown";', 15, OUTLINE.symbols)).toBeNull();
    expect(findDefinition([scale], '      =     "Pump";', 15)).toBeNull();
  });
});

/**
 * The Graph document hook (frontend/src/graph/useGraphDocument.ts) over a fake server reader: it
 * reads the text, edits change model and text at once (only the edited items' lines), undo back
 * to the start gives the original file byte for byte and redo the edited texts again, a text
 * changed elsewhere is read again (and is one undo step), a text with syntax errors is not drawn,
 * and the checker's findings follow the edited text.
 */
import fs from 'node:fs';
import path from 'node:path';
import { act, renderHook, waitFor } from '@testing-library/react';
import { useState } from 'react';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { Diagnostic } from '../../frontend/src/api/types';
import type { GraphBlock } from '../../frontend/src/graph/model';

interface Entry {
  name: string;
  source: string;
  blocks: GraphBlock[];
  places: Record<string, number>[];
}

const entries = (JSON.parse(fs.readFileSync(path.join(__dirname, 'fixtures', 'graph-parity.json'), 'utf-8')) as { entries: Entry[] }).entries;
const g17 = entries.find((entry) => entry.name.endsWith('g17_conveyors.graph')) as Entry;
const g01 = entries.find((entry) => entry.name.endsWith('g01_first_step.graph')) as Entry;

const finding = (code: string): Diagnostic => ({ code, severity: 'warning', key: 'k', message: code, params: {}, span: null });
const reads: string[] = [];

vi.mock('../../frontend/src/api/client', async (importOriginal) => {
  const original = await importOriginal<typeof import('../../frontend/src/api/client')>();
  return {
    ...original,
    readGraph: vi.fn(async (_name: string, text: string) => {
      reads.push(text);
      const known = entries.find((entry) => entry.source === text);
      if (known) return { blocks: known.blocks, diagnostics: [], problems: [finding('GRA244')], places: known.places };
      if (text.includes('BROKEN')) {
        return { blocks: [], diagnostics: [{ ...finding('GRA112'), severity: 'error' }], problems: [], places: [] };
      }
      // An edited text: the hook only takes the findings from it.
      return { blocks: [], diagnostics: [], problems: [finding('GRA245')], places: [{ BLOCK: 7 }] };
    }),
  };
});

const { useGraphDocument } = await import('../../frontend/src/graph/useGraphDocument');
const { deleteItem, insertStepAfter, renameStep, setSettings } = await import('../../frontend/src/graph/edits');

function useFile(initial: string) {
  const [text, setText] = useState(initial);
  const doc = useGraphDocument('seq.graph', text, setText);
  return { text, setText, doc };
}

const onFirst = (change: (block: GraphBlock) => GraphBlock) => (blocks: readonly GraphBlock[]) =>
  blocks.map((block, index) => (index === 0 ? change(block) : block));

describe('useGraphDocument', () => {
  beforeEach(() => {
    reads.length = 0;
  });

  it('edits splice the text, undo to the start gives the original bytes, redo the edits again', async () => {
    const { result } = renderHook(() => useFile(g17.source));
    await waitFor(() => expect(result.current.doc.state.status).toBe('ready'));
    expect(result.current.doc.blocks).toEqual(g17.blocks);
    expect(result.current.doc.problems.map((p) => p.code)).toEqual(['GRA244']);
    expect(result.current.doc.places).toEqual(g17.places);
    expect(result.current.doc.canUndo).toBe(false);

    const texts = [g17.source];
    act(() => result.current.doc.edit(onFirst((block) => insertStepAfter(block, 0, { kind: 'step', name: 'A_on' }).block), 'insertStep'));
    texts.push(result.current.text);
    act(() => result.current.doc.edit(onFirst((block) => renameStep(block, 'B_on', 'Belt_B') ?? block), 'rename'));
    texts.push(result.current.text);
    act(() => result.current.doc.edit(onFirst((block) => deleteItem(block, 0, { kind: 'step', name: 'A_off' })?.block ?? block), 'delete'));
    texts.push(result.current.text);
    act(() => result.current.doc.edit(onFirst((block) => setSettings(block, { ...block.settings, skip_steps: true })), 'settings'));
    texts.push(result.current.text);
    expect(new Set(texts).size).toBe(5);
    // The file's header comment and the untouched items are kept as written.
    expect(result.current.text.startsWith(g17.source.slice(0, g17.source.indexOf('TITLE')))).toBe(true);
    expect(result.current.text).toContain('TRANSITION Trans1 (1) FROM Idle TO Emergency\nCOMMENT = priority 1: emergency first\nCONDITION Contact("Emergency") END_CONDITION');
    expect(result.current.text).toContain('SKIP_STEPS := TRUE;');
    expect(result.current.doc.pending).toBe(false);
    expect(result.current.doc.undoLabel).toBe('settings');

    for (let k = texts.length - 2; k >= 0; k -= 1) {
      act(() => result.current.doc.undo());
      expect(result.current.text).toBe(texts[k]);
    }
    expect(result.current.text).toBe(g17.source);
    expect(result.current.doc.blocks).toEqual(g17.blocks);
    expect(result.current.doc.canUndo).toBe(false);
    for (let k = 1; k < texts.length; k += 1) {
      act(() => result.current.doc.redo());
      expect(result.current.text).toBe(texts[k]);
    }
    expect(result.current.doc.canRedo).toBe(false);
    // Edits are not read back by the server as a model: the only reads are the first one and checks.
    expect(reads.filter((text) => text === g17.source).length).toBeGreaterThanOrEqual(1);
  });

  it('the checker looks at the edited text again, shortly after the edit', async () => {
    const { result } = renderHook(() => useFile(g17.source));
    await waitFor(() => expect(result.current.doc.state.status).toBe('ready'));
    act(() => result.current.doc.edit(onFirst((block) => insertStepAfter(block, 0, { kind: 'step', name: 'Idle' }).block), 'insertStep'));
    const edited = result.current.text;
    await waitFor(() => expect(result.current.doc.problems.map((p) => p.code)).toEqual(['GRA245']));
    expect(reads).toContain(edited);
    expect(result.current.doc.places).toEqual([{ BLOCK: 7 }]);
    expect(result.current.doc.blocks?.[0]?.sequencers[0]?.steps.map((s) => s.name)).toContain('Step7');
  });

  it('a text changed elsewhere is read again and is one undo step; a broken text is not drawn', async () => {
    const { result } = renderHook(() => useFile(g17.source));
    await waitFor(() => expect(result.current.doc.state.status).toBe('ready'));
    act(() => result.current.setText(g01.source));
    expect(result.current.doc.pending).toBe(true);
    // Edits wait while the model is older than the text.
    act(() => result.current.doc.edit(() => [], 'delete'));
    expect(result.current.text).toBe(g01.source);
    await waitFor(() => expect(result.current.doc.blocks).toEqual(g01.blocks));
    expect(result.current.doc.pending).toBe(false);
    expect(result.current.doc.undoLabel).toBe('text');
    act(() => result.current.doc.undo());
    expect(result.current.text).toBe(g17.source);
    expect(result.current.doc.blocks).toEqual(g17.blocks);

    act(() => result.current.setText('BROKEN'));
    await waitFor(() => expect(result.current.doc.state.status).toBe('unreadable'));
    const state = result.current.doc.state;
    expect(state.status === 'unreadable' && state.problems.map((p) => p.code)).toEqual(['GRA112']);
    expect(result.current.doc.pending).toBe(true);
  });
});

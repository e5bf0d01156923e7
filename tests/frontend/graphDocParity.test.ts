/**
 * The Graph document's text side against the Python reference, on every entry of
 * fixtures/graph-parity.json (the course's `.graph` sources and the checker's fixtures that read):
 * the TypeScript printer writes what `print_graph` writes, byte for byte, item by item; and an
 * edit of one step or transition of a hand-written source changes exactly that item's lines, the
 * way the generator spliced them and checked that the Python reader reads back the edited model.
 * The fixture is written by fixtures/make_graph_parity.py; a pytest fails when it is out of date.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import type { GraphBlock, Step, Transition } from '../../frontend/src/graph/model';
import { printGraph, stepLines, transitionLines } from '../../frontend/src/graph/print';
import { scanText, spliceText } from '../../frontend/src/graph/textEdit';

interface Edit {
  block: number;
  sequencer: number;
  kind: 'step' | 'transition';
  name: string;
  item: Step | Transition;
  start: number;
  end: number;
  lines: string[];
}

interface Entry {
  name: string;
  source: string;
  places: Record<string, number>[];
  blocks: GraphBlock[];
  text: string;
  items: { kind: 'step' | 'transition'; name: string; lines: string[] }[][][];
  edits: Edit[];
}

const fixture = JSON.parse(fs.readFileSync(path.join(__dirname, 'fixtures', 'graph-parity.json'), 'utf-8')) as { entries: Entry[] };
const entries = fixture.entries;

function withItem(blocks: readonly GraphBlock[], edit: Edit): GraphBlock[] {
  return blocks.map((block, b) =>
    b !== edit.block
      ? block
      : {
          ...block,
          sequencers: block.sequencers.map((sequencer, s) => {
            if (s !== edit.sequencer) return sequencer;
            if (edit.kind === 'step') return { ...sequencer, steps: sequencer.steps.map((step) => (step.name === edit.name ? (edit.item as Step) : step)) };
            return {
              ...sequencer,
              transitions: sequencer.transitions.map((t) => (t.name === edit.name ? (edit.item as Transition) : t)),
            };
          }),
        },
  );
}

describe('the Graph printer gives the Python text', () => {
  it('covers the course sources and the fixtures', () => {
    expect(entries.filter((entry) => entry.name.startsWith('tests/scenarios/graph/')).length).toBe(34);
    expect(entries.length).toBeGreaterThan(60);
  });

  it.each(entries.map((entry) => [entry.name, entry] as const))('%s', (_name, entry) => {
    expect(printGraph(entry.blocks)).toBe(entry.text);
    entry.blocks.forEach((block, b) =>
      block.sequencers.forEach((sequencer, s) => {
        const expected = entry.items[b]?.[s] ?? [];
        for (const item of expected) {
          const found =
            item.kind === 'step'
              ? stepLines(sequencer.steps.find((step) => step.name === item.name) as Step)
              : transitionLines(sequencer.transitions.find((t) => t.name === item.name) as Transition);
          expect(found).toEqual(item.lines);
        }
      }),
    );
  });
});

const files = entries.filter((entry) => !entry.name.startsWith('random #'));

describe('the scanner follows every printed text', () => {
  it.each(entries.map((entry) => [entry.name, entry] as const))('%s', (_name, entry) => {
    expect(scanText(entry.text, entry.blocks)).not.toBeNull();
  });
});

describe('splicing an edit into a printed text gives the printed text of the edited model', () => {
  it.each(entries.map((entry) => [entry.name, entry] as const))('%s', (_name, entry) => {
    entry.blocks.forEach((block, b) =>
      block.sequencers.forEach((sequencer, s) => {
        const items: Edit[] = [
          ...sequencer.steps.map((step) => ({ kind: 'step' as const, name: step.name, item: { ...step, comment: 'changed', initial: !step.initial } })),
          ...sequencer.transitions.map((t) => ({ kind: 'transition' as const, name: t.name, item: { ...t, comment: '', condition: null } })),
        ].map((edit) => ({ ...edit, block: b, sequencer: s, start: 0, end: 0, lines: [] }));
        for (const edit of items) {
          const after = withItem(entry.blocks, edit);
          expect(spliceText(entry.text, entry.blocks, after), `${edit.kind} ${edit.name}`).toBe(printGraph(after));
        }
      }),
    );
  });
});

describe('an edit of one item changes only its lines', () => {
  it.each(files.map((entry) => [entry.name, entry] as const))('%s', (_name, entry) => {
    expect(scanText(entry.source, entry.blocks)).not.toBeNull();
    expect(spliceText(entry.source, entry.blocks, [...entry.blocks])).toBe(entry.source);
    const items = entry.blocks.flatMap((block) => block.sequencers.flatMap((sequencer) => [...sequencer.steps, ...sequencer.transitions]));
    if (items.length > 0) expect(entry.edits.length).toBeGreaterThan(0);
    const lines = entry.source.split('\n');
    for (const edit of entry.edits) {
      const expected = [...lines.slice(0, edit.start), ...edit.lines, ...lines.slice(edit.end)].join('\n');
      expect(spliceText(entry.source, entry.blocks, withItem(entry.blocks, edit)), `${edit.kind} ${edit.name}`).toBe(expected);
    }
  });

  it('keeps Windows line ends (CRLF) in a spliced file', () => {
    for (const entry of files) {
      const crlf = entry.source.split('\n').join('\r\n');
      for (const edit of entry.edits) {
        const lines = entry.source.split('\n');
        const expected = [...lines.slice(0, edit.start), ...edit.lines, ...lines.slice(edit.end)].join('\r\n');
        expect(spliceText(crlf, entry.blocks, withItem(entry.blocks, edit)), `${entry.name} ${edit.name}`).toBe(expected);
      }
    }
  });

  it('prints the whole text when the structure is hidden in (* *) comments', () => {
    const entry = entries.find((e) => e.name.endsWith('g17_conveyors.graph')) as Entry;
    const source = entry.source.replace('END_STEP', 'END_STEP (* STEP Hidden (9)\nEND_STEP *)');
    const edit = entry.edits[0] as Edit;
    expect(spliceText(source, entry.blocks, withItem(entry.blocks, edit))).toBe(printGraph(withItem(entry.blocks, edit)));
  });
});

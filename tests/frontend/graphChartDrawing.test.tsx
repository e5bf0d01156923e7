/**
 * The S7-Graph chart as a user meets it (frontend/src/graph/GraphChart.tsx): the course's
 * two-conveyor sequence (g17) drawn once per step and transition with the test ids and roles the
 * e2e flows use, initial steps double, jumps labelled with their target, left to right on a
 * Persian page; the keyboard (arrows along the chart, S7-Graph's keys editing through the
 * document, F2's inline dialog); online, active and disturbed steps with their time, the
 * transitions' condition state and the FB's mode; the checker's findings on their items.
 */
import fs from 'node:fs';
import path from 'node:path';
import { fireEvent, render, screen, waitFor, within } from '@testing-library/react';
import { useState } from 'react';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it, vi } from 'vitest';
import type { GraphStatus } from '../../frontend/src/api/monitor';
import type { Diagnostic } from '../../frontend/src/api/types';
import { GraphChart } from '../../frontend/src/graph/GraphChart';
import { chartCommand } from '../../frontend/src/graph/chartKeys';
import { problemsByItem } from '../../frontend/src/graph/chartProblems';
import { conditionText } from '../../frontend/src/graph/chartGraph';
import type { GraphBlock } from '../../frontend/src/graph/model';
import type { GraphSelection } from '../../frontend/src/graph/selection';
import type { GraphDocument } from '../../frontend/src/graph/useGraphDocument';
import type { GraphMonitor } from '../../frontend/src/graph/useGraphMonitoring';
import { createI18n } from '../../frontend/src/i18n/setup';

const fixture = JSON.parse(fs.readFileSync(path.resolve(__dirname, 'fixtures/graph-chart.json'), 'utf8')) as { files: Record<string, GraphBlock[]> };
const g17 = fixture.files['g17_conveyors.graph']!;
const g02a = fixture.files['g02a_stop_and_jump.graph']!;

function fakeDoc(blocks: readonly GraphBlock[], extra: Partial<GraphDocument> = {}): GraphDocument {
  return {
    state: { status: 'ready' },
    blocks,
    problems: [],
    places: [],
    pending: false,
    edit: vi.fn(),
    undo: vi.fn(),
    redo: vi.fn(),
    canUndo: true,
    canRedo: false,
    retry: vi.fn(),
    ...extra,
  };
}

function monitorOf(status: GraphStatus | null): GraphMonitor {
  return { status, elements: new Map(), session: null, db: 'DB1', hold: null, problem: null };
}

function Harness({ doc, monitor = null, language = 'en', initial = null, onSelect }: { doc: GraphDocument; monitor?: GraphMonitor | null; language?: 'en' | 'fa'; initial?: GraphSelection['item']; onSelect?: (s: GraphSelection) => void }) {
  return <Stateful doc={doc} monitor={monitor} language={language} initial={initial} onSelect={onSelect} />;
}

const i18ns = { en: createI18n('en'), fa: createI18n('fa') };

function Stateful({ doc, monitor, language, initial, onSelect }: { doc: GraphDocument; monitor: GraphMonitor | null; language: 'en' | 'fa'; initial: GraphSelection['item']; onSelect?: (s: GraphSelection) => void }) {
  const [selection, setSelection] = useState<GraphSelection>({ block: 0, sequencer: 0, item: initial });
  return (
    <I18nextProvider i18n={i18ns[language]}>
      <GraphChart
        doc={doc}
        selection={selection}
        onSelect={(next) => {
          setSelection(next);
          onSelect?.(next);
        }}
        onOpenStep={(step) => onSelect?.({ block: -1, sequencer: -1, item: { kind: 'step', name: step } })}
        monitor={monitor}
        readOnly={false}
      />
    </I18nextProvider>
  );
}

async function drawn() {
  const chart = await screen.findByTestId('graph-chart');
  await waitFor(() => expect(chart.querySelector('svg')).not.toBeNull(), { timeout: 15_000 });
  return chart;
}

// elkjs compiles much of its code on its first layout: the first drawing may take a few seconds on a busy machine.
describe('the sequencer chart', { timeout: 20_000 }, () => {
  it('draws every step and transition of the two-conveyor sequence once, initial steps double, jumps with their target', async () => {
    render(<Harness doc={fakeDoc(g17)} />);
    const chart = await drawn();
    expect(chart.getAttribute('dir')).toBe('ltr');
    expect(chart.querySelector('svg')!.getAttribute('dir')).toBe('ltr');
    const seq = g17[0]!.sequencers[0]!;
    expect(screen.getByRole('tab', { name: seq.name }).getAttribute('aria-selected')).toBe('true');
    for (const step of seq.steps) {
      const drawnStep = screen.getAllByTestId(`graph-step-${step.number}`);
      expect(drawnStep).toHaveLength(1);
      expect(drawnStep[0]!.getAttribute('data-initial')).toBe(String(step.initial));
      expect(drawnStep[0]!.getAttribute('data-state')).toBe('inactive');
      expect(drawnStep[0]!.querySelectorAll('rect')).toHaveLength(step.initial ? 2 : 1);
    }
    for (const transition of seq.transitions) {
      expect(screen.getAllByTestId(`graph-transition-${transition.number}`)).toHaveLength(1);
      const jump = screen.queryByTestId(`graph-jump-${transition.number}`);
      if (transition.jump) {
        const target = seq.steps.find((s) => s.name === transition.target[0])!;
        expect(jump?.textContent).toBe(`→ S${target.number} ${target.name}`);
      } else expect(jump).toBeNull();
    }
    // Conditions are written beside their bars.
    const trans2 = seq.transitions.find((t) => t.number === 2)!;
    expect(screen.getByTestId('graph-transition-2').textContent).toContain(conditionText(trans2.condition).slice(0, 10));
    // Edges for every non-jump target and every source; alternative lines where Idle opens three ways.
    expect(chart.querySelectorAll('[data-branch="alternative"]').length).toBeGreaterThan(0);
    expect(screen.getByRole('toolbar')).toBeTruthy();
  });

  it('stays left to right on a Persian page while its toolbar follows the page', async () => {
    render(<Harness doc={fakeDoc(g02a)} language="fa" />);
    const chart = await drawn();
    expect(chart.getAttribute('dir')).toBe('ltr');
    expect(screen.getByRole('toolbar').getAttribute('dir')).toBe('rtl');
    expect(screen.getByTestId('graph-insert-step').textContent).toBe('گام + گذار');
    expect(screen.getByTestId('graph-jump-6').textContent).toBe('→ S1 Step1');
  });

  it('moves the selection along the chart with the arrows and opens the step view with Enter', async () => {
    const selected = vi.fn();
    render(<Harness doc={fakeDoc(g02a)} onSelect={selected} />);
    const chart = await drawn();
    chart.focus();
    fireEvent.keyDown(chart, { key: 'ArrowDown' });
    await waitFor(() => expect(screen.getByTestId('graph-step-1').getAttribute('aria-selected')).toBe('true'));
    fireEvent.keyDown(chart, { key: 'ArrowDown' });
    await waitFor(() => expect(screen.getByTestId('graph-step-1').getAttribute('aria-selected')).toBe('false'));
    const transition = screen.getAllByRole('option').find((o) => o.getAttribute('aria-selected') === 'true')!;
    expect(transition.getAttribute('data-testid')).toMatch(/^graph-transition-/);
    fireEvent.keyDown(chart, { key: 'Enter' });
    // Enter on a transition opens its source step.
    expect(selected).toHaveBeenLastCalledWith({ block: -1, sequencer: -1, item: { kind: 'step', name: 'Step1' } });
    fireEvent.click(screen.getByTestId('graph-step-2'));
    expect(screen.getByTestId('graph-step-2').getAttribute('aria-selected')).toBe('true');
    fireEvent.doubleClick(screen.getByTestId('graph-step-2'));
    expect(selected).toHaveBeenLastCalledWith({ block: -1, sequencer: -1, item: { kind: 'step', name: 'Step2' } });
  });

  it('edits through the document: Insert, Ctrl+Z, the toolbar, and refuses what the edits refuse', async () => {
    const doc = fakeDoc(g02a);
    render(<Harness doc={doc} initial={{ kind: 'step', name: 'Step2' }} />);
    const chart = await drawn();
    expect((screen.getByTestId('graph-insert-simultaneous') as HTMLButtonElement).disabled).toBe(true);
    expect((screen.getByTestId('graph-insert-alternative') as HTMLButtonElement).disabled).toBe(false);
    fireEvent.keyDown(chart, { key: 'Insert' });
    expect(doc.edit).toHaveBeenCalledTimes(1);
    const [change, label] = (doc.edit as ReturnType<typeof vi.fn>).mock.calls[0]!;
    expect(label).toBe('insert step');
    const after = (change as (b: readonly GraphBlock[]) => readonly GraphBlock[])(g02a);
    expect(after[0]!.sequencers[0]!.steps.length).toBe(g02a[0]!.sequencers[0]!.steps.length + 1);
    fireEvent.keyDown(chart, { key: 'z', code: 'KeyZ', ctrlKey: true });
    expect(doc.undo).toHaveBeenCalledTimes(1);
    fireEvent.click(screen.getByTestId('graph-undo'));
    expect(doc.undo).toHaveBeenCalledTimes(2);
    expect((screen.getByTestId('graph-redo') as HTMLButtonElement).disabled).toBe(true);
  });

  it('renames and renumbers in the inline dialog of F2, and says why a taken number is refused', async () => {
    const doc = fakeDoc(g02a);
    render(<Harness doc={doc} initial={{ kind: 'step', name: 'Step2' }} />);
    const chart = await drawn();
    fireEvent.keyDown(chart, { key: 'F2' });
    const dialog = await screen.findByRole('dialog', { name: 'Rename the step' });
    const number = within(dialog).getByTestId('graph-rename-number') as HTMLInputElement;
    expect((within(dialog).getByTestId('graph-rename-name') as HTMLInputElement).value).toBe('Step2');
    expect(number.value).toBe('2');
    fireEvent.change(number, { target: { value: '3' } });
    fireEvent.click(within(dialog).getByTestId('graph-rename-ok'));
    expect(within(dialog).getByRole('alert').textContent).toContain('3');
    expect(doc.edit).not.toHaveBeenCalled();
    fireEvent.change(number, { target: { value: '12' } });
    fireEvent.change(within(dialog).getByTestId('graph-rename-name'), { target: { value: 'Filling' } });
    fireEvent.click(within(dialog).getByTestId('graph-rename-ok'));
    expect(screen.queryByRole('dialog')).toBeNull();
    const [change] = (doc.edit as ReturnType<typeof vi.fn>).mock.calls[0]!;
    const renamed = (change as (b: readonly GraphBlock[]) => readonly GraphBlock[])(g02a)[0]!.sequencers[0]!;
    expect(renamed.steps.find((s) => s.name === 'Filling')?.number).toBe(12);
    expect(renamed.transitions.find((t) => t.number === 14)?.source).toEqual(['Filling']);
  });

  it('shows online: active and disturbed steps with their time, the transitions state, the mode and error flags', async () => {
    const status: GraphStatus = {
      db: 'DB1',
      at: 0,
      mode: 'AUTO',
      steps: [
        { number: 1, name: 'Step1', state: 'inactive', t_ms: 0, u_ms: 0, interlock_error: false, supervision_error: false },
        { number: 2, name: 'Step2', state: 'active', t_ms: 1500, u_ms: 1500, interlock_error: false, supervision_error: false },
        { number: 3, name: 'Step3', state: 'disturbed', t_ms: 12500, u_ms: 2000, interlock_error: false, supervision_error: true },
      ],
      transitions: [
        { number: 1, name: 'Trans1', tt: false },
        { number: 14, name: 'Trans14', tt: true },
      ],
    };
    render(<Harness doc={fakeDoc(g02a)} monitor={monitorOf(status)} />);
    await drawn();
    expect(screen.getByTestId('graph-step-2').getAttribute('data-state')).toBe('active');
    expect(screen.getByTestId('graph-step-3').getAttribute('data-state')).toBe('disturbed');
    expect(screen.getByTestId('graph-step-time-2').textContent).toBe('1.5 s');
    expect(screen.getByTestId('graph-step-time-3').textContent).toBe('12 s');
    expect(screen.queryByTestId('graph-step-time-1')).toBeNull();
    expect(screen.getByTestId('graph-transition-14').getAttribute('data-tt')).toBe('true');
    expect(screen.getByTestId('graph-transition-14').getAttribute('class')).toContain('pf-on');
    expect(screen.getByTestId('graph-transition-1').getAttribute('data-tt')).toBe('false');
    const mode = screen.getByTestId('graph-monitor-mode');
    expect(mode.getAttribute('data-mode')).toBe('AUTO');
    expect(mode.textContent).toContain('Mode AUTO');
    expect(mode.textContent).toContain('Supervision error');
  });

  it('marks the steps and transitions the checker found problems in, with the finding as tooltip', async () => {
    const problem: Diagnostic = { code: 'GRA299', severity: 'warning', key: 'no_such_key_here', message: 'Something about step 3', params: {}, span: { line: 41 } };
    const places = [{ BLOCK: 6, 'SEQ:SEQ': 10, S1: 12, T1: 20, S3: 40, 'S3/A1': 41, T6: 50 }];
    expect(problemsByItem([problem], places, 0).get('S3')).toEqual([problem]);
    render(<Harness doc={fakeDoc(g02a, { problems: [problem], places })} />);
    await drawn();
    const step = screen.getByTestId('graph-step-3');
    expect(step.getAttribute('class')).toContain('graph-step--warning');
    expect(step.querySelector('title')!.textContent).toContain('GRA299 Something about step 3');
    expect(screen.getByTestId('graph-step-2').getAttribute('class')).not.toContain('problem');
  });

  it('leaves notes (severity info) to the problems panel and marks errors apart from warnings', async () => {
    const note: Diagnostic = { code: 'GRA244', severity: 'info', key: 'x', message: 'Step2 has no actions', params: {}, span: { line: 30 } };
    const error: Diagnostic = { code: 'GRA203', severity: 'error', key: 'y', message: 'No such step', params: {}, span: { line: 50 } };
    const places = [{ BLOCK: 6, S1: 12, T1: 20, S2: 30, S3: 40, T6: 50 }];
    render(<Harness doc={fakeDoc(g02a, { problems: [note, error], places })} />);
    await drawn();
    expect(screen.getByTestId('graph-step-2').getAttribute('class')).not.toMatch(/warning|problem/);
    expect(screen.getByTestId('graph-transition-6').getAttribute('class')).toContain('graph-transition--problem');
  });
});

describe('the chart keys', () => {
  it('are S7-Graph shortcuts, Alt+letter in any keyboard layout', () => {
    const key = (k: string, more: Partial<{ code: string; altKey: boolean; ctrlKey: boolean; shiftKey: boolean }> = {}) =>
      chartCommand({ key: k, altKey: false, ctrlKey: false, metaKey: false, shiftKey: false, ...more });
    expect(key('Insert')).toBe('insertStep');
    expect(key('ش', { code: 'KeyA', altKey: true })).toBe('alternative');
    expect(key('s', { code: 'KeyS', altKey: true })).toBe('simultaneous');
    expect(key('j', { code: 'KeyJ', altKey: true })).toBe('jump');
    expect(key('e', { code: 'KeyE', altKey: true })).toBe('end');
    expect(key('Delete')).toBe('delete');
    expect(key('F2')).toBe('rename');
    expect(key('Enter')).toBe('open');
    expect(key('z', { ctrlKey: true })).toBe('undo');
    expect(key('y', { ctrlKey: true })).toBe('redo');
    expect(key('Z', { ctrlKey: true, shiftKey: true })).toBe('redo');
    expect(key('ArrowLeft', { altKey: true })).toBe('moveLeft');
    expect(key('ArrowDown')).toBeNull();
    expect(key('a')).toBeNull();
  });
});

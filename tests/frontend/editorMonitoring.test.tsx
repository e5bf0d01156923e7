/**
 * Monitoring and debugging in the source editor, with the fake Monaco and a fake socket: the
 * glyph-margin breakpoints and their dialog, the STL status columns and the SCL inline values of
 * the block at the caret, the held line, and the monitoring toggle.
 */
import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect, useState } from 'react';
import { I18nextProvider } from 'react-i18next';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { BlockStatus, HoldState } from '../../frontend/src/api/monitor';
import type { Problem } from '../../frontend/src/api/monitorClient';
import { CpuToolbar } from '../../frontend/src/cpu/CpuToolbar';
import { SessionProvider } from '../../frontend/src/cpu/SessionContext';
import { EditorTabsProvider } from '../../frontend/src/editor/EditorTabsContext';
import { EditorMonitoring } from '../../frontend/src/editor/monitoring/EditorMonitoring';
import { MonitorToggle } from '../../frontend/src/editor/monitoring/MonitorToggle';
import { breakpoints } from '../../frontend/src/editor/monitoring/breakpointStore';
import type { MonacoApi } from '../../frontend/src/editor/monaco/load';
import type { Language } from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';
import { BottomPanel } from '../../frontend/src/panels/BottomPanel';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { projectContents } from '../../frontend/src/projects/projectContents';
import { FakeEditor, FakeModel, loadMonaco } from './fakeMonaco';
import { json, mockServer } from './helpers';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

const OB1 = Array.from({ length: 60 }, (_, k) => (k === 0 ? 'ORGANIZATION_BLOCK OB 1' : `      A     M ${k}.0;`)).join('\n');
const SCALE = `FUNCTION "Scale" : REAL
VAR_INPUT
  Raw : INT;
END_VAR
BEGIN
  Scale := INT_TO_REAL(Raw) / 276.48;
END_FUNCTION`;

const SESSION = { id: 's1', blocks: ['OB1', 'FC10'], cpu: cpuState(), clients: [], websocket: '/api/sessions/s1/ws' };
const BLOCKS = {
  blocks: [
    { kind: 'OB', number: 1, name: 'Main', title: '', language: 'stl', file: 'OB1.awl', line: 1 },
    { kind: 'FC', number: 10, name: 'Scale', title: '', language: 'scl', file: 'Scale.scl', line: 1 },
  ],
  diagnostics: [],
};

let sockets: FakeSocket[] = [];
const socket = () => sockets[sockets.length - 1]!;
const messages = (type: string) => socket().sent.filter((message) => message.type === type);

function ChooseProject() {
  const { setProjectId } = useActiveProject();
  useEffect(() => setProjectId(1), [setProjectId]);
  return null;
}

interface HarnessProps {
  editor: FakeEditor;
  monaco: MonacoApi;
  file: string;
  language: 'stl' | 'scl';
}

/** One editor with its monitoring, the toggle, the CPU toolbar and the bottom panel. */
function Harness({ editor, monaco, file, language }: HarnessProps) {
  const [on, setOn] = useState(false);
  const [problem, setProblem] = useState<Problem | null>(null);
  return (
    <>
      <CpuToolbar />
      <EditorMonitoring
        editor={editor as never}
        monaco={monaco}
        projectId={1}
        file={file}
        language={language}
        monitoring={on}
        lineHeight={20}
        onProblem={setProblem}
      />
      <MonitorToggle on={on} onChange={setOn} projectId={1} problem={problem} />
      <BottomPanel />
    </>
  );
}

async function setup({ file = 'OB1.awl', language = 'stl' as 'stl' | 'scl', ui = 'en' as Language } = {}) {
  const monaco = (await loadMonaco()) as unknown as MonacoApi;
  const editor = new FakeEditor(document.createElement('div'), { model: new FakeModel(file === 'OB1.awl' ? OB1 : SCALE, language) });
  const user = userEvent.setup();
  const view = render(
    <I18nextProvider i18n={createI18n(ui)}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <ChooseProject />
          <SessionProvider>
            <Harness editor={editor} monaco={monaco} file={file} language={language} />
          </SessionProvider>
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return { editor, user, ...view };
}

async function connect(user: ReturnType<typeof userEvent.setup>) {
  await user.click(screen.getByTestId('cpu-download'));
  await waitFor(() => expect(sockets).toHaveLength(1));
  act(() => {
    socket().open();
    socket().receive(hello());
    socket().receive(frame({ seq: 1, cpu: cpuState({ mode: 'RUN' }) }));
  });
}

const glyphs = (editor: FakeEditor) => editor.decorations().filter((d) => d.options.glyphMarginClassName !== undefined && String(d.options.glyphMarginClassName).includes('nasaq-bp'));

beforeEach(() => {
  sockets = [];
  localStorage.clear();
  breakpoints.clear();
  projectContents.clear();
  vi.stubGlobal(
    'WebSocket',
    class extends FakeSocket {
      constructor(url: string) {
        super(url);
        sockets.push(this);
      }
    },
  );
  mockServer({
    'POST /api/projects/1/sessions': () => json(SESSION, 201),
    'GET /api/projects/1/files': () => json([]),
    'GET /api/projects/1/blocks': () => json(BLOCKS),
    'GET /api/sessions/s1/diagnostics': () => json([]),
    'DELETE /api/sessions/s1': () => new Response(null, { status: 204 }),
  });
});

afterEach(() => {
  vi.useRealTimers();
});

describe('breakpoints in the glyph margin', () => {
  it('toggles with a click and F9, shows red dots, and keeps the server in step', async () => {
    const { editor, user } = await setup();
    expect(editor.options.glyphMargin).toBe(true);
    act(() => editor.clickGlyph(9));
    expect(breakpoints.ofFile(1, 'OB1.awl').map((bp) => bp.line)).toEqual([9]);
    expect(glyphs(editor).map((d) => [d.range.startLineNumber, d.options.glyphMarginClassName])).toEqual([[9, 'nasaq-bp']]);

    await connect(user);
    expect(messages('set_breakpoint')).toEqual([expect.objectContaining({ location: { file: 'OB1.awl', line: 9 }, condition: null })]);
    act(() => socket().ackAll({ set_breakpoint: { id: 7 } }));

    act(() => {
      editor.moveCaret(12);
      editor.runAction('nasaq.toggleBreakpoint');
    });
    expect(glyphs(editor).map((d) => d.range.startLineNumber)).toEqual([9, 12]);
    await waitFor(() => expect(messages('set_breakpoint')).toHaveLength(2));

    act(() => editor.clickGlyph(9));
    expect(glyphs(editor).map((d) => d.range.startLineNumber)).toEqual([12]);
    await waitFor(() => expect(messages('clear_breakpoint')).toEqual([expect.objectContaining({ id: 7 })]));
    // A click elsewhere than the glyph margin does nothing.
    expect(editor.actions.get('nasaq.toggleBreakpoint')?.keybindings).toEqual([67]);
  });

  it('edits a condition in a dialog; a refused line offers the next line with code, in Persian', async () => {
    const { editor, user } = await setup({ ui: 'fa' });
    await connect(user);
    act(() => editor.clickGlyph(3, true));
    const dialog = await screen.findByTestId('breakpoint-dialog');
    expect(dialog.closest('.code-editor')).toBeNull();
    await user.type(within(dialog).getByTestId('breakpoint-condition'), 'MW 10 > 5');
    await user.click(within(dialog).getByTestId('breakpoint-save'));
    const set = messages('set_breakpoint').at(-1)!;
    expect(set).toMatchObject({ location: { file: 'OB1.awl', line: 3 }, condition: 'MW 10 > 5' });
    act(() =>
      socket().receive({
        type: 'error',
        ref: set.ref as number,
        code: 'MON604',
        key: 'mon_no_code_here',
        message: 'OB1.awl line 3 has no code',
        params: { where: 'OB1.awl line 3', hint: ' (the next line with code is 5)' },
      }),
    );
    const error = await within(dialog).findByTestId('breakpoint-error');
    expect(error.textContent).toContain('MON604');
    expect(error.textContent).toContain('کد'); // the Persian text of the catalogue
    // Grey and hollow: conditional, refused.
    expect(glyphs(editor)[0]!.options.glyphMarginClassName).toBe('nasaq-bp nasaq-bp--conditional nasaq-bp--refused');

    await user.click(within(dialog).getByTestId('breakpoint-move'));
    const moved = messages('set_breakpoint').at(-1)!;
    expect(moved).toMatchObject({ location: { file: 'OB1.awl', line: 5 }, condition: 'MW 10 > 5' });
    act(() => socket().receive({ type: 'ack', ref: moved.ref as number, result: { id: 2 } }));
    await waitFor(() => expect(screen.queryByTestId('breakpoint-dialog')).toBeNull());
    expect(breakpoints.ofFile(1, 'OB1.awl')).toEqual([{ projectId: 1, file: 'OB1.awl', line: 5, condition: 'MW 10 > 5', enabled: true }]);
    expect(glyphs(editor)[0]!.options.glyphMarginClassName).toBe('nasaq-bp nasaq-bp--conditional');
  });

  it('removes a breakpoint from its dialog, and saves without a session', async () => {
    const { editor, user } = await setup();
    act(() => editor.clickGlyph(4));
    act(() => {
      editor.moveCaret(4);
      editor.runAction('nasaq.editBreakpointCondition');
    });
    const dialog = await screen.findByTestId('breakpoint-dialog');
    await user.click(within(dialog).getByTestId('breakpoint-enabled'));
    await user.click(within(dialog).getByTestId('breakpoint-save'));
    expect(screen.queryByTestId('breakpoint-dialog')).toBeNull();
    expect(breakpoints.find(1, 'OB1.awl', 4)?.enabled).toBe(false);
    expect(glyphs(editor)[0]!.options.glyphMarginClassName).toBe('nasaq-bp nasaq-bp--disabled');
    act(() => editor.clickGlyph(4, true));
    await user.click(within(await screen.findByTestId('breakpoint-dialog')).getByTestId('breakpoint-remove'));
    expect(breakpoints.list()).toEqual([]);
    expect(glyphs(editor)).toEqual([]);
  });
});

const stlStatus = (lines: number[], scan = 5): BlockStatus => ({
  block: 'OB1',
  language: 'stl',
  elements: [],
  graph: null,
  scan,
  instructions: lines.map((line, index) => ({
    index,
    line,
    rlo: line % 2,
    sta: 1,
    accu1: line,
    accu2: 0,
    stw: 0b110,
    ar1: 0,
    ar2: 0,
    operand: null,
  })),
  lines: [],
});

describe('monitoring the block at the caret', () => {
  it('opens the block, draws the STL status of the visible lines, and closes it when switched off', async () => {
    const { editor, user } = await setup();
    const toggle = screen.getByTestId('monitor-toggle');
    expect(toggle.getAttribute('aria-pressed')).toBe('false');
    await user.click(toggle);
    expect(toggle.getAttribute('aria-pressed')).toBe('true');
    expect(screen.getByText('Download the project to monitor it')).toBeTruthy();
    await connect(user);
    await waitFor(() => expect(messages('open_block')).toEqual([expect.objectContaining({ block: 'OB1' })]));
    act(() => socket().ackAll());

    const body = await screen.findByTestId('stl-status-body');
    expect(screen.getByTestId('stl-status-head-accu1').textContent).toBe('STANDARD');
    act(() => socket().receive(frame({ seq: 2, block: stlStatus([2, 3, 30, 45]) })));
    await waitFor(() => expect(body.dataset.rows).toBe('2'));
    const rows = () => [...body.querySelectorAll<HTMLElement>('.stl-status__row:not([hidden])')];
    expect(rows().map((row) => row.dataset.line)).toEqual(['2', '3']);
    expect(rows()[1]!.textContent).toBe('1130000000110');
    expect(screen.getByTestId('stl-status-bar').textContent).toContain('scan 5');

    // Scrolled down: the rows of the lines now in view, in the same elements.
    const first = rows()[0];
    act(() => editor.scrollTo(20 * 25));
    await waitFor(() => expect(rows().map((row) => row.dataset.line)).toEqual(['30', '45']));
    expect(rows()[0]).toBe(first);
    expect(rows()[0]!.style.transform).toBe('translateY(80px)');

    // Hexadecimal on request.
    await user.click(screen.getByTestId('stl-status-format'));
    await waitFor(() => expect(rows()[0]!.querySelector('[data-column="accu1"]')!.textContent).toBe('16#0000_001E'));

    await user.click(toggle);
    expect(screen.queryByTestId('stl-status')).toBeNull();
    expect(messages('open_block').at(-1)).toMatchObject({ block: null });
  });

  it('says when the block is not in the downloaded program', async () => {
    const { user } = await setup();
    await connect(user);
    await user.click(screen.getByTestId('monitor-toggle'));
    await waitFor(() => expect(messages('open_block')).toHaveLength(1));
    act(() =>
      socket().receive({
        type: 'error',
        ref: messages('open_block')[0]!.ref as number,
        code: 'MON613',
        key: 'mon_unknown_block',
        message: 'OB1 is not a code block of the downloaded program.',
        params: { block: 'OB1' },
      }),
    );
    expect((await screen.findByTestId('monitor-problem')).textContent).toContain('MON613');
  });

  it('shows the values of an SCL line after it, at most a few times a second, and clears them', async () => {
    const { editor, user } = await setup({ file: 'Scale.scl', language: 'scl' });
    await connect(user);
    await user.click(screen.getByTestId('monitor-toggle'));
    await waitFor(() => expect(messages('open_block')).toEqual([expect.objectContaining({ block: 'FC10' })]));
    const inline = () => editor.decorations().filter((d) => d.options.after !== undefined);
    act(() =>
      socket().receive(
        frame({ seq: 2, block: { block: 'FC10', language: 'scl', elements: [], graph: null, scan: 3, instructions: [], lines: [{ line: 6, values: { Raw: 13824, Scale: 50 } }] } }),
      ),
    );
    await waitFor(() => expect(inline()).toHaveLength(1));
    expect(inline()[0]!.range).toMatchObject({ startLineNumber: 6, startColumn: SCALE.split('\n')[5]!.length + 1 });
    expect((inline()[0]!.options.after as { content: string }).content).toBe('\u2003Raw = 13824  Scale = 50');
    // Frames in quick succession: one update after the interval, with the newest values.
    const collection = editor.decorationCollections.find((c) => c.items.some((d) => d.options.after !== undefined))!;
    const before = collection.sets;
    act(() => {
      for (let k = 0; k < 10; k += 1) {
        socket().receive(
          frame({ seq: 10 + k, block: { block: 'FC10', language: 'scl', elements: [], graph: null, scan: 4 + k, instructions: [], lines: [{ line: 6, values: { Raw: k } }] } }),
        );
      }
    });
    expect(collection.sets).toBe(before);
    await waitFor(() => expect((inline()[0]!.options.after as { content: string }).content).toBe('\u2003Raw = 9'));
    expect(collection.sets).toBe(before + 1);
    // A frame of another block is not shown.
    act(() => socket().receive(frame({ seq: 3, block: { block: 'OB1', language: 'stl', elements: [], graph: null, scan: 4, instructions: [], lines: [] } })));
    await waitFor(() => expect(inline()).toHaveLength(0));
    await user.click(screen.getByTestId('monitor-toggle'));
    expect(inline()).toHaveLength(0);
  });
});

const HOLD: HoldState = {
  reason: 'breakpoint',
  breakpoint: 1,
  location: { block: 'OB1', instruction: 3, line: 9, file: 'OB1.awl', network: 1 },
  registers: { accu1: 42, accu2: 0, ar1: 0, ar2: 0, stw: 3, rlo: 1, sta: 1 },
  locals: [{ name: 'count', type: 'INT', value: 3 }],
  call_stack: [{ block: 'OB1', instruction: 3, line: 9, file: 'OB1.awl', network: 1 }],
  graph_step: null,
  graph_block: null,
};

describe('a hold', () => {
  it('highlights the held line, brings the call stack forward, and clears when released', async () => {
    const { editor, user } = await setup();
    await connect(user);
    expect(screen.getByTestId('panel-tab-debug').getAttribute('aria-selected')).toBe('false');
    act(() => socket().receive(frame({ seq: 2, cpu: cpuState({ mode: 'HOLD' }), hold: HOLD })));
    const held = () => editor.decorations().filter((d) => d.options.className === 'nasaq-hold-line');
    expect(held().map((d) => [d.range.startLineNumber, d.options.isWholeLine, d.options.glyphMarginClassName])).toEqual([
      [9, true, 'nasaq-hold-arrow'],
    ]);
    expect(editor.revealed).toContain(9);
    expect(screen.getByTestId('panel-tab-debug').getAttribute('aria-selected')).toBe('true');
    expect(screen.getByTestId('debug-local-count').textContent).toContain('3');
    act(() => socket().receive(frame({ seq: 3, cpu: cpuState({ mode: 'RUN' }), released: true })));
    expect(held()).toEqual([]);
    expect(screen.getByTestId('debug-panel').dataset.holding).toBe('false');
  });
});

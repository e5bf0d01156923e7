/**
 * The S7-Graph Control Sequencer over a real SessionProvider, a fake server (fetch) and a fake
 * socket: the FB is opened on the session, its mode shows pressed, every button sends the
 * `graph_control` message the protocol wants to the instance DB of the status, a refused command
 * is shown translated, the step breakpoint is set and cleared, the hold says which step is about
 * to become active, single step and continue go out; without a session everything is disabled.
 */
import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect, useState } from 'react';
import { I18nextProvider } from 'react-i18next';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { BlockStatus, GraphStatus, HoldState } from '../../frontend/src/api/monitor';
import { CpuToolbar } from '../../frontend/src/cpu/CpuToolbar';
import { SessionProvider } from '../../frontend/src/cpu/SessionContext';
import { EditorTabsProvider } from '../../frontend/src/editor/EditorTabsContext';
import { useBreakpointSync } from '../../frontend/src/editor/monitoring/useBreakpointSync';
import { ControlSequencer } from '../../frontend/src/graph/ControlSequencer';
import type { GraphBlock, Step } from '../../frontend/src/graph/model';
import type { GraphSelection } from '../../frontend/src/graph/selection';
import { stepBreakpoints } from '../../frontend/src/graph/stepBreakpoints';
import { useGraphMonitoring, type GraphMonitor } from '../../frontend/src/graph/useGraphMonitoring';
import type { Language } from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { json, mockServer } from './helpers';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

const SESSION = { id: 's1', blocks: ['OB1', 'FB1'], cpu: cpuState(), clients: [], websocket: '/api/sessions/s1/ws' };

const step = (number: number, name: string, initial = false): Step => ({
  number,
  name,
  initial,
  comment: '',
  interlock: null,
  supervision: null,
  actions: [],
});

const BLOCK: GraphBlock = {
  name: 'FB 1',
  title: '',
  comment: '',
  settings: { parameters: 'STANDARD', skip_steps: false, acknowledge_required: true, interlock_blocks: false },
  declarations: '',
  pre: [],
  post: [],
  sequencers: [
    {
      name: 'SEQ1',
      comment: '',
      steps: [step(1, 'Idle', true), step(2, 'Fill'), step(3, 'Drain')],
      transitions: [
        { number: 1, name: 'Trans1', comment: '', source: ['Idle'], target: ['Fill'], jump: false, condition: null },
        { number: 2, name: 'Trans2', comment: '', source: ['Fill'], target: ['Drain'], jump: false, condition: null },
        { number: 3, name: 'Trans3', comment: '', source: ['Drain'], target: ['Idle'], jump: true, condition: null },
      ],
    },
  ],
};

function graphStatus(overrides: Partial<GraphStatus> = {}, active = 'Fill', disturbed: 'interlock' | 'supervision' | null = null): GraphStatus {
  return {
    db: 'DB1',
    at: 0,
    mode: 'AUTO',
    steps: BLOCK.sequencers[0]!.steps.map((s) => ({
      number: s.number,
      name: s.name,
      state: s.name === active ? (disturbed ? 'disturbed' : 'active') : 'inactive',
      t_ms: s.name === active ? 1500 : 0,
      u_ms: s.name === active ? 1500 : 0,
      interlock_error: s.name === active && disturbed === 'interlock',
      supervision_error: s.name === active && disturbed === 'supervision',
    })),
    transitions: [1, 2, 3].map((n) => ({ number: n, name: `Trans${n}`, tt: false })),
    ...overrides,
  };
}

function blockStatus(graph: GraphStatus | null): BlockStatus {
  return { block: 'FB1', language: 'graph', scan: 5, instructions: [], lines: [], elements: [], graph };
}

function graphHold(stepNumber: number): HoldState {
  return {
    reason: 'breakpoint',
    breakpoint: 4,
    location: { block: 'FB1', instruction: 120, line: null, file: 'Seq.graph', network: null },
    registers: {},
    locals: [],
    call_stack: [],
    graph_step: stepNumber,
    graph_block: 'FB1',
  };
}

let sockets: FakeSocket[] = [];
const socket = () => sockets[sockets.length - 1]!;
const text = (element: Element) => element.textContent ?? '';
const sent = (type: string) => socket().sent.filter((message) => message.type === type);
let monitorSeen: GraphMonitor | null = null;

function ChooseProject() {
  const { setProjectId } = useActiveProject();
  useEffect(() => setProjectId(1), [setProjectId]);
  return null;
}

function Harness({ selection, monitoring = true }: { selection: GraphSelection; monitoring?: boolean }) {
  const monitor = useGraphMonitoring({ enabled: monitoring, projectId: 1, file: 'Seq.graph', block: BLOCK.name });
  monitorSeen = monitor;
  useBreakpointSync();
  const [open, setOpen] = useState(true);
  return (
    <>
      <CpuToolbar />
      <button type="button" onClick={() => setOpen(true)}>
        reopen
      </button>
      <ControlSequencer open={open} onClose={() => setOpen(false)} monitor={monitor} selection={selection} block={BLOCK} />
    </>
  );
}

function setup(
  language: Language = 'en',
  selection: GraphSelection = { block: 0, sequencer: 0, item: { kind: 'step', name: 'Fill' } },
  monitoring = true,
) {
  const user = userEvent.setup();
  const i18n = createI18n(language);
  const tree = (chosen: GraphSelection) => (
    <I18nextProvider i18n={i18n}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <ChooseProject />
          <SessionProvider>
            <Harness selection={chosen} monitoring={monitoring} />
          </SessionProvider>
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>
  );
  const view = render(tree(selection));
  return { user, select: (chosen: GraphSelection) => view.rerender(tree(chosen)), ...view };
}

/** Downloads, connects, and lets the FB's status arrive (the DB is known from it). */
async function connect(user: ReturnType<typeof userEvent.setup>, status: GraphStatus | null = graphStatus()) {
  await user.click(screen.getByTestId('cpu-download'));
  await waitFor(() => expect(sockets).toHaveLength(1));
  act(() => {
    socket().open();
    socket().receive(hello());
    socket().receive(frame({ seq: 1, cpu: cpuState({ mode: 'RUN' }) }));
  });
  await waitFor(() => expect(sent('open_block')).toEqual([expect.objectContaining({ block: 'FB1', networks: null })]));
  act(() => socket().ackAll({ open_block: { block: 'FB1', language: 'graph', instructions: 300 } }));
  if (status) act(() => socket().receive(frame({ seq: 2, block: blockStatus(status) })));
}

beforeEach(() => {
  sockets = [];
  monitorSeen = null;
  localStorage.clear();
  for (const bp of [...stepBreakpoints.list()]) stepBreakpoints.toggle(bp);
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
    'GET /api/sessions/s1/diagnostics': () => json([]),
    'DELETE /api/sessions/s1': () => new Response(null, { status: 204 }),
  });
});

describe('the Control Sequencer', () => {
  it('is disabled, saying why, while no session runs', () => {
    setup();
    const dialog = screen.getByRole('dialog', { name: /Control Sequencer/ });
    expect((dialog).getAttribute('aria-modal')).toBe('false');
    expect(text(within(dialog).getByTestId('graph-control-why'))).toContain('No simulation runs');
    for (const id of ['graph-mode-auto', 'graph-mode-man', 'graph-ack', 'graph-step-on', 'graph-push', 'graph-init', 'graph-off', 'graph-single-step']) {
      expect(within(dialog).getByTestId(id).matches(':disabled')).toBe(true);
    }
  });

  it('shows the mode and the error flags, and sends every command to the instance DB', async () => {
    const { user } = setup();
    await connect(user, graphStatus({}, 'Fill', 'supervision'));
    const status = screen.getByTestId('graph-control-status');
    expect(text(status)).toContain('Mode: AUTO');
    expect(text(status)).toContain('Supervision error in Fill');
    expect((screen.getByTestId('graph-mode-auto')).getAttribute('aria-pressed')).toBe('true');
    expect((screen.getByTestId('graph-mode-man')).getAttribute('aria-pressed')).toBe('false');
    expect(screen.queryByTestId('graph-control-why')).toBeNull();
    expect(monitorSeen?.db).toBe('DB1');

    await user.click(screen.getByTestId('graph-ack'));
    await user.click(screen.getByTestId('graph-mode-man'));
    // The step number starts as the selected step's (Fill is step 2).
    expect((screen.getByTestId('graph-step-number') as HTMLInputElement).value).toBe('2');
    await user.click(screen.getByTestId('graph-step-on'));
    await user.clear(screen.getByTestId('graph-step-number'));
    await user.type(screen.getByTestId('graph-step-number'), '3');
    await user.click(screen.getByTestId('graph-step-off'));
    await user.click(screen.getByTestId('graph-mode-tap'));
    await user.click(screen.getByTestId('graph-push'));
    await user.click(screen.getByTestId('graph-init'));
    await user.click(screen.getByTestId('graph-off'));
    await user.click(screen.getByTestId('graph-mode-top'));
    await user.click(screen.getByTestId('graph-mode-auto'));
    expect(sent('graph_control').map(({ ref: _ref, ...message }) => message)).toEqual([
      { type: 'graph_control', db: 'DB1', op: 'ack' },
      { type: 'graph_control', db: 'DB1', op: 'man' },
      { type: 'graph_control', db: 'DB1', op: 'step_on', step: 2 },
      { type: 'graph_control', db: 'DB1', op: 'step_off', step: 3 },
      { type: 'graph_control', db: 'DB1', op: 'tap' },
      { type: 'graph_control', db: 'DB1', op: 'push' },
      { type: 'graph_control', db: 'DB1', op: 'init' },
      { type: 'graph_control', db: 'DB1', op: 'off' },
      { type: 'graph_control', db: 'DB1', op: 'top' },
      { type: 'graph_control', db: 'DB1', op: 'auto' },
    ]);

    // The next status says MAN: MAN is pressed, the flags are gone.
    act(() => socket().receive(frame({ seq: 3, block: blockStatus(graphStatus({ mode: 'MAN' })) })));
    expect((screen.getByTestId('graph-mode-man')).getAttribute('aria-pressed')).toBe('true');
    expect((screen.getByTestId('graph-mode-auto')).getAttribute('aria-pressed')).toBe('false');
    expect(text(screen.getByTestId('graph-control-status'))).toContain('No errors');
    expect(text(screen.getByTestId('graph-control-status'))).toContain('Active: Fill');
  });

  it('takes the step number from the selection until the user types one', async () => {
    const { user, select } = setup('en', { block: 0, sequencer: 0, item: { kind: 'transition', name: 'Trans3' } });
    await connect(user);
    const input = () => screen.getByTestId('graph-step-number') as HTMLInputElement;
    // A transition selected: its source step (Drain, 3).
    expect(input().value).toBe('3');
    select({ block: 0, sequencer: 0, item: { kind: 'step', name: 'Idle' } });
    expect(input().value).toBe('1');
    expect(text(screen.getByTestId('graph-break-step'))).toContain('Break when Idle becomes active');
    // A number no step has is marked (the server would refuse it with MON619).
    await user.clear(input());
    await user.type(input(), '9');
    expect(input().getAttribute('aria-invalid')).toBe('true');
  });

  it('shows a refused command in the interface language (Persian), and the interlock check box', async () => {
    const { user } = setup('fa');
    await connect(user);
    expect((screen.getByRole('dialog')).getAttribute('dir')).toBe('rtl');
    await user.click(screen.getByTestId('graph-step-on'));
    const [message] = sent('graph_control');
    act(() =>
      socket().receive({
        type: 'error',
        ref: message!.ref as number,
        code: 'MON621',
        key: 'mon_graph_not_manual',
        message: 'Steps are switched on and off by hand only in MAN mode; DB1 is in AUTO mode. Select MAN first.',
        params: { db: 'DB1', mode: 'AUTO' },
      }),
    );
    const alert = await screen.findByTestId('graph-control-error');
    expect(text(alert)).toContain('MON621');
    expect(text(alert)).toContain('ابتدا MAN را انتخاب کنید');

    // The check boxes show the DB's own flags (watched) and switch them.
    await waitFor(() => expect(sent('watch').at(-1)).toMatchObject({ entries: ['DB1.G7_IL_OFF', 'DB1.G7_SV_OFF'] }));
    act(() => socket().receive(frame({ seq: 3, watch: { 'DB1.G7_IL_OFF': { value: true, forced: false, error: null } } })));
    const interlock = screen.getByTestId('graph-check-interlock');
    expect((interlock as HTMLInputElement).checked).toBe(false);
    await user.click(interlock);
    expect(sent('graph_control').at(-1)).toMatchObject({ db: 'DB1', op: 'interlock_on' });
    // A new command clears the old error.
    expect(screen.queryByTestId('graph-control-error')).toBeNull();
  });

  it('sets a breakpoint on the selected step, shows the hold, steps by transition and continues', async () => {
    const { user } = setup();
    await connect(user);
    const toggle = screen.getByTestId('graph-break-step');
    expect(text(toggle)).toContain('Break when Fill becomes active');
    expect((toggle).getAttribute('aria-pressed')).toBe('false');
    expect(screen.getByTestId('graph-continue').matches(':disabled')).toBe(true);
    await user.click(toggle);
    await waitFor(() => expect(sent('set_breakpoint')).toEqual([expect.objectContaining({ location: { block: 'FB1', step: 2 }, condition: null })]));
    act(() => socket().ackAll({ set_breakpoint: { id: 4 } }));
    expect((toggle).getAttribute('aria-pressed')).toBe('true');

    act(() => socket().receive(frame({ seq: 3, cpu: cpuState({ mode: 'HOLD' }), hold: graphHold(2) })));
    expect(text(screen.getByTestId('graph-control-held'))).toContain('Held: Fill is about to become active');
    expect((screen.getByTestId('graph-control-status')).getAttribute('data-held')).toBe('2');

    await user.click(screen.getByTestId('graph-single-step'));
    expect(sent('step').map(({ ref: _ref, ...message }) => message)).toEqual([{ type: 'step', by: 'transition' }]);
    act(() => socket().receive(frame({ seq: 4, hold: graphHold(3) })));
    expect(text(screen.getByTestId('graph-control-held'))).toContain('Held: Drain is about to become active');
    // A hold at a step of another Graph FB says which.
    act(() => socket().receive(frame({ seq: 5, hold: { ...graphHold(7), graph_block: 'FB2' } })));
    expect(text(screen.getByTestId('graph-control-held'))).toContain('Held: step 7 of FB2 is about to become active');
    await user.click(screen.getByTestId('graph-continue'));
    expect(sent('continue')).toHaveLength(1);
    act(() => socket().receive(frame({ seq: 6, released: true, cpu: cpuState({ mode: 'RUN' }) })));
    expect(screen.queryByTestId('graph-control-held')).toBeNull();

    // Off again: the server's breakpoint is cleared.
    await user.click(toggle);
    await waitFor(() => expect(sent('clear_breakpoint')).toEqual([expect.objectContaining({ id: 4 })]));
    expect((toggle).getAttribute('aria-pressed')).toBe('false');
  });

  it('asks to switch monitoring on when a session runs but the chart is not monitored', async () => {
    const { user } = setup('en', undefined, false);
    await user.click(screen.getByTestId('cpu-download'));
    await waitFor(() => expect(sockets).toHaveLength(1));
    act(() => {
      socket().open();
      socket().receive(hello());
    });
    await waitFor(() => expect(text(screen.getByTestId('graph-control-why'))).toContain('Monitoring is off'));
    expect(screen.getByTestId('graph-ack').matches(':disabled')).toBe(true);
    expect(sent('open_block')).toEqual([]);
  });

  it('says the FB has not been called yet when no status came, and closes with Escape', async () => {
    const { user } = setup();
    await connect(user, null);
    expect(text(screen.getByTestId('graph-control-why'))).toContain('Waiting for FB 1');
    expect(screen.getByTestId('graph-mode-auto').matches(':disabled')).toBe(true);
    // Single step works without the DB (it acts on the CPU).
    expect(screen.getByTestId('graph-single-step').matches(':disabled')).toBe(false);
    screen.getByRole('dialog').focus();
    await user.keyboard('{Escape}');
    expect(screen.queryByRole('dialog')).toBeNull();
  });
});

/**
 * useGraphMonitoring over a real SessionProvider and a fake socket: the FB is opened on the
 * session while monitoring is on and closed after; the sequencer status, the elements by origin
 * id, the instance DB and the hold come from the frames; a frame that changes nothing does not
 * re-render, and a changed step or element is the only new object (a 200-step chart redraws one
 * step, not all of them).
 */
import { act, render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect, useState } from 'react';
import { I18nextProvider } from 'react-i18next';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { BlockStatus, ElementStatus, GraphStatus } from '../../frontend/src/api/monitor';
import { CpuToolbar } from '../../frontend/src/cpu/CpuToolbar';
import { SessionProvider } from '../../frontend/src/cpu/SessionContext';
import { EditorTabsProvider } from '../../frontend/src/editor/EditorTabsContext';
import { adoptSessionBreakpoints } from '../../frontend/src/cpu/reattach';
import { createStepBreakpointStore, stepRequestsFor, STEP_BREAKPOINTS_STORAGE_KEY } from '../../frontend/src/graph/stepBreakpoints';
import { foldElements, foldGraphStatus, useGraphMonitoring, type GraphMonitor } from '../../frontend/src/graph/useGraphMonitoring';
import { createI18n } from '../../frontend/src/i18n/setup';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { json, mockServer } from './helpers';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

const SESSION = { id: 's1', blocks: ['OB1', 'FB1'], cpu: cpuState(), clients: [], websocket: '/api/sessions/s1/ws' };
const STEPS = 200;

function sequencer(active: number, time = 100, mode: GraphStatus['mode'] = 'AUTO'): GraphStatus {
  return {
    db: 'DB1',
    at: 0,
    mode,
    steps: Array.from({ length: STEPS }, (_, k) => ({
      number: k + 1,
      name: `Step${k + 1}`,
      state: k + 1 === active ? 'active' : 'inactive',
      t_ms: k + 1 === active ? time : 0,
      u_ms: k + 1 === active ? time : 0,
      interlock_error: false,
      supervision_error: false,
    })),
    transitions: Array.from({ length: STEPS }, (_, k) => ({ number: k + 1, name: `Trans${k + 1}`, tt: k + 1 === active })),
  };
}

const element = (id: string, value: boolean | number | null, out: boolean | null = null): ElementStatus => ({ network: 0, id, value, out, pins: {} });

function status(graph: GraphStatus, elements: ElementStatus[] = []): BlockStatus {
  return { block: 'FB1', language: 'graph', scan: 1, instructions: [], lines: [], elements, graph };
}

let sockets: FakeSocket[] = [];
const socket = () => sockets[sockets.length - 1]!;
const sent = (type: string) => socket().sent.filter((message) => message.type === type);
let seen: GraphMonitor[] = [];
const last = () => seen[seen.length - 1]!;

function ChooseProject() {
  const { setProjectId } = useActiveProject();
  useEffect(() => setProjectId(1), [setProjectId]);
  return null;
}

function Probe() {
  const [on, setOn] = useState(true);
  const monitor = useGraphMonitoring({ enabled: on, projectId: 1, file: 'Seq.graph', block: 'FB 1' });
  seen.push(monitor);
  return (
    <button type="button" data-testid="toggle" onClick={() => setOn((value) => !value)}>
      {on ? 'on' : 'off'}
    </button>
  );
}

async function setup() {
  const user = userEvent.setup();
  render(
    <I18nextProvider i18n={createI18n('en')}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <ChooseProject />
          <SessionProvider>
            <CpuToolbar />
            <Probe />
          </SessionProvider>
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  await user.click(screen.getByTestId('cpu-download'));
  await waitFor(() => expect(sockets).toHaveLength(1));
  act(() => {
    socket().open();
    socket().receive(hello());
    socket().receive(frame({ seq: 1, cpu: cpuState({ mode: 'RUN' }) }));
  });
  await waitFor(() => expect(sent('open_block')).toEqual([expect.objectContaining({ block: 'FB1', networks: null })]));
  return { user };
}

beforeEach(() => {
  sockets = [];
  seen = [];
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

describe('useGraphMonitoring', () => {
  it('brings the sequencer, the elements by origin, the DB and the hold; closes the FB when off', async () => {
    const { user } = await setup();
    expect(last().session?.id).toBe('s1');
    expect(last().status).toBeNull();
    act(() => socket().ackAll({ open_block: { block: 'FB1', language: 'graph', instructions: 900 } }));
    act(() =>
      socket().receive(frame({ seq: 2, block: status(sequencer(2), [element('T2/e1', true), element('S2/A1', true), element('S2/C/e1', false), element('PRE1/e2', 7)]) })),
    );
    expect(last().db).toBe('DB1');
    expect(last().status?.mode).toBe('AUTO');
    expect(last().status?.steps[1]).toMatchObject({ name: 'Step2', state: 'active', t_ms: 100 });
    expect([...last().elements.keys()]).toEqual(['T2/e1', 'S2/A1', 'S2/C/e1', 'PRE1/e2']);
    expect(last().elements.get('PRE1/e2')?.value).toBe(7);

    const hold = {
      reason: 'step' as const,
      breakpoint: null,
      location: { block: 'FB1', instruction: 40, line: null, file: 'Seq.graph', network: null },
      registers: {},
      locals: [],
      call_stack: [],
      graph_step: 3,
      graph_block: 'FB1',
    };
    act(() => socket().receive(frame({ seq: 3, hold })));
    expect(last().hold?.graph_step).toBe(3);
    // A frame of another block (a LAD editor of another tab took the open block) is not this FB's.
    act(() => socket().receive(frame({ seq: 4, block: { ...status(sequencer(5)), block: 'FC3', language: 'lad', graph: null } })));
    expect(last().status).toBeNull();
    expect(last().db).toBe('DB1');

    await user.click(screen.getByTestId('toggle'));
    await waitFor(() => expect(sent('open_block').at(-1)).toMatchObject({ block: null }));
    expect(last().status).toBeNull();
    expect(last().session).toBeNull();
    expect(last().hold).toBeNull();
  });

  it('does not re-render for a frame that changes nothing, and keeps unchanged steps and elements', async () => {
    await setup();
    act(() => socket().ackAll({ open_block: { block: 'FB1', language: 'graph', instructions: 900 } }));
    act(() => socket().receive(frame({ seq: 2, block: status(sequencer(2, 100), [element('T2/e1', true), element('T3/e1', false)]) })));
    const first = last();
    const renders = seen.length;
    // The same content again (new objects from the socket): no render at all.
    act(() => socket().receive(frame({ seq: 3, block: status(sequencer(2, 100), [element('T2/e1', true), element('T3/e1', false)]) })));
    expect(seen.length).toBe(renders);

    // The active step's time and one element changed: only those are new objects.
    act(() => socket().receive(frame({ seq: 4, block: status(sequencer(2, 200), [element('T2/e1', true), element('T3/e1', true)]) })));
    const next = last();
    expect(next.status).not.toBe(first.status);
    expect(next.status!.steps[1]).not.toBe(first.status!.steps[1]);
    const kept = next.status!.steps.filter((step, k) => step === first.status!.steps[k]).length;
    expect(kept).toBe(STEPS - 1);
    // No transition changed: the same array.
    expect(next.status!.transitions).toBe(first.status!.transitions);
    expect(next.elements.get('T2/e1')).toBe(first.elements.get('T2/e1'));
    expect(next.elements.get('T3/e1')).not.toBe(first.elements.get('T3/e1'));
    expect(next.session).toBe(first.session);
  });

  it('reports a refused command as the problem, and a new one clears it', async () => {
    await setup();
    act(() => socket().ackAll({ open_block: { block: 'FB1', language: 'graph', instructions: 900 } }));
    act(() => last().session!.send({ type: 'graph_control', db: 'DB9', op: 'auto' }));
    const message = sent('graph_control')[0]!;
    expect(message).toMatchObject({ type: 'graph_control', db: 'DB9', op: 'auto' });
    act(() =>
      socket().receive({ type: 'error', ref: message.ref as number, code: 'MON617', key: 'mon_graph_unknown_db', message: 'DB9 is not a data block of the downloaded program.', params: { db: 'DB9' } }),
    );
    await waitFor(() => expect(last().problem?.code).toBe('MON617'));
    act(() => last().session!.send({ type: 'graph_control', db: 'DB1', op: 'auto' }));
    expect(last().problem).toBeNull();
  });
});

describe('folding a new status into the previous one', () => {
  it('returns the previous objects when nothing changed', () => {
    const a = sequencer(4);
    expect(foldGraphStatus(a, sequencer(4))).toBe(a);
    expect(foldGraphStatus(a, sequencer(4, 100, 'MAN'))).not.toBe(a);
    expect(foldGraphStatus(a, null)).toBeNull();
    const elements = foldElements(new Map(), [element('T1/e1', true)]);
    expect(foldElements(elements, [element('T1/e1', true)])).toBe(elements);
    expect(foldElements(elements, [element('T1/e1', false)]).get('T1/e1')?.value).toBe(false);
    expect(foldElements(elements, []).size).toBe(0);
    // An element of a numbered network (not a Graph origin) keeps its network in the key.
    expect([...foldElements(new Map(), [{ ...element('e1', true), network: 2 }]).keys()]).toEqual(['2/e1']);
  });
});

describe('step breakpoints', () => {
  it('are kept in the browser, sent as Location.step, and adopted from a session a page attaches to', () => {
    const storage = new Map<string, string>();
    const backing = { getItem: (key: string) => storage.get(key) ?? null, setItem: (key: string, value: string) => void storage.set(key, value) };
    const store = createStepBreakpointStore(backing);
    store.toggle({ projectId: 1, block: 'FB1', step: 2 });
    expect(stepRequestsFor(store.list(), 1)).toEqual([{ key: '1:FB1@step2', location: { block: 'FB1', step: 2 }, condition: null }]);
    expect(stepRequestsFor(store.list(), 2)).toEqual([]);
    // A reload reads them back.
    expect(createStepBreakpointStore(backing).list()).toEqual([{ projectId: 1, block: 'FB1', step: 2 }]);
    expect(JSON.parse(storage.get(STEP_BREAKPOINTS_STORAGE_KEY)!)).toHaveLength(1);

    // The session lists one this browser does not know (set in another tab): it is added.
    const lines = { find: vi.fn(), put: vi.fn() };
    adoptSessionBreakpoints(lines, 1, [{ id: 9, location: { block: 'FB1', step: 4 }, condition: null, block: 'FB1', file: 'Seq.graph' }], store);
    expect(lines.put).not.toHaveBeenCalled();
    expect(store.list().map((bp) => bp.step)).toEqual([2, 4]);
    store.toggle({ projectId: 1, block: 'FB1', step: 2 });
    expect(store.list().map((bp) => bp.step)).toEqual([4]);
  });
});

/**
 * The session's WebSocket client against a fake socket: frames merged into one state, acks and
 * errors matched to their commands by ref, subscriptions sent again after a reconnect with
 * backoff, and a session the server closed or does not know ends the client.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { DiagnosticEntry } from '../../frontend/src/api/monitor';
import {
  MonitorClient,
  MonitorCommandError,
  initialMonitorState,
  mergeDiagnosticHistory,
  mergeFrame,
  socketUrl,
} from '../../frontend/src/api/monitorClient';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

let sockets: FakeSocket[] = [];

function makeClient(options: Partial<ConstructorParameters<typeof MonitorClient>[0]> = {}) {
  const client = new MonitorClient({
    url: 'ws://nasaq.test/api/sessions/s1/ws',
    createSocket: (url) => {
      const socket = new FakeSocket(url);
      sockets.push(socket);
      return socket;
    },
    initialDelayMs: 100,
    maxDelayMs: 400,
    ...options,
  });
  client.connect();
  return client;
}

const last = () => sockets[sockets.length - 1]!;

beforeEach(() => {
  sockets = [];
});

afterEach(() => {
  vi.useRealTimers();
});

describe('mergeFrame', () => {
  it('keeps what a null field leaves unchanged and merges watch values by entry', () => {
    let state = initialMonitorState();
    state = mergeFrame(state, frame({ seq: 1, cpu: cpuState({ scans: 1 }), watch: { MW10: { value: 5, forced: false, error: null } } }));
    state = mergeFrame(state, frame({ seq: 2, watch: { Q4: { value: true, forced: true, error: null } } }));
    expect(state.seq).toBe(2);
    expect(state.cpu?.scans).toBe(1);
    expect(state.watch).toEqual({
      MW10: { value: 5, forced: false, error: null },
      Q4: { value: true, forced: true, error: null },
    });
  });

  it('appends trend samples and diagnostic entries, and ends a hold on released', () => {
    const entry: DiagnosticEntry = { time_ms: 10, code: 'SIM501', message: 'watchdog', block: 'OB1', network: 1, line: 3, key: '', params: {} };
    const hold = {
      reason: 'step' as const,
      breakpoint: null,
      location: { block: 'OB1', instruction: 0, line: 3, file: 'OB1.awl', network: 1 },
      registers: { ACCU1: 1 },
      locals: [],
      call_stack: [],
      graph_step: null,
      graph_block: null,
    };
    let state = initialMonitorState();
    state = mergeFrame(state, frame({ seq: 1, trend: [{ scan: 1, time_ms: 10, values: [true] }], hold }));
    state = mergeFrame(state, frame({ seq: 2, trend: [{ scan: 2, time_ms: 20, values: [false] }], diagnostics: [entry] }));
    expect(state.trend.map((sample) => sample.scan)).toEqual([1, 2]);
    expect(state.hold).toEqual(hold);
    expect(state.diagnostics).toEqual([entry]);
    state = mergeFrame(state, frame({ seq: 3, released: true }));
    expect(state.hold).toBeNull();
    expect(state.released).toBe(true);
  });

  it('merges the diagnostic history with what frames brought meanwhile, each entry once', () => {
    const a: DiagnosticEntry = { time_ms: 1, code: 'SIM527', message: 'a', block: null, network: null, line: null, key: '', params: {} };
    const b: DiagnosticEntry = { ...a, time_ms: 2, message: 'b' };
    expect(mergeDiagnosticHistory([a], [a, b])).toEqual([a, b]);
  });
});

describe('MonitorClient', () => {
  it('uses the page host for the socket', () => {
    expect(socketUrl('/api/sessions/x/ws', { protocol: 'https:', host: 'plc.school:8443' })).toBe(
      'wss://plc.school:8443/api/sessions/x/ws',
    );
    expect(socketUrl('/api/sessions/x/ws', { protocol: 'http:', host: '127.0.0.1:8000' })).toBe(
      'ws://127.0.0.1:8000/api/sessions/x/ws',
    );
  });

  it('subscribes to the CPU on hello and merges frames into its state', () => {
    const client = makeClient();
    const seen: number[] = [];
    client.subscribe(() => seen.push(client.getState().seq));
    expect(client.getState().connection).toBe('connecting');
    last().open();
    last().receive(hello(7));
    expect(client.getState().connection).toBe('open');
    expect(client.getState().hello?.client).toBe(7);
    // The CPU state, and what the session keeps for a page that attaches (breakpoints, trend).
    expect(last().sentTypes()).toEqual(['subscribe_cpu', 'session_state']);
    last().receive(frame({ seq: 4, cpu: cpuState({ mode: 'RUN', scans: 12 }) }));
    expect(client.getState().cpu?.mode).toBe('RUN');
    expect(client.getState().cpu?.scans).toBe(12);
    expect(seen.at(-1)).toBe(4);
  });

  it('resolves a command with its ack and rejects another with its error, matched by ref', async () => {
    const client = makeClient();
    last().open();
    last().receive(hello());
    const run = client.send({ type: 'run' });
    const force = client.send({ type: 'force', address: 'M0.0', value: true });
    const [runRef, forceRef] = last().sent.slice(-2).map((message) => message.ref as number);
    expect(runRef).not.toBe(forceRef);
    // Answers may come in any order; the ref decides.
    last().receive({
      type: 'error',
      ref: forceRef,
      code: 'MON603',
      key: 'mon_unknown_target',
      message: 'M0.0: only inputs and outputs (I, Q) can be forced',
      params: { target: 'M0.0', reason: 'only inputs and outputs (I, Q) can be forced' },
    });
    last().receive({ type: 'ack', ref: runRef, result: null });
    await expect(run).resolves.toBeNull();
    const error = await force.catch((caught: unknown) => caught);
    expect(error).toBeInstanceOf(MonitorCommandError);
    expect(error).toMatchObject({ code: 'MON603', key: 'mon_unknown_target', params: { target: 'M0.0' } });
  });

  it('rejects a command while not connected, and the unanswered ones when the socket drops', async () => {
    const client = makeClient();
    await expect(client.send({ type: 'run' })).rejects.toMatchObject({ code: 'NET000', key: 'server_unreachable' });
    last().open();
    last().receive(hello());
    const waiting = client.send({ type: 'stop' });
    last().drop(1006);
    await expect(waiting).rejects.toMatchObject({ code: 'NET000' });
  });

  it('sends the union of every panel’s watch entries once per tick, and keeps the ack’s report', async () => {
    const client = makeClient();
    last().open();
    last().receive(hello());
    client.setWatch('io', ['PIB0', 'QB4']);
    client.setWatch('table', ['QB4', '"Motor"']);
    await Promise.resolve();
    const watches = last().sent.filter((message) => message.type === 'watch');
    expect(watches).toHaveLength(1);
    expect(watches[0]!.entries).toEqual(['PIB0', 'QB4', '"Motor"']);
    last().receive({
      type: 'ack',
      ref: watches[0]!.ref as number,
      result: { entries: [{ entry: 'PIB0', type: 'BYTE' }, { entry: 'QB4', type: 'BYTE' }, { entry: '"Motor"', type: 'BOOL' }] },
    });
    await Promise.resolve();
    expect(client.getState().watchReports['"Motor"']).toEqual({ entry: '"Motor"', type: 'BOOL' });
    // The same union again sends nothing; a panel leaving changes it.
    client.setWatch('table', ['QB4', '"Motor"']);
    await Promise.resolve();
    expect(last().sent.filter((message) => message.type === 'watch')).toHaveLength(1);
    client.setWatch('io', []);
    await Promise.resolve();
    expect(last().sent.filter((message) => message.type === 'watch').at(-1)!.entries).toEqual(['QB4', '"Motor"']);
  });

  it('reconnects with a growing delay and sends its subscriptions again', async () => {
    vi.useFakeTimers();
    const client = makeClient();
    last().open();
    last().receive(hello(1));
    client.setWatch('table', ['MW10']);
    await Promise.resolve();
    void client.setTrend(['MW10']).catch(() => undefined);
    void client.openBlock('OB1').catch(() => undefined);

    last().drop(1006);
    expect(client.getState().connection).toBe('reconnecting');
    expect(sockets).toHaveLength(1);
    vi.advanceTimersByTime(99);
    expect(sockets).toHaveLength(1);
    vi.advanceTimersByTime(1);
    expect(sockets).toHaveLength(2);
    // The second try fails too: twice the delay.
    last().drop(1006);
    vi.advanceTimersByTime(199);
    expect(sockets).toHaveLength(2);
    vi.advanceTimersByTime(1);
    expect(sockets).toHaveLength(3);

    last().open();
    last().receive(hello(2));
    await Promise.resolve();
    expect(client.getState().connection).toBe('open');
    expect(client.getState().hello?.client).toBe(2);
    expect(last().sentTypes().sort()).toEqual(['open_block', 'session_state', 'subscribe_cpu', 'trend', 'watch']);
    expect(last().sent.find((message) => message.type === 'watch')!.entries).toEqual(['MW10']);

    // A success resets the backoff.
    last().drop(1006);
    vi.advanceTimersByTime(100);
    expect(sockets).toHaveLength(4);
    client.close();
  });

  it('ends when the server closes the session (MON614), and when it does not know it', () => {
    vi.useFakeTimers();
    const client = makeClient();
    last().open();
    last().receive(hello());
    last().receive({ type: 'error', ref: null, code: 'MON614', key: 'mon_session_closed', message: 'closed', params: {} });
    expect(client.getState().connection).toBe('closed');
    expect(client.getState().closedBy?.code).toBe('MON614');
    vi.advanceTimersByTime(60_000);
    expect(sockets).toHaveLength(1);

    const other = makeClient();
    last().drop(1008); // refused before its hello: no such session
    expect(other.getState().connection).toBe('closed');
    expect(other.getState().closedBy).toMatchObject({ code: 'MON609', params: { id: 's1' } });
    vi.advanceTimersByTime(60_000);
    expect(sockets).toHaveLength(2);
  });

  it('loads the diagnostic history after connecting', async () => {
    const entry: DiagnosticEntry = { time_ms: 5, code: 'SIM527', message: 'stop in hold', block: 'OB1', network: null, line: 2, key: '', params: {} };
    const client = makeClient({ loadDiagnostics: async () => [entry] });
    last().open();
    last().receive(hello());
    await vi.waitFor(() => expect(client.getState().diagnostics).toEqual([entry]));
  });

  it('starts the trend afresh and forgets the old program’s state after a download', async () => {
    const client = makeClient();
    last().open();
    last().receive(hello());
    const started = client.setTrend(['"Motor"']);
    const trend = last().sent.find((message) => message.type === 'trend')!;
    last().receive({ type: 'ack', ref: trend.ref as number, result: { entries: [{ entry: '"Motor"', type: 'BOOL' }] } });
    await started;
    expect(client.getState().trendTypes).toEqual(['BOOL']);
    last().receive(frame({ seq: 1, trend: [{ scan: 1, time_ms: 10, values: [true] }] }));
    expect(client.getState().trend).toHaveLength(1);
    client.programReplaced();
    expect(client.getState().trend).toHaveLength(0);
    expect(last().sentTypes().filter((type) => type === 'trend')).toHaveLength(2);
  });
});

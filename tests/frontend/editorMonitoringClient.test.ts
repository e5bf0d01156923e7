/**
 * The monitoring client's breakpoint registry against a fake socket: the editor's breakpoints are
 * set when the session connects, cleared when removed, set again after a reconnect and after a
 * download, and the server's refusals are kept per breakpoint.
 */
import { beforeEach, describe, expect, it } from 'vitest';
import { MonitorClient, type BreakpointRequest } from '../../frontend/src/api/monitorClient';
import { FakeSocket, hello } from './monitorFakes';

let sockets: FakeSocket[] = [];
const last = () => sockets[sockets.length - 1]!;
const flush = () => new Promise((resolve) => setTimeout(resolve, 0));

function connected(): MonitorClient {
  const client = new MonitorClient({
    url: 'ws://nasaq.test/api/sessions/s1/ws',
    createSocket: (url) => {
      const socket = new FakeSocket(url);
      sockets.push(socket);
      return socket;
    },
    initialDelayMs: 1,
    maxDelayMs: 1,
  });
  client.connect();
  last().open();
  last().receive(hello());
  return client;
}

const bp = (line: number, condition: string | null = null): BreakpointRequest => ({
  key: `1:Scale.scl:${line}`,
  location: { file: 'Scale.scl', line },
  condition,
});

const sentOf = (type: string, socket = last()) => socket.sent.filter((message) => message.type === type);

function answer(socket: FakeSocket, ref: number, result: Record<string, unknown>) {
  socket.receive({ type: 'ack', ref, result });
}

beforeEach(() => {
  sockets = [];
});

describe('breakpoints in the monitoring client', () => {
  it('sets each breakpoint once, reports its id, and clears it when it is removed', async () => {
    const client = connected();
    client.setBreakpoints([bp(17), bp(20, '#Raw > 100')]);
    const sets = sentOf('set_breakpoint');
    expect(sets.map((message) => [message.location, message.condition])).toEqual([
      [{ file: 'Scale.scl', line: 17 }, null],
      [{ file: 'Scale.scl', line: 20 }, '#Raw > 100'],
    ]);
    expect(client.getState().breakpoints['1:Scale.scl:17']).toEqual({ state: 'pending', id: null, problem: null });
    answer(last(), sets[0]!.ref as number, { id: 4 });
    answer(last(), sets[1]!.ref as number, { id: 5 });
    await flush();
    expect(client.getState().breakpoints['1:Scale.scl:17']).toEqual({ state: 'set', id: 4, problem: null });

    // The same list again sends nothing; one removed is cleared by its id.
    client.setBreakpoints([bp(17), bp(20, '#Raw > 100')]);
    expect(sentOf('set_breakpoint')).toHaveLength(2);
    client.setBreakpoints([bp(20, '#Raw > 100')]);
    expect(sentOf('clear_breakpoint').map((message) => message.id)).toEqual([4]);
    expect(client.getState().breakpoints['1:Scale.scl:17']).toBeUndefined();

    // A changed condition: cleared and set again.
    client.setBreakpoints([bp(20, '#Raw > 200')]);
    expect(sentOf('clear_breakpoint').map((message) => message.id)).toEqual([4, 5]);
    expect(sentOf('set_breakpoint').at(-1)?.condition).toBe('#Raw > 200');
  });

  it('keeps the refusal of a breakpoint with its code and params', async () => {
    const client = connected();
    client.setBreakpoints([bp(3)]);
    const ref = sentOf('set_breakpoint')[0]!.ref as number;
    last().receive({
      type: 'error',
      ref,
      code: 'MON604',
      key: 'mon_no_code_here',
      message: 'Scale.scl line 3 has no code',
      params: { where: 'Scale.scl line 3', hint: ' (the next line with code is 17)' },
    });
    await flush();
    const report = client.getState().breakpoints['1:Scale.scl:3'];
    expect(report?.state).toBe('refused');
    expect(report?.problem?.code).toBe('MON604');
    expect(report?.problem?.params.hint).toContain('17');
  });

  it('clears a breakpoint the server set after it was already removed', async () => {
    const client = connected();
    client.setBreakpoints([bp(17)]);
    const ref = sentOf('set_breakpoint')[0]!.ref as number;
    client.setBreakpoints([]);
    expect(sentOf('clear_breakpoint')).toHaveLength(0); // no id yet
    answer(last(), ref, { id: 9 });
    await flush();
    expect(sentOf('clear_breakpoint').map((message) => message.id)).toEqual([9]);
    expect(client.getState().breakpoints).toEqual({});
  });

  it('waits for the connection, and sets them all again after a reconnect and a download', async () => {
    const client = new MonitorClient({
      url: 'ws://nasaq.test/api/sessions/s1/ws',
      createSocket: (url) => {
        const socket = new FakeSocket(url);
        sockets.push(socket);
        return socket;
      },
      initialDelayMs: 1,
      maxDelayMs: 1,
    });
    client.connect();
    client.setBreakpoints([bp(17)]);
    expect(last().sent).toHaveLength(0);
    last().open();
    last().receive(hello());
    expect(sentOf('set_breakpoint')).toHaveLength(1);
    expect(sentOf('clear_breakpoint')).toHaveLength(0); // nothing of ours can be set yet

    answer(last(), sentOf('set_breakpoint')[0]!.ref as number, { id: 4 });
    await flush();
    client.setBreakpoints([bp(17), bp(20)]);
    answer(last(), sentOf('set_breakpoint')[1]!.ref as number, { id: 5 });
    await flush();

    last().drop(1006);
    // Line 20's breakpoint is removed while the connection is down.
    client.setBreakpoints([bp(17)]);
    await new Promise((resolve) => setTimeout(resolve, 5));
    expect(sockets).toHaveLength(2);
    last().open();
    last().receive(hello());
    // The session kept what the old socket set: ours are set again (the server answers with the
    // ids they have), nothing is cleared before the session says what it holds.
    expect(last().sentTypes().filter((type) => type.endsWith('breakpoint'))).toEqual(['set_breakpoint']);
    const state = sentOf('session_state')[0]!.ref as number;
    answer(last(), state, {
      breakpoints: [
        { id: 4, location: { file: 'Scale.scl', line: 17 }, condition: null, block: 'FC1', file: 'Scale.scl' },
        { id: 5, location: { file: 'Scale.scl', line: 20 }, condition: null, block: 'FC1', file: 'Scale.scl' },
        { id: 8, location: { file: 'Other.scl', line: 3 }, condition: null, block: 'FC2', file: 'Other.scl' },
      ],
      trend: [],
    });
    await flush();
    // The one removed offline was ours: cleared; another page's (id 8) stays.
    expect(sentOf('clear_breakpoint').map((message) => message.id)).toEqual([5]);

    client.programReplaced();
    expect(sentOf('set_breakpoint')).toHaveLength(2);
    client.close();
  });

  it('hands the breakpoints the session holds to the page that attaches, and its trend entries', async () => {
    const seen: unknown[] = [];
    const client = new MonitorClient({
      url: 'ws://nasaq.test/api/sessions/s1/ws',
      createSocket: (url) => {
        const socket = new FakeSocket(url);
        sockets.push(socket);
        return socket;
      },
      onSessionState: (state) => seen.push(state),
    });
    client.connect();
    last().open();
    last().receive(hello());
    const held = { id: 3, location: { block: 'OB 1', network: 2 }, condition: 'MW10 > 5', block: 'OB1', file: 'Main.lad' };
    answer(last(), sentOf('session_state')[0]!.ref as number, { breakpoints: [held], trend: ['MW10', 'Q0.0'] });
    await flush();
    expect(seen).toEqual([{ breakpoints: [held], trend: ['MW10', 'Q0.0'] }]);
    expect(client.getState().sessionTrend).toEqual(['MW10', 'Q0.0']);
    // A page without trend entries of its own does not stop the trend the session records.
    await client.setTrend([]);
    expect(sentOf('trend')).toHaveLength(0);
    client.close();
  });
});

/** A fake WebSocket and message builders for the monitoring client and the panels' tests. */
import type { CpuState, Frame, Hello, ServerMessage } from '../../frontend/src/api/monitor';
import type { SocketLike } from '../../frontend/src/api/monitorClient';

export class FakeSocket implements SocketLike {
  readyState = 0;
  readonly sent: Array<Record<string, unknown>> = [];
  closed: { code?: number; reason?: string } | null = null;
  onopen: ((event: unknown) => void) | null = null;
  onmessage: ((event: { data: unknown }) => void) | null = null;
  onclose: ((event: { code: number; reason: string }) => void) | null = null;
  onerror: ((event: unknown) => void) | null = null;

  constructor(readonly url: string) {}

  send(data: string): void {
    if (this.readyState !== 1) throw new Error('not open');
    this.sent.push(JSON.parse(data) as Record<string, unknown>);
  }

  close(code?: number, reason?: string): void {
    this.readyState = 3;
    this.closed = { code, reason };
  }

  open(): void {
    this.readyState = 1;
    this.onopen?.({});
  }

  receive(message: ServerMessage | Record<string, unknown>): void {
    this.onmessage?.({ data: JSON.stringify(message) });
  }

  drop(code: number): void {
    this.readyState = 3;
    this.onclose?.({ code, reason: '' });
  }

  sentTypes(): string[] {
    return this.sent.map((message) => String(message.type));
  }

  private readonly answered = new Set<number>();

  /** Answers every command not answered yet with an ack (results by message type). */
  ackAll(results: Record<string, Record<string, unknown> | null> = {}): void {
    for (const message of this.sent) {
      const ref = message.ref as number;
      if (this.answered.has(ref)) continue;
      this.answered.add(ref);
      this.receive({ type: 'ack', ref, result: results[String(message.type)] ?? null });
    }
  }
}

export function hello(client = 1): Hello {
  return { type: 'hello', session: 's1', client, protocol: 1, max_frames_per_second: 30, max_watch_entries: 500 };
}

export function cpuState(overrides: Partial<CpuState> = {}): CpuState {
  return {
    mode: 'STOP',
    time_mode: 'virtual',
    cycle_ms: 10,
    scans: 0,
    time_ms: 0,
    stop_code: null,
    stop_reason: null,
    cycle: null,
    forced: [],
    ...overrides,
  };
}

export function frame(overrides: Partial<Frame> & { seq: number }): Frame {
  return {
    type: 'frame',
    cpu: null,
    watch: null,
    block: null,
    trend: null,
    hold: null,
    released: false,
    diagnostics: null,
    plant: null,
    plant_removed: false,
    ...overrides,
  };
}

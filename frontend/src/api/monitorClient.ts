/**
 * The WebSocket client of one simulation session (protocol: backend/nasaq/monitor/PROTOCOL.md).
 *
 * - Commands get a `ref` and return a promise: resolved by the server's `ack` (its `result`),
 *   rejected by its `error` as a {@link MonitorCommandError} with the catalogue code, key and
 *   params, so the UI can translate it. A command sent while the socket is not open, or left
 *   unanswered when it closes, is rejected with the client's "server unreachable" code.
 * - Subscriptions are state, not commands: the CPU state is always subscribed, the watch list is
 *   the union of what every panel asked for (see {@link MonitorClient.setWatch}), the trend and
 *   the open block are one each. They are sent again after every reconnect.
 * - Frames carry only what changed; {@link mergeFrame} folds them into one immutable
 *   {@link MonitorState}, which React reads through `useSyncExternalStore`.
 * - A dropped connection is retried with exponential backoff; a session the server closed
 *   (MON614) or does not know (MON609) ends the client instead.
 * - The session belongs to the project, not to this page: after every `hello` the client asks
 *   for the `session_state` (the breakpoints set, the trend recorded) and hands it to
 *   `onSessionState`, so that a reloaded page or a second tab shows the breakpoints again;
 *   `state.sessionTrend` tells the trend panel which entries the session records (asking for the
 *   same entries brings their history in the next frame).
 */
import type {
  BlockStatus,
  ClientMessage,
  CpuState,
  DiagnosticEntry,
  Frame,
  Hello,
  HoldState,
  Location as ProgramLocation,
  PlantFrame,
  ServerMessage,
  TrendSample,
  WatchValue,
} from './monitor';
import { CLIENT_ERROR_CODES } from './client';

type DistributiveOmit<T, K extends PropertyKey> = T extends unknown ? Omit<T, K> : never;

/** A client message without its `ref`: the client numbers them. */
export type MonitorCommand = DistributiveOmit<ClientMessage, 'ref'>;

/** What every problem shown to the user has: a catalogue code, a key to translate, params. */
export interface Problem {
  code: string;
  key: string;
  message: string;
  params: Record<string, unknown>;
}

/** A command the server refused (its `error` message), or one the connection lost. */
export class MonitorCommandError extends Error implements Problem {
  readonly code: string;
  readonly key: string;
  readonly params: Record<string, unknown>;

  constructor(problem: Problem) {
    super(problem.message);
    this.name = 'MonitorCommandError';
    this.code = problem.code;
    this.key = problem.key;
    this.params = problem.params;
  }
}

export const CONNECTION_LOST: Problem = {
  code: CLIENT_ERROR_CODES.unreachable,
  key: 'server_unreachable',
  message: 'The Nasaq server cannot be reached.',
  params: {},
};

/** The server answer to `watch`: each entry's type, or why it cannot be watched. */
export interface WatchEntryReport {
  entry: string;
  type?: string;
  code?: string;
  error?: string;
}

export type ConnectionStatus = 'connecting' | 'open' | 'reconnecting' | 'closed';

/** A breakpoint the client keeps set on the server (see {@link MonitorClient.setBreakpoints}). */
export interface BreakpointRequest {
  /** The caller's name for it (the editor uses `project:file:line`). */
  key: string;
  location: ProgramLocation;
  condition: string | null;
}

/** A breakpoint the session has set, as `session_state` lists it (PROTOCOL.md). */
export interface SessionBreakpoint {
  id: number;
  /** The location as it was set (`{file, line}` or `{block, network}` ...). */
  location: ProgramLocation;
  condition: string | null;
  /** The block it is in, and that block's source file. */
  block: string;
  file: string | null;
}

/** The ack of `session_state`: what a client that attaches shows again. */
export interface SessionStateResult {
  breakpoints: SessionBreakpoint[];
  /** The entries of the trend the session records (empty: none). */
  trend: string[];
}

/** What the server said about a breakpoint: waiting for its answer, set as `id`, or refused. */
export interface BreakpointReport {
  state: 'pending' | 'set' | 'refused';
  id: number | null;
  problem: Problem | null;
}

export interface MonitorState {
  connection: ConnectionStatus;
  hello: Hello | null;
  /** The `seq` of the last frame merged. */
  seq: number;
  cpu: CpuState | null;
  /** The newest value of each watched entry (every panel's entries together). */
  watch: Readonly<Record<string, WatchValue>>;
  /** What the last `watch` ack said about each entry (type or error). */
  watchReports: Readonly<Record<string, WatchEntryReport>>;
  block: BlockStatus | null;
  /** The entries of the trend samples' `values`, in order. */
  trendEntries: readonly string[];
  trendTypes: readonly string[];
  trend: readonly TrendSample[];
  hold: HoldState | null;
  /** The previous hold ended (and no new one started). */
  released: boolean;
  /** The CPU's diagnostic buffer as far as this client knows it, oldest first. */
  diagnostics: readonly DiagnosticEntry[];
  /** Why the session ended for this client (MON614 closed, MON609 unknown, MON605 full). */
  closedBy: Problem | null;
  /** The server's answer for each breakpoint of {@link MonitorClient.setBreakpoints}, by key. */
  breakpoints: Readonly<Record<string, BreakpointReport>>;
  /**
   * The entries of the trend the session recorded when this client attached (a reload, a second
   * tab): a trend panel with no entries of its own shows these (`setTrend` with them brings the
   * history).
   */
  sessionTrend: readonly string[];
  /** The virtual plant of the session (frontend/src/plants), as the last frame that had one sent it. */
  plant: PlantFrame | null;
}

export const MAX_TREND_SAMPLES = 20_000;
export const MAX_DIAGNOSTICS = 1_000;

export function initialMonitorState(): MonitorState {
  return {
    connection: 'connecting',
    hello: null,
    seq: 0,
    cpu: null,
    watch: {},
    watchReports: {},
    block: null,
    trendEntries: [],
    trendTypes: [],
    trend: [],
    hold: null,
    released: false,
    diagnostics: [],
    closedBy: null,
    breakpoints: {},
    sessionTrend: [],
    plant: null,
  };
}

function appendCapped<T>(items: readonly T[], more: readonly T[], cap: number): readonly T[] {
  const joined = items.length === 0 ? [...more] : [...items, ...more];
  return joined.length > cap ? joined.slice(joined.length - cap) : joined;
}

/**
 * Folds a frame into the state. A `null` field did not change; `watch` holds only the entries
 * whose value changed; `trend` and `diagnostics` are new items to append.
 */
export function mergeFrame(state: MonitorState, frame: Frame): MonitorState {
  const next: MonitorState = { ...state, seq: frame.seq };
  if (frame.cpu) next.cpu = frame.cpu;
  if (frame.watch) next.watch = { ...state.watch, ...frame.watch };
  if (frame.block) next.block = frame.block;
  if (frame.trend && frame.trend.length > 0) next.trend = appendCapped(state.trend, frame.trend, MAX_TREND_SAMPLES);
  if (frame.hold) {
    // The server sends the hold again after every command carried out at it (a page attaching
    // sends several): an unchanged one keeps its object, so what follows the hold (the editor
    // opening the held file) reacts once.
    const same = state.hold !== null && JSON.stringify(state.hold) === JSON.stringify(frame.hold);
    next.hold = same ? state.hold : frame.hold;
    next.released = false;
  } else if (frame.released) {
    next.hold = null;
    next.released = true;
  }
  if (frame.diagnostics && frame.diagnostics.length > 0) {
    next.diagnostics = appendCapped(state.diagnostics, frame.diagnostics, MAX_DIAGNOSTICS);
  }
  if (frame.plant) next.plant = frame.plant;
  else if (frame.plant_removed) next.plant = null;
  return next;
}

const entryKey = (entry: DiagnosticEntry) =>
  `${entry.time_ms}|${entry.code}|${entry.message}|${entry.block}|${entry.network}|${entry.line}`;

/**
 * The buffer as the REST call returned it, followed by what frames brought that it does not
 * have yet (frames and the call may overlap right after connecting).
 */
export function mergeDiagnosticHistory(
  history: readonly DiagnosticEntry[],
  fromFrames: readonly DiagnosticEntry[],
): readonly DiagnosticEntry[] {
  const known = new Set(history.map(entryKey));
  const extra = fromFrames.filter((entry) => !known.has(entryKey(entry)));
  return appendCapped(history, extra, MAX_DIAGNOSTICS);
}

/** The part of `WebSocket` the client uses (a fake one in the tests). */
export interface SocketLike {
  readonly readyState: number;
  send(data: string): void;
  close(code?: number, reason?: string): void;
  onopen: ((event: unknown) => void) | null;
  onmessage: ((event: { data: unknown }) => void) | null;
  onclose: ((event: { code: number; reason: string }) => void) | null;
  onerror: ((event: unknown) => void) | null;
}

const OPEN = 1;

export interface MonitorClientOptions {
  /** The session's socket URL (see {@link socketUrl}). */
  url: string;
  createSocket?: (url: string) => SocketLike;
  /** Delay before the first retry, doubled per failure up to `maxDelayMs`. */
  initialDelayMs?: number;
  maxDelayMs?: number;
  /** Loads the diagnostic buffer's history after each connect (GET .../diagnostics). */
  loadDiagnostics?: () => Promise<readonly DiagnosticEntry[]>;
  /** Gets what the session keeps (breakpoints, trend) after each connect. */
  onSessionState?: (state: SessionStateResult) => void;
}

/** `ws(s)://<this host><path>`: the socket is always on the server that served the page. */
export function socketUrl(path: string, location: Pick<Location, 'protocol' | 'host'> = window.location): string {
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}${path}`;
}

interface Pending {
  resolve: (result: Record<string, unknown> | null) => void;
  reject: (error: MonitorCommandError) => void;
}

type Listener = () => void;

export class MonitorClient {
  private readonly options: Required<Omit<MonitorClientOptions, 'loadDiagnostics' | 'onSessionState'>> &
    Pick<MonitorClientOptions, 'loadDiagnostics' | 'onSessionState'>;
  private state: MonitorState = initialMonitorState();
  private readonly listeners = new Set<Listener>();
  private socket: SocketLike | null = null;
  private nextRef = 1;
  private readonly pending = new Map<number, Pending>();
  private attempts = 0;
  private retryTimer: ReturnType<typeof setTimeout> | null = null;
  private ended = false;
  private readonly watchOwners = new Map<string, readonly string[]>();
  private sentWatch: readonly string[] | null = null;
  private watchQueued = false;
  private trendEntries: readonly string[] = [];
  private openBlockName: string | null = null;
  private openBlockNetworks: number[] | null = null;
  /** The breakpoints the caller wants, by key. */
  private wantedBreakpoints = new Map<string, BreakpointRequest>();
  /** What was sent for each key (the request object) and the id the server gave it. */
  private readonly sentBreakpoints = new Map<string, { request: BreakpointRequest; id: number | null }>();
  /** The ids this client's breakpoints had before the connection dropped. */
  private previousBreakpointIds = new Set<number>();
  /** Whether this client ever asked for a trend (only then an empty one is sent). */
  private trendSent = false;

  constructor(options: MonitorClientOptions) {
    this.options = {
      createSocket: (url) => new WebSocket(url) as unknown as SocketLike,
      initialDelayMs: 500,
      maxDelayMs: 10_000,
      ...options,
    };
  }

  // -- the store React reads -------------------------------------------------------------------
  getState = (): MonitorState => this.state;

  subscribe = (listener: Listener): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  private update(change: Partial<MonitorState> | ((state: MonitorState) => MonitorState)): void {
    this.state = typeof change === 'function' ? change(this.state) : { ...this.state, ...change };
    for (const listener of [...this.listeners]) listener();
  }

  // -- connection ------------------------------------------------------------------------------
  /** Opens the socket (again); nothing happens once the client has ended. */
  connect(): void {
    if (this.ended || this.socket) return;
    this.retryTimer = null;
    const socket = this.options.createSocket(this.options.url);
    this.socket = socket;
    socket.onmessage = (event) => {
      if (this.socket === socket) this.receive(event.data);
    };
    socket.onclose = (event) => {
      if (this.socket === socket) this.dropped(event.code);
    };
    socket.onerror = () => undefined; // a close event follows
  }

  /** Ends the client: closes the socket, never reconnects. */
  close(): void {
    this.ended = true;
    if (this.retryTimer !== null) clearTimeout(this.retryTimer);
    this.retryTimer = null;
    const socket = this.socket;
    this.socket = null;
    this.failPending();
    if (socket) {
      socket.onmessage = null;
      socket.onclose = null;
      socket.close(1000, 'closed by the client');
    }
    if (this.state.connection !== 'closed') this.update({ connection: 'closed' });
  }

  private dropped(code: number): void {
    const hadHello = this.state.hello !== null && this.state.connection === 'open';
    this.socket = null;
    this.failPending();
    if (this.ended) return;
    if (!hadHello && code === 1008) {
      // Refused before the hello: the server does not know the session (it closes with MON609).
      this.end({
        code: 'MON609',
        key: 'mon_session_not_found',
        message: 'The simulation session does not exist.',
        params: { id: this.sessionIdFromUrl() },
      });
      return;
    }
    this.sentWatch = null;
    for (const sent of this.sentBreakpoints.values()) if (sent.id !== null) this.previousBreakpointIds.add(sent.id);
    const delay = Math.min(this.options.maxDelayMs, this.options.initialDelayMs * 2 ** this.attempts);
    this.attempts += 1;
    this.update({ connection: 'reconnecting' });
    this.retryTimer = setTimeout(() => this.connect(), delay);
  }

  private end(reason: Problem): void {
    this.ended = true;
    const socket = this.socket;
    this.socket = null;
    this.failPending();
    if (socket) {
      socket.onmessage = null;
      socket.onclose = null;
      socket.close(1000, 'session ended');
    }
    this.update({ connection: 'closed', closedBy: reason });
  }

  private sessionIdFromUrl(): string {
    return /\/sessions\/([^/]+)\/ws/.exec(this.options.url)?.[1] ?? '';
  }

  private failPending(): void {
    const waiting = [...this.pending.values()];
    this.pending.clear();
    for (const item of waiting) item.reject(new MonitorCommandError(CONNECTION_LOST));
  }

  // -- receiving -------------------------------------------------------------------------------
  private receive(data: unknown): void {
    if (typeof data !== 'string') return;
    let message: ServerMessage;
    try {
      message = JSON.parse(data) as ServerMessage;
    } catch {
      return;
    }
    switch (message.type) {
      case 'hello':
        this.attempts = 0;
        this.update({ connection: 'open', hello: message });
        this.resubscribe();
        void this.loadHistory();
        void this.loadSessionState();
        return;
      case 'frame':
        this.update((state) => mergeFrame(state, message));
        return;
      case 'ack': {
        const waiting = message.ref === null ? undefined : this.pending.get(message.ref);
        if (waiting && message.ref !== null) {
          this.pending.delete(message.ref);
          waiting.resolve(message.result);
        }
        return;
      }
      case 'error': {
        const problem: Problem = {
          code: message.code,
          key: message.key,
          message: message.message,
          params: message.params ?? {},
        };
        const waiting = message.ref === null ? undefined : this.pending.get(message.ref);
        if (waiting && message.ref !== null) {
          this.pending.delete(message.ref);
          waiting.reject(new MonitorCommandError(problem));
          return;
        }
        if (problem.code === 'MON614' || this.state.connection !== 'open') this.end(problem);
        return;
      }
    }
  }

  private async loadHistory(): Promise<void> {
    const load = this.options.loadDiagnostics;
    if (!load) return;
    try {
      const history = await load();
      this.update((state) => ({ ...state, diagnostics: mergeDiagnosticHistory(history, state.diagnostics) }));
    } catch {
      // The frames still bring every new entry; the history is a nicety.
    }
  }

  /**
   * What the session keeps: its breakpoints go to `onSessionState` (the editors show them and
   * set them through `setBreakpoints`, which the server answers with the same ids); those this
   * client had set before a reconnect and no longer wants (removed while offline) are cleared.
   */
  private async loadSessionState(): Promise<void> {
    const dropped = this.previousBreakpointIds;
    this.previousBreakpointIds = new Set();
    let found: SessionStateResult;
    try {
      const result = (await this.send({ type: 'session_state' })) as Partial<SessionStateResult> | null;
      found = { breakpoints: result?.breakpoints ?? [], trend: result?.trend ?? [] };
    } catch {
      return; // the connection dropped: asked again at the next hello
    }
    const wanted = [...this.wantedBreakpoints.values()];
    const kept: SessionBreakpoint[] = [];
    for (const bp of found.breakpoints) {
      const ours = wanted.some((request) => sameBreakpoint(request, { key: '', location: bp.location, condition: bp.condition }));
      if (!ours && dropped.has(bp.id)) this.sendQuietly({ type: 'clear_breakpoint', id: bp.id });
      else kept.push(bp);
    }
    this.update({ sessionTrend: [...found.trend] });
    this.options.onSessionState?.({ breakpoints: kept, trend: found.trend });
  }

  // -- sending ---------------------------------------------------------------------------------
  /** Sends a command; resolves with the ack's result, rejects with the server's error. */
  send(command: MonitorCommand): Promise<Record<string, unknown> | null> {
    const socket = this.socket;
    if (!socket || socket.readyState !== OPEN || this.state.connection !== 'open') {
      return Promise.reject(new MonitorCommandError(CONNECTION_LOST));
    }
    const ref = this.nextRef++;
    return new Promise((resolve, reject) => {
      this.pending.set(ref, { resolve, reject });
      try {
        socket.send(JSON.stringify({ ...command, ref }));
      } catch {
        this.pending.delete(ref);
        reject(new MonitorCommandError(CONNECTION_LOST));
      }
    });
  }

  /** Sends the subscriptions again: after a (re)connect, or after a new program was downloaded. */
  resubscribe(): void {
    if (this.state.connection !== 'open') return;
    this.sendQuietly({ type: 'subscribe_cpu', on: true });
    this.sentWatch = null;
    this.flushWatch();
    if (this.trendEntries.length > 0) {
      // The session sends the trend's history again with the first frame: start from none.
      this.update({ trend: [] });
      this.sendTrend().catch(() => undefined);
    } else this.trendSent = false; // the session dropped this client's trend with its socket
    if (this.openBlockName !== null) {
      this.sendQuietly({ type: 'open_block', block: this.openBlockName, networks: this.openBlockNetworks });
    }
    this.resendBreakpoints();
  }

  private sendQuietly(command: MonitorCommand): void {
    this.send(command).catch(() => undefined);
  }

  /**
   * The entries `owner` (a panel) wants to watch; the server gets the union of every owner's
   * entries, sent once per tick however many owners changed theirs.
   */
  setWatch(owner: string, entries: readonly string[]): void {
    if (entries.length === 0) this.watchOwners.delete(owner);
    else this.watchOwners.set(owner, [...entries]);
    if (this.watchQueued) return;
    this.watchQueued = true;
    queueMicrotask(() => {
      this.watchQueued = false;
      this.flushWatch();
    });
  }

  /** Every entry watched, in the order the owners gave them, each once. */
  watchedEntries(): string[] {
    return [...new Set([...this.watchOwners.values()].flat())];
  }

  private flushWatch(): void {
    const entries = this.watchedEntries();
    const previous = this.sentWatch;
    if (previous && previous.length === entries.length && previous.every((entry, i) => entry === entries[i])) return;
    if (this.state.connection !== 'open') return;
    if (previous === null && entries.length === 0) {
      this.sentWatch = entries;
      return;
    }
    this.sentWatch = entries;
    const kept = new Set(entries);
    this.update((state) => ({
      ...state,
      watch: Object.fromEntries(Object.entries(state.watch).filter(([entry]) => kept.has(entry))),
    }));
    this.send({ type: 'watch', entries })
      .then((result) => {
        const reports = ((result?.entries ?? []) as WatchEntryReport[]).map((report) => [report.entry, report] as const);
        this.update((state) => ({ ...state, watchReports: Object.fromEntries(reports) }));
      })
      .catch(() => undefined);
  }

  /** Records `entries` at the end of every scan (at most 32); the samples start afresh. */
  setTrend(entries: readonly string[]): Promise<void> {
    this.trendEntries = [...entries];
    this.update({ trend: [], trendEntries: [...entries], trendTypes: [] });
    if (this.state.connection !== 'open') return Promise.resolve();
    return this.sendTrend();
  }

  private async sendTrend(): Promise<void> {
    const entries = this.trendEntries;
    // An empty trend from a client that never asked for one would stop the trend the session
    // keeps for whoever asks next (a reloaded page's panel restoring its entries).
    if (entries.length === 0 && !this.trendSent) return;
    this.trendSent = entries.length > 0;
    const result = await this.send({ type: 'trend', entries: [...entries] });
    const types = ((result?.entries ?? []) as WatchEntryReport[]).map((report) => report.type ?? '');
    if (this.trendEntries === entries) this.update({ trendTypes: types });
  }

  /**
   * The block whose status frames carry, or none; `networks` (1-based) limits the status to the
   * networks a diagram editor shows, so only those are instrumented.
   */
  openBlock(block: string | null, networks: readonly number[] | null = null): Promise<Record<string, unknown> | null> {
    this.openBlockName = block;
    this.openBlockNetworks = networks ? [...networks] : null;
    if (block === null) this.update({ block: null });
    if (this.state.connection !== 'open') return Promise.resolve(null);
    return this.send({ type: 'open_block', block, networks: this.openBlockNetworks });
  }

  /**
   * The breakpoints to keep set (all of them, each time): the client sets the new ones, clears
   * the removed ones and sets a changed one again. They are sent again after every (re)connect
   * and download, since a new program starts without breakpoints; `state.breakpoints` tells
   * which the server refused and why.
   */
  setBreakpoints(requests: readonly BreakpointRequest[]): void {
    this.wantedBreakpoints = new Map(requests.map((request) => [request.key, request]));
    const reports = { ...this.state.breakpoints };
    for (const key of Object.keys(reports)) if (!this.wantedBreakpoints.has(key)) delete reports[key];
    for (const [key, sent] of [...this.sentBreakpoints]) {
      const wanted = this.wantedBreakpoints.get(key);
      if (wanted && sameBreakpoint(wanted, sent.request)) continue;
      this.sentBreakpoints.delete(key);
      if (sent.id !== null) this.sendQuietly({ type: 'clear_breakpoint', id: sent.id });
    }
    this.update({ breakpoints: reports });
    for (const request of this.wantedBreakpoints.values()) {
      if (!this.sentBreakpoints.has(request.key)) this.sendBreakpoint(request);
    }
  }

  private resendBreakpoints(): void {
    // The session keeps its breakpoints while no client is connected: setting ours again gets
    // the ids of those already there (no duplicates); those removed meanwhile are cleared once
    // `session_state` has listed them.
    this.sentBreakpoints.clear();
    for (const request of this.wantedBreakpoints.values()) this.sendBreakpoint(request);
  }

  private sendBreakpoint(request: BreakpointRequest): void {
    if (this.state.connection !== 'open') return;
    const sent = { request, id: null as number | null };
    this.sentBreakpoints.set(request.key, sent);
    const report = (value: BreakpointReport) => {
      if (this.sentBreakpoints.get(request.key) !== sent) return;
      this.update((state) => ({ ...state, breakpoints: { ...state.breakpoints, [request.key]: value } }));
    };
    report({ state: 'pending', id: null, problem: null });
    this.send({ type: 'set_breakpoint', location: request.location, condition: request.condition })
      .then((result) => {
        const id = typeof result?.id === 'number' ? result.id : null;
        if (this.sentBreakpoints.get(request.key) !== sent) {
          // Removed or changed while the server was setting it.
          if (id !== null) this.sendQuietly({ type: 'clear_breakpoint', id });
          return;
        }
        sent.id = id;
        report({ state: 'set', id, problem: null });
      })
      .catch((error: unknown) => {
        if (!(error instanceof MonitorCommandError) || error.code === CONNECTION_LOST.code) {
          // Sent again at the next hello.
          if (this.sentBreakpoints.get(request.key) === sent) this.sentBreakpoints.delete(request.key);
          return;
        }
        report({ state: 'refused', id: null, problem: { code: error.code, key: error.key, message: error.message, params: error.params } });
      });
  }

  /** Forgets what belonged to the replaced program (after a download into this session). */
  programReplaced(): void {
    this.update({ block: null, hold: null, released: false, diagnostics: [], trend: [] });
    this.resubscribe();
  }
}

function sameBreakpoint(a: BreakpointRequest, b: BreakpointRequest): boolean {
  const x = a.location;
  const y = b.location;
  return (
    a.condition === b.condition &&
    x.file === y.file &&
    x.block === y.block &&
    x.line === y.line &&
    x.network === y.network &&
    x.instruction === y.instruction &&
    (x.step ?? null) === (y.step ?? null)
  );
}

/**
 * Online status of an S7-Graph FB: while monitoring is on, the FB on screen is opened on the
 * session (all of it: the chart, the step view and the permanent instructions draw from the same
 * status), and each sampled call brings its sequencer (mode, steps, transitions, read from the
 * instance DB the call used) and its elements' states keyed by their origin (`T3/e2`, `S2/C/e1`,
 * `S2/A1`, `PRE1/e2`).
 *
 * A 200-step sequencer must not re-render the world at every frame: the status is folded into
 * the previous one keeping every unchanged step, transition and element object (and the map
 * itself when nothing in it changed), so components memoised on them skip their work, and the
 * hook's host re-renders only when something it shows changed.
 */
import { useCallback, useEffect, useMemo, useRef, useState, useSyncExternalStore } from 'react';
import type { BlockStatus, ClientMessage, ElementStatus, GraphStatus, GraphStepStatus, GraphTransitionStatus, HoldState } from '../api/monitor';
import { initialMonitorState, type MonitorCommand, type MonitorState, type Problem } from '../api/monitorClient';
import { problemOf, useSession } from '../cpu/SessionContext';
import { OPEN_DELAY_MS, sessionBlockName } from '../lad/useLadMonitoring';

export interface GraphMonitor {
  /** The sequencer of the FB's last sampled call (BlockStatus.graph). */
  status: GraphStatus | null;
  /** Element states by origin id: 'T3/e2', 'S2/C/e1', 'S2/V/e1', 'S2/A1', 'PRE1/e2', 'POST1/e1'. */
  elements: ReadonlyMap<string, ElementStatus>;
  /** The session to send `graph_control` (and debugger) messages to; null: none runs. */
  session: { id: string; send: (message: ClientMessage) => void } | null;
  /** The instance DB the status was read from ('DB1'), kept while the FB is not sampled. */
  db: string | null;
  /** Where the CPU holds (any block: continue and step act on the CPU). */
  hold: HoldState | null;
  /** The last failure of opening the FB or of a command sent through `session`. */
  problem: Problem | null;
}

interface Options {
  enabled: boolean;
  projectId: number | null;
  file: string | null;
  /** GraphBlock.name: 'FB 1' or '"Seq_drill"'. */
  block: string;
}

const NO_ELEMENTS: ReadonlyMap<string, ElementStatus> = new Map();
const IDLE: MonitorState = { ...initialMonitorState(), connection: 'closed' };
const noSubscription = () => () => undefined;

function sameValue(a: unknown, b: unknown): boolean {
  return a === b || (Number.isNaN(a) && Number.isNaN(b));
}

function samePins(a: Record<string, unknown>, b: Record<string, unknown>): boolean {
  if (a === b) return true;
  const keys = Object.keys(a);
  if (keys.length !== Object.keys(b).length) return false;
  return keys.every((key) => key in b && sameValue(a[key], b[key]));
}

function sameStep(a: GraphStepStatus, b: GraphStepStatus): boolean {
  return (
    a.number === b.number &&
    a.name === b.name &&
    a.state === b.state &&
    a.t_ms === b.t_ms &&
    a.u_ms === b.u_ms &&
    a.interlock_error === b.interlock_error &&
    a.supervision_error === b.supervision_error
  );
}

function sameTransition(a: GraphTransitionStatus, b: GraphTransitionStatus): boolean {
  return a.number === b.number && a.name === b.name && a.tt === b.tt;
}

/** `items` with each item equal to the one at the same place in `previous` replaced by it. */
function keepItems<T>(previous: readonly T[] | undefined, items: readonly T[], same: (a: T, b: T) => boolean): { items: T[]; kept: boolean } {
  let kept = previous !== undefined && previous.length === items.length;
  const out = items.map((item, k) => {
    const old = previous?.[k];
    if (old !== undefined && same(old, item)) return old;
    kept = false;
    return item;
  });
  return { items: out, kept };
}

/** The new sequencer status, sharing every unchanged part with the previous one. */
export function foldGraphStatus(previous: GraphStatus | null, next: GraphStatus | null): GraphStatus | null {
  if (next === null || previous === null) return next;
  if (previous === next) return previous;
  const steps = keepItems(previous.steps, next.steps, sameStep);
  const transitions = keepItems(previous.transitions, next.transitions, sameTransition);
  if (steps.kept && transitions.kept && previous.db === next.db && previous.at === next.at && previous.mode === next.mode) return previous;
  return { ...next, steps: steps.kept ? previous.steps : steps.items, transitions: transitions.kept ? previous.transitions : transitions.items };
}

/** The key of an element in `elements`: its origin id (network 0, a Graph FB's elements). */
export function elementKey(element: Pick<ElementStatus, 'network' | 'id'>): string {
  return element.network === 0 ? element.id : `${element.network}/${element.id}`;
}

/** The element states by origin id, sharing the unchanged ones (and the map) with `previous`. */
export function foldElements(
  previous: ReadonlyMap<string, ElementStatus>,
  elements: readonly ElementStatus[],
): ReadonlyMap<string, ElementStatus> {
  if (elements.length === 0) return previous.size === 0 ? previous : NO_ELEMENTS;
  let changed = elements.length !== previous.size;
  const next = new Map<string, ElementStatus>();
  for (const element of elements) {
    const key = elementKey(element);
    const old = previous.get(key);
    if (old && old.network === element.network && sameValue(old.value, element.value) && old.out === element.out && samePins(old.pins ?? {}, element.pins ?? {})) {
      next.set(key, old);
    } else {
      changed = true;
      next.set(key, element);
    }
  }
  return changed ? next : previous;
}

interface Snapshot {
  hold: HoldState | null;
  status: GraphStatus | null;
  elements: ReadonlyMap<string, ElementStatus>;
  db: string | null;
}

const EMPTY_SNAPSHOT: Snapshot = { hold: null, status: null, elements: NO_ELEMENTS, db: null };

export function useGraphMonitoring({ enabled, projectId, file, block }: Options): GraphMonitor {
  const { session, client } = useSession();
  const online = enabled && client !== null && session !== null && session.projectId === projectId && file !== null;
  const name = sessionBlockName(block);
  const [problem, setProblem] = useState<Problem | null>(null);
  /** The name the session gave the opened block ('FB1' for '"Seq_drill"'). */
  const opened = useRef<string | null>(null);

  useEffect(() => {
    if (!online || !client || !name) return;
    let live = true;
    opened.current = null;
    const timer = setTimeout(() => {
      client.openBlock(name, null).then(
        (result) => {
          if (!live) return;
          opened.current = typeof result?.block === 'string' ? result.block : null;
          setProblem(null);
        },
        (error: unknown) => live && setProblem(problemOf(error)),
      );
    }, OPEN_DELAY_MS);
    return () => {
      live = false;
      clearTimeout(timer);
    };
  }, [online, client, name]);

  useEffect(() => {
    if (!online || !client) return;
    return () => {
      client.openBlock(null).catch(() => undefined);
      setProblem(null);
    };
  }, [online, client]);

  // The snapshot changes only when what this FB shows changed (see foldGraphStatus).
  const snapshot = useRef<Snapshot>(EMPTY_SNAPSHOT);
  const input = useRef<{ block: BlockStatus | null; hold: HoldState | null; key: string } | null>(null);
  const read = useCallback((): Snapshot => {
    const state = online && client ? client.getState() : IDLE;
    const key = `${online}|${name}`;
    const seen = input.current;
    if (seen && seen.block === state.block && seen.hold === state.hold && seen.key === key) return snapshot.current;
    input.current = { block: state.block, hold: state.hold, key };
    const last = snapshot.current;
    // The session names the block as its ack said ('FB1' for a symbol); until then a symbolic
    // name can only be matched by the language.
    const mine = (candidate: BlockStatus | null) =>
      candidate !== null &&
      (candidate.block === name ||
        candidate.block === opened.current ||
        (opened.current === null && name.startsWith('"') && candidate.language === 'graph'));
    const ours = mine(state.block) ? state.block : null;
    const graph = ours?.graph ?? null;
    const status = foldGraphStatus(last.status, graph);
    const elements = ours ? foldElements(last.elements, ours.elements ?? []) : NO_ELEMENTS;
    // The DB stays known while the FB is not sampled (a frame without it, a hold elsewhere).
    const db = online ? (graph?.db ?? (seen?.key === key ? last.db : null)) : null;
    if (status === last.status && elements === last.elements && db === last.db && state.hold === last.hold) return last;
    snapshot.current = { status, elements, db, hold: state.hold };
    return snapshot.current;
  }, [online, client, name]);
  const subscribe = online && client ? client.subscribe : noSubscription;
  const current = useSyncExternalStore(subscribe, read, read);

  const send = useCallback(
    (message: ClientMessage) => {
      if (!client) return;
      const { ref: _ref, ...command } = message;
      void _ref;
      setProblem(null);
      client.send(command as MonitorCommand).catch((error: unknown) => setProblem(problemOf(error)));
    },
    [client],
  );
  const sessionId = online ? (session?.id ?? null) : null;
  const target = useMemo(() => (sessionId ? { id: sessionId, send } : null), [sessionId, send]);

  return useMemo(
    () => ({
      status: online ? current.status : null,
      elements: online ? current.elements : NO_ELEMENTS,
      session: target,
      db: online ? current.db : null,
      hold: online ? current.hold : null,
      problem: online ? problem : null,
    }),
    [online, current, target, problem],
  );
}

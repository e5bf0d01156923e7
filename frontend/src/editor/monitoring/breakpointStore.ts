/**
 * The user's breakpoints: per project file and line (or, in a LAD/FBD block, per network), with a
 * condition and an enabled flag. They
 * belong to the browser, not to a session, so they survive tab switches, reloads and downloads
 * (localStorage); `useBreakpointSync` hands the enabled ones of the session's project to the
 * monitoring client, which keeps them set on the server.
 */
import type { BreakpointRequest } from '../../api/monitorClient';

export interface Breakpoint {
  projectId: number;
  /** The project file (`Scale.scl`). */
  file: string;
  /** The source line; with `block`, the network number in that block (a LAD/FBD network breakpoint). */
  line: number;
  /** A LAD/FBD block of the file (`OB 1`), for a breakpoint on one of its networks. */
  block?: string;
  /** `<operand> <op> <value>` (see PROTOCOL.md), null for an unconditional breakpoint. */
  condition: string | null;
  enabled: boolean;
}

export const BREAKPOINTS_STORAGE_KEY = 'nasaq.debug.breakpoints';

/** The key of a breakpoint, shared with the client's reports. */
export function breakpointKey(projectId: number, file: string, line: number, block?: string): string {
  return block ? `${projectId}:${file}:${block}#${line}` : `${projectId}:${file}:${line}`;
}

export const keyOf = (bp: Pick<Breakpoint, 'projectId' | 'file' | 'line' | 'block'>) => breakpointKey(bp.projectId, bp.file, bp.line, bp.block);

function isBreakpoint(value: unknown): value is Breakpoint {
  const bp = value as Breakpoint;
  return (
    typeof bp === 'object' &&
    bp !== null &&
    Number.isInteger(bp.projectId) &&
    typeof bp.file === 'string' &&
    Number.isInteger(bp.line) &&
    bp.line > 0 &&
    (bp.condition === null || typeof bp.condition === 'string') &&
    (bp.block === undefined || typeof bp.block === 'string') &&
    typeof bp.enabled === 'boolean'
  );
}

/** What the server needs for the enabled breakpoints of one project. */
export function requestsFor(breakpoints: readonly Breakpoint[], projectId: number): BreakpointRequest[] {
  return breakpoints
    .filter((bp) => bp.enabled && bp.projectId === projectId)
    .map((bp) => ({
      key: keyOf(bp),
      location: bp.block ? { block: bp.block, network: bp.line } : { file: bp.file, line: bp.line },
      condition: bp.condition,
    }));
}

type Listener = () => void;

export interface BreakpointStore {
  list: () => readonly Breakpoint[];
  /** The breakpoints of one file, by line (network breakpoints too). */
  ofFile: (projectId: number, file: string) => readonly Breakpoint[];
  /** With `block`: the breakpoint of network `line` of that block. */
  find: (projectId: number, file: string, line: number, block?: string) => Breakpoint | undefined;
  /** Adds an unconditional breakpoint at the line (or network), or removes the one there. */
  toggle: (projectId: number, file: string, line: number, block?: string) => void;
  /** Adds or changes the breakpoint at the line (an empty condition: none). */
  put: (
    projectId: number,
    file: string,
    line: number,
    change: { condition?: string | null; enabled?: boolean },
    block?: string,
  ) => void;
  remove: (projectId: number, file: string, line: number, block?: string) => void;
  /** Moves a breakpoint to another line (where the server says there is code). */
  move: (projectId: number, file: string, from: number, to: number) => void;
  /** Removes every breakpoint (of one project, when given). */
  clear: (projectId?: number) => void;
  subscribe: (listener: Listener) => () => void;
}

export function createBreakpointStore(storage: Pick<Storage, 'getItem' | 'setItem'> | null = safeStorage()): BreakpointStore {
  let items: readonly Breakpoint[] = read();
  const listeners = new Set<Listener>();

  function read(): Breakpoint[] {
    try {
      const parsed: unknown = JSON.parse(storage?.getItem(BREAKPOINTS_STORAGE_KEY) ?? '[]');
      return Array.isArray(parsed) ? parsed.filter(isBreakpoint) : [];
    } catch {
      return [];
    }
  }

  function commit(next: readonly Breakpoint[]) {
    items = [...next].sort(
      (a, b) => a.projectId - b.projectId || a.file.localeCompare(b.file) || (a.block ?? '').localeCompare(b.block ?? '') || a.line - b.line,
    );
    try {
      storage?.setItem(BREAKPOINTS_STORAGE_KEY, JSON.stringify(items));
    } catch {
      // A full or blocked storage: the breakpoints still work until the page reloads.
    }
    listeners.forEach((listener) => listener());
  }

  const same = (projectId: number, file: string, line: number, block?: string) => (bp: Breakpoint) =>
    bp.projectId === projectId && bp.file === file && bp.line === line && bp.block === block;

  const store: BreakpointStore = {
    list: () => items,
    ofFile: (projectId, file) => items.filter((bp) => bp.projectId === projectId && bp.file === file),
    find: (projectId, file, line, block) => items.find(same(projectId, file, line, block)),
    toggle(projectId, file, line, block) {
      if (store.find(projectId, file, line, block)) store.remove(projectId, file, line, block);
      else commit([...items, { projectId, file, line, condition: null, enabled: true, ...(block ? { block } : {}) }]);
    },
    put(projectId, file, line, change, block) {
      const found = store.find(projectId, file, line, block);
      const condition = change.condition === undefined ? (found?.condition ?? null) : change.condition?.trim() || null;
      const enabled = change.enabled ?? found?.enabled ?? true;
      const others = items.filter((bp) => !same(projectId, file, line, block)(bp));
      commit([...others, { projectId, file, line, condition, enabled, ...(block ? { block } : {}) }]);
    },
    remove(projectId, file, line, block) {
      commit(items.filter((bp) => !same(projectId, file, line, block)(bp)));
    },
    move(projectId, file, from, to) {
      const found = store.find(projectId, file, from);
      if (!found || from === to) return;
      const rest = items.filter((bp) => !same(projectId, file, from)(bp) && !same(projectId, file, to)(bp));
      commit([...rest, { ...found, line: to }]);
    },
    clear(projectId) {
      commit(projectId === undefined ? [] : items.filter((bp) => bp.projectId !== projectId));
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
  return store;
}

function safeStorage(): Storage | null {
  try {
    return typeof localStorage === 'undefined' ? null : localStorage;
  } catch {
    return null;
  }
}

/** The app's breakpoints. */
export const breakpoints = createBreakpointStore();

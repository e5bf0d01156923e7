import {
  createContext,
  useCallback,
  useContext,
  useEffect,
  useMemo,
  useRef,
  useState,
  useSyncExternalStore,
  type ReactNode,
} from 'react';
import { ApiError, asApiError } from '../api/client';
import {
  MonitorClient,
  MonitorCommandError,
  initialMonitorState,
  socketUrl,
  type MonitorCommand,
  type MonitorState,
  type Problem,
} from '../api/monitorClient';
import {
  createProjectSession,
  downloadProgram,
  findProjectSession,
  getSessionDiagnostics,
  projectSources,
  type SessionOut,
  type SourceText,
} from '../api/sessions';
import { flushFile } from '../editor/autosave';
import { breakpoints } from '../editor/monitoring/breakpointStore';
import { useActiveProject } from '../projects/ActiveProject';
import { adoptSessionBreakpoints } from './reattach';

/**
 * The simulation session the workbench monitors: the running session of the active project.
 * It belongs to the project, not to this page: opening the project (a reload, a second tab,
 * another browser) attaches to the session the server runs for it, with its CPU state, forces,
 * breakpoints and trend; leaving the page or the project leaves the session running until the
 * server's idle time closes it. A download makes one when the project has none.
 */
export interface ActiveSession {
  id: string;
  projectId: number;
  blocks: string[];
  websocket: string;
}

export interface SessionContextValue {
  session: ActiveSession | null;
  client: MonitorClient | null;
  /** The project's files as last downloaded (symbols, which I/O bytes the program uses). */
  sources: readonly SourceText[];
  downloading: boolean;
  /** The last failure of a CPU action, shown by the toolbar until dismissed. */
  problem: Problem | null;
  /**
   * Downloads the active project: a new session, or the program of the running session replaced
   * (a CPU in RUN is stopped for it and warm-restarted after).
   */
  download: () => Promise<void>;
  /** Sends a command; a refusal becomes `problem`. Resolves with the ack's result or null. */
  command: (command: MonitorCommand) => Promise<Record<string, unknown> | null>;
  report: (problem: Problem | null) => void;
}

/** Any failure as the problem shape the UI translates. */
export function problemOf(error: unknown): Problem {
  if (error instanceof MonitorCommandError) return error;
  const api = error instanceof ApiError ? error : asApiError(error);
  return { code: api.code, key: api.key, message: api.message, params: api.params };
}

const noSession: SessionContextValue = {
  session: null,
  client: null,
  sources: [],
  downloading: false,
  problem: null,
  download: async () => undefined,
  command: async () => null,
  report: () => undefined,
};

const SessionContext = createContext<SessionContextValue>(noSession);

export interface SessionProviderProps {
  children: ReactNode;
  /** Makes the socket client (tests pass one with a fake socket). */
  createClient?: (session: ActiveSession) => MonitorClient;
}

function defaultClient(session: ActiveSession): MonitorClient {
  return new MonitorClient({
    url: socketUrl(session.websocket),
    loadDiagnostics: () => getSessionDiagnostics(session.id),
    // The breakpoints the session holds show again in the editors (another browser has none).
    onSessionState: (state) => adoptSessionBreakpoints(breakpoints, session.projectId, state.breakpoints),
  });
}

function fromOut(out: SessionOut, projectId: number): ActiveSession {
  return { id: out.id, projectId, blocks: out.blocks, websocket: out.websocket };
}

/** Where a tab remembers the project whose session it monitors, for the page after a reload. */
export const ATTACHED_PROJECT_KEY = 'nasaq.session.project';

function tabStorage(): Storage | null {
  try {
    return typeof sessionStorage === 'undefined' ? null : sessionStorage;
  } catch {
    return null;
  }
}

export function SessionProvider({ children, createClient = defaultClient }: SessionProviderProps) {
  const { projectId, setProjectId } = useActiveProject();
  const [session, setSession] = useState<ActiveSession | null>(null);
  const [client, setClient] = useState<MonitorClient | null>(null);
  const [sources, setSources] = useState<readonly SourceText[]>([]);
  const [downloading, setDownloading] = useState(false);
  const [problem, setProblem] = useState<Problem | null>(null);
  const current = useRef<{ session: ActiveSession | null; client: MonitorClient | null }>({ session: null, client: null });
  const busy = useRef(false);
  /** The project whose session this page wants (the active one). */
  const wantedProject = useRef<number | null>(projectId);

  /** Monitors `out` (closing the socket of the session monitored before, which runs on). */
  const attach = useCallback(
    async (out: SessionOut, project: number) => {
      const active = fromOut(out, project);
      current.current.client?.close();
      const made = createClient(active);
      current.current = { session: active, client: made };
      setSession(active);
      setClient(made);
      made.connect();
      const texts = await projectSources(project).catch(() => []);
      if (current.current.session === active) setSources(texts);
    },
    [createClient],
  );

  const detach = useCallback(() => {
    current.current.client?.close();
    current.current = { session: null, client: null };
    setSession(null);
    setClient(null);
    setSources([]);
  }, []);

  /** Attaches to the project's running session, if the server runs one. */
  const reattach = useCallback(
    async (project: number) => {
      const found = await findProjectSession(project).catch(() => null);
      // A download may have started meanwhile, or the user moved to another project.
      if (!found || busy.current || wantedProject.current !== project) return;
      if (current.current.session?.id === found.id && current.current.client?.getState().connection !== 'closed') return;
      await attach(found, project);
    },
    [attach],
  );

  // A reloaded page works on the project it was monitoring: that project is active again and
  // its session attached (the tab's own storage: a new tab starts with the project it opens).
  useEffect(() => {
    const saved = Number(tabStorage()?.getItem(ATTACHED_PROJECT_KEY) ?? NaN);
    if (projectId === null && Number.isInteger(saved) && saved > 0) setProjectId(saved);
  }, []); // only when the page starts
  useEffect(() => {
    try {
      if (session) tabStorage()?.setItem(ATTACHED_PROJECT_KEY, String(session.projectId));
    } catch {
      // A full or blocked storage: a reload then starts without a project, as before.
    }
  }, [session]);

  useEffect(() => {
    wantedProject.current = projectId;
    const running = current.current.session;
    if (running && running.projectId === projectId) return;
    // Another project: its session runs on (it belongs to its project); this one's is found.
    if (running) detach();
    if (projectId !== null) void reattach(projectId);
  }, [projectId, detach, reattach]);

  // A session closed under this page (a download in another tab replaced it, closed from the
  // session list, idle): the project's current session, if any, is attached instead.
  useEffect(() => {
    if (!client) return;
    return client.subscribe(() => {
      const { connection, closedBy } = client.getState();
      const running = current.current;
      if (connection !== 'closed' || !closedBy || running.client !== client || !running.session) return;
      if (busy.current) return;
      void reattach(running.session.projectId);
    });
  }, [client, reattach]);

  const start = useCallback(
    async (project: number) => {
      // The old CPU runs on until the new program has compiled, as on a real PLC; the server
      // then closes the project's older session.
      await attach(await createProjectSession(project), project);
    },
    [attach],
  );

  const download = useCallback(async () => {
    if (projectId === null || busy.current) return;
    busy.current = true;
    setDownloading(true);
    setProblem(null);
    try {
      // What the editor has not saved yet goes first: the server compiles the saved files.
      await flushFile(projectId).catch(() => undefined);
      const { session: running, client: socket } = current.current;
      const reusable =
        running !== null &&
        socket !== null &&
        running.projectId === projectId &&
        socket.getState().connection !== 'closed';
      if (!reusable) {
        await start(projectId);
        return;
      }
      const texts = await projectSources(projectId);
      // As TIA Portal's load dialog does by default: a running CPU is stopped for the download
      // and started again (warm restart) with the new program.
      const wasRunning = (socket.getState().cpu?.mode ?? 'STOP') !== 'STOP';
      if (wasRunning) await socket.send({ type: 'stop' });
      try {
        await downloadProgram(running.id, texts);
      } catch (error) {
        // The session was closed meanwhile (idle, server restart): start a new one.
        if (error instanceof ApiError && error.code === 'MON609') {
          await start(projectId);
          return;
        }
        throw error;
      }
      setSources(texts);
      socket.programReplaced();
      if (wasRunning) await socket.send({ type: 'run' });
    } catch (error) {
      setProblem(problemOf(error));
    } finally {
      busy.current = false;
      setDownloading(false);
    }
  }, [projectId, start]);

  const command = useCallback(async (message: MonitorCommand) => {
    const socket = current.current.client;
    if (!socket) return null;
    setProblem(null);
    try {
      return await socket.send(message);
    } catch (error) {
      setProblem(problemOf(error));
      return null;
    }
  }, []);

  // Ctrl+B (Cmd+B on a Mac) downloads, as in STEP 7.
  useEffect(() => {
    const onKey = (event: KeyboardEvent) => {
      if ((event.ctrlKey || event.metaKey) && !event.altKey && !event.shiftKey && event.key.toLowerCase() === 'b') {
        event.preventDefault();
        void download();
      }
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [download]);

  useEffect(() => () => current.current.client?.close(), []);

  const value = useMemo<SessionContextValue>(
    () => ({ session, client, sources, downloading, problem, download, command, report: setProblem }),
    [session, client, sources, downloading, problem, download, command],
  );
  return <SessionContext.Provider value={value}>{children}</SessionContext.Provider>;
}

export function useSession(): SessionContextValue {
  return useContext(SessionContext);
}

const IDLE: MonitorState = { ...initialMonitorState(), connection: 'closed' };
const noSubscription = () => () => undefined;

/** A part of the session's monitor state; re-renders when that part changes. */
export function useMonitor<T>(select: (state: MonitorState) => T): T {
  const { client } = useSession();
  const read = () => select(client ? client.getState() : IDLE);
  return useSyncExternalStore(client ? client.subscribe : noSubscription, read, read);
}

/** Watches `entries` while the calling component is mounted (`owner` names it). */
export function useWatchEntries(owner: string, entries: readonly string[]): void {
  const { client } = useSession();
  const key = entries.join('\n');
  useEffect(() => {
    if (!client) return;
    client.setWatch(owner, key === '' ? [] : key.split('\n'));
    return () => client.setWatch(owner, []);
  }, [client, owner, key]);
}

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
  deleteSession,
  downloadProgram,
  getSessionDiagnostics,
  projectSources,
  type SessionOut,
  type SourceText,
} from '../api/sessions';
import { flushFile } from '../editor/autosave';
import { useActiveProject } from '../projects/ActiveProject';

/** The simulation session the workbench monitors: one at a time, made by a download. */
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
  });
}

function fromOut(out: SessionOut, projectId: number): ActiveSession {
  return { id: out.id, projectId, blocks: out.blocks, websocket: out.websocket };
}

export function SessionProvider({ children, createClient = defaultClient }: SessionProviderProps) {
  const { projectId } = useActiveProject();
  const [session, setSession] = useState<ActiveSession | null>(null);
  const [client, setClient] = useState<MonitorClient | null>(null);
  const [sources, setSources] = useState<readonly SourceText[]>([]);
  const [downloading, setDownloading] = useState(false);
  const [problem, setProblem] = useState<Problem | null>(null);
  const current = useRef<{ session: ActiveSession | null; client: MonitorClient | null }>({ session: null, client: null });
  const busy = useRef(false);

  const start = useCallback(
    async (project: number) => {
      // The old CPU runs on until the new program has compiled, as on a real PLC.
      const created = fromOut(await createProjectSession(project), project);
      const old = current.current;
      old.client?.close();
      if (old.session) void deleteSession(old.session.id).catch(() => undefined);
      const made = createClient(created);
      current.current = { session: created, client: made };
      setSession(created);
      setClient(made);
      made.connect();
      setSources(await projectSources(project).catch(() => []));
    },
    [createClient],
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

  // Leaving the page ends the session rather than leaving it to the idle timeout.
  useEffect(() => {
    const onHide = () => {
      const running = current.current.session;
      if (!running) return;
      current.current.client?.close();
      void fetch(`/api/sessions/${encodeURIComponent(running.id)}`, { method: 'DELETE', keepalive: true }).catch(
        () => undefined,
      );
    };
    window.addEventListener('pagehide', onHide);
    return () => window.removeEventListener('pagehide', onHide);
  }, []);

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

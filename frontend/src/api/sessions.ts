/**
 * The REST side of simulation sessions (PROTOCOL.md, "Sessions"): create one from a project's
 * saved files, find the project's running session (to attach to it after a reload or in another
 * tab), list them all, download a changed program in STOP, the diagnostic buffer, the trend CSV,
 * delete.
 * Failures are {@link ApiError}s with the catalogue's code and key, as for every API call.
 */
import { ApiError, CLIENT_ERROR_CODES, getFile, listFiles } from './client';
import type { CpuState, DiagnosticEntry } from './monitor';
import type { ApiProblem } from './types';

/** `POST /api/projects/{id}/sessions`, `GET /api/sessions/{id}` (backend `SessionOut`). */
export interface SessionOut {
  id: string;
  blocks: string[];
  cpu: CpuState;
  /** The connected sockets (their hello's `client`). */
  clients: number[];
  /** The socket's path on this server, e.g. `/api/sessions/ab12/ws`. */
  websocket: string;
  /** The project the session was made from (null: sources posted directly). */
  project_id: number | null;
  /** That project's current name. */
  project_name: string | null;
  profile: 'S7-300' | 'S7-400' | 'S7-1500';
  /** When it was created (ISO 8601, UTC). */
  started_at: string;
  age_seconds: number;
}

/** `PUT /api/sessions/{id}/program` (backend `DownloadOut`). */
export interface DownloadOut {
  changed: string[];
}

/** One source file sent with a download (backend `Source`). */
export interface SourceText {
  name: string;
  text: string;
}

const UNREACHABLE: ApiProblem = {
  code: CLIENT_ERROR_CODES.unreachable,
  key: 'server_unreachable',
  message: 'The Nasaq server cannot be reached.',
};

async function problemOf(response: Response): Promise<ApiProblem> {
  try {
    const body = (await response.json()) as { error?: Partial<ApiProblem> } | null;
    const error = body?.error;
    if (error && typeof error.code === 'string' && typeof error.key === 'string' && typeof error.message === 'string') {
      return error as ApiProblem;
    }
  } catch {
    // not JSON: below
  }
  if (response.status >= 502 && response.status <= 504) return UNREACHABLE;
  return {
    code: CLIENT_ERROR_CODES.badResponse,
    key: 'unexpected_response',
    message: `The server answered HTTP ${response.status} without an error description.`,
    params: { status: response.status },
  };
}

async function call<T>(method: string, path: string, body?: unknown, parse: 'json' | 'none' = 'json'): Promise<T> {
  const headers: Record<string, string> = { Accept: 'application/json' };
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  let response: Response;
  try {
    response = await fetch(path, {
      method,
      headers,
      ...(body === undefined ? {} : { body: JSON.stringify(body) }),
    });
  } catch {
    throw new ApiError(UNREACHABLE, 0);
  }
  if (!response.ok) throw new ApiError(await problemOf(response), response.status);
  if (parse === 'none') return undefined as T;
  try {
    return (await response.json()) as T;
  } catch {
    throw new ApiError(
      { code: CLIENT_ERROR_CODES.badResponse, key: 'unexpected_response', message: 'The answer is not JSON.' },
      response.status,
    );
  }
}

const sessionPath = (id: string) => `/api/sessions/${encodeURIComponent(id)}`;

/** Compiles the project's saved files into a new simulated CPU, in STOP. 422 MON611 when they do not compile. */
export function createProjectSession(projectId: number): Promise<SessionOut> {
  return call<SessionOut>('POST', `/api/projects/${projectId}/sessions`, {});
}

/** Every session on the server, newest first; with `projectId` only that project's. */
export function listSessions(projectId?: number): Promise<SessionOut[]> {
  return call<SessionOut[]>('GET', projectId === undefined ? '/api/sessions' : `/api/sessions?project_id=${projectId}`);
}

/** The project's running session (the newest), or null when it runs none. */
export async function findProjectSession(projectId: number): Promise<SessionOut | null> {
  return (await listSessions(projectId))[0] ?? null;
}

export function getSession(id: string): Promise<SessionOut> {
  return call<SessionOut>('GET', sessionPath(id));
}

/** Replaces the program of a session in STOP (409 MON607 in RUN). */
export function downloadProgram(id: string, sources: SourceText[]): Promise<DownloadOut> {
  return call<DownloadOut>('PUT', `${sessionPath(id)}/program`, { sources });
}

export function deleteSession(id: string): Promise<void> {
  return call<void>('DELETE', sessionPath(id), undefined, 'none');
}

export function getSessionDiagnostics(id: string): Promise<DiagnosticEntry[]> {
  return call<DiagnosticEntry[]>('GET', `${sessionPath(id)}/diagnostics`);
}

/** Where the trend samples of socket `client` are served as CSV. */
export function trendCsvUrl(id: string, client: number): string {
  return `${sessionPath(id)}/trend.csv?client=${client}`;
}

/** Every saved source of the project with its text, as a download sends them (watch tables are
 * project files but no program: they stay out). */
export async function projectSources(projectId: number): Promise<SourceText[]> {
  const files = (await listFiles(projectId)).filter((file) => file.language !== 'watch');
  const texts = await Promise.all(files.map((file) => getFile(projectId, file.name)));
  return texts.map(({ name, text }) => ({ name, text }));
}

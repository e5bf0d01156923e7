import type {
  ApiProblem,
  Diagnostic,
  ErrorLocation,
  FileInfo,
  FileOut,
  FileSave,
  Health,
  ImportOut,
  Project,
  ProjectBuild,
  ProjectCreate,
  UnsavedFile,
} from './types';
import type { GraphBlock } from '../graph/model';
import type { LadBlock } from '../lad/model';

/** Codes the client itself gives to failures that never reached an API answer. */
export const CLIENT_ERROR_CODES = {
  unreachable: 'NET000',
  badResponse: 'NET001',
} as const;

/** A failed API call: the server's error object, or a client-side stand-in for it. */
export class ApiError extends Error {
  readonly code: string;
  readonly key: string;
  readonly params: Record<string, unknown>;
  readonly location: ErrorLocation | null;
  /** HTTP status, or 0 when the server could not be reached at all. */
  readonly status: number;

  constructor(problem: ApiProblem, status: number) {
    super(problem.message);
    this.name = 'ApiError';
    this.code = problem.code;
    this.key = problem.key;
    this.params = problem.params ?? {};
    this.location = problem.location ?? null;
    this.status = status;
  }

  /** True when no server answered (network down, server stopped, proxy failed). */
  get unreachable(): boolean {
    return this.status === 0 || this.code === CLIENT_ERROR_CODES.unreachable;
  }
}

/** Any thrown value as an ApiError (unknown failures become "unexpected response"). */
export function asApiError(error: unknown): ApiError {
  if (error instanceof ApiError) return error;
  return new ApiError(
    { code: CLIENT_ERROR_CODES.badResponse, key: 'unexpected_response', message: String(error) },
    0,
  );
}

function isProblem(value: unknown): value is ApiProblem {
  if (typeof value !== 'object' || value === null) return false;
  const candidate = value as Record<string, unknown>;
  return (
    typeof candidate.code === 'string' &&
    typeof candidate.message === 'string' &&
    typeof candidate.key === 'string'
  );
}

async function problemFrom(response: Response): Promise<ApiProblem> {
  let body: unknown = null;
  try {
    body = await response.json();
  } catch {
    body = null;
  }
  const error = typeof body === 'object' && body !== null ? (body as { error?: unknown }).error : null;
  if (isProblem(error)) return error;
  // A proxy with no backend behind it answers 502/503/504 without our error shape.
  if (response.status === 502 || response.status === 503 || response.status === 504) {
    return {
      code: CLIENT_ERROR_CODES.unreachable,
      key: 'server_unreachable',
      message: `The Nasaq server cannot be reached (HTTP ${response.status}).`,
    };
  }
  return {
    code: CLIENT_ERROR_CODES.badResponse,
    key: 'unexpected_response',
    message: `The server answered HTTP ${response.status} without an error description.`,
    params: { status: response.status },
  };
}

/** A JSON call to the API; failures are {@link ApiError}s with the catalogue's code. */
export async function request<T>(path: string, init: RequestInit = {}): Promise<T> {
  const headers = new Headers(init.headers);
  headers.set('Accept', 'application/json');
  if (init.body !== undefined && !headers.has('Content-Type')) headers.set('Content-Type', 'application/json');

  let response: Response;
  try {
    response = await fetch(path, { ...init, headers });
  } catch (cause) {
    if (cause instanceof DOMException && cause.name === 'AbortError') throw cause;
    throw new ApiError(
      {
        code: CLIENT_ERROR_CODES.unreachable,
        key: 'server_unreachable',
        message: 'The Nasaq server cannot be reached.',
      },
      0,
    );
  }

  if (!response.ok) throw new ApiError(await problemFrom(response), response.status);
  if (response.status === 204) return undefined as T;

  try {
    return (await response.json()) as T;
  } catch {
    throw new ApiError(
      {
        code: CLIENT_ERROR_CODES.badResponse,
        key: 'unexpected_response',
        message: 'The server answered with something that is not JSON.',
        params: { status: response.status },
      },
      response.status,
    );
  }
}

export function getHealth(signal?: AbortSignal): Promise<Health> {
  return request<Health>('/api/health', { signal: signal ?? null });
}

export function listProjects(signal?: AbortSignal): Promise<Project[]> {
  return request<Project[]>('/api/projects', { signal: signal ?? null });
}

export function createProject(input: ProjectCreate): Promise<Project> {
  return request<Project>('/api/projects', {
    method: 'POST',
    body: JSON.stringify({ name: input.name, description: input.description }),
  });
}

/** `PATCH /api/projects/{id}`: a new name (unique, letter case aside; API105 otherwise). */
export function renameProject(projectId: number, name: string): Promise<Project> {
  return request<Project>(`/api/projects/${projectId}`, { method: 'PATCH', body: JSON.stringify({ name }) });
}

export function deleteProject(projectId: number): Promise<void> {
  return request<void>(`/api/projects/${projectId}`, { method: 'DELETE' });
}

/** `/api/projects/{id}/files/{name}`, the name escaped (names may hold spaces and any letters). */
export function fileUrl(projectId: number, name: string): string {
  return `/api/projects/${projectId}/files/${encodeURIComponent(name)}`;
}

export function listFiles(projectId: number, signal?: AbortSignal): Promise<FileInfo[]> {
  return request<FileInfo[]>(`/api/projects/${projectId}/files`, { signal: signal ?? null });
}

export function getFile(projectId: number, name: string, signal?: AbortSignal): Promise<FileOut> {
  return request<FileOut>(fileUrl(projectId, name), { signal: signal ?? null });
}

/**
 * Creates or replaces a file (autosave). With `base_version` the server refuses a stale save
 * with 409 (API111, `params.current_version`); without it the save is unconditional.
 */
export function saveFile(
  projectId: number,
  name: string,
  body: FileSave,
  options: { signal?: AbortSignal; keepalive?: boolean } = {},
): Promise<FileInfo> {
  return request<FileInfo>(fileUrl(projectId, name), {
    method: 'PUT',
    body: JSON.stringify({ text: body.text, base_version: body.base_version ?? null }),
    signal: options.signal ?? null,
    keepalive: options.keepalive ?? false,
  });
}

export function renameFile(projectId: number, name: string, newName: string): Promise<FileInfo> {
  return request<FileInfo>(fileUrl(projectId, name), { method: 'PATCH', body: JSON.stringify({ name: newName }) });
}

export function duplicateFile(projectId: number, name: string, newName: string): Promise<FileInfo> {
  return request<FileInfo>(`${fileUrl(projectId, name)}/duplicate`, {
    method: 'POST',
    body: JSON.stringify({ name: newName }),
  });
}

export function deleteFile(projectId: number, name: string): Promise<void> {
  return request<void>(fileUrl(projectId, name), { method: 'DELETE' });
}

/** The blocks the project's saved files define, and the compiler's diagnostics. */
export function getBlocks(projectId: number, signal?: AbortSignal): Promise<ProjectBuild> {
  return request<ProjectBuild>(`/api/projects/${projectId}/blocks`, { signal: signal ?? null });
}

/** Compiles the project with one unsaved editor text in place of its stored file. */
export function checkSource(projectId: number, unsaved: UnsavedFile, signal?: AbortSignal): Promise<ProjectBuild> {
  return request<ProjectBuild>(`/api/projects/${projectId}/check`, {
    method: 'POST',
    body: JSON.stringify({ name: unsaved.name, text: unsaved.text }),
    signal: signal ?? null,
  });
}

/** Where the browser downloads the project as a zip of its sources. */
export function exportUrl(projectId: number): string {
  return `/api/projects/${projectId}/export.zip`;
}

/** Creates a project from a zip of sources; without a name the zip's one top folder names it. */
export function importProject(zip: Blob, name?: string): Promise<ImportOut> {
  const query = name ? `?name=${encodeURIComponent(name)}` : '';
  return request<ImportOut>(`/api/projects/import${query}`, {
    method: 'POST',
    body: zip,
    headers: { 'Content-Type': 'application/zip' },
  });
}

/** A LAD/FBD file read as the network model (`POST /api/lad/read`): its blocks and syntax problems. */
export interface LadRead {
  blocks: LadBlock[];
  diagnostics: Diagnostic[];
}

export function readLad(name: string, text: string, signal?: AbortSignal): Promise<LadRead> {
  return request<LadRead>('/api/lad/read', { method: 'POST', body: JSON.stringify({ name, text }), signal: signal ?? null });
}

/**
 * An S7-Graph file read as the sequencer model (`POST /api/graph/read`): its blocks, its syntax
 * problems (the chart is not drawn while there are errors), the checker's findings and, per
 * block, the line of each part (`S3`, `T2`, `S3/A1`, `SEQ:<name>` ...).
 */
export interface GraphRead {
  blocks: GraphBlock[];
  diagnostics: Diagnostic[];
  problems: Diagnostic[];
  places: Record<string, number>[];
}

export function readGraph(name: string, text: string, signal?: AbortSignal): Promise<GraphRead> {
  return request<GraphRead>('/api/graph/read', { method: 'POST', body: JSON.stringify({ name, text }), signal: signal ?? null });
}

/** A source converted between STL, LAD and FBD (`POST /api/convert`). */
export interface Converted {
  text: string;
  diagnostics: Diagnostic[];
  converted: number;
  kept: number;
  blocks: LadBlock[] | null;
}

export function convertSource(name: string, text: string, to: 'stl' | 'lad' | 'fbd', signal?: AbortSignal): Promise<Converted> {
  return request<Converted>('/api/convert', { method: 'POST', body: JSON.stringify({ name, text, to }), signal: signal ?? null });
}

/** Turns a project's STL source into a LAD (or FBD) source: the new file replaces it. */
export function convertFile(projectId: number, name: string, to: 'lad' | 'fbd'): Promise<FileInfo> {
  return request<FileInfo>(`${fileUrl(projectId, name)}/convert`, { method: 'POST', body: JSON.stringify({ to }) });
}

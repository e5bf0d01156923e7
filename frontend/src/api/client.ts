import type { ApiProblem, ErrorLocation, Health, Project, ProjectCreate } from './types';

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

async function request<T>(path: string, init: RequestInit = {}): Promise<T> {
  const headers = new Headers(init.headers);
  headers.set('Accept', 'application/json');
  if (init.body !== undefined) headers.set('Content-Type', 'application/json');

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

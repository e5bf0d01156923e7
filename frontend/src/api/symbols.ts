/**
 * The symbol table editor's and the DB editor's calls (backend `nasaq.api.symbols`):
 * `/api/projects/{id}/symbols/{file}` (rows with problems, versioned save, export, import) and
 * `/api/projects/{id}/blocks/{block}/members` (a DB's variables with their values).
 * Failures are {@link ApiError}s with the catalogue's code, as for every call.
 */
import { ApiError, CLIENT_ERROR_CODES } from './client';
import type { OutlineMember } from './outline';
import type { ApiProblem, Diagnostic } from './types';

export type SymbolFormat = 'sdf' | 'asc' | 'seq' | 'csv';
export const SYMBOL_FORMATS: readonly SymbolFormat[] = ['sdf', 'asc', 'seq', 'csv'];
export type SymbolField = 'name' | 'address' | 'type' | 'comment';
export const SYMBOL_FIELDS: readonly SymbolField[] = ['name', 'address', 'type', 'comment'];

/** One row of a symbol table (backend `SymbolRow`). */
export interface SymbolRow {
  name: string;
  address: string;
  type: string;
  comment: string;
}

/** What is wrong with one cell (backend `RowProblem`): `row` counts from 0. */
export interface RowProblem {
  row: number;
  field: SymbolField;
  problem: Diagnostic;
}

/** `GET`/`PUT /symbols/{file}` (backend `SymbolTableOut`). */
export interface SymbolTableOut {
  name: string;
  format: SymbolFormat;
  version: number;
  rows: SymbolRow[];
  problems: RowProblem[];
}

export type ImportMode = 'replace' | 'merge';

/** A DB's variables (backend `DbMembersOut`); members as the outline's. */
export interface DbMembers {
  kind: 'DB';
  number: number;
  name: string;
  file: string;
  line: number | null;
  instance_of: number | null;
  members: OutlineMember[];
}

export type { OutlineMember as DbMember } from './outline';

function clientProblem(code: string, key: string, message: string, status: number): ApiError {
  const body: ApiProblem = { code, key, message, params: { status } };
  return new ApiError(body, status);
}

async function call<T>(url: string, init: RequestInit = {}): Promise<T> {
  const headers = new Headers(init.headers);
  headers.set('Accept', 'application/json');
  if (typeof init.body === 'string' && !headers.has('Content-Type')) headers.set('Content-Type', 'application/json');
  let response: Response;
  try {
    response = await fetch(url, { ...init, headers });
  } catch (cause) {
    if (cause instanceof DOMException && cause.name === 'AbortError') throw cause;
    throw clientProblem(CLIENT_ERROR_CODES.unreachable, 'server_unreachable', 'The Nasaq server cannot be reached.', 0);
  }
  let body: unknown = null;
  try {
    body = await response.json();
  } catch {
    body = null;
  }
  if (response.ok && body !== null) return body as T;
  const error = (body as { error?: ApiProblem } | null)?.error;
  if (error && typeof error.code === 'string' && typeof error.key === 'string') throw new ApiError(error, response.status);
  throw clientProblem(
    CLIENT_ERROR_CODES.badResponse,
    'unexpected_response',
    `The server answered HTTP ${response.status} without an error description.`,
    response.status,
  );
}

export function symbolsUrl(projectId: number, file: string): string {
  return `/api/projects/${projectId}/symbols/${encodeURIComponent(file)}`;
}

export function getSymbols(projectId: number, file: string, signal?: AbortSignal): Promise<SymbolTableOut> {
  return call<SymbolTableOut>(symbolsUrl(projectId, file), { signal: signal ?? null });
}

/** Saves rows into the file (its own format); a stale `baseVersion` is refused with 409 API111. */
export function saveSymbols(
  projectId: number,
  file: string,
  rows: readonly SymbolRow[],
  baseVersion: number | null,
  options: { keepalive?: boolean } = {},
): Promise<SymbolTableOut> {
  return call<SymbolTableOut>(symbolsUrl(projectId, file), {
    method: 'PUT',
    body: JSON.stringify({ rows, base_version: baseVersion }),
    keepalive: options.keepalive ?? false,
  });
}

/** Where the browser downloads the table in a STEP 7 format (Windows-1252, CRLF). */
export function symbolsExportUrl(projectId: number, file: string, format: SymbolFormat): string {
  return `${symbolsUrl(projectId, file)}/export?format=${format}`;
}

/** Reads an uploaded table (`upload.name` says its format) into the file: replaced or merged by name. */
export function importSymbols(
  projectId: number,
  file: string,
  upload: Blob,
  uploadName: string,
  mode: ImportMode,
  baseVersion: number | null,
): Promise<SymbolTableOut> {
  const query = new URLSearchParams({ name: uploadName, mode });
  if (baseVersion !== null) query.set('base_version', String(baseVersion));
  return call<SymbolTableOut>(`${symbolsUrl(projectId, file)}/import?${query}`, {
    method: 'POST',
    body: upload,
    headers: { 'Content-Type': 'application/octet-stream' },
  });
}

/** A DB's variables, by `DB10` or its symbol. */
export function getDbMembers(projectId: number, block: string, signal?: AbortSignal): Promise<DbMembers> {
  return call<DbMembers>(`/api/projects/${projectId}/blocks/${encodeURIComponent(block)}/members`, { signal: signal ?? null });
}

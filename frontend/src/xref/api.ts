/**
 * Cross-references, the assignment list and rename (backend `nasaq.api.xref`). Failures are
 * {@link ApiError}s with the catalogue's code (XRF7xx), as for every call.
 */
import { ApiError, CLIENT_ERROR_CODES } from '../api/client';
import type { ApiProblem } from '../api/types';

export type Access = 'read' | 'write' | 'read_write' | 'set' | 'reset' | 'start' | 'count' | 'enable' | 'call' | 'open';

/** One use of an operand (backend `XrefEntry`). */
export interface XrefEntry {
  file: string;
  block: string;
  block_name: string;
  language: string;
  network: number | null;
  line: number;
  column: number;
  element: string | null;
  access: Access;
  instruction: string;
  address: string;
  symbol: string;
  exact: boolean;
}

export interface XrefResult {
  target: string;
  address: string;
  symbol: string;
  entries: XrefEntry[];
}

export interface AssignedBit {
  bit: number;
  read: boolean;
  write: boolean;
  symbol: string;
}

export interface AssignedByte {
  area: string;
  byte: number;
  bits: AssignedBit[];
  widths: ('byte' | 'word' | 'dword')[];
  symbols: string[];
}

export interface AssignedTimer {
  kind: 'T' | 'C';
  number: number;
  accesses: Access[];
  symbol: string;
}

export interface AssignmentList {
  bytes: AssignedByte[];
  timers: AssignedTimer[];
}

export interface RenameChange {
  file: string;
  line: number;
  column: number;
  before: string;
  after: string;
}

export interface FileVersion {
  name: string;
  version: number;
}

export interface RenamePreview {
  target: string;
  kind: 'symbol' | 'block' | 'member';
  old_name: string;
  new_name: string;
  changes: RenameChange[];
  files: FileVersion[];
}

export interface UndoFile {
  name: string;
  text: string;
  version: number;
}

export interface RenameApplied extends RenamePreview {
  undo: UndoFile[];
}

function clientProblem(code: string, key: string, message: string, status: number): ApiError {
  const body: ApiProblem = { code, key, message, params: { status } };
  return new ApiError(body, status);
}

async function call<T>(url: string, init: RequestInit = {}): Promise<T> {
  const headers = new Headers(init.headers);
  headers.set('Accept', 'application/json');
  if (init.body !== undefined) headers.set('Content-Type', 'application/json');
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
    `The server answered HTTP ${response.status} without an answer.`,
    response.status,
  );
}

const base = (projectId: number) => `/api/projects/${projectId}`;

export function getCrossReferences(projectId: number, target: string, signal?: AbortSignal): Promise<XrefResult> {
  const query = new URLSearchParams({ target });
  return call<XrefResult>(`${base(projectId)}/xref?${query.toString()}`, { signal: signal ?? null });
}

export function getAssignments(projectId: number, signal?: AbortSignal): Promise<AssignmentList> {
  return call<AssignmentList>(`${base(projectId)}/assignments`, { signal: signal ?? null });
}

export function previewRename(projectId: number, target: string, newName: string): Promise<RenamePreview> {
  return call<RenamePreview>(`${base(projectId)}/rename/preview`, {
    method: 'POST',
    body: JSON.stringify({ target, new_name: newName }),
  });
}

export function applyRename(projectId: number, preview: RenamePreview): Promise<RenameApplied> {
  return call<RenameApplied>(`${base(projectId)}/rename`, {
    method: 'POST',
    body: JSON.stringify({ target: preview.target, new_name: preview.new_name, files: preview.files }),
  });
}

export function undoRename(projectId: number, undo: UndoFile[]): Promise<{ files: FileVersion[] }> {
  return call<{ files: FileVersion[] }>(`${base(projectId)}/rename/undo`, {
    method: 'POST',
    body: JSON.stringify({ files: undo }),
  });
}

/**
 * `GET /api/projects/{id}/outline`: a project's symbols and blocks with their interface members,
 * what the editor completes, explains on hover and jumps to (backend `nasaq.workbench.outline`).
 * The shapes are held to the OpenAPI document by `tests/frontend/intellisenseApi.test.ts`.
 */
import { ApiError, CLIENT_ERROR_CODES } from './client';
import type { ApiProblem, BlockKind, BlockLanguage } from './types';

/** One row of a symbol table (backend `OutlineSymbol`). */
export interface OutlineSymbol {
  name: string;
  /** As the table writes it, spacing normalised: `Q 4.0`, `DB 1`. */
  address: string;
  type: string;
  comment: string;
  file: string;
  line: number;
}

export type MemberSection = 'IN' | 'OUT' | 'IN_OUT' | 'STAT' | 'TEMP' | 'RETURN' | 'DATA';

/** A variable of a block's interface or a DB's data, flattened (backend `Member`). */
export interface OutlineMember {
  /** Dotted from the top: `Motor.Speed`, `Values[1]`. */
  path: string;
  name: string;
  type: string;
  section: MemberSection;
  depth: number;
  offset: string | null;
  initial: string | null;
  actual: string | null;
  comment: string;
  elementary: boolean;
  file: string | null;
  line: number | null;
}

/** An S7-Graph step (backend `OutlineStep`). */
export interface OutlineStep {
  number: number;
  name: string;
  initial: boolean;
  line: number;
}

/** An S7-Graph transition from its source step(s) to its target step(s) (backend `OutlineTransition`). */
export interface OutlineTransition {
  number: number;
  name: string;
  source: string[];
  /** Empty: a sequence end. */
  target: string[];
  line: number;
}

/** One sequencer of an S7-Graph FB, for jumping to its steps and transitions (backend `OutlineSequencer`). */
export interface OutlineSequencer {
  name: string;
  line: number;
  steps: OutlineStep[];
  transitions: OutlineTransition[];
}

/** A block with its members (backend `OutlineBlock`). */
export interface OutlineBlock {
  kind: BlockKind;
  number: number;
  name: string;
  language: BlockLanguage;
  file: string;
  line: number | null;
  return_type: string | null;
  instance_of: string | null;
  members: OutlineMember[];
  /** An S7-Graph FB's sequencers; absent or null for every other block. */
  sequencers?: OutlineSequencer[] | null;
}

export interface ProjectOutline {
  symbols: OutlineSymbol[];
  blocks: OutlineBlock[];
}

function problem(code: string, key: string, message: string, status: number): ApiError {
  const body: ApiProblem = { code, key, message, params: { status } };
  return new ApiError(body, status);
}

/** The outline; failures are {@link ApiError}s with the catalogue's code, as for every call. */
export async function getOutline(projectId: number, signal?: AbortSignal): Promise<ProjectOutline> {
  let response: Response;
  try {
    response = await fetch(`/api/projects/${projectId}/outline`, { headers: { Accept: 'application/json' }, signal: signal ?? null });
  } catch (cause) {
    if (cause instanceof DOMException && cause.name === 'AbortError') throw cause;
    throw problem(CLIENT_ERROR_CODES.unreachable, 'server_unreachable', 'The Nasaq server cannot be reached.', 0);
  }
  let body: unknown = null;
  try {
    body = await response.json();
  } catch {
    body = null;
  }
  if (response.ok && body !== null) return body as ProjectOutline;
  const error = (body as { error?: ApiProblem } | null)?.error;
  if (error && typeof error.code === 'string' && typeof error.key === 'string') throw new ApiError(error, response.status);
  throw problem(
    CLIENT_ERROR_CODES.badResponse,
    'unexpected_response',
    `The server answered HTTP ${response.status} without an outline.`,
    response.status,
  );
}

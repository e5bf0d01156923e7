/**
 * Cross-references, the assignment list and rename (backend `nasaq.api.xref`). Failures are
 * {@link ApiError}s with the catalogue's code (XRF7xx), as for every call.
 */
import { request as call } from '../api/client';

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

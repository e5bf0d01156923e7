import { deleteFile, renameFile, saveFile } from '../api/client';
import type { FileInfo } from '../api/types';
import { discardFile, flushFile } from '../editor/autosave';
import { readStoredList, forgetStoredList } from '../panels/useStoredList';
import type { DisplayFormat } from '../panels/watchFormat';
import { projectContents } from '../projects/projectContents';
import { HEADER, WATCH_TABLE_SUFFIX, isWatchTableName, printWatchTable, type WatchLine } from './format';

/** The project's watch tables, by name. */
export function watchTableFiles(files: readonly FileInfo[]): FileInfo[] {
  return files.filter((file) => isWatchTableName(file.name));
}

/** `VAT_1`, `VAT_2`, …: the first name STEP 7 would give a new table that no file uses. */
export function freeTableName(files: readonly FileInfo[]): string {
  const taken = new Set(files.map((file) => file.name.toLowerCase()));
  let number = 1;
  while (taken.has(`vat_${number}${WATCH_TABLE_SUFFIX}`)) number += 1;
  return `VAT_${number}`;
}

const FORBIDDEN = /[\u0000-\u001f\u007f/\\:*?"<>|]/;

/** Whether a table name is one the server takes as a file name (workbench/names.py). */
export function isTableName(name: string): boolean {
  return name.trim() === name && name !== '' && !name.startsWith('.') && !name.endsWith('.') && !FORBIDDEN.test(name);
}

export async function createTable(projectId: number, title: string, lines: WatchLine[] = []): Promise<FileInfo> {
  const name = `${title}${WATCH_TABLE_SUFFIX}`;
  const info = await saveFile(projectId, name, { text: printWatchTable({ header: [HEADER], lines }) });
  projectContents.putFile(projectId, info);
  return info;
}

export async function renameTable(projectId: number, name: string, title: string): Promise<FileInfo> {
  await flushFile(projectId, name);
  const info = await renameFile(projectId, name, `${title}${WATCH_TABLE_SUFFIX}`);
  projectContents.putFile(projectId, info, name);
  return info;
}

export async function deleteTable(projectId: number, name: string): Promise<void> {
  discardFile(projectId, name);
  await deleteFile(projectId, name);
  projectContents.removeFile(projectId, name);
}

/** Where the watch table of a project was kept before tables became files. */
export const legacyStorageKey = (projectId: number) => `nasaq.watch.${projectId}`;

interface LegacyRow {
  entry: string;
  format: DisplayFormat | null;
}

function isLegacyRow(item: unknown): item is LegacyRow {
  const row = item as LegacyRow | null;
  return typeof row === 'object' && row !== null && typeof row.entry === 'string';
}

const migrating = new Set<number>();

/**
 * Moves the rows the browser kept for a project (before watch tables were files) into a new
 * table file, once; the stored list is forgotten only after the file is saved. Resolves with
 * the new file, or null when there was nothing to move.
 */
export async function migrateLegacyTable(projectId: number, files: readonly FileInfo[]): Promise<FileInfo | null> {
  const key = legacyStorageKey(projectId);
  const rows = readStoredList(key, isLegacyRow);
  if (rows.length === 0 || migrating.has(projectId)) return null;
  migrating.add(projectId);
  try {
    const lines: WatchLine[] = rows.map((row) => ({
      kind: 'row',
      row: { operand: row.entry.trim(), format: row.format, modify: '', force: '', comment: '' },
    }));
    const info = await createTable(projectId, freeTableName(files), lines);
    forgetStoredList(key);
    return info;
  } finally {
    migrating.delete(projectId);
  }
}

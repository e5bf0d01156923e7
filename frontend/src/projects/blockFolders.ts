import type { ComponentType } from 'react';
import type { BlockKind } from '../api/types';
import { BlocksIcon, EyeIcon, FolderIcon, TableIcon, TypeIcon } from '../ui/icons';

/**
 * The folders every S7 project shows under its name: its blocks by kind, as SIMATIC Manager and
 * TIA Portal list them, and its source files (STL, SCL and the symbol table), as STEP 7's
 * "Sources" folder does.
 */
export type FolderId = BlockKind | 'sources' | 'watch';

export interface BlockFolder {
  id: FolderId;
  /** Catalogue key of the folder's name. */
  labelKey: string;
  Icon: ComponentType<{ className?: string }>;
}

export const BLOCK_FOLDERS: readonly BlockFolder[] = [
  { id: 'OB', labelKey: 'projects.folders.ob', Icon: BlocksIcon },
  { id: 'FB', labelKey: 'projects.folders.fb', Icon: BlocksIcon },
  { id: 'FC', labelKey: 'projects.folders.fc', Icon: BlocksIcon },
  { id: 'DB', labelKey: 'projects.folders.db', Icon: TableIcon },
  { id: 'UDT', labelKey: 'projects.folders.udt', Icon: TypeIcon },
  { id: 'sources', labelKey: 'projects.folders.sources', Icon: FolderIcon },
  // TIA Portal's "Watch and force tables": the project's .vat files (watchtables/format.ts)
  { id: 'watch', labelKey: 'watchTables.folder', Icon: EyeIcon },
];

export const projectKey = (id: number) => `project:${id}`;
export const folderKey = (id: number, folder: FolderId) => `project:${id}/${folder}`;
export const blockKey = (id: number, kind: BlockKind, number: number) => `project:${id}/${kind}/${kind}${number}`;
export const fileKey = (id: number, name: string) => `project:${id}/sources/${name}`;

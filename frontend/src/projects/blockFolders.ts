import type { ComponentType } from 'react';
import { BlocksIcon, TableIcon, TypeIcon } from '../ui/icons';

/** The folders every S7 project shows under its name, as in SIMATIC Manager and TIA Portal. */
export interface BlockFolder {
  id: 'blocks' | 'types' | 'symbols';
  /** Catalogue key of the folder's name. */
  labelKey: string;
  Icon: ComponentType<{ className?: string }>;
}

export const BLOCK_FOLDERS: readonly BlockFolder[] = [
  { id: 'blocks', labelKey: 'projects.folders.blocks', Icon: BlocksIcon },
  { id: 'types', labelKey: 'projects.folders.types', Icon: TypeIcon },
  { id: 'symbols', labelKey: 'projects.folders.symbols', Icon: TableIcon },
];

export const projectKey = (id: number) => `project:${id}`;
export const folderKey = (id: number, folder: BlockFolder['id']) => `project:${id}/${folder}`;

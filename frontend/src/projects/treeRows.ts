import type { ApiError } from '../api/client';
import type { FileInfo, Project, TreeBlock } from '../api/types';
import { BLOCK_FOLDERS, blockKey, fileKey, folderKey, projectKey, type BlockFolder } from './blockFolders';
import type { ProjectContents } from './projectContents';

interface RowBase {
  key: string;
  level: number;
  posinset: number;
  setsize: number;
  projectId: number;
}

export type TreeRow =
  | (RowBase & { type: 'project'; project: Project; expanded: boolean })
  | (RowBase & { type: 'folder'; folder: BlockFolder; count: number; expanded: boolean | null })
  | (RowBase & { type: 'block'; block: TreeBlock })
  | (RowBase & { type: 'file'; file: FileInfo })
  | (RowBase & { type: 'loading' })
  | (RowBase & { type: 'error'; error: ApiError });

/** Projects start closed, folders open; `toggled` holds the keys the user turned the other way. */
export function isExpanded(key: string, toggled: ReadonlySet<string>): boolean {
  const byDefault = !/^project:\d+$/.test(key);
  return toggled.has(key) ? !byDefault : byDefault;
}

/** How a block reads in the tree: `OB1`, `FB10`. */
export function blockLabel(block: TreeBlock): string {
  return `${block.kind}${block.number}`;
}

/**
 * The visible rows of the flat tree, in order: each project, and under an open one its block
 * folders that have blocks, then its Sources folder; under an open folder its blocks or files.
 */
export function treeRows(
  projects: readonly Project[],
  toggled: ReadonlySet<string>,
  contentsOf: (projectId: number) => ProjectContents | undefined,
): TreeRow[] {
  const rows: TreeRow[] = [];
  projects.forEach((project, index) => {
    const key = projectKey(project.id);
    const expanded = isExpanded(key, toggled);
    rows.push({
      type: 'project',
      key,
      level: 1,
      posinset: index + 1,
      setsize: projects.length,
      projectId: project.id,
      project,
      expanded,
    });
    if (!expanded) return;
    const contents = contentsOf(project.id);
    if (!contents || (contents.status === 'loading' && contents.files.length === 0)) {
      rows.push({ type: 'loading', key: `${key}/loading`, level: 2, posinset: 1, setsize: 1, projectId: project.id });
      return;
    }
    if (contents.status === 'error' && contents.error) {
      rows.push({
        type: 'error',
        key: `${key}/error`,
        level: 2,
        posinset: 1,
        setsize: 1,
        projectId: project.id,
        error: contents.error,
      });
      return;
    }
    const sources = contents.files.filter((file) => file.language !== 'watch');
    const tables = contents.files.filter((file) => file.language === 'watch');
    const folders = BLOCK_FOLDERS.filter(
      (folder) =>
        folder.id === 'sources' ||
        (folder.id === 'watch' ? tables.length > 0 : contents.blocks.some((block) => block.kind === folder.id)),
    );
    folders.forEach((folder, folderIndex) => {
      const files = folder.id === 'watch' ? tables : folder.id === 'sources' ? sources : null;
      const members = files ?? contents.blocks.filter((block) => block.kind === folder.id);
      const fKey = folderKey(project.id, folder.id);
      const open = members.length > 0 ? isExpanded(fKey, toggled) : null;
      rows.push({
        type: 'folder',
        key: fKey,
        level: 2,
        posinset: folderIndex + 1,
        setsize: folders.length,
        projectId: project.id,
        folder,
        count: members.length,
        expanded: open,
      });
      if (!open) return;
      if (files) {
        files.forEach((file, fileIndex) =>
          rows.push({
            type: 'file',
            key: fileKey(project.id, file.name),
            level: 3,
            posinset: fileIndex + 1,
            setsize: files.length,
            projectId: project.id,
            file,
          }),
        );
      } else {
        const blocks = members as TreeBlock[];
        blocks.forEach((block, blockIndex) =>
          rows.push({
            type: 'block',
            key: blockKey(project.id, block.kind, block.number),
            level: 3,
            posinset: blockIndex + 1,
            setsize: blocks.length,
            projectId: project.id,
            block,
          }),
        );
      }
    });
  });
  return rows;
}

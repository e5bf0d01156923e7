import { useTranslation } from 'react-i18next';
import type { Project } from '../api/types';
import { ComingBadge } from '../ui/ComingBadge';
import { ChevronIcon, ProjectIcon } from '../ui/icons';
import { BLOCK_FOLDERS, folderKey, projectKey, type BlockFolder } from './blockFolders';

interface ProjectNodeProps {
  project: Project;
  position: number;
  count: number;
  expanded: boolean;
  selected: boolean;
  tabStop: string | null;
  onToggle: () => void;
  onSelect: () => void;
}

/**
 * One project in the tree and, when expanded, its block folders. The tree is flat
 * (levels given by aria-level), so each item's name is just its own row's text.
 */
export function ProjectNode({ project, position, count, expanded, selected, tabStop, onToggle, onSelect }: ProjectNodeProps) {
  const key = projectKey(project.id);
  return (
    <>
      <li
        role="treeitem"
        aria-expanded={expanded}
        aria-selected={selected}
        aria-level={1}
        aria-setsize={count}
        aria-posinset={position}
        tabIndex={tabStop === key ? 0 : -1}
        data-tree-key={key}
        data-testid={`project-node-${project.id}`}
        className="tree-item"
      >
        <div
          className={selected ? 'tree-row tree-row--selected' : 'tree-row'}
          onClick={() => {
            onSelect();
            onToggle();
          }}
          title={project.description || undefined}
        >
          <ChevronIcon className={expanded ? 'tree-twisty tree-twisty--open' : 'tree-twisty'} />
          <ProjectIcon className="tree-icon tree-icon--project" />
          <span className="tree-label">
            <bdi>{project.name}</bdi>
          </span>
        </div>
      </li>
      {expanded
        ? BLOCK_FOLDERS.map((folder, index) => (
            <FolderItem
              key={folder.id}
              folder={folder}
              treeKey={folderKey(project.id, folder.id)}
              position={index + 1}
              tabStop={tabStop}
            />
          ))
        : null}
    </>
  );
}

interface FolderItemProps {
  folder: BlockFolder;
  treeKey: string;
  position: number;
  tabStop: string | null;
}

/** A block folder under a project; its contents arrive with block editing. */
function FolderItem({ folder, treeKey, position, tabStop }: FolderItemProps) {
  const { t } = useTranslation();
  return (
    <li
      role="treeitem"
      aria-level={2}
      aria-setsize={BLOCK_FOLDERS.length}
      aria-posinset={position}
      tabIndex={tabStop === treeKey ? 0 : -1}
      data-tree-key={treeKey}
      className="tree-item tree-item--folder"
      title={t('projects.folders.comingTitle')}
    >
      <div className="tree-row tree-row--leaf">
        <folder.Icon className="tree-icon" />
        <span className="tree-label">{t(folder.labelKey)}</span>{' '}
        <ComingBadge title={t('projects.folders.comingTitle')} />
      </div>
    </li>
  );
}
